"""python -m checker lint-lab ID (checker/authoring/lint_lab.py, the rules in checker/authoring/lab_rules.py).

  - every lab in checker/labs/ keeps every rule (found by listing the folder, as lint-lab finds them);
  - each rule, broken once in a copy of Sleeping Crates, gives exactly that rule's one line: the copy's
    solution, starter and corpus sit under a temporary root (labs.Lab(id, root=...)), its modules' folder is
    copied where a rule reads files, and a module attribute is monkeypatched where a rule reads the module
    (the real lab's modules are imported once per process; monkeypatch puts them back);
  - an unknown ID is one line naming it and the known labs;
  - the rules the guide (checker/README.md, "Writing a lab") lists are lint-lab's, in its order;
  - the limits lint-lab holds hints to are the tests' own.
"""
import dataclasses
import os
import re
import shutil

import pytest

import corpus_verdicts
import test_hints_coach
from checker import cli, labs
from checker.authoring import assign, lab_rules, lint_lab
from checker.judging.checks import Hint, Registry

ROOT = labs.PROJECT_ROOT
LAB = "sleeping_crates"   # the cheapest lab to lint (its corpus is the smallest)


@pytest.mark.parametrize("lab_id", labs.found())
def test_every_lab_keeps_every_rule(lab_id, capsys):
    assert cli.main(["lint-lab", lab_id]) == 0
    out, err = capsys.readouterr()
    assert out.splitlines() == [f"lab {lab_id} keeps all {len(lab_rules.RULES)} rules "
                                f"({len(lab_rules.STATED)} more are left to the tests: --rules lists them)"]
    assert err == ""


def test_an_unknown_id_is_one_line_naming_it_and_the_labs(capsys):
    assert cli.main(["lint-lab", "no_such_lab"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert "no lab 'no_such_lab'" in err and ", ".join(labs.found()) in err


def test_rules_lists_every_rule_once_in_order(capsys):
    assert cli.main(["lint-lab", "--rules"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == len(lab_rules.RULES) + len(lab_rules.STATED)
    assert [line.split(". ", 1)[1] for line in lines[:len(lab_rules.RULES)]] == [r.text for r in lab_rules.RULES]
    assert len({r.id for r in lab_rules.RULES}) == len(lab_rules.RULES)


def test_the_guide_lists_the_rules_lint_lab_states_in_its_order():
    with open(os.path.join(ROOT, "checker", "README.md"), encoding="utf-8") as handle:
        guide = handle.read()
    section = guide[guide.index("### Writing a lab"):]
    section = section[:section.index("\n### ", 5)] if "\n### " in section[5:] else section
    listed = re.findall(r"^\d+\. (.+)$", section, re.M)
    wanted = [r.text for r in lab_rules.RULES] + [f"{s.text} (left to `{s.test}`)" for s in lab_rules.STATED]
    assert listed == wanted


def test_the_limits_are_the_tests_own():
    """lint-lab and the tests hold hints to the same numbers (tests/corpus_verdicts.py, tests/test_hints_coach.py)."""
    assert lab_rules.HINT_LIMIT == corpus_verdicts.HINT
    assert lab_rules.WINDOW == test_hints_coach.WINDOW and test_hints_coach.handed_out is lab_rules.handed_out


# ---------------------------------------------------------------- each rule broken once


@pytest.fixture
def copy(tmp_path):
    """A Subject for a copy of Sleeping Crates under tmp_path: its solution, starter, corpus and corpus test, and
    a copy of its modules' folder (the modules imported are still the real ones)."""
    for rel in (f"solutions/{LAB}.py", f"starters/{LAB}_starter.py", f"tests/corpus_{LAB}.py"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(os.path.join(ROOT, rel), tmp_path / rel)
    folder = tmp_path / "labs" / LAB
    shutil.copytree(os.path.join(labs.HERE, LAB), folder, ignore=shutil.ignore_patterns("__pycache__"))
    return lab_rules.Subject(labs.Lab(LAB, root=str(tmp_path)), folder=str(folder))


def broken_rules(subject):
    return [rule.id for rule, _ in lint_lab.lint(subject)]


def edit(subject, rel, old, new, starter=True):
    """Replace `old` (once) by `new` in the copy's file `rel`; after a solution edit, write its starter again."""
    path = os.path.join(subject.lab.root, rel)
    with open(path, encoding="utf-8") as handle:
        text = handle.read()
    assert text.count(old) >= 1, old
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(text.replace(old, new, 1))
    if starter and rel.startswith("solutions/"):
        with open(subject.lab.starter, "w", encoding="utf-8") as handle:
            handle.write(assign.starter_text(text.replace(old, new, 1)))


def test_the_copy_keeps_every_rule(copy):
    assert broken_rules(copy) == []


def registry(*checks):
    fake = Registry()
    fake.checks = list(checks)
    return fake


def checks_of(lab_id=LAB):
    return list(labs.Lab(lab_id).checks.checks)


def _unread(sub, functions):
    return sub.name


MODULE_BREAKS = {   # rule -> (module: "checks", "probes" or "scenes", attribute, the value that breaks it)
    "checks_names": ("checks", "STEP_ADVICE", None),
    "shared_checks_first": ("checks", "CHECKS", lambda: registry(*checks_of()[1::-1], *checks_of()[2:])),
    "step_rows": ("checks", "STEP_ADVICE", {2: "a", 3: "b"}),
    "runs_check": ("checks", "CHECKS", lambda: registry(*[dataclasses.replace(c, needs_scenarios=False)
                                                          if c.id == "runs" else c for c in checks_of()])),
    "checks_read_what_they_take": ("checks", "CHECKS", lambda: registry(*checks_of(), dataclasses.replace(
        checks_of()[-1], id="unread", func=_unread))),
    "scene_seconds": ("checks", "SCENE_SECONDS", {"sleep": 1.4, "gone": 1.0}),
    "picture_scenes": ("checks", "PICTURE_SCENES", {"runs": ("sleep", "gone")}),
    "short_hints": ("checks", "HINTS", lambda: dict(labs.Lab(LAB).module.HINTS, timer=Hint(2, "t", "x " * 130))),
    "hints_hand_out_no_code": ("checks", "HINTS", lambda: dict(labs.Lab(LAB).module.HINTS, timer=Hint(
        2, "t", "write calm = speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN there"))),
    "hint_symptoms": ("checks", "HINTS", lambda: dict(labs.Lab(LAB).module.HINTS, timer=Hint(
        2, "t", "If the crates explode apart, look at the timer."))),
    "scenarios": ("scenes", "SCENARIOS", {}),
    "probes_names": ("probes", "REQUIRED", ("sleep_timer", "moves", "wake_on_contact", "build")),
    "pure": ("probes", "PURE", ("sleep_timer", "main")),
    "splices": ("probes", "SPLICES", (("moves", (2,)),)),
}


@pytest.mark.parametrize("rule_id", MODULE_BREAKS)
def test_a_module_that_breaks_a_rule_gets_exactly_its_line(rule_id, copy, monkeypatch):
    import importlib
    kind, name, value = MODULE_BREAKS[rule_id]
    module = importlib.import_module(f"checker.labs.{LAB}.{kind}")
    if value is None:
        monkeypatch.delattr(module, name)
    else:
        monkeypatch.setattr(module, name, value() if callable(value) else value, raising=False)
    found = lint_lab.lint(copy)
    assert [rule.id for rule, _ in found] == [rule_id], [lint_lab.line(r, copy, b) for r, b in found]
    text = lint_lab.line(*found[0][:1], copy, found[0][1])
    assert "\n" not in text and " — " in text and text.startswith(f"checker/labs/{LAB}/")


def test_a_reference_helper_left_unmarked_is_named(copy, monkeypatch):
    import importlib
    probes = importlib.import_module(f"checker.labs.{LAB}.probes")

    def reference_timer(timer, dt):
        return timer + dt
    reference_timer.__module__ = probes.__name__
    monkeypatch.setattr(probes, "reference_timer", reference_timer, raising=False)
    ((rule, problem),) = lint_lab.lint(copy)
    assert rule.id == "reference_names" and "reference_timer not marked @reference" in problem.what


def test_a_lab_folder_with_another_file_or_a_path_of_its_own_is_named(copy):
    extra = os.path.join(copy.folder, "helpers.py")   # show.py may be there (the lab's drawings); no other
    with open(extra, "w", encoding="utf-8") as handle:
        handle.write("x = 1\n")
    assert broken_rules(copy) == ["lab_files"]
    os.remove(extra)
    with open(os.path.join(copy.folder, "scenes.py"), "a", encoding="utf-8") as handle:
        handle.write("\nROOT = '.'\n")
    ((rule, problem),) = lint_lab.lint(copy)
    assert rule.id == "no_own_paths" and problem.what == "assigns ROOT" and problem.file.endswith("scenes.py")


SOURCE_BREAKS = {   # rule -> (file, old, new): one edit of the copy (a solution edit writes the starter again)
    "prompts": (f"solutions/{LAB}.py", '    # Step 2 (lesson:', '    # step two (lesson:'),
    "starter_is_assigned": (f"starters/{LAB}_starter.py", '"""Sleeping Crates:', '"""Sleeping Crates, edited:'),
    "placeholders": (f"solutions/{LAB}.py", "# until you write step 2,", "# until step 2 is written,"),
    "starter_header": (f"solutions/{LAB}.py", "wasted", "lost"),
    "lesson_citations": (f"solutions/{LAB}.py", '    # Step 2 (lesson: "', '    # Step 2 (lesson: "Nowhere'),
    "numbered_steps": (f"solutions/{LAB}.py", "\nimport ", "\n# Step 6: nothing more.\nimport "),
    "title_names_the_file": (f"solutions/{LAB}.py", '"""Sleeping Crates:', '"""Sleepy Boxes:'),
    "world_factories": (f"solutions/{LAB}.py", "def make_world(rng):", "def make_world(rng, mode):"),
    "no_flags": (f"solutions/{LAB}.py", "    # END PROMPT\n", "    # END PROMPT\n    _ = getattr(body, 'x', 0)\n"),
}


@pytest.mark.parametrize("rule_id", SOURCE_BREAKS)
def test_a_file_that_breaks_a_rule_gets_exactly_its_line(rule_id, copy):
    rel, old, new = SOURCE_BREAKS[rule_id]
    edit(copy, rel, old, new, starter=rule_id != "prompts")
    found = lint_lab.lint(copy)
    assert [rule.id for rule, _ in found] == [rule_id], [lint_lab.line(r, copy, b) for r, b in found]
    text = lint_lab.line(found[0][0], copy, found[0][1])
    assert "\n" not in text and " — " in text


def test_a_placeholder_that_is_the_whole_answer_is_named(copy):
    solution = open(copy.lab.solution, encoding="utf-8").read()
    answer = lab_rules.region_lines(solution)[3]
    code = [line.strip() for line in answer if line.strip() and not line.strip().startswith("#")]
    assert len(code) == 1, code   # step 3 is one line: handing it out as the placeholder gives the answer away
    edit(copy, f"solutions/{LAB}.py", "    # starter: return body.inv_mass != 0",
         f"    # starter: {code[0]}")
    ((rule, problem),) = lint_lab.lint(copy)
    assert rule.id == "placeholders" and "holds the whole answer" in problem.what


def test_a_missing_starter_or_corpus_is_one_line_and_what_needs_it_waits(copy):
    os.remove(os.path.join(copy.lab.root, "tests", f"corpus_{LAB}.py"))
    assert [lint_lab.line(r, copy, b) for r, b in lint_lab.lint(copy)] == [
        f"{os.path.join(copy.lab.root, 'tests', f'corpus_{LAB}.py')}: no such file — write the corpus "
        "(new-lab writes a first one)"]
    os.remove(copy.lab.starter)
    assert broken_rules(copy) == ["solution_and_starter"]


def test_a_corpus_too_small_is_named(copy):
    with open(os.path.join(copy.lab.root, "tests", f"corpus_{LAB}.py"), "a", encoding="utf-8") as handle:
        handle.write("\nWRONG = WRONG[:9]\n")
    ((rule, problem),) = lint_lab.lint(copy)
    assert rule.id == "corpus" and problem.what.endswith(" correct and 9 wrong entries")


def test_a_module_that_does_not_import_is_one_line_per_rule_that_reads_it(copy, monkeypatch):
    def fails(self):
        raise ImportError("No module named 'numpyy'")
    monkeypatch.setattr(labs.Lab, "module", property(fails))
    found = lint_lab.lint(copy)
    assert found and all("could not be checked (ImportError: No module named 'numpyy')" in b.what for _, b in found)
    assert [rule.id for rule, _ in found] == ["checks_names"]   # the rules that read checks.py wait for it


def test_a_count_kept_at_module_level_is_named_and_a_threading_local_is_not(copy):
    """Bullets once counted its exact swept tests in a module-level list; files judged in parallel threads mixed
    two files' counts and failed a right one."""
    path = os.path.join(copy.folder, "probes.py")
    kept = open(path, encoding="utf-8").read()
    with open(path, "a", encoding="utf-8") as handle:
        handle.write("\n_COUNT = [0]\n\n\ndef _counted(*args):\n    _COUNT[0] += 1\n")
    ((rule, problem),) = lint_lab.lint(copy)
    line = len(kept.splitlines()) + 6
    assert rule.id == "no_module_state" and problem.what == f"line {line} writes the module-level _COUNT"
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(kept + "\nimport threading\n_COUNT = threading.local()\n\n\ndef _counted():\n"
                     "    _COUNT.n = 0\n")
    assert broken_rules(copy) == []
    assert lab_rules.module_state_writes("S = {}\nL = []\nN = 0\ndef f(x):\n    global N\n    S.update(x)\n"
                                         "    L.append(x)\n    x.append(1)\n    own = []\n    own.append(1)\n") == [
        (5, "N"), (6, "S"), (7, "L")]


def test_every_rule_has_its_broken_copy_here():
    """A rule added to lab_rules.py without a broken copy in this file fails here."""
    covered = set(MODULE_BREAKS) | set(SOURCE_BREAKS) | {
        "reference_names", "lab_files", "no_own_paths", "corpus", "solution_and_starter", "placeholders",
        "no_module_state"}
    assert covered == {rule.id for rule in lab_rules.RULES}


def test_a_broken_rule_through_the_command_line_is_one_line_and_exit_1(monkeypatch, capsys):
    from checker.labs.sleeping_crates import checks
    monkeypatch.setattr(checks, "SCENE_SECONDS", {})
    assert cli.main(["lint-lab", LAB]) == 1
    out, err = capsys.readouterr()
    assert err == "" and out.splitlines() == [
        f"checker/labs/{LAB}/checks.py: SCENE_SECONDS names nothing, the scenes are sleep — measure the solution's "
        "run of each scene and give it its seconds"]
