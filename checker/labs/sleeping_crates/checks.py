"""Sleeping Crates (Lesson 11 "Going Further"): the checks, their bounds and the hints.

Order of checks (stable), one per lesson step where a step is the student's:
  loads, handout_unchanged, runtime_lines,
  timer_rule (step 2), skips_sleepers (step 3), wakes_on_contact (step 4),
  narrow_work (the cost criterion, on a 40-crate grid built by the lab's build()),
  runs, then the scene's criteria: pile_sleeps, no_sleep_in_air, drop_wakes_pile.
Checks are worth 1 point, the four criteria 2 points each.

The function checks call the student's sleep_timer, moves and wake_on_contact
on checker/labs/sleeping_crates/probes.py's cases and name the first that differs, and the
mistake when it is a usual one. narrow_work counts World.counters' narrow-phase
tests in one step of the same 40-crate pile awake and asleep (deterministic,
unlike a time). The scene (checker/labs/sleeping_crates/scenes.py) runs only when every
function check passes.

Every bound of the criteria was set from what solutions/sleeping_crates.py
measures in the same scene, with the measured value noted next to it.
"""

import math

from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from checker.judging.causes import consistent_mistake, mistake
from lesson11 import records as metrics
from . import scenes
from checker.judging.checks import Fail, Hint, Passed, Registry
from checker.judging.common import shown

TITLE = "Sleeping Crates"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("sleep_timer", "sleep_timer_of_world", "update_sleep"), 3: ("moves", "moves_of_world"),
                4: ("wake_on_contact", "wake_of_world", "wake", "wake_pair")}
STEP_ADVICE = {2: "add dt while calm, else start from 0, yourself",
               3: "return whether the body moves yourself",
               4: "return the sleeping body of an awake pair yourself"}

ABS = 1e-9      # s: the timer against the rule (same arithmetic, timer + dt)

# ---------------------------------------------------------------- bounds (measured on the solution)
NARROW_SHARE = 0.1     # asleep / awake narrow tests in one step of the 40-crate pile; solution: 0 / 484 = 0
SLEEP_WITHIN = 2.0     # s from settling to every crate of the loose pile asleep; solution: 0.50 s (0.40 -> 0.90)
SLEPT_BY = 1.4         # s: the loose pile must be asleep before this (the scene lasts 1.5 s); solution: 0.90 s
WAKE_AGAIN = 1.4       # s: the dropped crate and the pile all asleep again by then; solution: 1.02 s
PENETRATION = 1.0      # px below the floor's top face at the end; solution: loose 0.26, dropped-on pile 0.24
PAIR_OVERLAP = 2.0     # px between two crates at the end; solution: loose 0.39, dropped-on pile 0.50
SINK = 2.0             # px a pile crate's centre ends below where it slept; solution: 0.44
JUMP = 3.0             # px a pile crate's centre rises above where it slept; solution: 0.04
THROW_HEIGHT = 60.0    # px the thrown crate must rise (it did leave the floor); solution: 82.2 (v²/2g = 81.6)

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "timer": Hint(2, "the sleep timer",
                  "Going further, Sleeping: while speed < SLEEP_SPEED (px/s) and |spin| < SLEEP_SPIN (rad/s), the "
                  "timer grows by dt (s); otherwise it starts again from 0."),
    "moves": Hint(3, "skip sleeping bodies",
                  "Going further, Sleeping: moves(body) is True only for a dynamic (inv_mass != 0) and awake body; "
                  "static and sleeping bodies give False."),
    "wake": Hint(4, "wake on contact",
                 "Going further, Sleeping: wake the sleeping body of a pair whose other body is dynamic and awake, "
                 "in both orders; the floor wakes nothing. Return a list, [] for none."),
    "handout": lab_checks.handout_hint("the thresholds, build(), the scene, the World, the `# lab runtime` "
                                       "lines, the final print"),
    "runtime": lab_checks.RUNTIME_HINT,
    "settle": Hint(5, "watch the pile sleep",
                   "The function checks pass, yet the scene misbehaves: run the file, drop crates and watch which "
                   "go dim and when (D shows the contacts)."),
    "crash": Hint(1, "run the file",
                  "Run the file yourself (python sleeping_crates.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("sleep",), "pile_sleeps": ("sleep",), "no_sleep_in_air": ("sleep",), "drop_wakes_pile": ("sleep",)}

CHECKS = Registry()


# CPU s of the solution's run of each scene (measured 2026-11-23, one job on this 2-core machine): the
# grader starts the longest first, so a long scene does not start last and run alone.
SCENE_SECONDS = {"sleep": 1.4}


def _function(sub, functions, probe, function, step):
    return lab_checks.function_data(sub, functions, probe, function, step, HINTS["crash"])


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, ("sleep_timer", "moves", "wake_on_contact", "build", "main"))


# ---------------------------------------------------------------- step 2: sleep_timer

# the known wrong rules of step 2, by the name the probe gives their answers (probes.timer_mistakes)
TIMER_MISTAKES = {
    "or": "calm when speed < SLEEP_SPEED `or` |spin| < SLEEP_SPIN; the rule needs both (`and`)",
    "ignores_spin": "the timer looks at the speed only: a spinning crate must start again from 0 too",
    "ignores_speed": "the timer looks at the spin only: a moving crate must start again from 0 too",
    "signed_spin": "the spin is compared with its sign: a crate spinning backwards counts as calm; compare abs(spin)",
    "speed_dt": "speed * dt (px per step) is compared with SLEEP_SPEED, which is in px/s",
    "both_dt": "speed * dt and |spin| * dt (per step) are compared with SLEEP_SPEED and SLEEP_SPIN, which are per "
               "second",
    "thresholds_dt": "the thresholds are scaled to one step (SLEEP_SPEED * dt, SLEEP_SPIN * dt); they are per "
                     "second, like speed and spin",
    "spin_vs_speed": "|spin| is compared with SLEEP_SPEED (5 px/s) where its own threshold is SLEEP_SPIN (0.1 rad/s)",
    "squared": "speed² and spin² are compared with SLEEP_SPEED and SLEEP_SPIN: compare speed and |spin| themselves",
    "speed_squared": "speed² is compared with SLEEP_SPEED: compare the speed itself",
    "never_resets": "the timer keeps its value when the crate moves: it must start again from 0",
    "counts_frames": "the timer adds 1 (a frame) per step; it counts seconds: add dt",
    "fixed_step": "the timer adds 1/120 s per step, not dt: a World stepping at another rate counts wrong",
    "returns_dt": "you return dt, not timer + dt: the timer must grow from its value",
    "no_growth": "the timer does not grow while the crate is calm: return timer + dt",
}


def _timer_mistake(cases, case):
    """The Mistake of the known wrong rule that gives the student's answer in every case, or None."""
    named = consistent_mistake(cases, lambda c, name: abs(c["got"] - c["mistakes"][name]) <= ABS,
                               [name for name, value in case["mistakes"].items() if abs(value - case["want"]) > ABS
                                and name in TIMER_MISTAKES])
    return mistake(f"timer_{named}", TIMER_MISTAKES[named]) if named else None


@CHECKS.check(depends=["loads"])
def timer_rule(sub, functions):
    """Step 2: sleep_timer() adds dt while speed < SLEEP_SPEED and |spin| < SLEEP_SPIN, else starts again from 0."""
    cases = _function(sub, functions, "sleep_timer", "sleep_timer", 2)
    for case in cases:
        got = case["got"]
        label = (f"sleep_timer({case['timer']:g}, {case['speed']:g}, {case['spin']:g}, {case['dt']:.4g}) "
                 f"({case['case']})")
        if isinstance(got, str):
            raise Fail(f"sleep_timer() must return a number of seconds.\n{label} returned {got}.", HINTS["timer"])
        if abs(got - case["want"]) <= ABS:
            continue
        numbers = all(not isinstance(c["got"], str) for c in cases)
        found = _timer_mistake(cases, case) if numbers else None
        first = found.text if found else "the timer does not follow the rule"
        raise Fail(f"{first}.\n{label} returned {got:.6g} s; the timer should be {case['want']:.6g} s.",
                   HINTS["timer"], found)
    return f"all {len(cases)} cases (calm, fast, spinning either way) follow the rule"


# ---------------------------------------------------------------- step 3: moves

@CHECKS.check(depends=["loads"])
def skips_sleepers(sub, functions):
    """Step 3: moves(body) is True for an awake dynamic body only (False for static and sleeping bodies)."""
    cases = _function(sub, functions, "moves", "moves", 3)
    for case in cases:
        got = case["got"]
        if isinstance(got, str):
            raise Fail(f"moves() must return True or False.\nfor {case['case']} it returned {got}.", HINTS["moves"])
        if got == case["want"]:
            continue
        if case["want"]:
            name, why = "moves_awake_false", "an awake crate must move, or nothing ever falls"
        elif "static" in case["case"]:
            name, why = "moves_static_true", ("a static body never moves: with moves() True for the floor, every "
                                              "sleeping crate on it is still tested")
        else:
            name, why = "moves_sleeping_true", "a sleeping crate does not move, so its quiet pairs are not tested"
        raise Fail(f"{why}.\nmoves() says {got} for {case['case']}; it should say {case['want']}.", HINTS["moves"],
                   mistake(name, why))
    return "awake crates move; static and sleeping bodies do not"


# ---------------------------------------------------------------- step 4: wake_on_contact

@CHECKS.check(depends=["loads"])
def wakes_on_contact(sub, functions):
    """Step 4: wake_on_contact(a, b) returns the sleeping body of a pair whose other body is dynamic and awake."""
    cases = _function(sub, functions, "wake_on_contact", "wake_on_contact", 4)
    for case in cases:
        got, want = case["got"], case["want"]
        label = f"wake_on_contact(a, b) with a {case['a']} and b {case['b']}"
        if isinstance(got, str):
            raise Fail(f"wake_on_contact() must return a list of bodies (or []).\n{label} returned {got}.",
                       HINTS["wake"])
        if got == want:
            continue
        names = " and ".join(got) if got else "nothing"
        if not want and "static" in (case["a"], case["b"]) and got:
            name, why = "wake_by_floor", "the floor never wakes a crate: a crate sleeps on the floor"
        elif not want and case["a"] == case["b"] == "asleep":
            name, why = "wake_two_sleepers", "two sleeping crates leave each other asleep"
        elif not want and case["a"] == case["b"] == "awake":
            name, why = "wake_awake", "neither is asleep: there is nothing to wake"
        elif want and not got:
            order = "the sleeping body second" if want == ["b"] else "the sleeping body first"
            name, why = "wake_one_order", f"an awake crate touching a sleeping one must wake it, with {order} " \
                                          "too: check both orders"
        else:
            name, why = "wake_not_only_sleeper", "only the sleeping body of the pair is woken"
        raise Fail(f"{why}.\n{label} wakes {names}; it should wake {' and '.join(want) or 'nothing'}.",
                   HINTS["wake"], mistake(name, why))
    return f"all {len(cases)} kinds of pair, both orders, wake the right body"


# ---------------------------------------------------------------- the cost criterion

@CHECKS.check(depends=["loads"], after=["timer_rule", "skips_sleepers", "wakes_on_contact"], max_score=2)
def narrow_work(sub, functions):
    """With a 40-crate pile asleep a step does at most a tenth of the narrow-phase tests of the same pile awake."""
    data = _function(sub, functions, "narrow_work", "build", None)
    awake, asleep = data["awake"], data["asleep"]
    if awake["narrow_tests"] == 0:
        raise Fail("the 40-crate pile, awake, made no narrow-phase test at all.\nbuild() must make the crates it is "
                   "given.", HINTS["handout"])
    share = asleep["narrow_tests"] / awake["narrow_tests"]
    if share > NARROW_SHARE:
        raise Fail(f"a sleeping pile still costs narrow-phase tests: skip every pair in which neither body moves.\n"
                   f"asleep, a step of the 40-crate pile made {asleep['narrow_tests']} tests, "
                   f"{shown(share, NARROW_SHARE)} of the {awake['narrow_tests']} awake (bound {NARROW_SHARE:g}).",
                   HINTS["moves"])
    if asleep["still_asleep"] < 40:
        raise Fail(f"one step woke the sleeping 40-crate pile, though nothing touched it.\n"
                   f"{asleep['still_asleep']} of 40 still asleep.", HINTS["wake"])
    return (f"{asleep['narrow_tests']} narrow tests asleep against {awake['narrow_tests']} awake "
            f"({asleep['pair_tests']} against {awake['pair_tests']} pairs visited)")


# ---------------------------------------------------------------- the scene

@CHECKS.check(after=["loads", "handout_unchanged", "runtime_lines", "timer_rule", "skips_sleepers",
                     "wakes_on_contact"], needs_scenarios=True)
def runs(sub):
    """main() runs the checker's scene to the end."""
    records = lab_checks.scene_records(sub, scenes.SCENARIOS, HINTS["crash"], HINTS["runtime"])
    for name, run in records.items():
        if not metrics.finite(run.record["records"]):
            raise Fail(f"a crate's position or speed became infinite or NaN.\nin the '{name}' scene.", HINTS["settle"])
    return records


def _loose(records):
    pile = scenes.measure_loose(records["sleep"].record)
    return dict(pile, asleep_after=None if pile["asleep"] is None else pile["asleep"] - pile["settled"])


def _throw(records):
    throw = scenes.measure_throw(records["sleep"].record)
    return dict(throw, frames_asleep_in_air=len(throw["asleep_in_air"]))


def _drop(records):
    drop = scenes.measure_drop(records["sleep"].record)
    return dict(drop, pile_crates_woken=len(drop["woke"]))


SANK, LANDED = "the sleeping pile sank", "the pile sank when a crate landed on it"
criteria.register(CHECKS, HINTS, (
    Criterion("pile_sleeps", "A loose pile of four crates settles and falls asleep within 2 s of settling, without "
              "sinking.", _loose, (
                  Bound("settled", math.inf, "four crates dropped a little above the floor never settled", "settle"),
                  Bound("asleep", SLEPT_BY, "a settled pile does not fall asleep in time", "timer", "s"),
                  Bound("asleep_after", SLEEP_WITHIN, "a settled pile does not fall asleep in time", "timer", "s"),
                  Bound("penetration", PENETRATION, SANK, "moves", "px"),
                  Bound("overlap", PAIR_OVERLAP, SANK, "moves", "px"))),
    Criterion("no_sleep_in_air", "A crate thrown straight up does not fall asleep at the top of its flight (or "
              "anywhere in the air).", _throw, (
                  Bound("height", THROW_HEIGHT, "a crate thrown up was stopped on its way up", "timer", "px", True),
                  Bound("frames_asleep_in_air", 0, "a thrown crate fell asleep in the air", "timer"))),
    Criterion("drop_wakes_pile", "A crate dropped on a sleeping pile wakes what it touches, and the pile settles "
              "and sleeps again without sinking or jumping.", _drop, (
                  Bound("landed", math.inf, "the crate dropped on the sleeping pile never touched it", "settle"),
                  Bound("pile_crates_woken", 1, "the crate landed on the sleeping pile woke none of it", "wake",
                        least=True),
                  Bound("sink", SINK, LANDED, "wake", "px"),
                  Bound("penetration", PENETRATION, LANDED, "wake", "px"),
                  Bound("overlap", PAIR_OVERLAP, LANDED, "wake", "px"),
                  Bound("jump", JUMP, "the pile jumped when a crate landed on it", "wake", "px"),
                  Bound("asleep_again", WAKE_AGAIN, "the pile does not fall asleep again in time", "timer", "s"))),
))
