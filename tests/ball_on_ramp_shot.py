"""Regenerate assets/ball_on_ramp.png: the Ball on the Ramp solution, headless, two balls rolling down the ramp.

    python tests/ball_on_ramp_shot.py

The lab's own scene (seed 11) and two left clicks (balls) over the top of the ramp, the second 40 frames
after the first; the runtime's `screenshot` setting saves the window 70 frames after the second, while
both roll (debug view on: contact points in red, the spokes show each ball turning).
"""
import os

from lab_run import ROOT, clicks, save_screenshot

SOLUTION = os.path.join(ROOT, "solutions", "ball_on_ramp.py")
DROPS = [(80, 230), (80, 230)]


def screenshot(path=os.path.join(ROOT, "assets", "ball_on_ramp.png")):
    script = clicks(DROPS, 20, 40)
    save_screenshot(SOLUTION, script, script[-1]["frame"] + 70, path, record_every=30)


if __name__ == "__main__":
    screenshot()
