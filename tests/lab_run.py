"""Run a lab file through the lab runtime in a child process, as the checker does, and read what it left.

Used by tests/test_lab_*.py and tests/test_runtime.py. The child is the plain
`python LAB.py` a student runs, with LESSON11_LAB_SETTINGS naming a settings
file and SDL's dummy drivers, so the file's `if __name__ == "__main__"` path
is the one under test. Measurements of a record (speed, floor penetration,
overlaps, flat error) are the checker's: lesson11/records.py and lesson11/crate_scenes.py.

Scene geometry of Tumbling Crates (px; y grows downward): the floor's top face
is at y = 560 (a 900 × 40 box centred at (450, 580)); the ramp is a 420 × 24
box centred at (230, 380) turned 22° clockwise, so its right end is lower.

    python tests/lab_run.py      regenerates assets/tumbling_crates*.png (the solver panel in all three)
"""
import json
import math
import os
import re
import subprocess
import sys

from pygame import Vector2

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
FPS = 60
FLOOR_TOP = 560.0                 # px, y of the floor's top face
HEIGHT = 600                      # px, window height
RAMP_CENTRE = Vector2(230, 380)   # px
RAMP_ANGLE = math.radians(22)     # rad, clockwise on screen
RAMP_THICKNESS = 24.0             # px
SLOPE = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))   # unit vector down the ramp
RAMP_UP = Vector2(math.sin(RAMP_ANGLE), -math.cos(RAMP_ANGLE))  # unit normal of the ramp's top face
FAST_MOVER = 30.0                 # px/s, the lab's threshold
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


def ramp_crate(along, w, h, gap=0.25):
    """Scenario entry: a w × h crate at rest on the ramp's top face, `along` px down the slope from its centre."""
    pos = RAMP_CENTRE + SLOPE * along + RAMP_UP * (RAMP_THICKNESS / 2 + h / 2 + gap)
    return {"w": w, "h": h, "pos": [pos.x, pos.y], "angle": RAMP_ANGLE}


def clicks(positions, first_frame, every):
    """Script entries: a left click at each position, `every` frames apart from `first_frame`."""
    return [{"frame": first_frame + k * every, "type": "click", "pos": list(pos)}
            for k, pos in enumerate(positions)]


# a dozen drop points over the floor right of the ramp (four columns 70 px apart), so they pile up
PILE_DROPS = [(590 + 70 * (k % 4), 150 + 50 * (k // 4)) for k in range(12)]


def pile_settings(settle_frames=240, every=20):
    """A dozen crates clicked in over the floor (no starting crates), then `settle_frames` frames of settling."""
    script = clicks(PILE_DROPS, 10, every)
    last_drop = script[-1]["frame"]
    return {"frames": last_drop + settle_frames, "fps": FPS, "seed": 11, "scenario": [], "script": script}


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
