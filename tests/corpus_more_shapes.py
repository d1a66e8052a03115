"""The More Shapes mistake corpus: plausible student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter
(starters/more_shapes_starter.py): the lines strictly between a step's start
marker and its end marker are replaced by the student's code for that step; a
step the entry does not give gets the solution's code, read from the same
regions of solutions/more_shapes.py, so the corpus follows the lab when the
lab changes. An entry that changes code OUTSIDE the steps lists exact
(old, new) edits, applied after the steps are filled; each old must occur
exactly once (tests/mutants.py), else building raises AssertionError naming
the entry.

Verdicts:
  CORRECT entries: every check passes.
  WRONG entries: `check` fails (or errors, for a crash) naming `step`; every
  other function check passes; bodies_inertia (it needs steps 2-4) may be
  skipped; a mistake outside the steps fails handout_unchanged and whatever
  its `also` lists.

    build(name) -> source text
    write_corpus(directory, names=None) -> {name: path}
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_files import CorpusFiles, with_says  # noqa: E402  (tests/corpus_files.py: starter + steps + edits)
from corpus_entries import makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)
from wrong_kinds import AS_TEXT, NUMBER, POINTS, VECTOR, returns, wrapped  # noqa: E402  (tests/wrong_kinds.py)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "more_shapes_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "more_shapes.py")

STEPS = (2, 3, 4, 5)
PER_STEP = 3   # wrong entries each step needs at least (tests/corpus_verdicts.py)

CHECK_STEP = {
    "loads": None, "handout_unchanged": None, "runtime_lines": None,
    "polygon_corners": 2, "centroid": 3, "inertia_sum": 4, "parallel_axes": 5,
    "bodies_inertia": None, "runs": None, "triangle_tips": None, "hexagon_tips": None, "pile_stable": None,
    "ramp_holds": None,
}
FUNCTION_CHECKS = ("polygon_corners", "centroid", "inertia_sum", "parallel_axes")
NEEDS_STEPS_2_TO_4 = ("bodies_inertia",)


wrong, correct = makers(CHECK_STEP)


# the lesson's sums of step 4 (polygon_inertia), which several wrong entries keep and end differently
INERTIA_SUMS = """
        num = den = 0.0
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            area2 = abs(cross(a, b))
            num += area2 * (a.dot(a) + a.dot(b) + b.dot(b))
            den += area2"""

WRONG = [
    # ---------------------------------------------------------------- step 2: regular_polygon
    wrong("corners_in_degrees", "uses 360 * k / sides in math.cos and math.sin (degrees into radians)",
          "polygon_corners", {2: """
        return [Vector2(radius * math.cos(360 * k / sides), radius * math.sin(360 * k / sides)) for k in range(sides)]
    """}, why="corner 1 of the triangle lands at 120 rad, not 2π/3"),
    wrong("corners_one_too_many", "off by one: range(sides + 1) repeats corner 0 at the end", "polygon_corners", {2: """
        step = 2 * math.pi / sides
        return [Vector2(radius * math.cos(k * step), radius * math.sin(k * step)) for k in range(sides + 1)]
    """}, why="a triangle gets 4 corners"),
    wrong("corners_sin_cos_swapped", "x from sin and y from cos: corner 0 at (0, radius)", "polygon_corners", {2: """
        return [Vector2(radius * math.sin(2 * math.pi * k / sides), radius * math.cos(2 * math.pi * k / sides))
                for k in range(sides)]
    """}, why="right circle, wrong angles: corner 0 is (0, 34) for the triangle"),
    wrong("corners_diameter", "treats radius as the diameter: radius / 2 from the centre", "polygon_corners", {2: """
        r = radius / 2
        return [Vector2(r * math.cos(2 * math.pi * k / sides), r * math.sin(2 * math.pi * k / sides))
                for k in range(sides)]
    """}, why="every corner is half as far out"),
    # ---------------------------------------------------------------- step 3: polygon_centroid
    wrong("centroid_average_of_corners", "returns the average of the corners", "centroid", {3: """
        total = Vector2()
        for p in points:
            total += p
        return total / len(points)
    """}, why="right for a triangle, wrong for the house (its roof pulls the average up)"),
    wrong("centroid_abs_area", "divides by 6 |A|: the sign flips for counter-clockwise points", "centroid", {3: """
        total = Vector2()
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            total += (a + b) * cross(a, b)
        return total / (6 * abs(area))
    """}, why="the reversed outlines give -C"),
    wrong("centroid_abs_cross", "weights each edge by |a × b| but divides by the signed A", "centroid", {3: """
        total = Vector2()
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            total += (a + b) * abs(cross(a, b))
        return total / (6 * area)
    """}, why="the reversed outlines give -C; the message must not tell it to use the signed A, which it does"),
    wrong("centroid_missing_factor", "divides by 2A (the factor 3 of the 6A is missing)", "centroid", {3: """
        total = Vector2()
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            total += (a + b) * cross(a, b)
        return total / (2 * area)
    """}, why="every centroid is 3 times too far from (0, 0)"),
    wrong("centroid_no_closing_edge", "off by one: the edge from the last point back to the first is left out",
          "centroid", {3: """
        total = Vector2()
        for i in range(len(points) - 1):
            a, b = points[i], points[i + 1]
            total += (a + b) * cross(a, b)
        return total / (6 * area)
    """}, why="the right triangle with a corner at (0, 0) passes (its closing edge adds 0), the house does not"),
    # ---------------------------------------------------------------- step 4: polygon_inertia
    wrong("inertia_missing_six", "forgets the 6 in the denominator", "inertia_sum", {4: INERTIA_SUMS + """
        return mass * num / den
    """}, why="6 times the lesson's value everywhere"),
    wrong("inertia_ignores_mass", "leaves out the mass: returns the inertia per unit mass", "inertia_sum", {4: INERTIA_SUMS + """
        return num / (6 * den)
    """}, why="right only for a mass of 1; the probe's masses run from 0.4 to 4.2"),
    # issue 40: the mass argument ignored, recomputed from the area as build() does
    wrong("inertia_mass_from_area", "ignores the mass argument and recomputes it from the area (area / 1000)",
          "inertia_sum", {4: INERTIA_SUMS + """
        mass = den / 2 / 1000
        return mass * num / (6 * den)
    """}, why="the probe's masses are near area / 1000 except the heavy 40 × 30 box (mass 9, area / 1000 = 1.2)"),
    wrong("inertia_dot_weight", "wrong operand: weighs each triangle by |a · b| instead of |a × b|", "inertia_sum", {4: """
        num = den = 0.0
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            area2 = abs(a.dot(b))
            num += area2 * (a.dot(a) + a.dot(b) + b.dot(b))
            den += area2
        return mass * num / (6 * den)
    """}, why="a regular polygon still passes (equal weights); the irregular ones do not"),
    wrong("inertia_unweighted", "averages the triangles' terms without weighing them by area", "inertia_sum", {4: """
        num = 0.0
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            num += a.dot(a) + a.dot(b) + b.dot(b)
        return mass * num / (6 * len(points))
    """}, why="exact for every regular polygon and every box; wrong for the house, trapezoid and hexagon"),
    wrong("inertia_precedence", "operator precedence: mass * num / 6 * den", "inertia_sum", {4: INERTIA_SUMS + """
        return mass * num / 6 * den
    """}, why="multiplies by the weights' sum instead of dividing"),
    wrong("inertia_wrong_sign", "subtracts the a·b term", "inertia_sum", {4: """
        num = den = 0.0
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            area2 = abs(cross(a, b))
            num += area2 * (a.dot(a) - a.dot(b) + b.dot(b))
            den += area2
        return mass * num / (6 * den)
    """}, why="every shape's inertia is off (a hexagon by a factor 1.5/2.5)"),
    # ---------------------------------------------------------------- step 5: separating_axes
    wrong("axes_dot_not_cross", "wrong operand: skips an axis when |axis · kept| is small (perpendicular, not parallel)",
          "parallel_axes", {5: """
        for axis in edge_normals(pa) + edge_normals(pb):
            if all(abs(axis.dot(kept)) > PARALLEL for kept in axes):
                axes.append(axis)
    """}, why="for two aligned boxes it drops the perpendicular direction and keeps the parallel twins"),
    wrong("axes_same_way_only", "skips only normals pointing the same way; opposite ones stay", "parallel_axes", {5: """
        for axis in edge_normals(pa) + edge_normals(pb):
            if all(axis.dot(kept) < 1 - PARALLEL for kept in axes):
                axes.append(axis)
    """}, why="a hexagon keeps all 6 normals (3 opposite pairs)"),
    wrong("axes_cross_without_abs", "skips when cross(axis, kept) < PARALLEL without abs(): non-parallel axes go too",
          "parallel_axes", {5: """
        for axis in edge_normals(pa) + edge_normals(pb):
            if all(cross(axis, kept) > PARALLEL for kept in axes):
                axes.append(axis)
    """}, why="a box keeps only its first normal: the perpendicular one has a negative cross"),
    wrong("axes_only_a", "only A's edge normals (deduplicated)", "parallel_axes", {5: """
        for axis in edge_normals(pa):
            if all(abs(cross(axis, kept)) > PARALLEL for kept in axes):
                axes.append(axis)
    """}, why="a box and a turned box: B's directions are missing, the lesson's diamond is called a hit"),
    wrong("axes_dot_threshold", "skips an axis when 1 - |axis · kept| <= PARALLEL (a cosine test, about θ²/2)",
          "parallel_axes", {5: """
        for axis in edge_normals(pa) + edge_normals(pb):
            if all(1 - abs(axis.dot(kept)) > PARALLEL for kept in axes):
                axes.append(axis)
    """}, why="two boxes turned 0.01° apart: 1 - cos θ = 1.5e-8 merges them, |sin θ| = 1.7e-4 keeps both"),
    wrong("axes_last_kept_only", "compares each normal with the last kept axis only", "parallel_axes", {5: """
        for axis in edge_normals(pa) + edge_normals(pb):
            if not axes or abs(cross(axis, axes[-1])) > PARALLEL:
                axes.append(axis)
    """}, why="a hexagon's fourth normal is compared with the third, not with its twin the first"),
    # ---------------------------------------------------------------- issue 33: values that name their formula
    wrong("corners_half_turn", "θk = πk / sides: π where 2π belongs", "polygon_corners", {2: """
        return [Vector2(radius * math.cos(math.pi * k / sides), radius * math.sin(math.pi * k / sides))
                for k in range(sides)]
    """}, why="the corners spread over half a turn: the triangle's corner 1 lands at 60°, not 120°"),
    wrong("centroid_xy_swapped", "sums the y coordinates into x and the x ones into y", "centroid", {3: """
        cx = cy = 0.0
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            w = cross(a, b)
            cx += (a.y + b.y) * w
            cy += (a.x + b.x) * w
        return Vector2(cx, cy) / (6 * area)
    """}, why="the house's centroid (30, -20.42) comes back as (-20.42, 30)"),
    wrong("inertia_returns_inverse", "returns 1 / I (the inverse inertia) instead of I", "inertia_sum", {4: INERTIA_SUMS + """
        return 6 * den / (mass * num)
    """}, why="the triangle's 433.5 comes back as 0.0023"),
    wrong("axes_not_unit", "builds the edge normals by hand, (-edge.y, edge.x), never normalised", "parallel_axes",
          {5: """
        for points in (pa, pb):
            for i, a in enumerate(points):
                edge = points[(i + 1) % len(points)] - a
                axis = Vector2(-edge.y, edge.x)
                if all(abs(cross(axis, kept)) > PARALLEL for kept in axes):
                    axes.append(axis)
    """}, why="a 60 px edge gives an axis of length 60: the shadows (and the depth) come out 60 times too long"),
    # ---------------------------------------------------------------- outside the steps
    wrong("outside_library_inertia", "build() lets Body compute the inertia (the student's polygon_inertia unused)",
          "handout_unchanged", edits=[(
              "                vel=item.get(\"vel\", (0, 0)), omega=item.get(\"omega\", 0.0), "
              "inertia=polygon_inertia(local, mass),\n",
              "                vel=item.get(\"vel\", (0, 0)), omega=item.get(\"omega\", 0.0),\n")],
          also=("bodies_inertia",),
          why="the handout's build() line changed; the checker replays build() with the handout's code, which "
              "calls polygon_inertia where this file's does not, so bodies_inertia cannot be judged (an error)"),
    wrong("outside_sat_no_flip", "deleted the handout's A-to-B flip in sat()", "handout_unchanged", edits=[(
        "    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:\n        best_axis = -best_axis  # always from A to B\n",
        "")], also=("parallel_axes",), why="sat() changed outside the steps; half its normals point B to A"),
    wrong("outside_parallel_tolerance", "set PARALLEL to 0.1 (skips axes 5.7° apart)", "handout_unchanged", edits=[(
        "PARALLEL = 1e-6 ", "PARALLEL = 0.1 ")], also=("parallel_axes",),
        why="a constant of the handout changed; the 0.01 rad pair loses a direction"),
]

CORRECT = [
    correct("correct_solution_steps", "the solution's own code in every step",
            why="the reference build equals the solution"),
    correct("correct_rotated_vectors", "rotate_rad for the corners, zip() over edges, a signed triangle fan", {
        2: """
            turn = 2 * math.pi / sides
            return [Vector2(radius, 0).rotate_rad(k * turn) for k in range(sides)]
        """,
        3: """
            cx = cy = 0.0
            for a, b in zip(points, points[1:] + points[:1]):
                w = a.x * b.y - a.y * b.x
                cx += (a.x + b.x) * w
                cy += (a.y + b.y) * w
            return Vector2(cx, cy) / (6 * area)
        """,
        4: """
            num = den = 0.0
            for a, b in zip(points, points[1:] + points[:1]):
                c = a.cross(b)  # signed: all one sign for a convex polygon around its centroid
                num += c * (a.length_squared() + a.dot(b) + b.length_squared())
                den += c
            return mass * num / (6 * den)
        """,
        5: """
            for axis in edge_normals(pa) + edge_normals(pb):
                if not any(abs(axis.cross(kept)) <= PARALLEL for kept in axes):
                    axes.append(axis)
        """}, why="the same formulas: rotate_rad(θ) of (r, 0) is (r cos θ, r sin θ); signed weights cancel in "
                  "the ratio; 'not any <=' is 'all >'"),
    correct("correct_triangle_fan_centroid", "centroid as the area-weighted mean of fan triangles from corner 0; "
            "math.fsum; a while loop", {
        2: """
            corners = []
            k = 0
            while k < sides:
                angle = k * 2 * math.pi / sides
                corners.append(Vector2(math.cos(angle), math.sin(angle)) * radius)
                k += 1
            return corners
        """,
        3: """
            origin = points[0]
            weighted = Vector2()
            total = 0.0
            for i in range(1, len(points) - 1):
                b, c = points[i], points[i + 1]
                part = cross(b - origin, c - origin) / 2  # signed area of triangle (origin, b, c)
                weighted += (origin + b + c) / 3 * part
                total += part
            return weighted / total
        """,
        4: """
            weights, terms = [], []
            for i in range(len(points)):
                a, b = points[i], points[(i + 1) % len(points)]
                weights.append(abs(cross(a, b)))
                terms.append(a.dot(a) + a.dot(b) + b.dot(b))
            return mass * math.fsum(w * t for w, t in zip(weights, terms)) / (6 * math.fsum(weights))
        """,
        5: """
            candidates = list(edge_normals(pa))
            candidates.extend(edge_normals(pb))
            for axis in candidates:
                parallel = False
                for kept in axes:
                    if abs(axis.x * kept.y - axis.y * kept.x) <= PARALLEL:
                        parallel = True
                        break
                if not parallel:
                    axes.append(axis)
        """}, why="a polygon's centroid is the area-weighted mean of its fan triangles' centroids; the rest "
                  "are the lesson's sums written longhand"),
    correct("correct_comprehensions", "sum() of generators; axes by index", {
        3: """
            n = len(points)
            total = sum(((points[i] + points[(i + 1) % n]) * cross(points[i], points[(i + 1) % n])
                         for i in range(n)), Vector2())
            return total / (6 * area)
        """,
        4: """
            n = len(points)
            edges = [(points[i], points[(i + 1) % n]) for i in range(n)]
            weights = [abs(cross(a, b)) for a, b in edges]
            num = sum(w * (a * a + a * b + b * b) for w, (a, b) in zip(weights, edges))
            return mass * num / (6 * sum(weights))
        """,
        5: """
            normals = edge_normals(pa) + edge_normals(pb)
            for i in range(len(normals)):
                if all(abs(cross(normals[i], kept)) > PARALLEL for kept in axes):
                    axes.append(normals[i])
        """}, why="Vector2 * Vector2 is the dot product; by index is the same loop"),
    correct("correct_b_first_one_way", "B's normals first, each axis turned to point right (or down)", {5: """
        for axis in edge_normals(pb) + edge_normals(pa):
            if axis.x < -PARALLEL or (abs(axis.x) <= PARALLEL and axis.y < 0):
                axis = -axis  # one way per direction
            if all(abs(cross(axis, kept)) > PARALLEL for kept in axes):
                axes.append(axis)
    """}, why="the same directions in another order and sense: sat() turns its normal from A to B anyway, "
              "and no two directions tie for the smallest overlap"),
]

# the words each wrong entry's first message must contain: it names the mistake, not only the step (issue 33)
SAYS = {
    "corners_in_degrees": ("in degrees",),
    "corners_one_too_many": ("4 corners",),
    "corners_sin_cos_swapped": ("x and y are swapped",),
    "corners_diameter": ("0.5 × radius",),
    "corners_half_turn": ("half a turn",),
    "centroid_average_of_corners": ("corners' average",),
    "centroid_abs_area": ("sign flipped",),
    "centroid_abs_cross": ("sign flipped",),
    "centroid_missing_factor": ("divided by 2A, not 6A",),
    "centroid_no_closing_edge": ("last point back to the first",),
    "centroid_xy_swapped": ("x and y swapped",),
    "inertia_missing_six": ("not divided by 6",),
    "inertia_ignores_mass": ("mass factor is missing",),
    "inertia_mass_from_area": ("mass argument is ignored",),
    "inertia_dot_weight": ("weighted by |a · b|",),
    "inertia_unweighted": ("not weighted by |a × b|",),
    "inertia_precedence": ("brackets",),
    "inertia_wrong_sign": ("a·b term is subtracted",),
    "inertia_returns_inverse": ("1 / I",),
    "axes_dot_not_cross": ("|axis · kept| is small",),
    "axes_same_way_only": ("the opposite way is parallel too",),
    "axes_cross_without_abs": ("has no abs()",),
    "axes_only_a": ("only A's edge normals",),
    "axes_dot_threshold": ("1 - |axis · kept|",),
    "axes_last_kept_only": ("last kept axis only",),
    "axes_not_unit": ("not a unit vector",),
    "outside_library_inertia": ("inertia=polygon_inertia(local, mass)",),
    "outside_sat_no_flip": ("best_axis) < 0",),
    "outside_parallel_tolerance": ("PARALLEL = 0.1",),
}
WRONG = with_says(WRONG, SAYS)

# What tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself (each key optional):
# short (its entries' name prefix), mechanisms (the issue-35 mechanisms that apply; tests/corpus_attacks.py
# says why), library_name / library_owner (the library's answer to the first step where it is not the first
# STEP_LIBRARY name), world_call, hidden, forger and side (the attacks' code where the default does not fit).
ATTACK = {
    "short": "ms",
    "mechanisms": (1, 2, 5, 6, 7, 8, 10),
    "world_call": "return [p for p in World().bodies] or Polygon(box_points(2 * radius, radius)).points",
    "side": (2, "regular_polygon", "from lesson11.physics2d import regular_polygon as found", "polygon_corners"),
}

# The wrong-kind values its step functions must fail on, never the checker (tests/test_wrong_kinds.py):
# [(function, step, [case, ...])], the cases written as tests/wrong_kinds.py says.
WRONG_KINDS = [("regular_polygon", 2, returns(POINTS) + wrapped(AS_TEXT + ["[str(p) for p in answer]"])),
               ("polygon_centroid", 3, returns(VECTOR) + wrapped(AS_TEXT + ["[answer]"])),
               ("polygon_inertia", 4, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]", "(answer,)"])),
               ("separating_axes", 5, returns(POINTS))]

# The wrong entry `python -m checker FILE --show` is tried on (tests/test_checker_show.py): one wrong step
# whose scene differs visibly from the solution's, and the kind of failing case --show draws for it.
SHOW_ENTRY, SHOW_CASE = 'inertia_missing_six', 'PolygonCase'

# the mistake id each entry's failing check must carry (issue 40: --json's "mistake")
MISTAKE_IDS = {
    "inertia_missing_six": "polygon_inertia_no_six", "inertia_ignores_mass": "polygon_inertia_no_mass",
    "inertia_dot_weight": "polygon_inertia_dot_weight", "inertia_unweighted": "polygon_inertia_unweighted",
    "inertia_precedence": "polygon_inertia_precedence", "inertia_wrong_sign": "polygon_inertia_minus_cross_term",
    "inertia_returns_inverse": "polygon_inertia_inverse", "inertia_mass_from_area": "polygon_inertia_mass_from_area",
}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"

# ================================================================ building the files (tests/corpus_files.py)

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_more_shapes.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
