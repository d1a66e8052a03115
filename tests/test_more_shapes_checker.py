"""The checker grades More Shapes: the solution passes every check, the starter fails at step 2 with its hint.

Both files are graded in one `python -m checker --json` run. The lab is one
module (checker/labs/more_shapes/checks.py) and one row of checker/labs/__init__.py; a file is a
More Shapes lab by its name or its text.
"""
import json
import os
import subprocess
import sys

import pytest

from checker import labs
from checker.labs.more_shapes import checks as more_shapes

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join("solutions", "more_shapes.py")
STARTER = os.path.join("starters", "more_shapes_starter.py")


@pytest.fixture(scope="module")
def graded():
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--timeout", "60", SOLUTION, STARTER],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 1, proc.stderr  # the starter fails
    document = json.loads(proc.stdout)
    return {lab["path"]: lab for lab in document["labs"]}


def test_the_lab_is_registered_and_recognised():
    (row,) = [lab for lab in labs.LABS if lab.id == "more_shapes"]
    assert row.title == "More Shapes" and row.probes == "checker.labs.more_shapes.probes"
    with open(os.path.join(ROOT, SOLUTION), encoding="utf-8") as handle:
        source = handle.read()
    assert labs.identify("student.py", source).id == "more_shapes"
    assert labs.identify("more_shapes.py", "").id == "more_shapes"
    with open(os.path.join(ROOT, "solutions", "tumbling_crates.py"), encoding="utf-8") as handle:
        assert labs.identify("student.py", handle.read()).id == "tumbling_crates"


def test_the_solution_passes_every_check(graded):
    lab = graded[SOLUTION]
    assert lab["lab"] == "more_shapes"
    failing = [(c["id"], c["status"], c["message"]) for c in lab["criteria"] if c["status"] != "pass"]
    assert not failing
    assert lab["score"] == lab["max_score"] == more_shapes.CHECKS.max_score == 18


def test_the_starter_fails_first_at_step_2_with_its_hint(graded):
    lab = graded[STARTER]
    checks = {c["id"]: c for c in lab["criteria"]}
    assert [checks[c]["status"] for c in ("loads", "handout_unchanged", "runtime_lines")] == ["pass"] * 3
    first = next(c for c in lab["criteria"] if c["status"] != "pass")
    assert first["id"] == "polygon_corners" and first["status"] == "fail" and first["step"] == 2
    assert first["hint"].startswith("[step 2: a regular polygon's corners]")
    for cid, step in (("centroid", 3), ("inertia_sum", 4), ("parallel_axes", 5)):
        assert checks[cid]["status"] == "fail" and checks[cid]["step"] == step
    assert checks["runs"]["status"] == "skip"  # a wrong file costs one probe run, no scene
