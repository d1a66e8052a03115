"""The More Shapes starter is the solution with steps 2-5 left to write, and it runs as handed out.

Step regions are the lines between `# --- step N: ... ---` and
`# --- end of step N ---`. Outside them the two files must be identical line
by line (module docstring included); inside, the solution has code and the
starter only comments and one placeholder line per step, which keeps the
starter running (squares that hardly turn, tested on every edge).
"""
import os

import pytest

from lab_run import ROOT, run_lab
from test_lab_starter import code_lines, split_regions

SOLUTION = os.path.join(ROOT, "solutions", "more_shapes.py")
STARTER = os.path.join(ROOT, "starters", "more_shapes_starter.py")
STUDENT_STEPS = {"2", "3", "4", "5"}
PLACEHOLDERS = {  # the only code a starter region may hold, by step
    "2": {"return box_points(radius, radius)"},
    "3": {"return Vector2()"},
    "4": {"return 1e9"},
    "5": {"axes = edge_normals(pa) + edge_normals(pb)"},
}


def test_both_files_mark_the_same_student_steps():
    assert set(split_regions(SOLUTION)[1]) == STUDENT_STEPS
    assert set(split_regions(STARTER)[1]) == STUDENT_STEPS


def test_files_are_identical_outside_the_step_regions():
    solution, _ = split_regions(SOLUTION)
    starter, _ = split_regions(STARTER)
    for number, (a, b) in enumerate(zip(solution, starter), 1):
        assert a == b, f"outside-region line {number} differs:\n solution: {a!r}\n starter:  {b!r}"
    assert len(solution) == len(starter)


@pytest.mark.parametrize("step", sorted(STUDENT_STEPS))
def test_starter_regions_hold_no_solution_code(step):
    region = split_regions(STARTER)[1][step]
    solution = code_lines(split_regions(SOLUTION)[1][step])
    assert solution, "the solution's region holds code"
    assert set(code_lines(region)) <= PLACEHOLDERS[step]
    assert not set(code_lines(region)) & set(solution)
    comments = [line.strip() for line in region if line.strip().startswith("#")]
    assert comments and comments[0].startswith(f"# Step {step} "), "the region's comment names its step"


def test_starter_comments_number_all_six_steps():
    with open(STARTER, encoding="utf-8") as handle:
        text = handle.read()
    for step in range(1, 7):
        assert f"# Step {step}" in text, f"no comment for step {step}"


def test_starter_runs_without_crashing(tmp_path):
    """As handed out the starter runs its scene and two clicks to the end and prints its line."""
    settings = {"frames": 60, "fps": 60, "seed": 11, "record_every": 30,
                "script": [{"frame": 10, "type": "click", "pos": [600, 100]},
                           {"frame": 20, "type": "click", "pos": [300, 80]}]}
    run = run_lab(STARTER, settings, tmp_path)
    assert "Simulated 1.0 s with 6 shapes; fast movers now:" in run.stdout, run.stdout
    assert run.record["frames_run"] == 60
    corners = [len(body["points"]) for body in run.crates(run.frames[-1])]
    assert 4 in corners and not {3, 6} & set(corners)  # no triangle or hexagon: squares until step 2
