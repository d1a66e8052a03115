"""The Ball on the Ramp starter is the solution with steps 2-7 left to write, and both files run headless.

Step regions are the lines between `# --- step N: ... ---` and `# --- end of step N ---`.
Outside them the two files are identical line by line; inside, the starter holds only
comments and the one-line placeholders that keep it running (PLACEHOLDERS).
"""
import os
import re

import pytest

from lab_run import HEIGHT, ROOT, run_lab
from test_lab_starter import code_lines, split_regions

SOLUTION = os.path.join(ROOT, "solutions", "ball_on_ramp.py")
STARTER = os.path.join(ROOT, "starters", "ball_on_ramp_starter.py")
STUDENT_STEPS = {"2", "3", "4", "5", "6", "7"}
PLACEHOLDERS = {"return pygame.Vector2(math.inf, math.inf)", "return math.inf", "return center"}


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
    assert solution, f"the solution's step {step} is empty"
    assert set(code_lines(region)) <= PLACEHOLDERS
    assert not set(code_lines(region)) & set(solution)
    comments = [line.strip() for line in region if line.strip().startswith("#")]
    assert comments and comments[0].startswith(f"# Step {step} "), "the region's comment names its step"


def test_starter_comments_number_all_eight_steps():
    with open(STARTER, encoding="utf-8") as handle:
        text = handle.read()
    for step in range(1, 9):
        assert re.search(rf"# Step {step}\b", text), f"no comment for step {step}"


def _balls(frame):
    return [body for body in frame["bodies"] if not body["static"] and not body["points"]]


def test_starter_runs_and_its_ball_falls_through_everything(tmp_path):
    """As handed out the ball meets nothing (closest_on_segment's placeholder is infinitely far): 3 s later
    the scene's ball and two clicked ones are below the window; the crates rest on the floor; clicks and D
    do not crash it."""
    script = [{"frame": 20, "type": "click", "pos": [300, 100]}, {"frame": 25, "type": "key", "key": "d"},
              {"frame": 30, "type": "click", "pos": [700, 100]}]
    settings = {"frames": 180, "fps": 60, "seed": 11, "record_every": 30, "script": script}
    run = run_lab(STARTER, settings, tmp_path)
    last = run.frames[-1]
    assert run.record["frames_run"] == 180
    assert len(_balls(last)) == 3
    assert all(ball["pos"][1] > HEIGHT for ball in _balls(last))
    crates = [body for body in last["bodies"] if not body["static"] and body["points"]]
    assert crates and all(max(p[1] for p in body["points"]) < 562 for body in crates)  # the library's sat still runs


def test_solution_runs_with_clicks_reset_and_debug(tmp_path):
    """A left click drops a ball next to the scene's one; R rebuilds the scene (one ball again); D toggles the view."""
    script = [{"frame": 10, "type": "click", "pos": [150, 100]}, {"frame": 40, "type": "key", "key": "d"},
              {"frame": 60, "type": "key", "key": "r"}, {"frame": 70, "type": "click", "pos": [600, 200]}]
    run = run_lab(SOLUTION, {"frames": 120, "fps": 60, "seed": 11, "record_every": 10, "script": script}, tmp_path)
    counts = [len(_balls(frame)) for frame in run.frames]
    assert max(counts[:6]) == 2 and counts[-1] == 2   # the click's ball, gone after R, then a new one
    assert any(c == 1 for c in counts)
