"""Billiards: its checks (steps declared in probes.py, criteria on scenes.py's runs) and bounds (solution's beside)."""
import math

from checker.judging import criteria, lab_checks
from checker.judging.checks import Hint, Registry
from checker.judging.criteria import Bound, Criterion
from lesson11 import records as metrics
from . import probes, scenes

TITLE = "Billiards"
STEP_LIBRARY = {2: ("circle_circle",), 3: ("resolve", "lesson_resolve", "apply_impulse"), 4: ()}
STEP_ADVICE = {2: "write the test yourself", 3: "compute j and change the velocities yourself", 4: "slow it yourself"}

CUE_KEEPS = 0.05        # of its speed, the cue ball after a head-on hit (e = 0.95); solution: 0.025
OBJECT_TAKES = 0.95     # of the cue ball's speed, the ball it hits; solution: 0.975
DRIFT = 1e-3            # |P - P0| / |P0| on the frictionless cloth; solution: 0.0
OVERLAP = 2.0           # px, two balls or a ball and a cushion, the whole break; solution: 0.21
REST_BY = 5.5           # s, every ball exactly at rest after the break; solution: 4.48

HINTS = {
    "contact": Hint(2, "two balls' contact", "Section 6: with d = cb - ca the balls overlap when |d| < ra + rb; "
                    "the normal is d made unit length (from A to B), the depth the overlap ra + rb - |d|."),
    "bounce": Hint(3, "the bounce impulse", "Section 5 with no spin: vn = (vB - vA) · n; no impulse if vn >= 0. "
                   "Otherwise j = -(1 + e) vn / (1/mA + 1/mB); B gains j n times its inverse mass, A loses it."),
    "cloth": Hint(4, "the cloth's slowing", "The speed falls by mu g dt each frame along -v, direction kept; a "
                  "ball slower than that ends at exactly (0, 0), never turned round."),
    "handout": lab_checks.handout_hint("the table, build(), the World, the `# lab runtime` lines"),
    "runtime": lab_checks.RUNTIME_HINT,
    "crash": Hint(1, "run the file", "Run python billiards.py yourself and fix the error at the line shown."),
}
PICTURE_SCENES = {"speeds_exchange": ("frictionless",), "momentum_kept": ("frictionless",),
                  "no_overlap": ("break",), "comes_to_rest": ("break",)}
SCENE_SECONDS = {"frictionless": 0.1, "break": 0.6}   # CPU s of the solution's runs

CHECKS = Registry()
lab_checks.register_common(CHECKS, HINTS, probes.REQUIRED)
for step in probes.STEPS:
    step.register(CHECKS, HINTS)


lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, ["loads", "handout_unchanged", "runtime_lines"]
                         + [s.check for s in probes.STEPS], "main() runs the checker's scenes to the end.", "a ball",
                         hint="crash")


def _exchange(records):
    last = metrics.dynamic(records["frictionless"].record["records"][-1])
    cue, hit = [metrics.speed(ball) / scenes.HEAD_ON_SPEED for ball in last[:2]]
    return {"cue_ball_kept": cue, "ball_hit_took": hit}


def _momentum(records):
    frames = records["frictionless"].record["records"]
    start = scenes.momentum(frames[0])
    drift, frame = max((math.dist(scenes.momentum(f), start) / math.hypot(*start), f["frame"]) for f in frames)
    return {"momentum_off_by": drift, "frame": frame}


def _overlap(records):
    depth, what, frame = max(scenes.overlap(f) + (f["frame"],) for f in records["break"].record["records"])
    return {"deepest_overlap": depth, "what": what, "frame": frame}


def _rest(records):
    """When the last ball stopped (s); None when one still rolls in the last frame."""
    frames = records["break"].record["records"]
    rolling = [f["frame"] for f in frames if any(metrics.speed(ball) > 0 for ball in metrics.dynamic(f))]
    if rolling and rolling[-1] == frames[-1]["frame"]:
        return {"all_at_rest": None}
    return {"all_at_rest": (rolling[-1] + 1) / metrics.FPS if rolling else 0.0}


criteria.register(CHECKS, HINTS, (
    Criterion("speeds_exchange", "Two equal balls meeting head-on swap speeds, all but the share e = 0.95 keeps "
              "back.", _exchange, (
                  Bound("cue_ball_kept", CUE_KEEPS, "two equal balls meeting head-on do not swap speeds", "bounce",
                        "%", scale=100),
                  Bound("ball_hit_took", OBJECT_TAKES, "two equal balls meeting head-on do not swap speeds",
                        "bounce", "%", least=True, scale=100)), max_score=1),
    Criterion("momentum_kept", "On a frictionless cloth the balls' total momentum stays as it was.", _momentum, (
        Bound("momentum_off_by", DRIFT, "the balls' total momentum changes when they meet", "bounce", "%",
              scale=100, frame="frame"),), max_score=1),
    Criterion("no_overlap", "In the break no ball sinks more than 2 px into another ball or a cushion.", _overlap, (
        Bound("deepest_overlap", OVERLAP, "balls sink into each other in the break ({what})", "contact", "px",
              frame="frame"),), max_score=1),
    Criterion("comes_to_rest", "After the break every ball stops, exactly, within 5.5 s.", _rest, (
        Bound("all_at_rest", REST_BY, "the balls do not come to rest after the break", "cloth", "s"),),
              max_score=1),
))
