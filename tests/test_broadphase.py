"""The sweep-and-prune broad phase against the all-pairs reference: the same pairs, the same results."""
import math
import random

from hypothesis import given, settings
from hypothesis import strategies as st

from lesson11.physics2d import LESSON_EFFECTS, Body, Circle, World, box_points
from lesson11.physics2d.broadphase import all_pairs, sweep_and_prune, sweep_boxes

coordinate = st.floats(-500, 500, allow_nan=False)
size = st.floats(0, 80, allow_nan=False)


@st.composite
def scenes(draw):
    """Boxes (some touching exactly, some zero-sized), moving flags, optional reach and base, optional bounds."""
    n = draw(st.integers(0, 25))
    boxes = []
    for _ in range(n):
        if boxes and draw(st.booleans()):
            # share an edge with an earlier box: the exact-touch cases the rounding slack is for
            other = draw(st.sampled_from(boxes))
            left = other[2]
        else:
            left = draw(coordinate)
        top = draw(coordinate)
        boxes.append((left, top, left + draw(size), top + draw(size)))
    moving = draw(st.lists(st.booleans(), min_size=n, max_size=n))
    reach = draw(st.none() | st.lists(st.floats(0, 30, allow_nan=False), min_size=n, max_size=n))
    base = draw(st.sampled_from([0.0, 2.0])) if reach is not None else 0.0
    bounds = None
    if draw(st.booleans()):
        grow = draw(st.lists(st.floats(0, 40, allow_nan=False), min_size=n, max_size=n))
        bounds = [(b[0] - g, b[1] - g, b[2] + g, b[3] + g) for b, g in zip(boxes, grow)]
    return boxes, moving, reach, base, bounds


@settings(max_examples=400, deadline=None)
@given(scenes())
def test_sweep_and_prune_finds_exactly_the_reference_pairs(scene):
    boxes, moving, reach, base, bounds = scene
    expected, every = all_pairs(boxes, moving, reach, base)
    found, met = sweep_and_prune(boxes, moving, reach, base, bounds)
    assert found == expected                      # the same pairs, in the same (i, j) order
    assert len(found) <= met <= every             # the sweep never tests more pairs than all pairs
    assert all(moving[i] or moving[j] for i, j in found)


@settings(max_examples=400, deadline=None)
@given(scenes())
def test_sweep_boxes_is_sweep_and_prune_without_margins(scene):
    """The lesson solver's written-out sweep: the same pairs and pairs met as sweep_and_prune (and with -0.0 edges)."""
    boxes, moving, _, _, _ = scene
    signed = [(-0.0 if k % 3 == 0 and b[0] == 0 else b[0],) + b[1:] for k, b in enumerate(boxes)]
    for case in (boxes, signed):
        assert sweep_boxes(case, moving) == sweep_and_prune(case, moving, None, 0.0, case)


def test_still_pairs_are_never_met():
    """Overlapping static or sleeping bodies cost the sweep nothing."""
    boxes = [(0.0, 0.0, 10.0, 10.0)] * 50
    assert sweep_and_prune(boxes, [False] * 50) == ([], 0)
    pairs, met = sweep_and_prune(boxes, [True] + [False] * 49)
    assert pairs == [(0, j) for j in range(1, 50)] and met == 49


def pile(seed=11, count=12):
    """A bin with `count` randomly sized and turned crates above it and one ball."""
    rng = random.Random(seed)
    bodies = [Body(box_points(400, 40), (300, 620), 0), Body(box_points(20, 400), (90, 400), 0),
              Body(box_points(20, 400), (510, 400), 0)]
    for i in range(count):
        w, h = rng.randint(40, 60), rng.randint(30, 50)
        bodies.append(Body(box_points(w, h), (140 + 60 * (i % 5), 380 - 60 * (i // 5)), 1.0,
                           angle=rng.uniform(0, math.pi)))
    bodies.append(Body(Circle(12), (300, 100), 1.0))
    return bodies


def run(broad_phase, steps, drop=None, **settings):
    world = World(pile(), broad_phase=broad_phase, **settings)
    asleep_at_drop = 0
    for k in range(steps):
        if k == drop:   # onto the sleeping pile: wakes what it lands on
            asleep_at_drop = sum(body.asleep for body in world.bodies)
            world.add(Body(box_points(50, 40), (300, 150), 1.0, angle=0.3))
        world.step()
    state = [(b.pos.x, b.pos.y, b.angle, b.vel.x, b.vel.y, b.omega, b.asleep) for b in world.bodies]
    counters = {key: world.counters[key] for key in ("narrow_tests", "contacts")}
    counters["asleep_at_drop"] = asleep_at_drop
    return state, counters, world.counters["pair_tests"]


SLEEP = LESSON_EFFECTS | {"sleep"}


def test_a_pile_is_bit_identical_with_either_broad_phase():
    """A 12-crate pile, both solvers, both lesson orders, with sleep and a wake: identical states and counters."""
    cases = [dict(steps=150), dict(steps=100, order="move-first"), dict(steps=200, solver="accumulated"),
             dict(steps=360, drop=330, effects=SLEEP), dict(steps=360, drop=330, effects=SLEEP, solver="accumulated")]
    for case in cases:
        reference = run("all-pairs", **case)
        swept = run("sweep-and-prune", **case)
        assert swept[:2] == reference[:2], case
        assert swept[2] < reference[2], case      # fewer pairs met than all pairs with a moving body
        if "drop" in case:
            assert swept[1]["asleep_at_drop"] > 0, case   # the pile was (partly) asleep when the crate fell


def test_broad_phase_setting_is_checked():
    try:
        World(broad_phase="grid")
    except ValueError as error:
        assert "broad_phase" in str(error)
    else:
        raise AssertionError("broad_phase='grid' was accepted")
