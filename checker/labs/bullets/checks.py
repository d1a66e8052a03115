"""Bullets (Lesson 11, Going Further): the checks, their bounds and the hints.

Order of checks (stable), one per lesson step where a step is the student's:
  loads, handout_unchanged, runtime_lines,
  toi_matches_root (step 2; also done-criterion 3), bounding_circle (step 3), broad_test (step 4),
  swept_move_resolves (step 5),
  runs, then the other three done-criteria: ccd_never_tunnels, substeps_still_tunnel, crate_momentum.
Checks are worth 1 point, the criteria (toi_matches_root among them) 2 points each.

The function checks compare the student's functions with analytic answers on
the cases of checker/labs/bullets/probes.py and name the first case that differs
(and the mistake, when it is a known one). A step is graded with the lesson's
code standing in for the steps it calls (time_of_impact with the lesson's
circle_toi and bounding_radius, swept_move with the lesson's time_of_impact),
so a mistake is reported once, under its own step. The criteria run only when
every function check passes; they come from the probe (the lab's own
BulletWorld, wall and modes, stepped in the child process), the one scene
(main() with scripted keys and clicks) only shows that the file runs.

Bounds come from the issue (no tunnel with CCD in >= 100 shots at 3000-12000
px/s; some tunnel with sub-steps x8 at 12000 px/s; 1e-9 s; 5 %); what
solutions/bullets.py measures is noted beside each.
"""
import math

from . import probes, scenes
from checker.judging import criteria, lab_checks
from checker.judging.common import close as _close, same_point as _same_point   # 1e-7 relative and absolute
from checker.judging.criteria import Bound, Criterion
from checker.judging.causes import consistent_mistake, mistake
from checker.judging.checks import Fail, Hint, Passed, Registry

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


# ---------------------------------------------------------------- helpers

def _bad(got):
    return isinstance(got, dict) and "bad" in got


def _function(sub, functions, probe, function, step):
    return lab_checks.function_data(sub, functions, probe, function, step, HINTS["crash"])


_vec = lab_checks.vec_text   # "(x, y)" for messages, shared by the labs


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, ("circle_toi", "bounding_radius", "time_of_impact", "swept_move",
                                            "BulletWorld", "apply_mode", "make_wall", "make_bullet", "main"), kind="names")


# ---------------------------------------------------------------- step 2: circle_toi (criterion 3)

probes.TOI.register(CHECKS, HINTS, max_score=2)   # declared in probes.py


# ---------------------------------------------------------------- step 3: bounding_radius, declared in probes.py

probes.BOUNDING.register(CHECKS, HINTS)


# ---------------------------------------------------------------- step 4: the broad test

def _hit_matches(got, want):
    if want is None:
        return got is None
    return (isinstance(got, dict) and "t" in got and _close(got["t"], want["t"])
            and _same_point(got["normal"], want["normal"]))


def _hit(hit):
    if hit is None:
        return "None (no hit)"
    if _bad(hit):
        return hit["bad"]
    return f"t = {hit['t']:.6g} s, normal {_vec(hit['normal'])}"


# step 4's known wrong broad tests, by the name the probe gives their answers (probes.BROAD_MISTAKES)
BROAD_TEXT = {
    "zero_is_falsy": "the broad test counts t = 0.0 as no contact (`if not t`): return None only when circle_toi() "
                     "gives None",
    "inverted": "the broad test is the wrong way round: it returns None when circle_toi() DOES reach the bounding "
                "circle",
    "point_bullet": "the broad test treats the bullet as a point (radius 0): give circle_toi() bullet.radius",
}


def _broad_mistake(cases, case):
    """The Mistake of the one known wrong broad test that gives the student's answer and exact-test count in
    every case, or None."""
    def gives(c, name):
        form = c["forms"][name]
        return _hit_matches(c["got"], form["hit"]) and c["exact_tests"] == form["exact_tests"]
    differs = [name for name, form in case.get("forms", {}).items() if not _hit_matches(form["hit"], case["want"])
               and name in BROAD_TEXT]
    named = consistent_mistake(cases, gives, differs)
    return mistake(f"broad_{named}", BROAD_TEXT[named]) if named else None


@CHECKS.check(depends=["loads"])
def broad_test(sub, functions):
    """Step 4: time_of_impact() skips a crate whose bounding circle the bullet cannot reach, and finds every hit."""
    cases = _function(sub, functions, "time_of_impact", "time_of_impact", 4)
    for case in cases:
        got, want = case["got"], case["want"]
        if not _hit_matches(got, want):
            evidence = f"for {case['case']}, time_of_impact() returned {_hit(got)}; expected {_hit(want)}."
            found = _broad_mistake(cases, case)
            if found:
                first = found.text
            elif want is not None and got is None and case["exact_tests"] == 0:
                first = "the broad test gave up on a crate the bullet does hit"
            else:
                first = "time_of_impact() does not find the lesson's hit"
            raise Fail(f"{first}.\n{evidence}", HINTS["broad"], found)
        if not case["needs_exact"] and case["exact_tests"]:
            text = "the broad test should have returned None first: the bullet cannot reach the bounding circle"
            raise Fail(f"{text}.\nfor {case['case']}, the answer is right but the exact swept test ran "
                       f"{case['exact_tests']} time(s).", HINTS["broad_missing"], mistake("broad_missing", text))
    return Passed(f"the broad test skips the crates out of reach and keeps every hit in all {len(cases)} cases",
                  value=cases)


# ---------------------------------------------------------------- step 5: the swept move

SWEPT_TEXT = {
    "stops": "the bullet stopped at the impact: the rest of the step (dt - t) was not spent",
    "old_velocity": "the bullet was resolved at the impact but spent the step with its velocity from before the hit "
                    "(it went on through)",
    "no_impulse": "nothing changed at the impact: resolve() was not called there, or was given the normal "
                  "reversed (-normal) and saw the bodies moving apart",
    "whole_step": "after the impact the bullet moved a whole dt more instead of the rest, dt - t",
    "far_side": "the impulse was applied on the far side of the bullet; the contact is on its surface towards "
                "the crate, bullet.pos + normal * radius",
    "resolve_first": "the hit was resolved where the bullet starts the step, then it moved the whole dt: it turned "
                     "back before it reached the impact",
    "at_centre": "the hit was resolved at the bullet's centre; the contact is on its surface, bullet.pos + "
                 "normal * radius",
    "move_then_resolve": "the bullet moved the whole step, then resolved: move it to the impact first, resolve "
                         "there, then spend dt - t",
}


def _same_outcome(got, want):
    """The bullet's position and velocity and every other body's position, velocity and spin agree."""
    return _same_point(got["bullet"]["pos"], want["bullet"]["pos"]) and \
        _same_point(got["bullet"]["vel"], want["bullet"]["vel"]) and len(got["others"]) == len(want["others"]) and \
        all(_same_point(g["vel"], w["vel"]) and _same_point(g["pos"], w["pos"])
            and _close(g.get("omega", 0.0), w.get("omega", 0.0)) for g, w in zip(got["others"], want["others"]))


@CHECKS.check(depends=["loads"])
def swept_move_resolves(sub, functions):
    """Step 5: swept_move() moves a bullet to its time of impact, resolves there and spends the rest of the step."""
    cases = _function(sub, functions, "swept_move", "swept_move", 5)
    for case in cases:
        got, want = case["got"], case["want"]
        if _same_outcome(got, want):
            continue
        # a case without a hit has no mistakes' outcomes: there every mistake moves the bullet as the lesson does
        named = consistent_mistake(cases, lambda c, key: _same_outcome(c["got"], c["variants"].get(key, c["want"])),
                                   [key for key, outcome in case["variants"].items()
                                    if not _same_outcome(outcome, want)])
        where = f"in '{case['case']}'" + (f" (impact at {case['t'] * 1000:.3f} ms)" if case["t"] is not None else "")

        spins = [(g.get("omega", 0.0), w.get("omega", 0.0)) for g, w in zip(got["others"], want["others"])
                 if not _close(g.get("omega", 0.0), w.get("omega", 0.0))]
        if spins and _same_point(got["bullet"]["pos"], want["bullet"]["pos"]):
            evidence = f"{where}, the crate spins at {spins[0][0]:.3f} rad/s; expected {spins[0][1]:.3f}"
        elif not _same_point(got["bullet"]["vel"], want["bullet"]["vel"]):   # the velocity says most: show it
            evidence = (f"{where}, the bullet leaves at {_vec(got['bullet']['vel'])} px/s; expected "
                        f"{_vec(want['bullet']['vel'])}")
        else:
            evidence = (f"{where}, the bullet ends at {_vec(got['bullet']['pos'])}; expected "
                        f"{_vec(want['bullet']['pos'])}")
        found = mistake(f"swept_{named}", SWEPT_TEXT[named]) if named else None
        first = found.text if found else "after swept_move() the bullet or the crate is not where the lesson's is"
        raise Fail(f"{first}.\n{evidence}.", HINTS["swept"], found)
    return Passed(f"the swept move matches the lesson in all {len(cases)} cases", value=cases)


FUNCTION_CHECKS = ["toi_matches_root", "bounding_circle", "broad_test", "swept_move_resolves"]


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
