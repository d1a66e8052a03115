"""More Shapes (Lesson 11 "Going Further"): the checks, their bounds and the hints.

Order of checks (stable), one per lesson step where a step is the student's:
  loads, handout_unchanged, runtime_lines,
  polygon_corners (step 2), centroid (step 3), inertia_sum (step 4), parallel_axes (step 5),
  bodies_inertia (the inertia criterion, on the lab's own bodies),
  runs, then the scenes' criteria: triangle_tips, hexagon_tips, pile_stable, ramp_holds.
Checks are worth 1 point, the five criteria 2 points each.

The function checks compare the student's regular_polygon, polygon_centroid,
polygon_inertia and separating_axes (and the handout's sat() running on the
student's axes) with the lesson's formulas on checker/labs/more_shapes/probes.py's
configurations and name the first that differs, and the mistake when it is
a usual one. The scenes (checker/labs/more_shapes/scenes.py) run only when every
function check passes. The lab's build() makes every scene body with the
student's functions, so the scenes exercise them.

Every bound of the criteria was set from what solutions/more_shapes.py
measures in the same scene, with the measured value noted next to it.
"""
import math

from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from checker.judging.causes import consistent_mistake, mistake
from lesson11 import records as metrics
from . import probes, scenes
from checker.judging.checks import Fail, Hint, Passed, Registry

TITLE = "More Shapes"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("regular_polygon",),
                3: ("polygon_centroid", "polygon_area", "convex_polygon", "Polygon", "Body", "from_world_points"),
                4: ("polygon_inertia", "inertia", "inv_inertia", "Polygon", "Body", "from_world_points"),
                5: ("sat", "separating_axes")}
STEP_ADVICE = {2: "place the corners at radius (cos θk, sin θk) yourself",
               3: "sum the triangle-fan areas and centroids yourself",
               4: "sum the triangle-fan terms yourself",
               5: "skip the parallel axes yourself"}

# ---------------------------------------------------------------- tolerances of the function checks
REL = 1e-7      # relative difference allowed against the reference (same inputs, other order of operations)
ABS = 1e-7      # absolute floor (px, px², mass·px²)
TOUCHING = 1e-6  # px: a depth this small for shapes exactly touching counts as "apart"

# ---------------------------------------------------------------- bounds (measured on the solution)
INERTIA_REL = 1e-3              # the lab's bodies against the analytic inertia; solution: 2e-16 (float rounding)
CENTRED = 1e-6                  # px: the lab's corners' centroid from (0, 0); solution: 6e-15
TIPPED_FLAT = math.radians(6)   # rad, the lowest side from flat at the end; solution: triangle 0.33°, hexagon 0.002°
TRIANGLE_TURN = math.radians(25)  # rad turned falling off its corner; solution: 53.5° (it lands 0.12 rad off)
HEXAGON_TURN = math.radians(50)   # rad: over at least one corner (60°); solution: 180.0° (three corners)
REST_SPEED = 5.0                # px/s over the last 0.5 s; solution: triangle 0.013, hexagon 0.48
REST_OMEGA = 0.2                # rad/s over the last 0.5 s; solution: triangle 0.00006, hexagon 0.017
PENETRATION = 1.0               # px below the floor's top face; solution: triangle 0.50, pile 0.50
PAIR_OVERLAP = 2.0              # px between two shapes in the pile; solution: 0.50
PILE_SPEED = 5.0                # px/s in the pile's last 0.5 s; solution: 1.62 (a pile is chaotic: margin 3x)
PILE_DRIFT = 3.0                # px a shape's centre moves in the pile's last 0.5 s; solution: 0.39
RAMP_SLIDE = 1.0                # px along the slope in 3 s (as Tumbling Crates); solution: pentagon 0.18, hexagon 0.06
RAMP_SPEED = 2.0                # px/s in the last second; solution: 0.29
GRAVITY = 980.0                 # px/s², the course's gravity
GRAVITY_TOLERANCE = 0.01        # relative; the solution measures 980.0 in the pile's free fall

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "corners": Hint(2, "a regular polygon's corners",
                    "Lesson §1: corner k at radius (cos θk, sin θk), θk = 2πk / sides in radians, k = 0 to sides - "
                    "1: corner 0 is (radius, 0)."),
    "centroid": Hint(3, "the area-weighted centroid",
                     "Lesson §4: the centre of mass weights each edge a→b by its area: C = Σ (a + b)(a × b) / (6 A), "
                     "A the signed area; not the corners' average."),
    "inertia": Hint(4, "the triangle-fan sum",
                    "Lesson §4: a fan of triangles (0, a, b): I = m Σ |a × b|(a·a + a·b + b·b) / (6 Σ |a × b|), m "
                    "the mass you are given; a 30 × 20 box of mass 2: 216.67."),
    "axes": Hint(5, "skip parallel axes, keep every direction",
                 "Common questions, parallel axes: keep an edge normal only if |axis × kept| > PARALLEL for every "
                 "kept axis: a box has 2 directions, a hexagon 3."),
    "handout": lab_checks.handout_hint("the shapes, build(), sat(), the scene, the World, the `# lab runtime` "
                                       "lines"),
    "runtime": lab_checks.RUNTIME_HINT,
    "sinking": Hint(6, "the push-out after the impulses",
                    "Shapes end deeper in the floor or each other than the pile allows: the World's push-out "
                    "(separate) must stay on, as handed out."),
    "settle": Hint(6, "watch them settle",
                   "The function checks pass, yet shapes keep moving: press D and watch the contacts and centre-of-"
                   "mass dots; compare your file with the handout."),
    "crash": Hint(1, "run the file",
                  "Run the file yourself (python more_shapes.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("solo", "pile"), "triangle_tips": ("solo",), "hexagon_tips": ("solo",), "pile_stable": ("pile",),
                  "ramp_holds": ("solo",)}

CHECKS = Registry()


# CPU s of the solution's run of each scene (measured 2026-11-23, one job on this 2-core machine): the
# grader starts the longest first, so a long scene does not start last and run alone.
SCENE_SECONDS = {"solo": 1.9, "pile": 1.8}


# ---------------------------------------------------------------- helpers

def _close(got, want, scale=1.0):
    return abs(got - want) <= ABS * max(scale, 1.0) + REL * abs(want)


_vec = lab_checks.vec_text   # "(x, y)" for messages, shared by the labs


def _function(sub, functions, probe, function, step):
    return lab_checks.function_data(sub, functions, probe, function, step, HINTS["crash"])


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, ("regular_polygon", "polygon_centroid", "polygon_inertia", "separating_axes",
                                            "sat", "build", "main"))


# ---------------------------------------------------------------- step 2: regular_polygon

probes.CORNERS.register(CHECKS, HINTS)   # declared in probes.py


# ---------------------------------------------------------------- step 3: polygon_centroid

def _close_point(got, want, scale):
    return want is not None and _close(got[0], want[0], scale) and _close(got[1], want[1], scale)


def _without_closing_edge(case):
    """The centroid sum with the last edge (last point back to the first) left out, or None."""
    points, area = case["points"], case["area"]
    if not area:
        return None
    x = y = 0.0
    for (ax, ay), (bx, by) in zip(points, points[1:]):
        w = ax * by - ay * bx
        x += (ax + bx) * w
        y += (ay + by) * w
    return [x / (6 * area), y / (6 * area)]


@CHECKS.check(depends=["loads"])
def centroid(sub, functions):
    """Step 3: polygon_centroid() is the area-weighted centroid Σ (a + b)(a × b) / (6 A), either winding."""
    cases = _function(sub, functions, "polygon_centroid", "polygon_centroid", 3)
    for case in cases:
        got, want = case["got"], case["want"]
        if isinstance(got, str):
            raise Fail(f"polygon_centroid() must return a point (a Vector2).\nfor {case['case']} it returned {got}.",
                       HINTS["centroid"])
        scale = max(max(abs(x), abs(y)) for x, y in case["points"])
        if _close(got[0], want[0], scale) and _close(got[1], want[1], scale):
            continue
        average = case["average"]
        found = None
        if _close(got[0], average[0], scale) and _close(got[1], average[1], scale):
            found = mistake("centroid_average", "your centroid is the corners' average, the centre of mass only for "
                                                "triangles and symmetric shapes: weight by area")
        elif _close(got[0], -want[0], scale) and _close(got[1], -want[1], scale):
            found = mistake("centroid_sign", "your centroid has its sign flipped when the points wind the other "
                                             "way: a × b and A must both be signed, or both not")
        elif all(not isinstance(c["got"], str) and _close_point(c["got"], c["want"][::-1], scale) for c in cases):
            found = mistake("centroid_xy_swapped", "your centroid has x and y swapped: the x sum takes the x "
                                                   "coordinates, Σ (a.x + b.x)(a × b)")
        elif _close_point(got, _without_closing_edge(case), scale):
            found = mistake("centroid_no_closing_edge", "the edge from the last point back to the first is "
                                                        "missing: wrap round with (i + 1) % len(points)")
        else:
            for factor, words in ((3, "2A"), (6, "A"), (2, "3A"), (1 / 2, "12A")):
                if _close(got[0], want[0] * factor, scale) and _close(got[1], want[1] * factor, scale):
                    found = mistake("centroid_divisor", f"your centroid is {factor:g} × the lesson's: the sum is "
                                                        f"divided by {words}, not 6A")
                    break
        first = found.text if found else "polygon_centroid() is not the area-weighted centroid"
        raise Fail(f"{first}.\nfor {case['case']}, yours is {_vec(got)}; the area-weighted centroid {_vec(want)}.",
                   HINTS["centroid"], found)
    return f"the centroid of all {len(cases)} outlines (both windings) is the area-weighted one"


# ---------------------------------------------------------------- step 4: polygon_inertia

probes.INERTIA.register(CHECKS, HINTS)   # declared in probes.py


# ---------------------------------------------------------------- step 5: separating_axes (and sat on them)

def _parallel(u, v):
    return abs(u[0] * v[1] - u[1] * v[0]) <= 1e-6


# the known wrong ways of skipping parallel axes, by the name the probe gives what they keep (probes._axes_forms)
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


def _same_axes(got, want):
    return len(got) == len(want) and all(_close(g[0], w[0]) and _close(g[1], w[1]) for g, w in zip(got, want))


def _axes_mistake(cases, case):
    """The Mistake of the known wrong skip rule that keeps the student's axes in every pair, or None. Its
    sentence says "your skip rule": the lesson's rule was stated just before, and this is the student's."""
    named = consistent_mistake(cases, lambda c, name: not isinstance(c["got"], str)
                               and _same_axes(c["got"], c["forms"][name]),
                               [name for name, form in case["forms"].items() if not _same_axes(form, case["want"])
                                and name in AXES_MISTAKES])
    return mistake(f"axes_{named}", f"your skip rule, in every pair: {AXES_MISTAKES[named]}") if named else None


def _label(case):
    return f"'{case['pair']}'" + (" with A and B swapped" if case["order"] == "B, A" else "")


@CHECKS.check(depends=["loads"])
def parallel_axes(sub, functions):
    """Step 5: separating_axes() gives every edge direction of both shapes once (a box 2, a hexagon 3), and sat() on
    them still finds the smallest overlap."""
    cases = _function(sub, functions, "separating_axes", "separating_axes", 5)
    for case in cases:
        got = case["got"]
        label = _label(case)
        if isinstance(got, str):
            raise Fail(f"separating_axes() must return a list of unit Vector2 axes.\nfor {label} it returned {got}.",
                       HINTS["axes"])
        for axis in got:
            if abs(math.hypot(*axis) - 1) > 1e-6:
                text = "an axis is not a unit vector: axes are unit edge normals (edge_normals gives them)"
                raise Fail(f"{text}.\nfor {label}, the axis {_vec(axis)} has length {math.hypot(*axis):.4g}.",
                           HINTS["axes"], mistake("axes_not_unit", text))
        normals = case["normals_a"] + case["normals_b"]
        stray = next((a for a in got if not any(_parallel(a, n) for n in normals)), None)
        if stray is not None:
            raise Fail(f"separating_axes() gives an axis that is not the normal of any edge of A or B.\nfor {label}: "
                       f"{_vec(stray)}.", HINTS["axes"])
        missing = next((n for n in normals if not any(_parallel(a, n) for a in got)), None)
        if missing is not None:
            whose = "A's" if missing in case["normals_a"] else "B's"
            near = next((a for a in got if 1 - abs(a[0] * missing[0] + a[1] * missing[1]) <= 1e-6), None)
            if near is not None:   # merged by a dot-product test: 1 - |a·b| ≈ θ²/2 is tiny long before θ is
                angle = math.degrees(math.asin(min(1.0, abs(near[0] * missing[1] - near[1] * missing[0]))))
                found = mistake("axes_dot_threshold", AXES_MISTAKES["dot_threshold"])
                raise Fail(f"{found.text}.\nfor {label}, {whose} edge normal {_vec(missing)} is missing, "
                           f"{angle:.2g}° from the kept axis {_vec(near)}.", HINTS["axes"], found)
            found = _axes_mistake(cases, case)
            first = found.text if found else "a direction that is not parallel to a kept axis was skipped"
            raise Fail(f"{first}.\nfor {label}, no axis along {whose} edge normal {_vec(missing)}: {len(got)} axes "
                       f"for {len(case['want'])} directions.", HINTS["axes"], found)
        twins = next(((a, b) for i, a in enumerate(got) for b in got[i + 1:] if _parallel(a, b)), None)
        if twins is not None:
            same = "the same way" if twins[0][0] * twins[1][0] + twins[0][1] * twins[1][1] > 0 else "opposite ways"
            found = _axes_mistake(cases, case)
            first = found.text if found else "a parallel axis is kept twice: skip one parallel to any kept axis"
            raise Fail(f"{first}.\nfor {label}, {_vec(twins[0])} and {_vec(twins[1])} are parallel (pointing "
                       f"{same}): {len(got)} axes for {len(case['want'])} directions.", HINTS["axes"], found)
    sats = _function(sub, functions, "sat", "sat", 5)
    for case in sats:
        got, want = case["got"], case["want"]
        label = _label(case)
        if got is not None and "bad" in got:
            raise Fail(f"sat() must return (normal, depth) or None.\nfor {label} it returned {got['bad']}.",
                       HINTS["axes"])
        if want is None:
            if got is not None and not ("touching" in case["pair"] and abs(got["depth"]) <= TOUCHING):
                raise Fail(f"with your axes sat() misses a gap: the shapes are apart along an edge normal.\nfor "
                           f"{label}, sat() says they overlap by {got['depth']:.2f} px.", HINTS["axes"])
            continue
        if got is None:
            raise Fail(f"with your axes sat() says apart where the shapes overlap.\nfor {label}, they overlap by "
                       f"{want['depth']:.2f} px.", HINTS["axes"])
        along = max(got["normal"][0] * t[0] + got["normal"][1] * t[1] for t in case["ties"] or [want["normal"]])
        if not _close(got["depth"], want["depth"]) or abs(along - 1) > 1e-6:
            raise Fail(f"with your axes sat() misses the smallest overlap.\nfor {label}: {got['depth']:.4g} px along "
                       f"{_vec(got['normal'])}; expected {want['depth']:.4g} px along {_vec(want['normal'])}.",
                       HINTS["axes"])
    hexagons = max((len(c["want"]) for c in cases if c["pair"] == "two aligned hexagons"), default=0)
    return Passed(f"every direction once in all {len(cases)} pairs (two aligned hexagons: {hexagons} axes), and sat() "
                  f"right in all {len(sats)}", value=cases)


# ---------------------------------------------------------------- the inertia criterion, on the lab's own bodies

def _bodies(sub, functions):
    """Each kind of body build() makes: its corners' centroid's distance from its position, its inertia's error."""
    return [dict(body, centroid_offset=math.hypot(*body["centroid"]), inertia_error=abs(body["inertia"] - want) / want)
            for body in _function(sub, functions, "bodies", "build", None)
            for want in [body["analytic"] if body["analytic"] is not None else body["reference"]]]


criteria.register(CHECKS, HINTS, (Criterion(
    "bodies_inertia", "Each shape the lab builds is centred on its centroid and has the analytic inertia of a regular "
    "polygon,\n    m r² (2 + cos(2π/n)) / 6, or of a box, m (w² + h²) / 12, within 0.1 %.", _bodies, (
        Bound("centroid_offset", CENTRED, "build() makes a {kind} that turns about the wrong point", "centroid", "px"),
        Bound("inertia_error", INERTIA_REL, "build() makes a {kind} whose inertia is not the analytic value (or the "
              "triangle-fan sum about its centroid)", "inertia"))),
), depends=("loads",), after=("polygon_corners", "centroid", "inertia_sum"), needs_scenarios=False)


# ---------------------------------------------------------------- the scenes

lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, ["loads", "handout_unchanged", "runtime_lines",
                         "parallel_axes", "bodies_inertia"], "main() runs each of the checker's two scenes to the end, "
                         "with the course's gravity.", "a shape", ("pile", GRAVITY, GRAVITY_TOLERANCE))


def _tipping(shape):
    def measure(records):
        record = records["solo"].record
        tipped = scenes.measure_tipping(record, shape)
        return dict(criteria.escapes(metrics.summary(record)), **tipped, sink=-tipped["floor_gap"])
    return measure


def _pile(records):
    record = records["pile"].record
    return dict(criteria.escapes(metrics.summary(record, scenes.PILE_TAIL)),
                **metrics.measure_pile(record, scenes.PILE_TAIL))


def _ramp(records):
    record = records["solo"].record
    speed = metrics.dynamic_arrays(record)["speed"][-metrics.FPS:, list(scenes.ON_RAMP)]
    return {"slid": max(abs(metrics.measure_ramp(record)[i]["slid"]) for i in scenes.ON_RAMP),
            "tail_speed": float(speed.max())}


def _rests(turn, what):
    """The bounds of a shape that must tip over (turn at least `turn`), land on a side and rest."""
    return (criteria.escape_bounds("shapes", "settle") + (
        Bound("sink", PENETRATION, f"{what} sank into the floor", "sinking", "px"),
        Bound("turned", turn, f"{what} did not tip over", "settle", "°", True, 180 / math.pi),
        Bound("side_error", TIPPED_FLAT, f"{what} did not land on a side", "settle", "°", scale=180 / math.pi),
        Bound("rest_speed", REST_SPEED, f"{what} is still moving at the end", "settle", "px/s"),
        Bound("rest_omega", REST_OMEGA, f"{what} is still turning at the end", "settle", "rad/s")))


criteria.register(CHECKS, HINTS, (
    Criterion("triangle_tips", "A triangle dropped on a corner falls onto a side and comes to rest.",
              _tipping(scenes.TRIANGLE), _rests(TRIANGLE_TURN, "the triangle dropped on its corner")),
    Criterion("hexagon_tips", "A hexagon pushed along the floor tips over its corners and stops, on a side.",
              _tipping(scenes.PUSHED), _rests(HEXAGON_TURN, f"the hexagon pushed at {scenes.PUSH_SPEED:g} px/s")),
    Criterion("pile_stable", "Shapes of every kind piled together neither sink into the floor or each other nor "
              "jitter.", _pile, criteria.escape_bounds("the pile's shapes", "settle") + (
                  Bound("floor_penetration", PENETRATION, "the pile sinks", "sinking", "px"),
                  Bound("pair_overlap", PAIR_OVERLAP, "the pile sinks", "sinking", "px"),
                  Bound("tail_speed", PILE_SPEED, "the pile jitters", "settle", "px/s"),
                  Bound("drift", PILE_DRIFT, "the pile jitters", "settle", "px"))),
    Criterion("ramp_holds", "A pentagon and a hexagon set on the 22° ramp stay put.", _ramp, (
        Bound("slid", RAMP_SLIDE, "shapes at rest on the 22° ramp did not stay put: friction 0.6 holds them",
              "settle", "px"),
        Bound("tail_speed", RAMP_SPEED, "shapes at rest on the 22° ramp did not stay put: friction 0.6 holds them",
              "settle", "px/s"))),
))
