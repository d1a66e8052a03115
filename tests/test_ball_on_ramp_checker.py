"""`python -m checker` on the Ball on the Ramp lab: the solution passes every check, cheaply; the starter fails
at its first step with that step's hint; the lab is one row of checker/labs/__init__.py."""
import json
import os
import subprocess
import sys

import pytest

from checker import labs
from checker.labs.ball_on_ramp import checks as ball_on_ramp

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "ball_on_ramp.py")
STARTER = os.path.join(ROOT, "starters", "ball_on_ramp_starter.py")
CPU_BUDGET = 5.0   # CPU s to grade the solution (the issue); measured 2.0-2.4 s (probe + 3 scenes + the grader)


def _children_cpu():
    """CPU s of the finished children, or None where there is no getrusage (Windows: no CPU budget measured)."""
    try:
        import resource
    except ImportError:
        return None
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_checker(*args):
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    before = _children_cpu()
    proc = subprocess.run([sys.executable, "-m", "checker", *args], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=600)
    return proc, None if before is None else _children_cpu() - before


@pytest.fixture(scope="module")
def solution_run():
    return run_checker("--json", "--quiet", "--jobs", "2", SOLUTION)


def test_the_lab_is_registered_with_one_row():
    rows = [lab for lab in labs.LABS if lab.module is ball_on_ramp]
    assert len(rows) == 1 and rows[0].id == "ball_on_ramp" and rows[0].title == "Ball on the Ramp"
    assert labs.identify("x/ball_on_ramp.py", "") is rows[0]
    assert labs.identify("x/lab.py", '"""Ball on the Ramp: my lab."""') is rows[0]
    assert labs.identify("x/tumbling_crates.py", "").id == "tumbling_crates"


def test_the_solution_passes_every_check_within_the_cpu_budget(solution_run):
    proc, cpu = solution_run
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-2000:]
    document = json.loads(proc.stdout)
    (lab,) = document["labs"]
    assert lab["lab"] == "ball_on_ramp" and lab["score"] == lab["max_score"] == 18
    assert [c["id"] for c in lab["criteria"]] == [c.id for c in ball_on_ramp.CHECKS.checks]
    if cpu is not None:   # Windows: no getrusage, the budget is measured on Linux and macOS
        assert cpu <= CPU_BUDGET, f"grading the solution took {cpu:.2f} CPU s (budget {CPU_BUDGET:g})"


def test_the_starter_fails_at_step_2_with_its_hint_and_runs_no_scene():
    proc, cpu = run_checker("--json", "--quiet", STARTER)
    assert proc.returncode == 1
    (lab,) = json.loads(proc.stdout)["labs"]
    checks = {c["id"]: c for c in lab["criteria"]}
    assert [checks[c]["status"] for c in ("loads", "handout_unchanged", "runtime_lines")] == ["pass"] * 3
    first = next(c for c in lab["criteria"] if c["status"] != "pass")
    assert first["id"] == "closest_point" and first["step"] == 2
    assert first["hint"].startswith("[step 2: the closest point on one edge]")
    assert "placeholder" in first["message"]
    for cid, step in (("inside_case", 3), ("push_out_split", 4), ("ball_inertia", 5), ("contact_on_surface", 6),
                      ("friction_rolls", 7)):
        assert checks[cid]["status"] == "fail" and checks[cid]["step"] == step, checks[cid]
    assert checks["runs"]["status"] == "skip"
    if cpu is not None:   # Windows: no getrusage
        assert cpu < 2.0, f"a failing file should stop after the probe; it took {cpu:.2f} CPU s"
