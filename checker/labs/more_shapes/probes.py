"""More Shapes' function steps declared as data (checker/judging/declared.py), and the probe of the lab's bodies.

Each Step holds its cases, the lesson's answer (computed in the grader only) and the known wrong forms:
    regular_polygon   (step 2) 3 to 12 sides, radii from 5 to 40 px, and one polygon drawn for the run
    polygon_centroid  (step 3) a right triangle, a house, a trapezoid, irregular outlines far from (0, 0), both windings
    polygon_inertia   (step 4) regular polygons and boxes (their analytic inertias), irregular centred outlines
    separating_axes   (step 5) pairs aligned (parallel edges to skip), turned (none to skip), nearly parallel (keep);
                      two drawn per run, one with a direction to skip and one without
    sat               (step 5) the same pairs and Tumbling Crates' pairs, through the lab's sat() on the student's axes,
                      and four drawn per run, overlapping and apart
    bodies            build() for every kind: the lab's bodies' mass and inertia (the inertia criterion)
Units: px, s, rad; mass = area / 1000.
"""
import math

from pygame import Vector2

from lesson11.physics2d import box_points, convex_polygon, cross, edge_normals, polygon_area
from lesson11.physics2d import polygon_centroid, polygon_inertia, regular_polygon

from checker.judging import probe_kit
from checker.judging.common import as_number, as_point, as_points, is_text
from checker.judging.common import close, same_point
from checker.judging.declared import Form, Step, forms_of
from checker.judging.lab_checks import vec_text
from checker.judging.probe_kit import judging, reference

reference_centroid = reference(polygon_centroid)
reference_inertia = reference(polygon_inertia)
reference_regular_polygon = reference(regular_polygon)
from checker.judging.tape import run_rng

REQUIRED = ("regular_polygon", "polygon_centroid", "polygon_inertia", "separating_axes", "sat", "build", "main")
PARALLEL = 1e-6   # |sin| below which two axes are parallel (the handout's PARALLEL)
TOUCHING = 1e-6   # px: a depth this small for shapes exactly touching counts as "apart"


def _plain(points):
    return [[float(p[0]), float(p[1])] for p in points]


# ---------------------------------------------------------------- step 2: regular_polygon

POLYGONS = ((3, 34.0), (4, 20.0), (5, 30.5), (6, 28.0), (7, 12.0), (8, 40.0), (12, 5.0))


@reference
def _corner_forms(sides, radius):
    """What the known wrong corner formulas give, by name: θk in degrees, πk / n (half a turn), x from sin."""
    def corners(angle, swap=False):
        points = [(radius * math.cos(angle(k)), radius * math.sin(angle(k))) for k in range(sides)]
        return [[y, x] if swap else [x, y] for x, y in points]
    return {"degrees": corners(lambda k: 360 * k / sides), "half_turn": corners(lambda k: math.pi * k / sides),
            "sin_cos": corners(lambda k: 2 * math.pi * k / sides, swap=True)}


def _near(got, want, radius):
    return close(got, want, floor=1e-7 * max(radius, 1.0))


def _same_corners(got, want, radius):
    return (not isinstance(got, str) and len(got) == len(want)
            and all(_near(g[0], w[0], radius) and _near(g[1], w[1], radius) for g, w in zip(got, want)))


def _corner_mistake(cases, case):
    """A known wrong formula the cases tell apart, else what this case's corners show: how many, how far, in
    which order."""
    named = CORNERS.named(cases, case)
    got, sides, radius = case["got"], case["sides"], case["radius"]
    if named or isinstance(got, str):
        return named
    if len(got) != sides:
        return Form("corners_count", f"your polygon has {len(got)} corners; a {sides}-gon has {sides}: k runs over "
                                     "range(sides)")
    distances = [math.hypot(*p) for p in got]
    if not all(_near(d, radius, radius) for d in distances):
        ratio = sum(distances) / len(distances) / radius
        if all(close(d / radius, ratio) for d in distances):
            return Form("corners_radius", f"every corner is {ratio:.4g} × radius from the centre; they belong on the "
                                          "circle of `radius` px")
        return Form("corners_off_circle", "the corners are not all `radius` px from the centre (0, 0)")
    if all(any(_near(g[0], w[0], radius) and _near(g[1], w[1], radius) for w in case["want"]) for g in got):
        return Form("corners_order", "these are the right corners in another order: corner k at θk = 2πk / sides")
    return Form("corners_angles", "the corners lie on the circle but at other angles: corner 0 at (radius, 0), each "
                                  "next 2π / sides further")


def _first_corner(case):
    got, want = case["got"], case["want"]
    k = next((k for k, (g, w) in enumerate(zip(got, want)) if not (_near(g[0], w[0], case["radius"])
              and _near(g[1], w[1], case["radius"]))), min(len(got), len(want)))
    shown = f"corner {k} is {vec_text(got[k])}, expected {vec_text(want[k])}" if k < min(len(got), len(want)) \
        else f"{len(got)} corners, expected {len(want)}"
    return f"regular_polygon({case['sides']}, {case['radius']:g}): {shown}."


def _polygons(module):
    rng = run_rng(module, "regular_polygon")   # and one polygon drawn for this run
    return [{"sides": sides, "radius": radius}
            for sides, radius in POLYGONS + ((rng.randint(3, 11), round(rng.uniform(6, 60), 1)),)]


CORNERS = Step(
    "polygon_corners", "Step 2: regular_polygon(sides, radius) puts corner k at radius (cos θk, sin θk), θk = 2πk / "
    "sides.", 2, "regular_polygon", _polygons, lambda polygon, c: as_points(polygon(c["sides"], c["radius"])),
    lambda c: _plain(reference_regular_polygon(c["sides"], c["radius"])), hint="corners",
    same=lambda got, want: _same_corners(got, want, math.hypot(*want[0])), bad=is_text,
    kind="a list of points", show=lambda points: f"{len(points)} corners from {vec_text(points[0])}",
    label=lambda c: f"regular_polygon({c['sides']}, {c['radius']:g})", diagnose=_corner_mistake,
    evidence=_first_corner, unnamed="regular_polygon() does not put corner k at θk = 2πk / sides",
    wrong=forms_of({"degrees": "θk = 360k / sides is in degrees; math.cos and math.sin take radians: θk = 2πk / sides",
                    "half_turn": "θk = πk / sides spreads the corners over half a turn: θk = 2πk / sides",
                    "sin_cos": "your x and y are swapped: x = radius cos θk, y = radius sin θk"},
                   lambda c: _corner_forms(c["sides"], c["radius"]), "corners_"))


# ---------------------------------------------------------------- step 3: polygon_centroid

def _shift(points, by):
    return [Vector2(p) + Vector2(by) for p in points]


def centroid_cases():
    """(name, corners): convex outlines NOT centred on (0, 0); a mirror copy runs the other way round."""
    house = [(0, 0), (0, -30), (30, -50), (60, -30), (60, 0)]
    return [
        ("a right triangle with its corner at (0, 0)", [(0, 0), (60, 0), (0, 40)]),
        ("a house (a box with a gable roof)", house),
        ("a trapezoid far from (0, 0)", _shift([(0, 0), (80, 0), (60, 30), (20, 30)], (300, 200))),
        ("an irregular hexagon", _shift([(0, 0), (40, -10), (70, 10), (75, 45), (30, 60), (-5, 30)], (-40, 25))),
        ("a kite with one long tail", [(0, 0), (20, -15), (90, 0), (20, 15)]),
        ("a box far from (0, 0)", _shift(box_points(50, 30), (120, -80))),
    ]


def drawn_outline(rng):
    """A convex outline drawn for this run: 5-8 corners on a stretched circle, far from (0, 0)."""
    sides = rng.randint(5, 8)
    angles = sorted(rng.uniform(0, 360) for _ in range(sides))
    if any(b - a < 20 for a, b in zip(angles, angles[1:] + [angles[0] + 360])):   # keep corners apart
        angles = [k * 360 / sides + rng.uniform(-8, 8) for k in range(sides)]
    stretch, turn = rng.uniform(1.2, 2.2), rng.uniform(0, 180)
    centre = Vector2(rng.uniform(-300, 300), rng.uniform(-300, 300))
    radius = rng.uniform(20, 60)
    return [centre + Vector2(radius * stretch * math.cos(math.radians(a)), radius * math.sin(math.radians(a)))
            .rotate(turn) for a in angles]


def _outlines(module):
    """centroid_cases() and an outline drawn for this run, each also the other way round."""
    drawn = [("an outline drawn for this run", drawn_outline(run_rng(module, "polygon_centroid")))]
    return [{"case": name + order, "points": _plain(points)} for name, corners in centroid_cases() + drawn
            for order, points in (("", corners), (" (the other way round)", list(reversed(corners))))]


def _size(case):
    return max(1.0, *(abs(v) for p in case["points"] for v in p))


def _scaled(got, want, size, factor=1.0):
    """got is want × factor to 1e-7 of the outline's size (and of want): the same sum in another order."""
    return want is not None and all(close(g, factor * w, floor=1e-7 * size) for g, w in zip(got, want))


@reference
def _centroid_forms(case):
    """What the corners' average, the x and y sums swapped and the sum without the closing edge give."""
    pts, want = [Vector2(p) for p in case["points"]], reference_centroid([Vector2(p) for p in case["points"]])
    weights = [cross(a, b) for a, b in zip(pts, pts[1:])]   # every edge but the last point back to the first
    open_sum = sum(((a + b) * w for (a, b), w in zip(zip(pts, pts[1:]), weights)), Vector2())
    return {"average": list(sum(pts, Vector2()) / len(pts)), "xy_swapped": [want.y, want.x],
            "no_closing_edge": list(open_sum / (6 * polygon_area(pts)))}


def _centroid_case(cases, case):
    """What this case's centroid shows by itself: -C (one winding's sign), or C times a wrong divisor."""
    got, want, size = case["got"], case["want"], _size(case)
    if _scaled(got, want, size, -1):
        return Form("centroid_sign", "your centroid has its sign flipped when the points wind the other way: a × b "
                                     "and A must both be signed, or both not")
    return next((Form("centroid_divisor", f"your centroid is {factor:g} × the lesson's: the sum is divided by {by}, "
                                          "not 6A") for factor, by in ((3, "2A"), (6, "A"), (2, "3A"), (1 / 2, "12A"))
                 if _scaled(got, want, size, factor)), None)


CENTROID = Step(
    "centroid", "Step 3: polygon_centroid() is the area-weighted centroid Σ (a + b)(a × b) / (6 A), either winding.",
    3, "polygon_centroid", _outlines, lambda centroid, c: centroid([Vector2(p) for p in c["points"]]),
    lambda c: list(reference_centroid([Vector2(p) for p in c["points"]])), answer=as_point, hint="centroid",
    bad=is_text, accepts=lambda c: _scaled(c["got"], c["want"], _size(c)),
    same=same_point, diagnose=_centroid_case,
    malformed=lambda c: f"polygon_centroid() must return a point (a Vector2).\nfor {c['case']} it returned {c['got']}.",
    evidence=lambda c: f"for {c['case']}, yours is {vec_text(c['got'])}; the area-weighted centroid "
                       f"{vec_text(c['want'])}.", unnamed="polygon_centroid() is not the area-weighted centroid",
    passed="the centroid of all {n} outlines (both windings) is the area-weighted one",
    wrong=forms_of({"average": "your centroid is the corners' average, the centre of mass only for triangles and "
                               "symmetric shapes: weight by area",
                    "xy_swapped": "your centroid has x and y swapped: the x sum takes the x coordinates, "
                                  "Σ (a.x + b.x)(a × b)",
                    "no_closing_edge": "the edge from the last point back to the first is missing: wrap round with "
                                       "(i + 1) % len(points)"}, _centroid_forms, "centroid_"),
    extra={"average": lambda c: _centroid_forms(c)["average"]})   # drawn by --show


# ---------------------------------------------------------------- step 4: polygon_inertia

@reference
def analytic_inertia(kind, mass, radius=None, w=None, h=None, sides=None):
    """The textbook inertia (mass·px²): a box m (w² + h²) / 12, a regular n-gon m r² (2 + cos(2π/n)) / 6."""
    if kind == "box":
        return mass * (w * w + h * h) / 12
    return mass * radius * radius * (2 + math.cos(2 * math.pi / sides)) / 6


@reference
def _inertia_forms(points, mass):
    """What the usual mistakes give for these centred points, by name (to name the student's): mostly the lesson's
    triangle-fan sum with one part changed (fan's switches)."""
    pts = [Vector2(p) for p in points]
    pairs = [(a, pts[(i + 1) % len(pts)]) for i, a in enumerate(pts)]
    total = sum(abs(cross(a, b)) for a, b in pairs)

    def fan(m=mass, weight=lambda a, b: abs(cross(a, b)), term=lambda a, b: a.dot(a) + a.dot(b) + b.dot(b), six=6):
        weights = [weight(a, b) for a, b in pairs]
        return m * sum(w * term(a, b) for w, (a, b) in zip(weights, pairs)) / (six * sum(weights)) if sum(weights) \
            else None
    return {
        "inverse": 1 / fan(),
        "dot_weight": fan(weight=lambda a, b: abs(a.dot(b))),
        "no_six": fan(six=1),
        "twelve": fan(six=12),
        "no_mass": fan(m=1),
        "no_cross_term": fan(term=lambda a, b: a.dot(a) + b.dot(b)),
        "unweighted": fan(weight=lambda a, b: 1),
        "corner_radii": mass * sum(p.length_squared() for p in pts) / len(pts),
        "times_mass_squared": fan(m=mass * mass),
        "precedence": fan() * total * total,   # mass * num / 6 * den: the weights' sum multiplies
        "minus_cross_term": fan(term=lambda a, b: a.dot(a) - a.dot(b) + b.dot(b)),
        # issue 40: the mass argument ignored, recomputed from the area (the handout's DENSITY, 1/1000 per px²)
        "mass_from_area": fan(m=total / 2 / 1000),
        "no_abs": fan(weight=cross),   # None when the signed weights cancel
    }


def inertia_cases():
    """(name, centred points, mass, the analytic inertia's arguments (analytic_inertia) or None)."""
    cases = []
    for sides, radius, mass in ((3, 34, 1.5), (4, 20, 0.8), (5, 30, 2.1), (6, 28, 2.0), (7, 15, 0.4), (8, 40, 4.2)):
        cases.append((f"a regular {sides}-gon of radius {radius} px, mass {mass:g}",
                      regular_polygon(sides, radius), mass,
                      {"kind": "polygon", "mass": mass, "radius": radius, "sides": sides}))
    # the last box is heavy for its size (mass 9, area / 1000 = 1.2), so a mass recomputed from the area shows
    for w, h, mass in ((30, 20, 2.0), (80, 45, 3.6), (12, 70, 0.84), (40, 30, 9.0)):
        cases.append((f"a {w} × {h} box, mass {mass:g}", box_points(w, h), mass,
                      {"kind": "box", "mass": mass, "w": w, "h": h}))
    for name, corners in centroid_cases()[:4]:
        centred = convex_polygon(corners)
        cases.append((f"{name}, centred on its centroid, mass 1.7", centred, 1.7, None))
        cases.append((f"{name}, centred, the other way round, mass 1.7", list(reversed(centred)), 1.7, None))
    return cases


def _inertia_cases(module):
    """inertia_cases() and an outline drawn for this run, as dicts."""
    rng = run_rng(module, "polygon_inertia")
    mass = rng.uniform(2.5, 9.0)
    drawn = [(f"an outline drawn for this run, centred, mass {mass:.3g}", convex_polygon(drawn_outline(rng)), mass,
              None)]
    return [{"case": name, "points": _plain(points), "mass": mass, "analytic_of": analytic}
            for name, points, mass, analytic in inertia_cases() + drawn]


# step 4's known wrong sums, by the name _inertia_forms gives their values
INERTIA_MISTAKES = {
    "inverse": "that is 1 / I: return the inertia I itself (the Body takes the inverse, inv_inertia, from it)",
    "dot_weight": "the triangles are weighted by |a · b| where the formula weights them by |a × b| (their area)",
    "no_six": "the sum is not divided by 6",
    "twelve": "the sum is divided by 12 where the formula has 6",
    "no_mass": "the mass factor is missing",
    "times_mass_squared": "the mass is multiplied in twice",
    "no_cross_term": "each triangle's term lacks a·b: it is a·a + a·b + b·b",
    "unweighted": "the triangles are not weighted by |a × b| (their area)",
    "corner_radii": "that is m × the mean squared corner distance, not the triangle-fan sum",
    "no_abs": "the weights are the signed a × b; use abs(cross(a, b)) so that either winding works",
    "precedence": "mass * num / 6 * den multiplies by the weights' sum: divide by (6 * den), brackets included",
    "minus_cross_term": "the a·b term is subtracted; each triangle adds a·a + a·b + b·b",
    "mass_from_area": "the mass argument is ignored: the mass is recomputed from the area (area / 1000); use the "
                      "`mass` you are given",
}

INERTIA = Step(
    "inertia_sum", "Step 4: polygon_inertia() is the triangle-fan sum m Σ |a × b|(a·a + a·b + b·b) / (6 Σ |a × b|).",
    4, "polygon_inertia", _inertia_cases, lambda inertia, c: inertia([Vector2(p) for p in c["points"]], c["mass"]),
    lambda c: reference_inertia([Vector2(p) for p in c["points"]], c["mass"]), answer=as_number, hint="inertia",
    same=lambda got, want: not isinstance(got, str) and want is not None and close(got, want),
    bad=is_text, kind="a number", show=lambda value: f"{value:.6g}",
    label=lambda c: f"polygon_inertia() for {c['case']}", unnamed="polygon_inertia() is not the triangle-fan sum",
    wrong=forms_of(INERTIA_MISTAKES, lambda c: _inertia_forms(c["points"], c["mass"]), "polygon_inertia_"),
    extra={"analytic": lambda c: analytic_inertia(**c["analytic_of"]) if c["analytic_of"] else None})


# ---------------------------------------------------------------- step 5: separating_axes and sat

def axis_pairs():
    """(name, A's world points, B's world points): aligned shapes share edge directions, turned ones do not."""
    box, ngon = probe_kit.box, probe_kit.ngon
    return [
        ("two aligned boxes", box(60, 40, (0, 0)), box(50, 30, (45, 20))),
        ("a box and a turned box", box(60, 40, (0, 0)), box(50, 30, (45, 20), 30)),
        ("two aligned hexagons", ngon(6, 30, (0, 0)), ngon(6, 24, (50, 10))),
        ("a hexagon on a box (the top and bottom edges are parallel)", box(200, 40, (0, 0)), ngon(6, 30, (20, -44))),
        ("a turned hexagon on a box", box(200, 40, (0, 0)), ngon(6, 30, (20, -48), 17)),
        ("a triangle and the same triangle upside down", ngon(3, 34, (0, 0)), ngon(3, 34, (30, 8), 180)),
        ("two triangles turned apart", ngon(3, 34, (0, 0), 10), ngon(3, 30, (40, 20), 75)),
        ("a pentagon and a pentagon turned half a corner", ngon(5, 30, (0, 0)), ngon(5, 30, (50, 8), 36)),
        ("a hexagon and a box turned 0.01 rad (nearly parallel: keep both)", ngon(6, 30, (0, 0)),
         box(60, 40, (40, 35), math.degrees(0.01))),
        # 0.01° apart: |a × b| = 1.7e-4 > PARALLEL keeps both; 1 - |a · b| = 1.5e-8 (about θ²/2) would merge them
        ("two boxes turned 0.01° apart (nearly parallel: keep both)", box(60, 40, (0, 0)),
         box(50, 30, (45, 20), 0.01)),
        ("two aligned boxes, far apart", box(40, 40, (0, 0)), box(40, 40, (300, 0))),
        # B's first normal is parallel to A's last: comparing with the last kept axis only shows as itself
        ("a box and a box turned a quarter turn", box(60, 40, (0, 0)), box(60, 40, (45, 20), 90)),
        ("a pentagon far from a triangle", ngon(5, 30, (0, 0), 10), ngon(3, 30, (200, 50))),
    ]


@reference
def distinct_directions(axes, keep=lambda axis, kept: all(abs(cross(axis, other)) > PARALLEL for other in kept)):
    """The lesson's answer: the axes in order, each kept unless parallel (|a × b| <= PARALLEL) to one kept; with
    another rule keep(axis, kept), what that rule keeps (a known wrong form)."""
    kept = []
    for axis in axes:
        if keep(axis, kept):
            kept.append(axis)
    return kept


def drawn_axis_pairs(rng):
    """Two pairs drawn for this run: odd-sided polygons with no edge directions in common (every normal is an axis)
    and a box beside a box or a hexagon turned to share a direction (a parallel twin to skip), so a table of the
    fixed pairs' axes with one rule for the rest (every normal, say) is wrong on one of them. Directions not
    shared are at least 3° apart: no pair near the PARALLEL threshold."""
    def clear(pa, pb, shared):
        normals_a, normals_b = edge_normals(pa), edge_normals(pb)
        sines = [abs(cross(u, v)) for u in normals_a for v in normals_b]
        sines += [abs(cross(u, v)) for normals in (normals_a, normals_b) for i, u in enumerate(normals)
                  for v in normals[i + 1:]]
        return all(sine <= PARALLEL or sine > 0.05 for sine in sines) and \
            any(abs(cross(u, v)) <= PARALLEL for u in normals_a for v in normals_b) == shared

    def near():
        return Vector2(rng.uniform(10, 80), 0).rotate(rng.uniform(0, 360))

    pairs = []
    while not pairs:
        pa = probe_kit.ngon(rng.choice((3, 5, 7)), rng.uniform(15, 45), (0, 0), rng.uniform(0, 360))
        pb = probe_kit.ngon(rng.choice((3, 5, 7)), rng.uniform(15, 45), near(), rng.uniform(0, 360))
        if clear(pa, pb, shared=False):
            pairs.append(("two odd-sided polygons drawn for this run, no edge parallel to another (1 of 2)", pa, pb))
    while len(pairs) < 2:
        angle = rng.uniform(0, 360)
        pa = probe_kit.box(rng.uniform(24, 90), rng.uniform(24, 90), (0, 0), angle)
        if rng.random() < 0.5:
            pb = probe_kit.box(rng.uniform(24, 90), rng.uniform(24, 90), near(), angle + rng.choice((0, 90, 180)))
        else:   # a hexagon's normals are 30° past its corners: turned so, one is along the box's first normal
            pb = probe_kit.ngon(6, rng.uniform(15, 45), near(), angle - 30 + 60 * rng.randint(0, 5))
        if clear(pa, pb, shared=True):
            pairs.append(("a box drawn for this run and a shape sharing its edge directions (2 of 2)", pa, pb))
    return pairs


def _pairs(pairs, drawn, salt):
    """The cases of step 5's probes: each pair of world points, fixed then drawn for this run (drawn(rng), rng from
    the run's seed and `salt`), then the same pair with A and B swapped."""
    return lambda module: [{"pair": name, "order": order, "a": _plain(first), "b": _plain(second)}
                           for name, pa, pb in pairs() + drawn(run_rng(module, salt))
                           for order, first, second in (("A, B", pa, pb), ("B, A", pb, pa))]


def _call_pair(function, case):
    return function([Vector2(p) for p in case["a"]], [Vector2(p) for p in case["b"]])


def _label(case):
    return f"for '{case['pair']}'" + (" with A and B swapped" if case["order"] == "B, A" else "")


def _normals(case, side, plain=True):
    """The edge normals of the case's shape A ("a") or B ("b"), as plain [x, y] or (plain=False) Vector2s."""
    normals = edge_normals([Vector2(p) for p in case[side]])
    return _plain(normals) if plain else normals


@reference
def _axes_forms(case):
    """What the known wrong ways of skipping parallel axes keep, by name (AXES_MISTAKES)."""
    normals_a = _normals(case, "a", plain=False)
    normals = normals_a + _normals(case, "b", plain=False)

    def kept_by(keep, normals=normals):
        return _plain(distinct_directions(normals, keep))
    return {
        "dot_not_cross": kept_by(lambda a, kept: all(abs(a.dot(k)) > PARALLEL for k in kept)),
        "same_way_only": kept_by(lambda a, kept: all(a.dot(k) < 1 - PARALLEL for k in kept)),
        "cross_without_abs": kept_by(lambda a, kept: all(cross(a, k) > PARALLEL for k in kept)),
        "only_a": kept_by(lambda a, kept: all(abs(cross(a, k)) > PARALLEL for k in kept), normals_a),
        "dot_threshold": kept_by(lambda a, kept: all(1 - abs(a.dot(k)) > PARALLEL for k in kept)),
        "last_kept_only": kept_by(lambda a, kept: not kept or abs(cross(a, kept[-1])) > PARALLEL),
        "none_skipped": kept_by(lambda a, kept: True),
    }


# the known wrong ways of skipping parallel axes, by the name _axes_forms gives what they keep
AXES_MISTAKES = {
    "dot_not_cross": "an axis is skipped when |axis · kept| is small, i.e. perpendicular; parallel means |axis × kept| "
                     "near 0",
    "same_way_only": "only an axis pointing the same way as a kept one is skipped; one pointing the opposite way is "
                     "parallel too",
    "cross_without_abs": "the test cross(axis, kept) > PARALLEL has no abs(): an axis turned the other way is "
                         "skipped though not parallel",
    "only_a": "only A's edge normals are there: B's edges give directions of their own",
    "dot_threshold": "the test 1 - |axis · kept| <= PARALLEL merges axes up to 0.08° apart: compare |axis × kept| "
                     "with PARALLEL",
    "last_kept_only": "each axis is compared with the last kept axis only: compare it with every kept axis",
    "none_skipped": "no axis is skipped: every parallel twin is kept",
}


def _parallel(u, v):
    return abs(u[0] * v[1] - u[1] * v[0]) <= 1e-6


def axes_fault(case):
    """None when the student's axes are every edge normal's direction of A and B once, as unit vectors; else
    (the Form this pair shows by itself, or None: the one-formula rule's; the first line then; the evidence)."""
    got, label, normals = case["got"], _label(case), case["normals_a"] + case["normals_b"]
    odd = next((a for a in got if abs(math.hypot(*a) - 1) > 1e-6), None)
    if odd is not None:
        return (Form("axes_not_unit", "an axis is not a unit vector: axes are unit edge normals (edge_normals gives "
                     "them)"), None, f"{label}, the axis {vec_text(odd)} has length {math.hypot(*odd):.4g}.")
    stray = next((a for a in got if not any(_parallel(a, n) for n in normals)), None)
    if stray is not None:
        return (Form(None, "separating_axes() gives an axis that is not the normal of any edge of A or B"), None,
                f"{label}: {vec_text(stray)}.")
    counts = f"{len(got)} axes for {len(case['want'])} directions"
    missing = next((n for n in normals if not any(_parallel(a, n) for a in got)), None)
    if missing is not None:
        whose = "A's" if missing in case["normals_a"] else "B's"
        near = next((a for a in got if 1 - abs(a[0] * missing[0] + a[1] * missing[1]) <= 1e-6), None)
        if near is not None:   # merged by a dot-product test: 1 - |a·b| ≈ θ²/2 is tiny long before θ is
            angle = math.degrees(math.asin(min(1.0, abs(near[0] * missing[1] - near[1] * missing[0]))))
            return (Form("axes_dot_threshold", AXES_MISTAKES["dot_threshold"]), None, f"{label}, {whose} edge normal "
                    f"{vec_text(missing)} is missing, {angle:.2g}° from the kept axis {vec_text(near)}.")
        return (None, "a direction that is not parallel to a kept axis was skipped",
                f"{label}, no axis along {whose} edge normal {vec_text(missing)}: {counts}.")
    twins = next(((a, b) for i, a in enumerate(got) for b in got[i + 1:] if _parallel(a, b)), None)
    if twins is not None:
        way = "the same way" if twins[0][0] * twins[1][0] + twins[0][1] * twins[1][1] > 0 else "opposite ways"
        return (None, "a parallel axis is kept twice: skip one parallel to any kept axis", f"{label}, "
                f"{vec_text(twins[0])} and {vec_text(twins[1])} are parallel (pointing {way}): {counts}.")
    return None


AXES = Step(
    "parallel_axes", "", 5, "separating_axes", _pairs(axis_pairs, drawn_axis_pairs, "separating_axes"),
    _call_pair,
    lambda c: _plain(distinct_directions(_normals(c, "a", plain=False) + _normals(c, "b", plain=False))),
    answer=as_points, hint="axes", bad=is_text, accepts=lambda c: axes_fault(c) is None,
    same=lambda got, want: not is_text(got) and len(got) == len(want) and all(map(same_point, got, want)),
    malformed=lambda c: f"separating_axes() must return a list of unit Vector2 axes.\n{_label(c)} it returned "
                        f"{c['got']}.", diagnose=lambda cases, c: axes_fault(c)[0],
    unnamed=lambda c: axes_fault(c)[1], evidence=lambda c: axes_fault(c)[2],
    wrong=forms_of({name: f"your skip rule, in every pair: {text}" for name, text in AXES_MISTAKES.items()},
                   _axes_forms, "axes_"),
    extra={"normals_a": lambda c: _normals(c, "a"), "normals_b": lambda c: _normals(c, "b")})


@reference
def _sat_reference(case):
    """The lesson's sat() for the pair, None or {"normal", "depth"}, and every edge normal (turned to point from A to
    B) whose overlap equals the smallest: when two directions tie, the axis sat() keeps depends on the order of the
    axes, and either is a right answer."""
    pa, pb = [Vector2(p) for p in case["a"]], [Vector2(p) for p in case["b"]]
    want = probe_kit.reference_sat(pa, pb, "lesson")
    if want is None:
        return None, []
    towards_b = probe_kit.centre_of(pb) - probe_kit.centre_of(pa)
    return {"normal": list(want[0]), "depth": want[1]}, [
        list(axis if towards_b.dot(axis) >= 0 else -axis) for axis, overlap, _ in probe_kit.axis_overlaps(pa, pb)
        if abs(overlap - want[1]) <= 1e-9 * max(1.0, want[1])]


def sat_fault(case):
    """None when sat() on the student's axes is the lesson's for this pair (apart, or the smallest overlap along
    one of the tied normals); else (the first line, the evidence)."""
    got, want, label = case["got"], case["want"], _label(case)
    if want is None:
        if got is None or ("touching" in case["pair"] and abs(got["depth"]) <= TOUCHING):
            return None
        return ("with your axes sat() misses a gap: the shapes are apart along an edge normal",
                f"{label}, sat() says they overlap by {got['depth']:.2f} px.")
    if got is None:
        return "with your axes sat() says apart where the shapes overlap", f"{label}, they overlap by " \
                                                                           f"{want['depth']:.2f} px."
    along = max(got["normal"][0] * t[0] + got["normal"][1] * t[1] for t in case["ties"] or [want["normal"]])
    if close(got["depth"], want["depth"]) and abs(along - 1) <= 1e-6:
        return None
    return ("with your axes sat() misses the smallest overlap", f"{label}: {got['depth']:.4g} px along "
            f"{vec_text(got['normal'])}; expected {want['depth']:.4g} px along {vec_text(want['normal'])}.")


SAT = Step(
    "parallel_axes", "", 5, "sat", _pairs(lambda: axis_pairs() + probe_kit.sat_pairs(), probe_kit.drawn_sat_pairs,
                                              "sat"), _call_pair,
    lambda c: _sat_reference(c)[0], answer=probe_kit.sat_answer, hint="axes",
    bad=lambda got: got is not None and "bad" in got, accepts=lambda c: sat_fault(c) is None,
    malformed=lambda c: f"sat() must return (normal, depth) or None.\n{_label(c)} it returned {c['got']['bad']}.",
    unnamed=lambda c: sat_fault(c)[0], evidence=lambda c: sat_fault(c)[1],
    extra={"ties": lambda c: _sat_reference(c)[1]})


# ---------------------------------------------------------------- the lab's bodies

BODY_ITEMS = (
    {"kind": "triangle", "size": 34, "pos": [100, 100]},
    {"kind": "pentagon", "size": 30, "pos": [100, 100]},
    {"kind": "hexagon", "size": 28, "pos": [100, 100]},
    {"kind": "box", "w": 60, "h": 40, "pos": [100, 100]},
    {"kind": "house", "w": 56, "h": 44, "pos": [100, 100]},
)
SIDES = {"triangle": 3, "pentagon": 5, "hexagon": 6}


def drawn_body_items(rng):
    """BODY_ITEMS with their sizes scaled by one factor drawn for this run (0.7-1.4) and their place drawn."""
    scale, pos = rng.uniform(0.7, 1.4), [rng.uniform(50, 750), rng.uniform(50, 550)]
    return [dict(item, pos=list(pos), **{key: round(item[key] * scale, 1) for key in ("size", "w", "h") if key in item})
            for item in BODY_ITEMS]


def probe_bodies(module, lab_path):
    """build() for each kind: the body's mass, inertia, corners' centroid and the analytic inertia (None for a house)."""
    cases = []
    for item in drawn_body_items(run_rng(module, "bodies")):
        body = module.build(dict(item))
        local = [Vector2(p) for p in body.local]
        cases.append({"kind": item["kind"], "item": item, "mass": body.mass, "inertia": body.inertia,
                      "corners": len(local)})
        if judging(module):
            cases[-1].update(_body_reference(item, body.mass, local))
    return cases


@reference
def _body_reference(item, mass, local):
    """For a body build() made of `item`: its outline's area and centroid, the analytic and the lesson's inertia."""
    kind = item["kind"]
    analytic = (analytic_inertia(kind, mass, radius=item["size"], sides=SIDES[kind]) if kind in SIDES else
                analytic_inertia("box", mass, w=item["w"], h=item["h"]) if kind == "box" else None)
    return {"area": abs(polygon_area(local)), "centroid": list(reference_centroid(local)), "analytic": analytic,
            "reference": reference_inertia(convex_polygon(local), mass)}


# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("regular_polygon", "polygon_centroid", "polygon_inertia", "separating_axes")

# probe name -> (the lab function it needs, the probe)
PROBES = {**CORNERS.probes(), **CENTROID.probes(), **INERTIA.probes(), **AXES.probes(), **SAT.probes(),
          "bodies": ("build", probe_bodies)}
