"""Regenerate assets/more_shapes.png: the More Shapes solution, headless, after a dozen dropped shapes settle.

    python tests/more_shapes_shot.py

The lab's own scene (seed 11) plus ten clicks (the kinds cycle: box, triangle, pentagon,
hexagon, house), over the ramp and the floor, then 4 s of settling; the runtime's
`screenshot` setting saves the window after the last frame (debug view on: contact
points, normals, and each body's centre of mass).
"""
import os
import tempfile

from lab_run import FPS, ROOT, clicks, run_lab

SOLUTION = os.path.join(ROOT, "solutions", "more_shapes.py")
DROPS = [(560, 120), (640, 100), (720, 120), (800, 100), (600, 40), (680, 30), (760, 40), (200, 80),
         (300, 120), (840, 40)]


def screenshot(path=os.path.join(ROOT, "assets", "more_shapes.png")):
    script = clicks(DROPS, 20, 25)
    settings = {"frames": script[-1]["frame"] + 4 * FPS, "fps": FPS, "seed": 11, "record_every": 60,
                "script": script, "screenshot": path}
    with tempfile.TemporaryDirectory() as work:
        run = run_lab(SOLUTION, settings, work)
    print(run.stdout.strip(), "->", path)


if __name__ == "__main__":
    screenshot()
