"""Remake every lab screenshot in assets/ from the current code, at the default settings, headless.

    python tests/screenshots.py

Runs each lab's solution (and Tumbling Crates' starter) under the lab runtime with SDL's dummy video driver,
one after another: assets/tumbling_crates.png, tumbling_crates_starter.png, tumbling_crates_panel.png,
more_shapes.png, ball_on_ramp.png, sleeping_crates.png and bullets.png, the two `checker --show` pictures
(tests/show_shot.py), and the lesson's contact picture, contact_picture.png (tests/contact_shot.py). Each script
can also run alone.
"""
import os
import sys

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import ball_on_ramp_shot  # noqa: E402
import bullets_shot  # noqa: E402
import contact_shot  # noqa: E402
import lab_run  # noqa: E402
import more_shapes_shot  # noqa: E402
import show_shot  # noqa: E402
import sleeping_crates_shot  # noqa: E402


def main():
    lab_run.screenshots()
    for module in (more_shapes_shot, ball_on_ramp_shot, sleeping_crates_shot, bullets_shot, show_shot):
        module.screenshot()
    contact_shot.draw()
    return 0


if __name__ == "__main__":
    sys.exit(main())
