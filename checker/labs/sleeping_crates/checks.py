"""Sleeping Crates (Lesson 11 "Going Further"): the checks, their bounds and the hints.

In order: loads, handout_unchanged, runtime_lines; steps 2-4 (timer_rule, skips_sleepers, wakes_on_contact), declared
in probes.py with their cases and wrong forms; narrow_work (the cost criterion: one step of a 40-crate pile awake and
asleep, World.counters' narrow-phase tests); runs; the scene's criteria (pile_sleeps, no_sleep_in_air,
drop_wakes_pile), declared as bounds tables (checker/judging/criteria.py). Steps are worth 1 point, criteria 2; every
bound was set from what solutions/sleeping_crates.py measures, noted beside it.
"""

import math

from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from . import probes, scenes
from checker.judging.checks import Hint, Registry

TITLE = "Sleeping Crates"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("sleep_timer", "sleep_timer_of_world", "update_sleep"), 3: ("moves", "moves_of_world"),
                4: ("wake_on_contact", "wake_of_world", "wake", "wake_pair")}
STEP_ADVICE = {2: "add dt while calm, else start from 0, yourself",
               3: "return whether the body moves yourself",
               4: "return the sleeping body of an awake pair yourself"}


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


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, ("sleep_timer", "moves", "wake_on_contact", "build", "main"))


# ---------------------------------------------------------------- steps 2 to 4, declared in probes.py

for step in probes.STEPS:
    step.register(CHECKS, HINTS)


# ---------------------------------------------------------------- the cost criterion

def _narrow(sub, functions):
    data = lab_checks.function_data(sub, functions, "narrow_work", "build", None, HINTS["crash"])
    awake, asleep = data["awake"]["narrow_tests"], data["asleep"]["narrow_tests"]
    return {"narrow_tests_awake": awake, "asleep_share": asleep / awake if awake else None,
            "crates_still_asleep": data["asleep"]["still_asleep"]}


criteria.register(CHECKS, HINTS, (Criterion(
    "narrow_work", "With a 40-crate pile asleep a step does at most a tenth of the narrow-phase tests of the same "
    "pile awake.", _narrow, (
        Bound("narrow_tests_awake", 1, "the 40-crate pile, awake, made no narrow-phase test: build() must make the "
              "crates it is given", "handout", least=True),
        Bound("asleep_share", NARROW_SHARE, "a sleeping pile still costs narrow-phase tests: skip every pair in "
              "which neither body moves", "moves"),
        Bound("crates_still_asleep", 40, "one step woke the sleeping 40-crate pile, though nothing touched it",
              "wake", least=True))),
), depends=("loads",), after=("timer_rule", "skips_sleepers", "wakes_on_contact"), needs_scenarios=False)


# ---------------------------------------------------------------- the scene

lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, ["loads", "handout_unchanged", "runtime_lines", "timer_rule",
                         "skips_sleepers", "wakes_on_contact"], "main() runs the checker's scene to the end.", "a crate")


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
