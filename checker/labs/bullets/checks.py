"""Bullets (Lesson 11, Going Further): the checks, their bounds and the hints.

Order (stable): loads, handout_unchanged, runtime_lines; the steps declared in probes.py (toi_matches_root, step 2
and done-criterion 3; bounding_circle; broad_test; swept_move_resolves); runs (main() in its scene: the file runs);
then, when every function check passes, the other criteria, measured by the probe in the lab's own BulletWorld.
Checks are worth 1 point, criteria 2. Bounds come from the issue (no tunnel with CCD in >= 100 shots at 3000-12000
px/s; some tunnel with sub-steps x8 at 12000 px/s; 1e-9 s; 5 %); what solutions/bullets.py measures is beside each.
"""
import math

from . import probes, scenes
from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from checker.judging.checks import Fail, Hint, Registry

TITLE = "Bullets"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("circle_toi",), 3: ("bounding_radius",), 4: ("time_of_impact", "circle_toi"),
                5: ("swept_move", "time_of_impact")}
STEP_ADVICE = {2: "solve the quadratic for the earlier root yourself",
               3: "take the farthest corner from the centre yourself",
               4: "write the broad test against the bounding circle yourself",
               5: "move to the impact, resolve there and spend the rest of the step yourself"}

# ---------------------------------------------------------------- tolerances and bounds
MIN_SHOTS = 100        # the issue: >= 100 shots with CCD; the probe fires 7 speeds x 16 = 112
WALL_X = 470.0         # px, the handout's wall (handout_unchanged keeps it)
MOMENTUM = 0.05        # the issue: the crate's momentum within 5 %; solution: 0.0000 % off

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "toi": Hint(2, "the time of impact of two circles",
                "Lesson, CCD: with dp = p2 - p1, dv = v2 - v1: a = dv·dv, b = 2 dp·dv, c = dp·dp - (r1 + r2)²; "
                "t = (-b - √(b² - 4ac)) / 2a, kept if 0 <= t <= dt."),
    "toi_later": Hint(2, "the earlier root is the first contact",
                      "Lesson, CCD: the two roots are when the circles start and stop touching; the first contact "
                      "is the earlier, (-b - √disc) / 2a."),
    "toi_apart": Hint(2, "no contact: apart, parallel, missing, too far",
                      "Lesson, CCD: return None when a == 0, the discriminant is negative, or t is outside "
                      "[0, dt] (the dt you are given)."),
    "toi_touching": Hint(2, "already touching",
                         "Lesson, CCD: when c <= 0 the circles already overlap: the impact is now, return 0.0 "
                         "before solving anything."),
    "bounding": Hint(3, "the bounding circle holds every corner",
                     "Going further, Bullets: the radius is the largest distance from the centre to a point of the "
                     "outline, centre.distance_to(p), the max over all points."),
    "broad": Hint(4, "the broad test before the exact test",
                  "Going further, Bullets: call circle_toi() for the bullet (its radius) against the bounding "
                  "circle; return None only when that gives None, else run the exact test."),
    "broad_missing": Hint(4, "skip what the bullet cannot reach",
                          "Going further, Bullets: the broad test returns None before the exact swept test when "
                          "the bullet cannot reach the bounding circle this step."),
    "swept": Hint(5, "move to the impact, resolve, spend the rest",
                  "Lesson, CCD: move to t, resolve there at bullet.pos + normal * radius, then move dt - t with "
                  "the new velocity."),
    "handout": lab_checks.handout_hint("the constants, the wall, the modes, BulletWorld, the `# lab runtime` "
                                       "lines"),
    "runtime": lab_checks.RUNTIME_HINT,
    "watch": Hint(6, "watch the bullets",
                  "The function checks pass, yet the bullets misbehave: press 5 (CCD), fire at the wall and watch "
                  "the tunnelled count; compare your file with the handout."),
    "crash": Hint(1, "run the file", "Run the file yourself (python bullets.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("scene",)}   # the criteria step the lab's BulletWorld in the probe: no scene to show

CHECKS = Registry()


def recognise(path, source):
    """True if the file is a Bullets lab: its name or its docstring's first line says so."""
    name = path.replace("\\", "/").rsplit("/", 1)[-1].lower()
    return name.startswith("bullets") or source.lstrip().startswith('"""Bullets:')


# CPU s of the solution's run of each scene (measured 2026-11-23, one job on this 2-core machine): the
# grader starts the longest first, so a long scene does not start last and run alone.
SCENE_SECONDS = {"scene": 0.2}


def _function(sub, functions, probe, function, step):
    return lab_checks.function_data(sub, functions, probe, function, step, HINTS["crash"])


lab_checks.register_common(CHECKS, HINTS, ("circle_toi", "bounding_radius", "time_of_impact", "swept_move", "BulletWorld",
                                            "apply_mode", "make_wall", "make_bullet", "main"), kind="names")
for step in probes.STEPS:   # declared in probes.py; circle_toi() is also done-criterion 3
    step.register(CHECKS, HINTS, max_score=2 if step is probes.TOI else 1)
FUNCTION_CHECKS = [step.check for step in probes.STEPS]


# ---------------------------------------------------------------- the scene and the criteria

def _past_the_wall(records):
    frames = records["scene"].record["records"]
    beyond = [frame["frame"] for frame in frames for body in frame["bodies"]
              if not body["static"] and not body["points"] and body["pos"][0] > WALL_X + 2]
    if beyond:
        raise Fail(f"a bullet got through the wall in CCD mode.\nsix bullets fired at the wall and the crates: one "
                   f"was beyond the wall at frame {beyond[0]}.", HINTS["watch"])
    return f"{len(frames)} frames, {max(len(f['bodies']) for f in frames) - 5} bullets at most, none past the wall"


lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, ["loads", "handout_unchanged", "runtime_lines"] + FUNCTION_CHECKS,
                         "main() runs the lab's scene in CCD mode with six bullets fired, and no bullet passes the wall.",
                         more=_past_the_wall, hint="watch")


def _shots(sub, functions):
    shots = _function(sub, functions, "shots", "swept_move", None)
    return dict(shots, shots_fired=shots["per_speed"] * len(shots["ccd"]), tunnelled=sum(shots["ccd"].values()),
                shots_tunnelled_with_substeps_x8=shots["x8"])


def _momentum(sub, functions):
    hit = _function(sub, functions, "crate_hit", "swept_move", None)
    got = math.hypot(*hit["got"])
    return {"crate_momentum": got, "momentum_off": abs(got - hit["want"]) / hit["want"]}


criteria.register(CHECKS, HINTS, (
    Criterion("ccd_never_tunnels", "With CCD no bullet tunnels through the 4 px wall at any speed from 3000 to 12000 "
              "px/s (>= 100 shots; criterion 1).", _shots, (
                  Bound("shots_fired", MIN_SHOTS, "too few shots were fired to grade tunnelling", "watch", least=True),
                  Bound("tunnelled", 0, "with CCD, bullets tunnelled through the wall", "watch"))),
    Criterion("substeps_still_tunnel", "With sub-stepping x8 alone some bullets still tunnel at 12000 px/s: the lab "
              "shows the lesson's point (criterion 2).", _shots, (
                  Bound("shots_tunnelled_with_substeps_x8", 1, "sub-stepping x8 stops every bullet, so the lab no "
                        "longer shows what it misses", "handout", least=True),)),
    Criterion("crate_momentum", "A bullet hitting a free crate with CCD gives it the lesson's momentum, "
              "M (1 + e) m v / (m + M), within 5 % (criterion 4).", _momentum, (
                  Bound("momentum_off", MOMENTUM, "a bullet hitting a free crate does not give it the lesson's "
                        "momentum", "watch"),)),
), depends=("loads",), after=FUNCTION_CHECKS, needs_scenarios=False)
