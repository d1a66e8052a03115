"""The Sleeping Crates mistake corpus: plausible student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter
(starters/sleeping_crates_starter.py): the lines strictly between a step's
start marker and its end marker are replaced by the student's code for that
step; a step the entry does not give gets the solution's code, read from the
same regions of solutions/sleeping_crates.py, so the corpus follows the lab
when the lab changes. An entry that changes code OUTSIDE the steps lists exact
(old, new) edits, applied after the steps are filled; each old must occur
exactly once (tests/mutants.py), else building raises AssertionError.

Verdicts:
  CORRECT entries: every check passes.
  WRONG entries: `check` fails (or errors, for a crash) naming `step`; every
  other function check passes; narrow_work (it needs steps 2 to 4) may be
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
from wrong_kinds import AS_TEXT, FLAGS, NUMBER, before_solution, returns, wrapped  # noqa: E402  (tests/wrong_kinds.py)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "sleeping_crates_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "sleeping_crates.py")

STEPS = (2, 3, 4)
PER_STEP = 3   # wrong entries each step needs at least (tests/corpus_verdicts.py)

CHECK_STEP = {
    "loads": None, "handout_unchanged": None, "runtime_lines": None,
    "timer_rule": 2, "skips_sleepers": 3, "wakes_on_contact": 4,
    "narrow_work": None, "runs": None, "pile_sleeps": None, "no_sleep_in_air": None, "drop_wakes_pile": None,
}
FUNCTION_CHECKS = ("timer_rule", "skips_sleepers", "wakes_on_contact")
NEEDS_STEPS_2_TO_4 = ("narrow_work",)


wrong, correct = makers(CHECK_STEP)


WRONG = [
    # ---------------------------------------------------------------- step 2: sleep_timer
    wrong("timer_never_resets", "adds dt while calm but keeps the timer when the crate moves", "timer_rule", {2: """
        if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            return timer + dt
        return timer
    """}, why="a crate at 6 px/s with 0.4 s on its timer keeps 0.4 s: calm instants add up and a throw sleeps"),
    wrong("timer_counts_frames", "adds 1 per step instead of dt", "timer_rule", {2: """
        if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            return timer + 1
        return 0.0
    """}, why="a crate at rest goes from 0 to 1 in one step: it sleeps after one step"),
    wrong("timer_signed_spin", "compares spin, not abs(spin), with SLEEP_SPIN", "timer_rule", {2: """
        if speed < SLEEP_SPEED and spin < SLEEP_SPIN:
            return timer + dt
        return 0.0
    """}, why="a crate spinning backwards at 0.3 rad/s counts as calm"),
    wrong("timer_or", "calm when speed OR spin is under its threshold", "timer_rule", {2: """
        if speed < SLEEP_SPEED or abs(spin) < SLEEP_SPIN:
            return timer + dt
        return 0.0
    """}, why="a crate spinning at 0.2 rad/s but slow counts as calm"),
    wrong("timer_ignores_spin", "looks at the speed only", "timer_rule", {2: """
        return timer + dt if speed < SLEEP_SPEED else 0.0
    """}, why="a slow crate spinning at 0.2 rad/s counts as calm"),
    # issue 33: two rules that use `and` and were told "`and`, not `or`", and one that forgets the timer
    wrong("timer_speed_times_dt", "compares speed * dt (px per step) with SLEEP_SPEED (px/s)", "timer_rule", {2: """
        if speed * dt < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            return timer + dt
        return 0.0
    """}, why="a crate moving at 6 px/s moves 0.05 px per step: counts as calm (uses `and`; told 'and, not or')"),
    wrong("timer_spin_vs_sleep_speed", "compares |spin| with SLEEP_SPEED instead of SLEEP_SPIN", "timer_rule", {2: """
        if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPEED:
            return timer + dt
        return 0.0
    """}, why="a slow crate spinning at 0.2 rad/s counts as calm (uses `and`; told 'and, not or')"),
    wrong("timer_returns_dt", "returns dt while calm instead of timer + dt", "timer_rule", {2: """
        if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            return dt
        return 0.0
    """}, why="a calm crate 0.25 s into its timer goes back to one step's 0.0083 s: it never sleeps"),
    # issue 40: per-step thresholds, a step fixed at 1/120 s, squared speeds
    wrong("timer_thresholds_per_step", "scales the thresholds to one step (SLEEP_SPEED * dt)", "timer_rule", {2: """
        if speed < SLEEP_SPEED * dt and abs(spin) < SLEEP_SPIN * dt:
            return timer + dt
        return 0.0
    """}, why="a calm crate at 2 px/s is over 5/120 px/s: it never sleeps"),
    wrong("timer_both_per_step", "compares speed * dt and |spin| * dt with the per-second thresholds", "timer_rule",
          {2: """
        if speed * dt < SLEEP_SPEED and abs(spin) * dt < SLEEP_SPIN:
            return timer + dt
        return 0.0
    """}, why="a crate moving at 6 px/s moves 0.05 px per step: counted calm"),
    wrong("timer_fixed_step", "adds 1/120 s instead of dt", "timer_rule", {2: """
        if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            return timer + 1 / 120
        return 0.0
    """}, why="right at 120 Hz; the case stepped at 1/60 s shows it"),
    wrong("timer_squared_speeds", "compares speed² and spin² with the thresholds", "timer_rule", {2: """
        if speed * speed < SLEEP_SPEED and spin * spin < SLEEP_SPIN:
            return timer + dt
        return 0.0
    """}, why="a crate spinning at 0.2 rad/s has spin² = 0.04 < 0.1: counted calm"),
    wrong("timer_speed_squared", "compares vel.length_squared()-style speed² with SLEEP_SPEED", "timer_rule", {2: """
        if speed ** 2 < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            return timer + dt
        return 0.0
    """}, why="a crate just under the threshold, 4.9 px/s, has speed² = 24 > 5: it never sleeps"),
    wrong("timer_returns_none", "sets a local timer but returns nothing", "timer_rule", {2: """
        if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:
            timer += dt
        else:
            timer = 0.0
    """}, why="the function returns None: the checker must say it needs a number, not crash"),
    # ---------------------------------------------------------------- step 3: moves
    wrong("moves_ignores_static", "not body.asleep only: the floor counts as moving", "skips_sleepers", {3: """
        return not body.asleep
    """}, why="moves(floor) is True, so every sleeping crate on the floor is still tested against it"),
    wrong("moves_ignores_sleep", "body.inv_mass != 0 only (the starter's line kept)", "skips_sleepers", {3: """
        return body.inv_mass != 0
    """}, why="a sleeping crate moves and its pairs are all tested"),
    wrong("moves_inverted", "returns True for sleeping bodies", "skips_sleepers", {3: """
        return body.inv_mass != 0 and body.asleep
    """}, why="an awake crate is not integrated: nothing falls"),
    wrong("moves_mass_zero", "flips the static test: mass == 0 counts as moving", "skips_sleepers", {3: """
        return body.mass == 0 or not body.asleep
    """}, why="the floor (mass 0) moves"),
    # ---------------------------------------------------------------- step 4: wake_on_contact
    wrong("wake_one_order", "checks only a asleep, b awake", "wakes_on_contact", {4: """
        if a.asleep and b.inv_mass != 0 and not b.asleep:
            return [a]
        return []
    """}, why="an awake crate listed first never wakes the sleeping one after it"),
    wrong("wake_by_floor", "any partner wakes a sleeping body, the floor too", "wakes_on_contact", {4: """
        return [body for body in (a, b) if body.asleep]
    """}, why="the floor wakes the crate sleeping on it (its pair is not tested, but a rule must not depend on that), "
              "and two sleeping crates wake each other"),
    wrong("wake_both", "wakes both bodies of any pair with a sleeper", "wakes_on_contact", {4: """
        if a.asleep or b.asleep:
            return [a, b]
        return []
    """}, why="the floor and an awake crate are 'woken' too"),
    wrong("wake_the_awake_one", "returns the awake body instead of the sleeping one", "wakes_on_contact", {4: """
        woken = []
        for sleeper, other in ((a, b), (b, a)):
            if sleeper.asleep and other.inv_mass != 0 and not other.asleep:
                woken.append(other)
        return woken
    """}, why="the sleeping crate is never woken"),
    wrong("wake_sets_flag", "sets asleep = False itself and returns nothing", "wakes_on_contact", {4: """
        for sleeper, other in ((a, b), (b, a)):
            if sleeper.asleep and other.inv_mass != 0 and not other.asleep:
                sleeper.asleep = False
    """}, why="returns None: the body wakes alone (its island and its timer are left as they were); the checker "
              "asks for the list of bodies to wake"),
    # ---------------------------------------------------------------- outside the steps
    wrong("outside_no_sleep_effect", "removed the \"sleep\" effect from the World", "handout_unchanged", edits=[(
        "effects=LESSON_EFFECTS | {\"sleep\"},", "effects=LESSON_EFFECTS,")],
        why="nothing ever sleeps; the handout is changed"),
]

CORRECT = [
    correct("correct_solution_steps", "the solution's own code in every step",
            why="the reference solution"),
    correct("correct_one_liners", "each step on one line", {2: """
        return timer + dt if speed < SLEEP_SPEED and -SLEEP_SPIN < spin < SLEEP_SPIN else 0.0
    """, 3: """
        return not (body.inv_mass == 0 or body.asleep)
    """, 4: """
        return [s for s, o in ((a, b), (b, a)) if s.asleep and o.inv_mass != 0 and not o.asleep]
    """}, why="the same rules written differently"),
    correct("correct_is_static_and_moves", "uses body.is_static and calls moves() for the partner", {3: """
        if body.is_static:
            return False
        return not body.asleep
    """, 4: """
        woken = []
        if a.asleep and moves(b):
            woken.append(a)
        if b.asleep and moves(a):
            woken.append(b)
        return woken
    """}, why="is_static is inv_mass == 0, and moves(partner) is 'dynamic and awake'"),
    correct("correct_timer_early_reset", "resets first, then adds", {2: """
        if speed >= SLEEP_SPEED or abs(spin) >= SLEEP_SPIN:
            return 0.0
        calm_for = timer
        calm_for += dt
        return calm_for
    """}, why="the negation of the calm test; the same values"),
]

# the words each wrong entry's first message must contain: it names the mistake, not only the step (issue 33)
SAYS = {
    "timer_never_resets": ("keeps its value",),
    "timer_thresholds_per_step": ("scaled to one step",),
    "timer_both_per_step": ("speed * dt and |spin| * dt",),
    "timer_fixed_step": ("1/120 s per step, not dt",),
    "timer_squared_speeds": ("speed² and spin²",),
    "timer_speed_squared": ("speed² is compared",),
    "timer_counts_frames": ("adds 1",),
    "timer_signed_spin": ("abs(spin)",),
    "timer_or": ("`or`",),
    "timer_ignores_spin": ("speed only",),
    "timer_speed_times_dt": ("speed * dt",),
    "timer_spin_vs_sleep_speed": ("|spin| is compared with SLEEP_SPEED",),
    "timer_returns_dt": ("you return dt, not timer + dt",),
    "timer_returns_none": ("returned None",),
    "moves_ignores_static": ("for the floor",),
    "moves_ignores_sleep": ("for a sleeping crate",),
    "moves_inverted": ("for an awake crate",),
    "moves_mass_zero": ("for the floor",),
    "wake_one_order": ("both orders",),
    "wake_by_floor": ("floor never wakes",),
    "wake_both": ("wakes a and b",),
    "wake_the_awake_one": ("wakes a; it should wake b",),
    "wake_sets_flag": ("in place",),
    "outside_no_sleep_effect": ('{"sleep"}',),
}
WRONG = with_says(WRONG, SAYS)

# What tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself (each key optional):
# short (its entries' name prefix), mechanisms (the issue-35 mechanisms that apply; tests/corpus_attacks.py
# says why), library_name / library_owner (the library's answer to the first step where it is not the first
# STEP_LIBRARY name), world_call, hidden, forger and side (the attacks' code where the default does not fit).
ATTACK = {
    "short": "sc",
    "mechanisms": (1, 2, 5, 6, 7, 8, 10),
    "library_name": "sleep_timer_of_world", "library_owner": "World()",   # the library's timer is World's
}

# The wrong-kind values its step functions must fail on, never the checker (tests/test_wrong_kinds.py):
# [(function, step, [case, ...])], the cases written as tests/wrong_kinds.py says.
WRONG_KINDS = [("sleep_timer", 2, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]"])),
               ("moves", 3, returns(FLAGS) + wrapped(["[answer]"])
                + before_solution(["body.asleep = 'no'", "body.vel = None", "body.sleep_time = 'x'"])),
               ("wake_on_contact", 4, returns(["a", "(a, b)", "[a, 'b']", "'ab'", "[a, b, a] * 400",
                                               "5", "{'a': a}"])
                + before_solution(["a.asleep = [1]", "b.omega = 'x'"]))]

# The wrong entry `python -m checker FILE --show` is tried on (tests/test_checker_show.py): one wrong step
# whose scene differs visibly from the solution's, and the kind of failing case --show draws for it.
SHOW_ENTRY, SHOW_CASE = 'timer_counts_frames', 'TimerCase'

# the mistake id each entry's failing check must carry (issue 40: --json's "mistake")
MISTAKE_IDS = {
    "timer_never_resets": "timer_never_resets", "timer_counts_frames": "timer_counts_frames",
    "timer_signed_spin": "timer_signed_spin", "timer_or": "timer_or", "timer_ignores_spin": "timer_ignores_spin",
    "timer_speed_times_dt": "timer_speed_dt", "timer_spin_vs_sleep_speed": "timer_spin_vs_speed",
    "timer_returns_dt": "timer_returns_dt", "timer_thresholds_per_step": "timer_thresholds_dt",
    "timer_both_per_step": "timer_both_dt", "timer_fixed_step": "timer_fixed_step",
    "timer_squared_speeds": "timer_squared", "timer_speed_squared": "timer_speed_squared",
}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"

# ================================================================ building the files (tests/corpus_files.py)

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_sleeping_crates.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
