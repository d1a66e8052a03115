"""World(circle_circle=...) hands a lab's own circle–circle test to the World (the Billiards lab's step 2).

The hook is a documented setting checked when set, the library's collision.circle_circle by default (the
trajectories of tests/test_trajectory_digest.py stay bit-identical with it), called on copies of the centres
for every pair of balls the lesson solver tests, on the plain search (the fast path) and on the readable one.
"""
import pytest
from pygame import Vector2

from lesson11.physics2d import Body, Circle, World, collision


def two_balls():
    """Two 10 px balls 18 px apart along x, A moving towards B at rest."""
    return Body(Circle(10), (0, 0), 1, vel=(100, 0)), Body(Circle(10), (18, 0), 1)


@pytest.mark.parametrize("fast", [True, False])
def test_a_world_given_a_student_s_circle_circle_calls_it_for_every_pair_of_balls(fast, monkeypatch):
    monkeypatch.setattr(collision, "FAST_PATHS", fast)
    calls = []

    def mine(ca, ra, cb, rb):
        calls.append((Vector2(ca), ra, Vector2(cb), rb))
        ca += Vector2(500, 0)   # in place: would move ball A if the World handed it body.pos itself
        return Vector2(1, 0), 3.0   # a depth of its own: the World must use the hook's answer

    a, b = two_balls()
    world = World([a, b], effects={"restitution"}, circle_circle=mine, substeps=1)
    world.step()
    assert calls and calls[0] == (Vector2(0, 0), 10, Vector2(18, 0), 10)
    assert world.contacts and world.contacts[0].depth == 3.0 and world.contacts[0].normal == Vector2(1, 0)
    assert a.pos.x < 1 and b.vel.x > 0   # A did not jump 500 px; the bounce used the contact the hook gave


def test_the_default_is_the_library_s_and_a_hook_that_is_not_a_function_is_a_one_line_error():
    assert World().circle_circle is collision.circle_circle
    assert "Default" in World.circle_circle.__doc__ or "default" in World.circle_circle.__doc__
    with pytest.raises(ValueError, match=r"^world circle_circle must be a function \(or None for the library's\)"):
        World(circle_circle=3)
    world = World()
    with pytest.raises(ValueError, match="circle_circle"):
        world.circle_circle = "circle"


def test_a_hook_answer_that_is_not_none_or_a_pair_is_a_one_line_error():
    a, b = two_balls()
    world = World([a, b], circle_circle=lambda ca, ra, cb, rb: 7)
    with pytest.raises(ValueError, match=r"must return None or \(normal, depth\), got 7"):
        world.step()


def test_a_hook_that_says_apart_gives_no_contact():
    a, b = two_balls()
    world = World([a, b], effects={"restitution"}, circle_circle=lambda ca, ra, cb, rb: None)
    world.step()
    assert world.contacts == [] and b.vel == Vector2(0, 0)


@pytest.mark.parametrize("fast", [True, False])
def test_the_hook_path_moves_balls_to_the_last_bit_as_the_library_s_own_call(fast, monkeypatch):
    """A hook that only calls the library (taking the hook's path: copies of the centres, the answer checked) gives
    the default World's trajectory bit for bit: a rack of ten balls broken by a fast one, 240 steps."""
    monkeypatch.setattr(collision, "FAST_PATHS", fast)
    def rack():
        balls = [Body(Circle(14), (100, 300), 1, vel=(900, 7))]
        balls += [Body(Circle(14), (400 + row * 24.7, 300 + (k - row / 2) * 28.5), 1)
                  for row in range(4) for k in range(row + 1)]
        return balls

    def trajectory(**hook):
        world = World(rack(), effects={"restitution", "correction"}, **hook)
        states = []
        for _ in range(240):
            world.step()
            states.append([(b.pos.x.hex(), b.pos.y.hex(), b.vel.x.hex(), b.vel.y.hex()) for b in world.bodies])
        return states, world.counters["contacts"]

    default, contacts = trajectory()
    assert contacts > 0 and trajectory(circle_circle=lambda ca, ra, cb, rb: collision.circle_circle(ca, ra, cb, rb)) \
        == (default, contacts)
