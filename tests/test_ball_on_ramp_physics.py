"""physics2d for Ball on the Ramp: the World's circle hooks, and a ball on the 22° ramp rolls and slides as it should.

World(circle_polygon=..., circle_point=...) hands a lab's own circle–polygon test and
contact point to the narrow phase (collision.collide); the library's circle_polygon and
circle_contact_point stay the defaults. The rolling figures below are the library's own
(no lab hooks), measured over 0.15-1.3 s of a ball let go 0.25 px above the ramp.
"""
import math

import pytest
from pygame import Vector2

from lesson11.physics2d import (Body, Circle, World, box_points, circle_contact_point, circle_polygon,
                                collide)

THETA = math.radians(22)
SLOPE = Vector2(math.cos(THETA), math.sin(THETA))
UP = Vector2(math.sin(THETA), -math.cos(THETA))
G = 980.0


def scene(friction=0.6, r=20, along=-170):
    floor = Body(box_points(900, 40), (450, 580), 0)
    ramp = Body(box_points(420, 24), (230, 380), 0, angle=THETA)
    ball = Body(Circle(r), Vector2(230, 380) + SLOPE * along + UP * (12 + r + 0.25), math.pi * r * r / 1000,
                friction=friction)
    return [floor, ramp, ball], ball


def roll(world, ball, seconds=1.3, start=0.15, r=20):
    """(fitted acceleration along the slope px/s², largest |ω r - v| / v, largest |ω| rad/s) after `start` s."""
    samples = []
    for frame in range(int(seconds * 60)):
        world.advance(1 / 60)
        t = (frame + 1) / 60
        if t >= start:
            samples.append((t, ball.vel.dot(SLOPE), ball.omega))
    n = len(samples)
    mt = sum(s[0] for s in samples) / n
    mv = sum(s[1] for s in samples) / n
    accel = sum((s[0] - mt) * (s[1] - mv) for s in samples) / sum((s[0] - mt) ** 2 for s in samples)
    slip = max(abs(s[2] * r - s[1]) / abs(s[1]) for s in samples)
    return accel, slip, max(abs(s[2]) for s in samples)


def test_a_ball_rolls_down_the_ramp_at_two_thirds_g_sin_theta():
    bodies, ball = scene(0.6)
    accel, slip, _ = roll(World(bodies), ball)
    want = 2 / 3 * G * math.sin(THETA)
    assert abs(accel - want) <= 0.03 * want   # measured 244.70 px/s² against 244.74 (0.02 %)
    assert slip <= 0.02                       # measured 0.03 %


def test_a_frictionless_ball_slides_at_g_sin_theta_without_spinning():
    bodies, ball = scene(0.0)
    accel, _, spin = roll(World(bodies), ball)
    want = G * math.sin(THETA)
    assert abs(accel - want) <= 0.01 * want   # measured 367.114 against 367.114
    assert spin <= 0.05                       # measured 1e-14 rad/s


def test_the_world_uses_the_lab_s_circle_hooks_for_both_orders_of_a_pair():
    calls = []

    def my_test(center, radius, points):
        calls.append(("test", Vector2(center), radius, len(points)))
        return circle_polygon(center, radius, points)

    def my_point(center, radius, normal, depth):
        calls.append(("point", Vector2(normal)))
        return center + normal * radius

    floor = Body(box_points(200, 20), (0, 10), 0)
    ball = Body(Circle(10), (0, -9.5), 1)
    world = World([floor, ball], circle_polygon=my_test, circle_point=my_point, substeps=1)
    world.step()
    assert any(c[0] == "test" for c in calls) and any(c[0] == "point" for c in calls)
    contact = world.contacts[0]
    assert contact.point.distance_to(ball.pos) == pytest.approx(10)   # on the surface, as my_point says
    calls.clear()
    world = World([ball, floor], circle_polygon=my_test, circle_point=my_point, substeps=1)  # circle first
    world.step()
    assert calls and world.contacts and world.contacts[0].normal.y > 0.99   # A = ball, B = floor: down


def test_default_hooks_are_the_library_s_and_the_point_is_halfway_into_the_overlap():
    world = World()
    assert world.circle_polygon is circle_polygon and world.circle_point is circle_contact_point
    floor = Body(box_points(200, 20), (0, 10), 0)
    ball = Body(Circle(10), (0, -8), 1)
    m = collide(floor, ball, floor.world_points(), [], "corners")
    assert m.depth == pytest.approx(2) and tuple(m.points[0]) == pytest.approx((0, 1))   # y = -8 + 10 - 1


def test_a_student_function_cannot_move_the_body_through_its_arguments():
    def sloppy(center, radius, points):
        center += Vector2(100, 0)   # in place: would move the ball if the World passed body.pos itself
        return None

    floor = Body(box_points(200, 20), (0, 10), 0)
    ball = Body(Circle(10), (0, -9.5), 1)
    collide(floor, ball, floor.world_points(), [], "corners", circle_test=sloppy)
    assert ball.pos == Vector2(0, -9.5)


@pytest.mark.parametrize("name", ["circle_polygon", "circle_point"])
def test_a_hook_that_is_not_a_function_is_a_one_line_error(name):
    with pytest.raises(ValueError, match=rf"^world {name} must be a function \(or None for the library's\), got 3$"):
        World(**{name: 3})
    world = World()
    with pytest.raises(ValueError, match=name):
        setattr(world, name, "circle")


def test_a_circle_test_that_returns_something_else_is_a_one_line_error():
    def bad_test(center, radius, points):
        return 5.0

    floor = Body(box_points(200, 20), (0, 10), 0)
    ball = Body(Circle(10), (0, -9.5), 1)
    with pytest.raises(ValueError, match=r"^bad_test\(\) must return None or \(normal, depth\), got 5.0$"):
        World([floor, ball], circle_polygon=bad_test).step()
