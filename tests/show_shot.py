"""Remake the two --show screenshots in assets/ from the current code, headless (issue 30).

    python tests/show_shot.py

assets/checker_show_replay.png: Tumbling Crates with step 6 left empty (tests/corpus_tumbling_crates.py's
spin_missing), `--show` replaying the corner scene 20 frames after the failing frame it names: the crates
stay on their corners, the solution's (cyan outlines) have tipped flat; the lab's solver panel (compact, top right,
clear of the crates) shows the settings the run recorded, "replay" in place of timings. assets/checker_show_sat.png: step 2
keeping the largest overlap (sat_largest_overlap), its first failing case drawn as the SAT explorer draws
it, the student's depth in magenta against the lesson's MTV in yellow. Both are graded as
`python -m checker FILE --show --seed 3` grades them (the student's code in the isolated child) and drawn by
checker/replay/show_view.py into a surface saved with pygame.image.save.
"""
import os
import sys
import tempfile

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))

import pygame  # noqa: E402

import corpus_tumbling_crates  # noqa: E402
from checker import labs
from checker.replay import show, show_view   # noqa: E402

ASSETS = os.path.join(os.path.dirname(HERE), "assets")
SEED = 3
AFTER = 20   # frames past the failing frame: the difference is plain by then


def _viewer(folder, entry):
    path = os.path.join(folder, "tumbling_crates.py")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(corpus_tumbling_crates.build(entry))
    lab = next(lab for lab in labs.LABS if lab.id == "tumbling_crates")
    row, replay, problem = show.prepare(path, lab, seed=SEED)
    assert replay is not None, problem
    return show_view.Viewer(replay)


def _press(viewer, *keys):
    for key in keys:
        viewer.handle(pygame.event.Event(pygame.KEYDOWN, key=key, mod=0, unicode=""))


def screenshot():
    pygame.display.init()
    pygame.font.init()
    surface = pygame.Surface(show_view.SIZE)
    written = []
    with tempfile.TemporaryDirectory() as folder:
        viewer = _viewer(folder, "spin_missing")
        _press(viewer, pygame.K_TAB, pygame.K_j, *[pygame.K_o] * AFTER)   # the scene, the failing frame, on
        viewer.draw(surface)
        written.append(os.path.join(ASSETS, "checker_show_replay.png"))
        pygame.image.save(surface, written[-1])
        viewer = _viewer(folder, "sat_largest_overlap")
        viewer.draw(surface)
        written.append(os.path.join(ASSETS, "checker_show_sat.png"))
        pygame.image.save(surface, written[-1])
    for path in written:
        print(f"saved {path}")
    return written


if __name__ == "__main__":
    screenshot()
