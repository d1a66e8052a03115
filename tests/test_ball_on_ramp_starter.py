"""Both Ball on the Ramp files run headless; the starter's ball, as handed out, meets nothing.

That the starter is the solution with steps 2-7 left to write is tested with
every lab's in test_lab_starter.py.
"""
import os

from lab_run import HEIGHT, ROOT, run_lab

SOLUTION = os.path.join(ROOT, "solutions", "ball_on_ramp.py")
STARTER = os.path.join(ROOT, "starters", "ball_on_ramp_starter.py")


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
