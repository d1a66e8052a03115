"""The Sleeping Crates starter runs as handed out: crates fall and pile up, and none ever sleeps.

That it is the solution with steps 2-4 left to write is tested with every
lab's in test_lab_starter.py.
"""
import os

from lab_run import ROOT, run_lab

STARTER = os.path.join(ROOT, "starters", "sleeping_crates_starter.py")


def test_starter_runs_and_nothing_sleeps(tmp_path):
    """As handed out the starter runs its scene and two clicks to the end and prints its line: 0 asleep."""
    settings = {"frames": 60, "fps": 60, "seed": 11, "record_every": 30,
                "script": [{"frame": 10, "type": "click", "pos": [600, 100]},
                           {"frame": 20, "type": "click", "pos": [300, 80]}]}
    run = run_lab(STARTER, settings, tmp_path)
    assert "Simulated 1.0 s with 10 crates; asleep now: 0;" in run.stdout, run.stdout
    assert run.record["frames_run"] == 60
    assert not any(body["asleep"] for frame in run.frames for body in frame["bodies"])
