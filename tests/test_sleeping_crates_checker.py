"""The checker grades Sleeping Crates: the solution passes every check, the starter fails at steps 2-4 with hints.

Both files are graded in one `python -m checker --json` run. The lab is one
module (checker/labs/sleeping_crates/checks.py) and one row of checker/labs/__init__.py; a file is
a Sleeping Crates lab by its name or its text.
"""
import json
import os
import subprocess
import sys

import pytest

from checker import labs
from checker.labs.sleeping_crates import checks as sleeping_crates

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join("solutions", "sleeping_crates.py")
STARTER = os.path.join("starters", "sleeping_crates_starter.py")


@pytest.fixture(scope="module")
def graded():
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--timeout", "60", SOLUTION, STARTER],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 1, proc.stderr  # the starter fails
    document = json.loads(proc.stdout)
    return {lab["path"]: lab for lab in document["labs"]}


def test_the_lab_is_registered_and_recognised():
    (row,) = [lab for lab in labs.LABS if lab.id == "sleeping_crates"]
    assert row.title == "Sleeping Crates" and row.probes == "checker.labs.sleeping_crates.probes"
    with open(os.path.join(ROOT, SOLUTION), encoding="utf-8") as handle:
        source = handle.read()
    assert labs.identify("student.py", source).id == "sleeping_crates"
    assert labs.identify("sleeping_crates.py", "").id == "sleeping_crates"
    for other in labs.LABS:   # and every other lab's solution is its own lab's
        with open(other.solution, encoding="utf-8") as handle:
            assert labs.identify("student.py", handle.read()).id == other.id


def test_the_solution_passes_every_check(graded):
    lab = graded[SOLUTION]
    assert lab["lab"] == "sleeping_crates" if "lab" in lab else True
    failing = [c for c in lab["criteria"] if c["status"] != "pass"]
    assert not failing, failing
    assert len(lab["criteria"]) == len(sleeping_crates.CHECKS.checks)


@pytest.mark.parametrize("check, step", [("timer_rule", 2), ("skips_sleepers", 3), ("wakes_on_contact", 4)])
def test_the_starter_fails_each_step_with_its_hint(graded, check, step):
    checks = {c["id"]: c for c in graded[STARTER]["criteria"]}
    assert checks[check]["status"] == "fail" and checks[check]["step"] == step
    assert checks[check]["hint"].startswith(f"[step {step}: ")
    assert checks["handout_unchanged"]["status"] == "pass" and checks["runtime_lines"]["status"] == "pass"


def test_every_bound_is_commented_with_the_solutions_figure():
    with open(sleeping_crates.__file__, encoding="utf-8") as handle:
        text = handle.read()
    block = text.split("# ---------------------------------------------------------------- bounds")[1].split("# ---")[0]
    lines = [line for line in block.splitlines() if "=" in line]
    assert len(lines) >= 8 and all("solution:" in line for line in lines), lines
