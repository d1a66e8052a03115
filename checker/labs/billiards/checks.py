"""Billiards: its checks (steps declared in probes.py, criteria on scenes.py's runs) and bounds (solution's beside)."""
import math

from checker.judging import lab_checks
from checker.judging.checks import Fail, Hint, Registry
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


@CHECKS.check(after=["loads", "handout_unchanged", "runtime_lines"] + [s.check for s in probes.STEPS],
              needs_scenarios=True)
def runs(sub):
    """main() runs the checker's scenes to the end."""
    records = lab_checks.scene_records(sub, scenes.SCENARIOS, HINTS["crash"], HINTS["runtime"])
    for name, run in records.items():
        if not metrics.finite(run.record["records"]):
            raise Fail(f"a ball's position or speed became infinite or NaN.\nin the '{name}' scene.", HINTS["crash"])
    return records


@CHECKS.check(depends=["runs"], needs_scenarios=True)
def speeds_exchange(records):
    """Two equal balls meeting head-on swap speeds, all but the share e = 0.95 keeps back."""
    last = metrics.dynamic(records["frictionless"].record["records"][-1])
    cue, hit = [metrics.speed(ball) / scenes.HEAD_ON_SPEED for ball in last[:2]]
    if cue > CUE_KEEPS or hit < OBJECT_TAKES:
        raise Fail(f"two equal balls meeting head-on do not swap speeds.\nthe cue ball kept {cue:.1%} of its speed "
                   f"(at most {CUE_KEEPS:.0%}), the ball hit took {hit:.1%} (at least {OBJECT_TAKES:.0%}).",
                   HINTS["bounce"])
    return f"the cue ball kept {cue:.1%} of its speed, the ball it hit took {hit:.1%}"


@CHECKS.check(depends=["runs"], needs_scenarios=True)
def momentum_kept(records):
    """On a frictionless cloth the balls' total momentum stays as it was."""
    frames = records["frictionless"].record["records"]
    start = scenes.momentum(frames[0])
    drift, when = max((math.dist(scenes.momentum(f), start) / math.hypot(*start), f["frame"] / metrics.FPS)
                      for f in frames)
    if drift > DRIFT:
        raise Fail(f"the balls' total momentum changes when they meet.\nat {when:.2f} s it was off by {drift:.1%} "
                   f"(bound {DRIFT:.1%}).", HINTS["bounce"])
    return f"total momentum kept to {drift:.1e} of itself"


@CHECKS.check(depends=["runs"], needs_scenarios=True)
def no_overlap(records):
    """In the break no ball sinks more than 2 px into another ball or a cushion."""
    depth, what, when = max(scenes.overlap(f) + (f["frame"] / metrics.FPS,) for f in records["break"].record["records"])
    if depth > OVERLAP:
        raise Fail(f"balls sink into each other in the break.\n{what} overlapped by {depth:.1f} px at {when:.2f} s "
                   f"(bound {OVERLAP:g} px).", HINTS["contact"])
    return f"the deepest overlap was {depth:.2f} px ({what})"


@CHECKS.check(depends=["runs"], needs_scenarios=True)
def comes_to_rest(records):
    """After the break every ball stops, exactly, within 5.5 s."""
    frames = records["break"].record["records"]
    rolling = [f["frame"] for f in frames if any(metrics.speed(ball) > 0 for ball in metrics.dynamic(f))]
    rest = (rolling[-1] + 1) / metrics.FPS if rolling else 0.0
    if rest > REST_BY:
        said = f"the last stopped at {rest:.2f} s" if rolling[-1] < frames[-1]["frame"] else "one rolled to the end"
        raise Fail(f"the balls do not come to rest after the break.\n{said} (bound {REST_BY:g} s).", HINTS["cloth"])
    return f"every ball at rest from {rest:.2f} s"
