"""The More Shapes starter runs as handed out: squares that hardly turn (its placeholders).

That it is the solution with steps 2-5 left to write is tested with every
lab's in test_lab_starter.py.
"""
import os

from lab_run import ROOT, run_lab

STARTER = os.path.join(ROOT, "starters", "more_shapes_starter.py")


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
