"""Run a lab file through the lab runtime in a child process, as the checker does, and read what it left.

Used by tests/test_lab_*.py and tests/test_runtime.py. The child is the plain
`python LAB.py` a student runs, with LESSON11_LAB_SETTINGS naming a settings
file and SDL's dummy drivers, so the file's `if __name__ == "__main__"` path
is the one under test. Measurements of a record (speed, floor penetration,
overlaps, flat error) are the checker's: lesson11/records.py and lesson11/crate_scenes.py, which
also hold the scene geometry (lesson11.records) and the scenes the tests and the bench share
(crate_scenes.ramp_crate, clicks, pile_settings).

    python tests/lab_run.py      regenerates assets/tumbling_crates*.png (the solver panel in all three)
"""
import json
import math
import os
import re
import subprocess
import sys

from pygame import Vector2

from lesson11.crate_scenes import clicks, pile_settings, ramp_crate  # noqa: F401  (the tests import them from here)
from lesson11.records import FAST_MOVER, FPS, RAMP_ANGLE  # noqa: F401

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
HEIGHT = 600                      # px, window height
SLOPE = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))   # unit vector down the ramp
LINE = re.compile(r"^Simulated (\d+\.\d) s with (\d+) crates; fast movers now: (\d+)$", re.M)


class LabRun:
    """One finished run: its stdout, the parsed printed line and the runtime's record."""

    def __init__(self, stdout, record):
        self.stdout = stdout
        self.record = record
        match = LINE.search(stdout)
        self.line = None if match is None else (float(match[1]), int(match[2]), int(match[3]))
        self.frames = record["records"] if record else []

    def crates(self, frame):
        """The dynamic bodies of one recorded frame."""
        return [body for body in frame["bodies"] if not body["static"]]


def run_lab(lab_path, settings, work_dir, timeout=120):
    """Run lab_path with the given runtime settings (a record is always asked for); returns a LabRun.

    Raises AssertionError with the child's stderr when it exits with an error.
    """
    settings = dict(settings)
    settings.setdefault("record", os.path.join(str(work_dir), "record.json"))
    settings_path = os.path.join(str(work_dir), "settings.json")
    with open(settings_path, "w", encoding="utf-8") as handle:
        json.dump(settings, handle)
    env = dict(os.environ, LESSON11_LAB_SETTINGS=settings_path, SDL_VIDEODRIVER="dummy",
               SDL_AUDIODRIVER="dummy", PYGAME_HIDE_SUPPORT_PROMPT="1",
               PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.run([sys.executable, lab_path], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=timeout)
    assert proc.returncode == 0, f"{os.path.basename(lab_path)} exited with {proc.returncode}:\n{proc.stderr}"
    with open(settings["record"], encoding="utf-8") as handle:
        record = json.load(handle)
    return LabRun(proc.stdout, record)


def save_screenshot(lab_path, script, frames, path, record_every=60):
    """Run lab_path (seed 11, FPS) for `frames` frames with the scripted events, save the window's last frame
    to `path` (the runtime's screenshot setting) and print what the lab printed."""
    import tempfile
    settings = {"frames": frames, "fps": FPS, "seed": 11, "record_every": record_every, "script": script,
                "screenshot": path}
    with tempfile.TemporaryDirectory() as work:
        run = run_lab(lab_path, settings, work)
    print(run.stdout.strip(), "->", path)


def screenshots():
    """Write assets/tumbling_crates.png (solution, settled pile, debug on), the starter's, and
    assets/tumbling_crates_panel.png (the same pile; 1.5 s before the end H opens the full panel and the Up
    key is pressed 14 times, so it shows 20 iterations and its graph the physics time rising)."""
    import tempfile
    with tempfile.TemporaryDirectory() as work:
        settings = pile_settings(settle_frames=300)
        settings["record_every"] = 60
        settings["screenshot"] = os.path.join(ROOT, "assets", "tumbling_crates.png")
        run = run_lab(SOLUTION, settings, work)
        print(run.stdout.strip(), "->", settings["screenshot"])
        starter = {"frames": 40, "fps": FPS, "seed": 11, "record_every": 40,
                   "screenshot": os.path.join(ROOT, "assets", "tumbling_crates_starter.png")}
        run = run_lab(STARTER, starter, work)
        print(run.stdout.strip(), "->", starter["screenshot"])
        settings = pile_settings(settle_frames=300)
        settings["record_every"] = 60
        settings["script"] += [{"frame": settings["frames"] - 90, "type": "key", "key": "h"}]   # the full panel
        settings["script"] += [{"frame": settings["frames"] - 90, "type": "key", "key": "up"}] * 14
        settings["screenshot"] = os.path.join(ROOT, "assets", "tumbling_crates_panel.png")
        run = run_lab(SOLUTION, settings, work)
        print(run.stdout.strip(), "->", settings["screenshot"])


if __name__ == "__main__":
    screenshots()
