"""physics2d's "sleep" effect, as Sleeping Crates uses it (the library's own rules, then the lab's functions).

  * a scene that does not declare "sleep" pays nothing: the same states and counters as before;
  * the sleep settings and hooks are validated when set;
  * a settled pile falls asleep, a thrown crate does not sleep in the air;
  * with a 40-crate pile asleep the broad phase visits no pair and the narrow phase tests nothing;
  * an awake crate landing on a sleeping pile wakes it (the whole island), and it sleeps again.
Units px, s, rad; y down; gravity (0, 980); step 1/120 s.
"""
import importlib.util
import os

import pytest

from lesson11.physics2d import EFFECTS, LESSON_EFFECTS, Body, World, box_points

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FLOOR_TOP = 560.0


def _lab():
    spec = importlib.util.spec_from_file_location("sleeping_lab", os.path.join(ROOT, "solutions",
                                                                               "sleeping_crates.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


LAB = _lab()


def floor():
    return Body(box_points(900, 40), (450, FLOOR_TOP + 20), 0)


def crate(x, y, **kw):
    return Body(box_points(50, 36), (x, y), 1.8, **kw)


def pile(asleep=False, n=5):
    """Three crates on the floor and two on them, resting exactly."""
    spots = [(400, 0), (452, 0), (504, 0), (426, 1), (478, 1)][:n]
    bodies = [crate(x, FLOOR_TOP - 18 - 36 * row) for x, row in spots]
    return bodies


def lab_world(bodies, **kw):
    return World(bodies, effects=LESSON_EFFECTS | {"sleep"}, sleep_timer=LAB.sleep_timer, moves=LAB.moves,
                 wake=LAB.wake_on_contact, **kw)


def test_sleep_is_a_declared_effect_off_by_default():
    assert "sleep" in EFFECTS and "sleep" not in LESSON_EFFECTS


def test_a_scene_without_sleep_pays_nothing():
    """Without "sleep" the hooks are never called and the states are those of a World built without them."""
    def boom(*args):
        raise AssertionError("called")
    plain = World([floor()] + pile())
    hooked = World([floor()] + pile(), sleep_timer=boom, moves=boom, wake=boom)
    for _ in range(60):
        plain.step()
        hooked.step()
    assert plain.counters == hooked.counters
    for a, b in zip(plain.bodies, hooked.bodies):
        assert (a.pos, a.angle, a.asleep) == (b.pos, b.angle, False)


@pytest.mark.parametrize("name, value", [("sleep_speed", -1), ("sleep_spin", float("nan")), ("sleep_after", 0),
                                         ("sleep_timer", 3), ("moves", "yes"), ("wake", 1)])
def test_sleep_settings_are_validated(name, value):
    with pytest.raises(ValueError, match=name):
        World(**{name: value})
    world = World()
    attribute = "wake_pair" if name == "wake" else name
    with pytest.raises(ValueError, match=name):
        setattr(world, attribute, value)


def test_library_rules_match_the_lab():
    world = World(effects=LESSON_EFFECTS | {"sleep"})
    for args in ((0.2, 1.0, 0.05, 1 / 120), (0.2, 6.0, 0.0, 1 / 120), (0.2, 1.0, -0.2, 1 / 120)):
        assert world.sleep_timer(*args) == LAB.sleep_timer(*args)


def test_a_settled_pile_sleeps_and_a_throw_does_not_sleep_in_the_air():
    thrown = crate(760, FLOOR_TOP - 19, vel=(0, -400))
    world = lab_world([floor()] + pile() + [thrown])
    slept_in_air = False
    for _ in range(int(1.6 * 120)):
        world.step()
        if thrown.asleep and max(p.y for p in thrown.world_points()) < FLOOR_TOP - 2:
            slept_in_air = True
    assert not slept_in_air
    assert all(body.asleep for body in world.bodies[1:])  # the solution: asleep at 0.5 s (pile), 1.4 s (throw)


def test_a_sleeping_pile_costs_no_pair_tests():
    world = lab_world([floor()] + pile())
    world.fall_asleep(world.bodies[1:])
    world.step()
    assert world.counters["pair_tests"] == 0 and world.counters["narrow_tests"] == 0


def test_a_crate_dropped_on_a_sleeping_pile_wakes_it_and_it_sleeps_again():
    bodies = pile()
    dropped = crate(440, FLOOR_TOP - 90 - 60, angle=0.1)
    world = lab_world([floor()] + bodies + [dropped])
    world.fall_asleep(bodies)
    start = [body.pos.y for body in bodies]
    woke = set()
    for _ in range(int(1.4 * 120)):
        world.step()
        woke |= {i for i, body in enumerate(bodies) if not body.asleep}
    assert woke == set(range(5))  # the island wakes as one
    assert all(body.asleep for body in world.bodies[1:])
    assert max(body.pos.y - y for body, y in zip(bodies, start)) < 2.0  # solution: 0.44 px lower at most
