"""Regenerate assets/sleeping_crates.png: the Sleeping Crates solution, headless, with 40 crates.

    python tests/sleeping_crates_shot.py

The lab's own scene (seed 11: eight crates) plus 32 clicks over the bin, one every
12 frames, then 5 s of settling. The pile is one island, so it stays awake
(about 110 ms of physics a frame) until every crate in it is calm, then falls
asleep as one (about 4 s after the last drop) and is drawn dimmed; the HUD shows the awake / asleep counts and the physics ms per frame.
The runtime's `screenshot` setting saves the window after the last frame.
"""
import os

from lab_run import FPS, ROOT, clicks, save_screenshot

SOLUTION = os.path.join(ROOT, "solutions", "sleeping_crates.py")
DROPS = [(120 + 85 * (k % 8) + 20 * (k // 8 % 2), 60 + 30 * (k // 8)) for k in range(32)]


def screenshot(path=os.path.join(ROOT, "assets", "sleeping_crates.png")):
    script = clicks(DROPS, 20, 12)
    save_screenshot(SOLUTION, script, script[-1]["frame"] + 5 * FPS, path)


if __name__ == "__main__":
    screenshot()
