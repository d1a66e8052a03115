"""The checker owes every entry of the Tumbling Crates mistake corpus its verdict (issue 9: no false pass).

tests/corpus_tumbling_crates.py builds realistic student files from the
current starter; this module writes them all into a temporary directory once,
grades them in ONE run of `python -m checker --json`, and checks each file's
verdict, one test per entry:

  correct entry: every check passes;
  wrong entry: the named check has an accepted status ("fail", or "error" for
  a crash) and its JSON step is the step the mistake is in; its message
  contains the entry's `says` words (it names the mistake); loads passes; a
  mistake inside the steps leaves handout_unchanged and runtime_lines passing;
  every other function check passes, except that a check depending on the
  failing one (sat_normal on sat_axes) may be skipped, a crash may take the
  other check of the same function with it (skip or error, never fail), and
  the entry's `also` checks are not constrained. runs and the four criteria
  need every function check, so they are not constrained for a wrong entry.

Grading the corpus runs each file's four scenes, about 12 s of CPU per file.
"""
import json
import os
import subprocess
import sys

import pytest

import corpus_tumbling_crates as corpus
import corpus_verdicts as verdicts

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NON_FUNCTION = ("loads", "handout_unchanged", "runtime_lines")


def run_checker(*args):
    """Run `python -m checker ARGS` from the repository root; returns (exit status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=7500)
    return proc.returncode, proc.stdout, proc.stderr


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """Every corpus entry written from the current starter and solution: {name: path}."""
    return corpus.write_corpus(tmp_path_factory.mktemp("corpus"))


@pytest.fixture(scope="module")
def graded(built):
    """{entry name: {check id: the check's JSON}}, from one checker run over the whole corpus."""
    # a long per-run limit: on a busy machine a scene can take longer than the default 20 s, and no entry loops
    status, out, err = run_checker("--json", "--csv", "none", "--quiet", "--timeout", "180", "--total-timeout", "7200",
                                   *built.values())
    assert status in (0, 1), f"the checker exited {status}: {err[-2000:]}"
    document = json.loads(out)
    names = {os.path.abspath(path): name for name, path in built.items()}
    result = {}
    for lab in document["labs"]:
        result[names[os.path.abspath(lab["path"])]] = {c["id"]: c for c in lab["criteria"]}
    assert set(result) == set(built), set(built) ^ set(result)
    return result


def _show(checks):
    return "\n".join(f"  {cid}: {c['status']} (step {c['step']}): {c['message']}" for cid, c in checks.items())


# ---------------------------------------------------------------- the corpus itself

def test_the_corpus_is_big_enough_and_covers_every_step():
    assert len(corpus.WRONG) >= 25
    assert len(corpus.ENTRIES) - len(corpus.WRONG) >= 5
    for step in corpus.STEPS:
        inside = [e.name for e in corpus.WRONG if e.step == step]
        assert len(inside) >= 3, (step, inside)
    assert [e.name for e in corpus.WRONG if e.check == "handout_unchanged"], "no mistake outside the steps"


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_is_well_formed(entry):
    assert entry.what and "\n" not in entry.what
    verdicts.assert_says_words(entry)   # a wrong entry lists the words its first message must contain
    assert entry.check == "pass" or entry.check in corpus.CHECK_STEP, entry.check
    if entry.check == "pass":
        assert entry.step is None and entry.status == ("pass",) and not entry.also
        return
    assert entry.step == corpus.CHECK_STEP[entry.check]
    assert entry.status and set(entry.status) <= {"fail", "error"}
    assert set(entry.also) <= set(corpus.CHECK_STEP) - {entry.check}
    assert entry.why, f"{entry.name}: say which input shows the mistake"
    # a mistake in a step changes only that step; a mistake outside the steps changes no step
    if entry.check == "handout_unchanged":
        assert entry.edits and not entry.steps
    else:
        assert list(entry.steps) == [entry.step] and not entry.edits


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_builds_from_the_starter_and_wrong_ones_differ_from_the_correct_build(entry):
    source = corpus.build(entry.name)  # raises AssertionError naming the entry when an edit no longer fits
    compile(source, entry.name + ".py", "exec")
    assert "Tumbling Crates" in source.split('"""')[1], "the checker recognises the lab by its docstring's title"
    placeholders = [line for line in source.splitlines() if line.strip().startswith("return None  # until you write")]
    assert not placeholders or entry.name == "sat_placeholder_left"   # (the solution's prompt quotes it as a comment)
    reference = corpus.build("correct_solution_steps")
    if entry.check != "pass":
        assert source != reference
    # the steps the entry does not give are the solution's
    given = corpus.step_code(source, entry.name)
    solution = corpus.step_code(open(corpus.SOLUTION, encoding="utf-8").read())
    for step in corpus.STEPS:
        assert given[step] == (entry.steps[step] if step in entry.steps else solution[step]), (entry.name, step)


def test_the_reference_build_is_the_solution():
    """Filling the starter's steps with the solution's code gives back the solution, byte for byte."""
    assert corpus.build("correct_solution_steps") == open(corpus.SOLUTION, encoding="utf-8").read()


def test_an_edit_that_no_longer_fits_fails_loudly_naming_the_entry():
    with pytest.raises(AssertionError, match="entry_x: the text to replace occurs 0 times"):
        corpus.apply_edits("a = 1\n", [("b = 2", "b = 3")], "entry_x")
    with pytest.raises(AssertionError, match="entry_x: the text to replace occurs 2 times"):
        corpus.apply_edits("a = 1\na = 1\n", [("a = 1", "a = 2")], "entry_x")
    with pytest.raises(AssertionError, match="starter: step 3 has no"):
        corpus.regions("# --- step 2: x ---\n# --- end of step 2 ---\n", "starter")


# ---------------------------------------------------------------- the checker's verdicts

@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_the_checker_gives_each_entry_its_verdict(entry, graded):
    checks = graded[entry.name]
    assert set(corpus.CHECK_STEP) <= set(checks), f"{entry.name}: missing checks\n{_show(checks)}"
    if entry.check == "pass":
        failing = {cid: c for cid, c in checks.items() if c["status"] != "pass"}
        assert not failing, f"{entry.name} is correct ({entry.what}) but:\n{_show(failing)}\nwhy correct: {entry.why}"
        return

    named = checks[entry.check]
    assert named["status"] in entry.status and named["step"] == entry.step, (
        f"{entry.name} ({entry.what}): expected {entry.check} {'/'.join(entry.status)} naming step {entry.step}; "
        f"got {named['status']} naming step {named['step']}: {named['message']}\nwhy: {entry.why}\n{_show(checks)}")
    verdicts.assert_first_message(entry, named, corpus)   # names the mistake (issue 33), two short lines (40)

    crash = "error" in entry.status
    for cid in NON_FUNCTION + corpus.FUNCTION_CHECKS:
        if cid == entry.check or cid in entry.also:
            continue
        got = checks[cid]["status"]
        if entry.check in corpus.DEPENDS.get(cid, ()):
            allowed = ("pass", "skip")
        elif crash and corpus.SAME_FUNCTION.get(entry.check) == cid:
            allowed = ("pass", "skip", "error")
        else:
            allowed = ("pass",)
        assert got in allowed, (f"{entry.name} ({entry.what}) is a mistake for {entry.check}, but {cid} is {got} "
                                f"(allowed: {', '.join(allowed)}): {checks[cid]['message']}\n{_show(checks)}")
