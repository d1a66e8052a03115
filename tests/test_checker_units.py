"""Unit tests of the checker's pieces that need no child process: the handout comparison, the check
registry (dependencies hand on values, `after` only gates, no check takes a value it does not read, a hint
is shown once), and how numbers are shown beside bounds."""
import os

import pytest

from checker.reading import handout
from checker.judging.checks import FAIL, PASS, SKIP, Fail, Hint, Passed, Registry
from checker.judging.common import shown

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = open(os.path.join(ROOT, "starters", "tumbling_crates_starter.py"), encoding="utf-8").read()
SOLUTION = open(os.path.join(ROOT, "solutions", "tumbling_crates.py"), encoding="utf-8").read()


def edited(source, old, new):
    assert source.count(old) == 1, old
    return source.replace(old, new)


# ---------------------------------------------------------------- the handout comparison

def test_the_solution_and_the_starter_share_their_handout():
    assert handout.compare(SOLUTION, STARTER).same
    assert handout.compare(STARTER, STARTER).same


def test_formatting_comments_and_docstrings_do_not_count():
    source = edited(SOLUTION, "WIDTH, HEIGHT = 900, 600", "WIDTH, HEIGHT = (900,\n                 600)  # px\n\n")
    source = edited(source, '    """Equal and opposite impulse at the contact: changes velocity AND spin."""',
                    "    '''My notes: equal and opposite.'''")
    source = source.replace("# Step 1: run this file and watch the crates fall.", "# (I ran it.)")
    assert handout.compare(source, STARTER).same


def test_an_added_import_is_allowed_and_listed():
    result = handout.compare("import numpy as np\n" + SOLUTION, STARTER)
    assert result.same and result.added_imports == ["line 1: import numpy as np"]


def test_a_debug_print_outside_the_steps_is_a_warning_naming_its_line():
    source = edited(SOLUTION, "def main():\n", "def main():\n    print('starting', len(WIDTH_LIST) if 0 else 0)\n"
                    .replace("WIDTH_LIST", "str(WIDTH)"))
    result = handout.compare(source, STARTER)
    line = source.splitlines().index("    print('starting', len(str(WIDTH)) if 0 else 0)") + 1
    assert result.same and result.problems == []
    assert len(result.warnings) == 1 and result.warnings[0].startswith(f"line {line}: ")


@pytest.mark.parametrize("added", ["    print(sat([], []))\n", "    print(random.random())\n",
                                   "    x = 1\n", "    print((lambda: 0)())\n"])
def test_a_print_that_calls_code_or_any_other_added_line_still_fails(added):
    result = handout.compare(edited(SOLUTION, "def main():\n", "def main():\n" + added), STARTER)
    assert not result.same and "was added" in result.problems[0]


MAIN_WORLD = "    rng = random.Random(lab.seed(11))  # lab runtime: seed()\n    world = make_world(rng)\n"


@pytest.mark.parametrize("old, new", [
    (MAIN_WORLD, MAIN_WORLD + "    print(f'{len(world.bodies)} bodies', sep='')\n"),
    (MAIN_WORLD, MAIN_WORLD + "    print('bodies: {}'.format(len(world.bodies)))\n"),
    ("def main():\n", "print('loaded', repr(WIDTH), round(HEIGHT / 3, 1), abs(-1))\n\n\ndef main():\n"),
])
def test_debug_prints_in_other_styles_and_places_are_warnings(old, new):
    source = edited(SOLUTION, old, new)
    result = handout.compare(source, STARTER)
    added = next(line for line in new.splitlines() if "print(" in line)
    line = source.splitlines().index(added) + 1
    assert result.same and result.problems == [] and result.warnings == [
        f"line {line}: `{added.strip()}` added outside the steps (a debug print is allowed; "
        "remove it before you hand in)"]


@pytest.mark.parametrize("added", ["    print('x', file=world)\n", "    print(world.step(0.1))\n",
                                   "    print(make_world(rng))\n", "    print(**{})\n"])
def test_a_print_that_writes_elsewhere_or_runs_code_still_fails(added):
    result = handout.compare(edited(SOLUTION, MAIN_WORLD, MAIN_WORLD + added), STARTER)
    assert not result.same and result.warnings == [] and "was added" in result.problems[0]


def test_an_import_that_rebinds_a_handout_name_is_an_edit():
    result = handout.compare(edited(SOLUTION, "import random\n", "import random\nfrom math import cos as cross\n"),
                             STARTER)
    assert not result.same


@pytest.mark.parametrize("old, new, words", [
    ("MAX_CRATES = 14", "MAX_CRATES = 3", "`MAX_CRATES = 3` (the handout has `MAX_CRATES = 14`)"),
    ("RESTING_SPEED = 30 ", "RESTING_SPEED = 5 ", "`RESTING_SPEED = 5"),
    ("    return World(lab.scene(make_scene(rng)), sat=sat, resolve=resolve)",
     "    return World(lab.scene(make_scene(rng)), sat=sat, resolve=resolve, gravity=(0, 500))", "gravity=(0, 500)"),
    ("    if vn >= 0:\n        return  # the contact points are already separating\n", "",
     "the handout's line `if vn >= 0:` was removed"),
    ("        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)",
     "        dt = clock.tick(60) / 1000", "`dt = clock.tick(60) / 1000`"),
])
def test_an_edit_outside_the_steps_is_named_with_its_line(old, new, words):
    source = edited(SOLUTION, old, new)
    result = handout.compare(source, STARTER)
    assert not result.same
    assert any(words in problem for problem in result.problems), result.problems
    line = next(i for i, text in enumerate(source.splitlines(), 1) if new and new.strip().splitlines()[0] in text) \
        if new else None
    if line:
        assert any(problem.startswith(f"line {line} ") for problem in result.problems), result.problems


def test_code_inside_the_steps_is_not_compared():
    source = edited(SOLUTION, "    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n",
                    "    import math\n    k = k + a.inv_inertia * ran ** 2\n    k = k + b.inv_inertia * rbn ** 2\n")
    assert handout.compare(source, STARTER).same


@pytest.mark.parametrize("old, new, words", [
    ("    # --- end of step 4 ---\n", "", "step 4's region has no `# --- end of step 4 ---` line"),
    ("    # --- step 6: the two spin updates ---\n", "", "ends step 6, but step 6 was not started"),
])
def test_broken_markers_are_a_one_line_error(old, new, words):
    with pytest.raises(handout.MarkerError, match="^the file: ") as caught:
        handout.compare(edited(SOLUTION, old, new), STARTER)
    assert words in str(caught.value) and "\n" not in str(caught.value)


def test_missing_step_markers_are_named():
    source = edited(SOLUTION, "    # --- step 6: the two spin updates ---\n", "")
    source = edited(source, "    # --- end of step 6 ---\n", "")
    with pytest.raises(handout.MarkerError, match="the marker lines of step 6 are missing"):
        handout.compare(source, STARTER)


# ---------------------------------------------------------------- the registry

def make_registry(calls):
    registry = Registry()
    advice = Hint(7, "watch them settle", "Press D.")

    @registry.check()
    def first(sub):
        """First."""
        calls.append(("first", sub))
        return Passed("first passed", value=41)

    @registry.check(depends=["first"])
    def second(sub, value):
        """Second."""
        calls.append(("second", value))
        raise Fail("second failed", advice)

    @registry.check(depends=["first"])
    def third(sub, value):
        """Third."""
        raise Fail("third failed", advice)

    @registry.check(depends=["second"], needs_scenarios=True)
    def fourth(sub, value):
        """Fourth."""
        calls.append(("fourth", value))

    return registry


def test_a_check_receives_what_its_dependency_returned_and_a_hint_is_shown_once():
    calls = []
    registry = make_registry(calls)
    state = registry.run("the submission", stop_at_scenarios=True)
    assert calls == [("first", "the submission"), ("second", 41)]
    assert not registry.wants_scenarios(state)  # fourth depends on second, which failed
    results = registry.run("the submission", state=state).ordered(registry)
    assert [r.status for r in results] == [PASS, FAIL, FAIL, SKIP]
    assert results[0].message == "first passed"
    assert results[1].hint == "[step 7: watch them settle] Press D."
    assert results[2].hint == "[step 7: watch them settle] see the hint under 'second' above."
    assert results[3].message == "skipped: needs 'second' to pass first"


def test_a_check_cannot_depend_on_a_later_one():
    registry = Registry()
    with pytest.raises(ValueError, match="unknown or later"):
        @registry.check(depends=["later"])
        def early(sub, value):
            """Early."""


def test_a_check_after_another_is_gated_by_it_but_not_handed_its_value():
    registry, calls = Registry(), []

    @registry.check()
    def first(sub):
        """First."""
        return Passed("first", value=41)

    @registry.check(after=["first"])
    def gated(sub):                      # takes the submission only
        """Gated."""
        calls.append(("gated", sub))
        return Passed("gated", value=[1, 2])

    @registry.check(depends=["gated"], after=["first"])
    def reader(values):                  # takes gated's value only: no submission
        """Reader."""
        calls.append(("reader", values))

    results = registry.run("the submission").ordered(registry)
    assert [r.status for r in results] == [PASS, PASS, PASS]
    assert calls == [("gated", "the submission"), ("reader", [1, 2])]
    assert registry.by_id("reader").prerequisites == ("first", "gated")


def test_a_gated_check_is_skipped_naming_the_earliest_prerequisite_that_did_not_pass():
    registry = Registry()

    @registry.check()
    def loads(sub):
        """Loads."""
        raise Fail("it crashed")

    @registry.check(depends=["loads"])
    def step(sub, functions):
        """Step 2: a step."""

    @registry.check(depends=["step"], after=["loads"], needs_scenarios=True)   # loads comes first in the registry
    def scene(value):
        """A scene."""

    state = registry.run("the submission", stop_at_scenarios=True)
    assert not registry.wants_scenarios(state)
    results = registry.run("the submission", state=state).ordered(registry)
    assert [r.status for r in results] == [FAIL, SKIP, SKIP]
    assert results[1].message == results[2].message == "skipped: needs 'loads' to pass first"


@pytest.mark.parametrize("signature", ["sub, value, extra", "sub", "*values", "sub, *, value"])
def test_a_check_whose_parameters_do_not_match_its_dependencies_is_refused_at_registration(signature):
    registry = Registry()

    @registry.check()
    def first(sub):
        """First."""

    namespace = {}
    exec(f'def second({signature}):\n    "Second."\n', namespace)
    with pytest.raises(ValueError, match="one parameter per check in `depends`"):
        registry.check(depends=["first"])(namespace["second"])


def _unused_parameters(func):
    """The parameters of `func` its body never reads (by name, anywhere in it, nested functions included)."""
    import ast
    import inspect
    import textwrap
    node = ast.parse(textwrap.dedent(inspect.getsource(func))).body[0]
    arguments = node.args
    names = [a.arg for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)]
    names += [a.arg for a in (arguments.vararg, arguments.kwarg) if a is not None]
    read = {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
    return [name for name in names if name not in read]


def test_the_unused_parameter_finder_sees_a_parameter_that_is_never_read():
    def check(sub, functions, *passed):     # the old `runs`: took every dependency's value, read one
        return sub.name
    assert _unused_parameters(check) == ["functions", "passed"]

    def reads_all(sub, functions):
        return sub.name, functions
    assert _unused_parameters(reads_all) == []


def test_no_check_of_any_lab_takes_a_value_it_does_not_read():
    """Checks take only what they read: a dependency that only gates is declared in `after`, not passed in."""
    from checker.labs import LABS
    unused = {(lab.id, check.id): _unused_parameters(check.func) for lab in LABS for check in lab.checks.checks}
    assert {key: names for key, names in unused.items() if names} == {}
    assert len(unused) == sum(len(lab.checks.checks) for lab in LABS) >= 5 * 10   # every check was inspected


# ---------------------------------------------------------------- numbers beside their bounds

@pytest.mark.parametrize("value, bound, text", [
    (5.004, 5, "5.004"), (4.99999, 5, "4.99999"), (16.4, 30, "16.4"), (5.04, 5.0, "5.04"), (12.0, 5, "12.0")])
def test_a_failing_value_never_reads_equal_to_its_bound(value, bound, text):
    assert shown(value, bound) == text
    assert shown(value, bound) != f"{bound:g}"


def test_list_prints_every_check_of_every_lab_with_its_points(capsys):
    from checker.cli import main
    from checker.labs import LABS
    assert main(["--list"]) == 0
    out = capsys.readouterr().out
    for lab in LABS:
        assert f"{lab.title} ({lab.id}): {len(lab.checks.checks)} checks, {lab.checks.max_score:g} points" in out
        for check in lab.checks.checks:
            assert f"{check.id}" in out and check.description in out


# ---------------------------------------------------------------- the grader's slots: longest first

def test_a_freed_slot_goes_to_the_longest_waiting_run_ties_first_come():
    import threading
    import time

    from checker.grade import Slots
    slots = Slots(1)
    slots.acquire(0.0)                       # the one slot is busy
    started = []

    def wait_then_note(name, priority):
        slots.acquire(priority)
        started.append(name)
        slots.release()
    threads = []
    for name, priority in (("short", 0.3), ("long", 6.4), ("tie-a", 1.5), ("tie-b", 1.5), ("probe", float("inf"))):
        thread = threading.Thread(target=wait_then_note, args=(name, priority))
        thread.start()
        threads.append(thread)
        while len(slots.waiting) < len(threads):  # queued in this order
            time.sleep(0.001)
    slots.release()
    for thread in threads:
        thread.join(5)
    assert started == ["probe", "long", "tie-a", "tie-b", "short"]
    assert slots.free == 1 and not slots.waiting


def test_each_lab_declares_what_its_scenes_cost_and_an_unknown_scene_costs_its_simulated_time():
    from checker.labs import LABS
    for lab in LABS:
        scenes = lab.scenarios()
        assert set(lab.module.SCENE_SECONDS) == set(scenes), lab.id
        assert all(lab.scene_seconds(name, settings) > 0 for name, settings in scenes.items())
    tumbling = LABS[0]
    assert max(tumbling.scenarios(), key=lambda n: tumbling.scene_seconds(n, {})) == "pile"
    assert tumbling.scene_seconds("new scene", {"frames": 240, "fps": 60}) == 4.0


def test_messages_never_show_a_negative_zero():
    from checker.judging import lab_checks
    assert lab_checks.vec_text((1.0, -0.0001)) == "(1.00, 0.00)"     # was "(1.00, -0.00)"
    assert lab_checks.vec_text((-0.0, -2.5)) == "(0.00, -2.50)"
    assert lab_checks.number_text(-0.006) == "-0.01" and lab_checks.number_text(-0.004, 2) == "0.00"


def test_the_shared_checks_name_a_missing_function_with_the_labs_own_words():
    from types import SimpleNamespace
    from checker.judging import lab_checks
    from checker.judging.checks import ERROR
    registry = Registry()
    hints = {"crash": Hint(1, "run the file", "Run it."), "handout": None, "runtime": None}
    lab_checks.register_common(registry, hints, ("Wall", "main"), kind="names")
    assert [c.description for c in registry.checks][0] == "The file imports without errors and defines Wall and main."
    probe = SimpleNamespace(status="done", result={"probe": {"missing": ["main"], "functions": {}}})
    results = registry.run(SimpleNamespace(probe=probe, name="lab.py")).ordered(registry)
    assert [r.status for r in results] == [ERROR, SKIP, SKIP]
    assert results[0].message == "lab.py defines no function main().\nmissing: main."   # two lines (issue 40)
    assert results[0].hint == ("[lesson: the handout's functions] Keep the handout's names: Wall and main; the "
                               "checker calls them.")
    single = Registry()
    lab_checks.register_common(single, hints, ("main",))
    assert single.checks[0].description == "The file imports without errors and defines main."
