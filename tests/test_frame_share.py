"""The frame-share benchmark (lesson11/bench/frame_share.py): its pile is the lab's clicked pile, its split adds up,
and its table says so when pymunk is missing. Its times are never asserted (no timed tests)."""
import math

import pytest

from lesson11 import hook_clock
from lesson11.bench import energy, frame_share


def test_twelve_clicks_are_the_labs_pile_and_more_clicks_widen_the_floor():
    assert frame_share.drops(12) == energy.PILE_DROPS
    points = frame_share.drops(200)
    assert len(set(points)) == 200 and max(y for _, y in points) < 560   # above the floor's top face
    world = frame_share.clicked_pile(40, settle_frames=0)
    floor, _, wall = world.bodies[:3]
    assert len(world.bodies) == 3 + 40
    right = max(x for x, _ in frame_share.drops(40))
    assert floor.aabb()[2] > right and wall.pos.x > right, "every click lands over the floor, left of the wall"


def test_the_split_adds_up_and_the_wrappers_change_nothing():
    pile = frame_share.clicked_pile(12, settle_frames=0)
    overhead = hook_clock.calibrate(frame_share.CLOCK, calls=2000, repeats=3)
    figures = frame_share.measure(pile, {}, 2, overhead)
    for form in frame_share.FORMS:
        f = figures[form]
        assert f["frame"] == pytest.approx(f["lab"] + f["engine"])
        assert f["lab"] > 0 and f["calls"] > 0 and math.isfinite(f["engine"])
    assert figures["fast"]["calls"] == figures["reference"]["calls"]   # the same steps, the same calls


def test_lab_hooks_are_the_labs_functions_only():
    world, _ = energy.lab_world({})
    assert set(hook_clock.lab_hooks(world)) == {"sat", "resolve"}
    tally = [0.0, 0]
    world.sat = hook_clock.wrap(world.sat, tally, frame_share.CLOCK)
    assert hook_clock.lab_hooks(world)["sat"] is energy.lab().sat   # a wrapped hook is still the lab's
    for _ in range(120):  # until the crates land: the World calls the wrapped sat
        world.step()
    assert tally[1] > 0


def test_table_says_when_pymunk_is_not_installed():
    figures = {"frame": 2.0, "lab": 1.5, "engine": 0.5, "timer": 2.0, "calls": 100}
    row = dict(figures, crates=12, setting="default 4 × 6", reference=dict(figures, frame=2.5, engine=1.0),
               listing=1.1, pymunk=None)
    text = frame_share.table([row])
    assert "| 25.0 % |" in text and "2.50, 40.0 %" in text and "not installed" in text
