"""Regenerate assets/more_shapes.png: the More Shapes solution, headless, after a dozen dropped shapes settle.

    python tests/more_shapes_shot.py

The lab's own scene (seed 11) plus ten clicks (the kinds cycle: box, triangle, pentagon,
hexagon, house), over the ramp and the floor, then 4 s of settling; the runtime's
`screenshot` setting saves the window after the last frame (debug view on: contact
points, normals, and each body's centre of mass).
"""
import os

from lab_run import FPS, ROOT, clicks, save_screenshot

SOLUTION = os.path.join(ROOT, "solutions", "more_shapes.py")
DROPS = [(560, 120), (640, 100), (720, 120), (800, 100), (600, 40), (680, 30), (760, 40), (200, 80),
         (300, 120), (840, 40)]


def screenshot(path=os.path.join(ROOT, "assets", "more_shapes.png")):
    script = clicks(DROPS, 20, 25)
    save_screenshot(SOLUTION, script, script[-1]["frame"] + 4 * FPS, path)


if __name__ == "__main__":
    screenshot()
