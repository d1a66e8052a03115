"""The checker owes every entry of the Bullets mistake corpus its verdict: no false pass, no false fail.

tests/corpus_bullets.py builds plausible student files from the current
starter; this module writes them all into a temporary folder once, grades them
in ONE run of `python -m checker --json`, and checks each file's verdict, one
test per entry:

  correct entry: every check passes;
  wrong entry: the named check has an accepted status ("fail", or "error" for a
  crash) and its JSON step is the step the mistake is in; loads passes; every
  other function check passes, and handout_unchanged and runtime_lines pass
  unless the mistake is outside the steps (then handout_unchanged is the named
  check). The scenes need every function check, so they are not constrained.

Grading the corpus (24 files) costs about 7 s of CPU (a wrong file stops after the probe).
"""
import json
import os
import subprocess
import sys

import pytest

import corpus_bullets as corpus

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NON_FUNCTION = ("loads", "handout_unchanged", "runtime_lines")


def run_checker(*args):
    """`python -m checker ARGS` from the repository root: (exit status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=1800)
    return proc.returncode, proc.stdout, proc.stderr


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    return corpus.write_corpus(tmp_path_factory.mktemp("bullets_corpus"))


@pytest.fixture(scope="module")
def graded(built):
    """{entry name: {check id: the check's JSON}}, from one checker run over the whole corpus."""
    status, out, err = run_checker("--json", "--quiet", "--timeout", "120", "--total-timeout", "1500",
                                   *built.values())
    assert status in (0, 1), f"the checker exited {status}: {err[-2000:]}"
    names = {os.path.abspath(path): name for name, path in built.items()}
    result = {}
    for lab in json.loads(out)["labs"]:
        assert lab["lab"] == "bullets", lab["path"]
        result[names[os.path.abspath(lab["path"])]] = {c["id"]: c for c in lab["criteria"]}
    assert set(result) == set(built)
    return result


def _show(checks):
    return "\n".join(f"  {cid}: {c['status']} (step {c['step']}): {c['message']}" for cid, c in checks.items())


def test_the_corpus_is_big_enough_and_covers_every_step():
    assert len(corpus.WRONG) >= 10 and len(corpus.CORRECT) >= 3
    for step in corpus.STEPS:
        assert [e.name for e in corpus.WRONG if e.step == step], f"no mistake in step {step}"
    assert [e.name for e in corpus.WRONG if e.check == "handout_unchanged"], "no mistake outside the steps"


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_builds_and_changes_only_its_own_step(entry):
    source = corpus.build(entry.name)
    compile(source, entry.name + ".py", "exec")
    assert "Bullets" in source.split('"""')[1]
    if entry.check != "pass":
        assert source != corpus.build("correct_solution_steps")
        if entry.check == "handout_unchanged":
            assert entry.edits and not entry.steps
        else:
            assert list(entry.steps) == [entry.step] and not entry.edits
            assert corpus.CHECK_STEP[entry.check] == entry.step


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
        f"got {named['status']} (step {named['step']}): {named['message']}\n{_show(checks)}")
    for cid in NON_FUNCTION + corpus.FUNCTION_CHECKS:
        if cid != entry.check:
            assert checks[cid]["status"] == "pass", f"{entry.name}: {cid} is {checks[cid]['status']}\n{_show(checks)}"
