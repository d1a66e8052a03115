"""Regenerate assets/bullets.png: the Bullets solution, headless, after shots with sub-steps x8 and then with CCD.

    python tests/bullets_shot.py

The lab's own scene (seed 11): key 4 (sub-steps x8), a dozen shots at the wall at
12000 px/s (some tunnel: red ticks on the wall), then key 5 (CCD) and a dozen
more (none tunnels), two at the crates; the window is saved one frame after the
last shot, so its streak (the bullet's path in that frame) is on the picture.
"""
import os

from lab_run import FPS, ROOT, save_screenshot

SOLUTION = os.path.join(ROOT, "solutions", "bullets.py")
WALL_AIMS = [(600, 60 + 30 * i) for i in range(12)]


def script():
    """Key 4, twelve shots; key 5, twelve shots and two at the crates; frame numbers from 1."""
    items = [{"frame": 1, "type": "key", "key": "4"}]
    items += [{"frame": 2 + 2 * i, "type": "click", "pos": list(aim)} for i, aim in enumerate(WALL_AIMS)]
    items.append({"frame": 30, "type": "key", "key": "5"})
    aims = [(260, 545), (390, 470)] + WALL_AIMS
    items += [{"frame": 31 + 2 * i, "type": "click", "pos": list(aim)} for i, aim in enumerate(aims)]
    return items


def screenshot(path=os.path.join(ROOT, "assets", "bullets.png")):
    items = script()
    save_screenshot(SOLUTION, items, items[-1]["frame"] + 1, path)


if __name__ == "__main__":
    screenshot()
