"""More Shapes (Lesson 11 "Going Further"): the checks, their bounds and the hints.

Order of checks (stable), one per lesson step where a step is the student's:
  loads, handout_unchanged, runtime_lines,
  polygon_corners (step 2), centroid (step 3), inertia_sum (step 4), parallel_axes (step 5),
  bodies_inertia (the inertia criterion, on the lab's own bodies),
  runs, then the scenes' criteria: triangle_tips, hexagon_tips, pile_stable, ramp_holds.
Checks are worth 1 point, the five criteria 2 points each.

The function checks are declared in probes.py (cases, the lesson's answers, the known wrong forms). The scenes
(scenes.py) run only when every function check passes; build() makes every scene body with the student's
functions, so the scenes exercise them. Every bound of the criteria was set from what solutions/more_shapes.py
measures in the same scene, with the measured value noted next to it.
"""
import math

from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from checker.judging.declared import register_together
from lesson11 import records as metrics
from . import probes, scenes
from checker.judging.checks import Hint, Passed, Registry

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


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, probes.REQUIRED)


# ---------------------------------------------------------------- steps 2-4, declared in probes.py

for declared_step in (probes.CORNERS, probes.CENTROID, probes.INERTIA):
    declared_step.register(CHECKS, HINTS)


# ---------------------------------------------------------------- step 5: separating_axes (and sat on them)

def _axes_passed(axes, sats):
    hexagons = max((len(c["want"]) for c in axes.value if c["pair"] == "two aligned hexagons"), default=0)
    return Passed(f"every direction once in all {len(axes.value)} pairs (two aligned hexagons: {hexagons} axes), and "
                  f"sat() right in all {len(sats.value)}", value=axes.value)


register_together((probes.AXES, probes.SAT), CHECKS, HINTS, "parallel_axes", "Step 5: separating_axes() gives every "
                  "edge direction of both shapes once (a box 2, a hexagon 3), and sat() on them still finds the "
                  "smallest overlap.", _axes_passed)   # declared in probes.py


# ---------------------------------------------------------------- the inertia criterion, on the lab's own bodies

def _bodies(sub, functions):
    """Each kind of body build() makes: its corners' centroid's distance from its position, its inertia's error."""
    return [dict(body, centroid_offset=math.hypot(*body["centroid"]), inertia_error=abs(body["inertia"] - want) / want)
            for body in lab_checks.function_data(sub, functions, "bodies", "build", None, HINTS["crash"])
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
