"""The checker owes every entry of the Sleeping Crates mistake corpus its verdict: no false pass, no false fail.

tests/corpus_sleeping_crates.py builds plausible student files from the current
starter; this module writes them all into a temporary directory once, grades
them in ONE run of `python -m checker --json`, and checks each file's
verdict, one test per entry:

  correct entry: every check passes;
  wrong entry: the named check fails (or errors, for a crash) naming the entry's step;
  loads passes; a mistake inside the steps leaves handout_unchanged and
  runtime_lines passing; every other function check passes; narrow_work
  (it needs steps 2 to 4) may be skipped; the entry's `also` checks are free.
  The scenes need every function check, so they are not constrained for a
  wrong entry (a wrong file stops after one probe run).
"""
import json
import os
import subprocess
import sys

import pytest

import corpus_sleeping_crates as corpus

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NON_FUNCTION = ("loads", "handout_unchanged", "runtime_lines")


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    return corpus.write_corpus(tmp_path_factory.mktemp("sleeping_crates_corpus"))


@pytest.fixture(scope="module")
def graded(built):
    """{entry name: {check id: the check's JSON}}, from one checker run over the whole corpus."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--csv", "none", "--quiet", "--timeout", "120",
                           *built.values()], cwd=ROOT, env=env, capture_output=True, text=True, timeout=1800)
    assert proc.returncode in (0, 1), f"the checker exited {proc.returncode}: {proc.stderr[-2000:]}"
    names = {os.path.abspath(path): name for name, path in built.items()}
    result = {names[os.path.abspath(lab["path"])]: {c["id"]: c for c in lab["criteria"]}
              for lab in json.loads(proc.stdout)["labs"]}
    assert set(result) == set(built)
    return result


def _show(checks):
    return "\n".join(f"  {cid}: {c['status']} (step {c['step']}): {c['message']}" for cid, c in checks.items())


def test_the_corpus_is_big_enough_and_covers_every_step():
    assert len(corpus.WRONG) >= 10 and len(corpus.CORRECT) >= 3
    for step in corpus.STEPS:
        assert len([e for e in corpus.WRONG if e.step == step]) >= 3, step
    assert [e for e in corpus.WRONG if e.check == "handout_unchanged"], "no mistake outside the steps"


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_is_well_formed_and_builds(entry):
    assert entry.what and "\n" not in entry.what and entry.why
    source = corpus.build(entry.name)
    compile(source, entry.name + ".py", "exec")
    assert "Sleeping Crates" in source.split('"""')[1], "the checker recognises the lab by its docstring's title"
    if entry.check == "pass":
        assert entry.step is None and not entry.edits
    elif entry.check == "handout_unchanged":
        assert entry.edits and not entry.steps
    else:
        assert list(entry.steps) == [entry.step] and not entry.edits
        assert source != corpus.build("correct_solution_steps")


def test_the_reference_build_is_the_solution():
    with open(corpus.SOLUTION, encoding="utf-8") as handle:
        assert corpus.build("correct_solution_steps") == handle.read()


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_the_checker_gives_each_entry_its_verdict(entry, graded):
    checks = graded[entry.name]
    assert set(corpus.CHECK_STEP) == set(checks), _show(checks)
    if entry.check == "pass":
        failing = {cid: c for cid, c in checks.items() if c["status"] != "pass"}
        assert not failing, f"{entry.name} is correct ({entry.what}) but:\n{_show(failing)}\nwhy: {entry.why}"
        return
    named = checks[entry.check]
    assert named["status"] in entry.status and named["step"] == entry.step, (
        f"{entry.name} ({entry.what}): expected {entry.check} {'/'.join(entry.status)} naming step {entry.step}; "
        f"got {named['status']} naming step {named['step']}: {named['message']}\nwhy: {entry.why}\n{_show(checks)}")
    if entry.step is not None:
        assert named["hint"].startswith(f"[step {entry.step}: "), named["hint"]
    for cid in NON_FUNCTION + corpus.FUNCTION_CHECKS + corpus.NEEDS_STEPS_2_TO_4:
        if cid == entry.check or cid in entry.also:
            continue
        allowed = ("pass", "skip") if cid in corpus.NEEDS_STEPS_2_TO_4 else ("pass",)
        assert checks[cid]["status"] in allowed, (f"{entry.name} ({entry.what}) is a mistake for {entry.check}, but "
                                                  f"{cid} is {checks[cid]['status']}:\n{_show(checks)}")
