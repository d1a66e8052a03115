"""Stability suite, inputs: NaN, infinity, negative mass and degenerate shapes are refused at the API.

Every public constructor and World entry point gets the bad values; each
refusal must be a ValueError whose one-line message names the value, never a
raw TypeError or ZeroDivisionError from deep inside the package, and never a
body that turns NaN later.
"""
import math

import pytest

from lesson11.physics2d import (Body, Circle, Polygon, Vector2, World, box_points, convex_polygon,
                                regular_polygon)

NAN, INF = math.nan, math.inf


def refused(make, *words):
    """Call make(); it must raise ValueError, on one line, mentioning every word. Returns the message."""
    with pytest.raises(ValueError) as caught:
        make()
    message = str(caught.value)
    assert "\n" not in message
    for word in words:
        assert word in message, f"{message!r} does not mention {word!r}"
    return message


@pytest.mark.parametrize("field, value, words", [
    ("pos", (NAN, 0), ("position", "finite")),
    ("pos", (0, INF), ("position", "finite")),
    ("pos", (1, 2, 3), ("position", "pair")),
    ("vel", (INF, 0), ("velocity", "finite")),
    ("vel", (0, -INF), ("velocity", "finite")),
    ("angle", NAN, ("angle", "finite")),
    ("omega", -INF, ("omega", "finite")),
    ("mass", NAN, ("mass", "finite")),
    ("mass", INF, ("mass", "finite")),
    ("mass", -1, ("mass", ">= 0")),
    ("mass", -1e-12, ("mass", ">= 0")),
    ("mass", None, ("mass", "number")),
    ("restitution", NAN, ("restitution",)),
    ("restitution", 1.5, ("restitution", "between 0 and 1")),
    ("friction", INF, ("friction", "finite")),
    ("friction", -0.1, ("friction", ">= 0")),
])
def test_body_refuses_nan_infinity_and_negative_mass(field, value, words):
    """Hard input: every number a Body takes, with NaN, ±infinity, negative or missing values."""
    settings = {"pos": (0, 0), "mass": 1.0}
    settings[field] = value
    refused(lambda: Body(box_points(10, 10), **settings), *words)


@pytest.mark.parametrize("shape, mass, words", [
    (Circle(1e-160), 1.0, ("inertia",)),                    # ½ m r² underflows to 0: 1/I would divide by zero
    (Polygon(box_points(10, 10)), 1e-320, ("inertia",)),   # 1/m and 1/I overflow to infinity
    (Polygon(box_points(10, 10)), 1e307, ("inertia",)),    # I overflows to infinity
])
def test_body_refuses_masses_whose_inertia_is_not_a_usable_number(shape, mass, words):
    """Hard input: finite, positive numbers whose inverse mass or inertia is 0 or infinite."""
    refused(lambda: Body(shape, (0, 0), mass), *words)


@pytest.mark.parametrize("points, words", [
    ([], ("3 distinct points",)),
    ([(0, 0), (1, 0)], ("3 distinct points",)),
    ([(0, 0), (0, 0), (0, 0), (5, 5), (5, 5)], ("3 distinct points",)),
    ([(0, 0), (1, 1), (2, 2), (3, 3)], ("non-zero area",)),
    ([(0, 0), (10, 0), (5, 2), (10, 10), (0, 10)], ("convex",)),
    ([(0, 0), (NAN, 0), (1, 1)], ("point 1", "finite")),
    ([(0, 0), (INF, 0), (1, 1)], ("point 1", "finite")),
    ([(0, 0), "x", (1, 1)], ("point 1", "pair")),
    # a pentagram: every corner turns the same way, but the outline goes round twice and crosses itself
    ([(10 * math.cos(4 * math.pi * k / 5), 10 * math.sin(4 * math.pi * k / 5)) for k in range(5)],
     ("convex", "crosses")),
    # a bow tie: the two halves' areas cancel
    ([(0, 0), (10, 10), (10, 0), (0, 10)], ("crosses",)),
])
def test_degenerate_polygons_are_refused(points, words):
    """Hard input: too few points, duplicates only, collinear, concave, self-crossing, NaN/inf/garbage corners."""
    refused(lambda: convex_polygon(points), *words)
    refused(lambda: Body(points, (0, 0), 1.0), *words)


@pytest.mark.parametrize("shape", [None, 5, 3.5])
def test_body_refuses_a_shape_that_is_not_points(shape):
    """Hard input: a Body given something that is neither a shape nor a list of points."""
    refused(lambda: Body(shape, (0, 0), 1.0), "polygon", repr(shape))


@pytest.mark.parametrize("make, words", [
    (lambda: Circle(NAN), ("radius", "finite")),
    (lambda: Circle(-INF), ("radius", "finite")),
    (lambda: Circle(0), ("radius", "positive")),
    (lambda: box_points(NAN, 1), ("width", "finite")),
    (lambda: box_points(1, INF), ("height", "finite")),
    (lambda: box_points(-2, 1), ("positive",)),
    (lambda: regular_polygon(2, 10), ("sides",)),
    (lambda: regular_polygon(5, NAN), ("radius", "finite")),
])
def test_shape_helpers_refuse_nan_infinity_and_non_positive_sizes(make, words):
    """Hard input: circle radius and box / regular-polygon sizes that are NaN, infinite, zero or negative."""
    refused(make, *words)


@pytest.mark.parametrize("settings, words", [
    ({"gravity": (NAN, 0)}, ("gravity", "finite")),
    ({"gravity": (0, INF)}, ("gravity", "finite")),
    ({"step_seconds": NAN}, ("step_seconds", "finite")),
    ({"step_seconds": 0}, ("step_seconds", "> 0")),
    ({"iterations": 0}, ("iterations",)),
    ({"slop": NAN}, ("slop", "finite")),
    ({"slop": -0.5}, ("slop", ">= 0")),
    ({"percent": INF}, ("percent", "finite")),
    ({"percent": -0.4}, ("percent", "between 0 and 1")),
    ({"percent": 4}, ("percent", "between 0 and 1")),
    ({"resting_speed": -30}, ("resting_speed", ">= 0")),
    ({"max_frame": NAN}, ("max_frame", "finite")),
    ({"effects": {"gravity", "magic"}}, ("magic",)),
])
def test_world_refuses_nan_infinity_and_out_of_range_settings(settings, words):
    """Hard input: World settings that are NaN, infinite or out of range (a negative percent pulls bodies together)."""
    refused(lambda: World(**settings), *words)


def test_world_refuses_nan_frames_and_bodies_and_catches_nan_in_a_step():
    """Hard input: NaN or infinite frame times and steps, a body made non-finite by hand, NaN mid-simulation."""
    world = World([Body(box_points(400, 20), (0, 10), 0)])
    for bad in (NAN, INF, -INF):
        refused(lambda: world.advance(bad), "frame time")
        refused(lambda: world.step(bad), "step dt")
    crate = Body(box_points(20, 20), (0, -12), 1.0)
    crate.omega = NAN
    refused(lambda: world.add(crate), "cannot add")
    assert len(world.bodies) == 1  # refused bodies are not half-added
    crate.omega = 0.0
    world.add(crate)
    world.step()
    crate.vel = Vector2(0, INF)
    refused(world.step, "body 1's vel", "finite")   # World.check_motion, before the step moves anything
    crate.vel = Vector2(0, 0)
    crate.vel.y = INF                                # changed in place: the next step's check sees it too
    refused(world.step, "body 1's vel", "finite")
    assert world.time == pytest.approx(world.step_seconds)  # refused before it moved anything


def set_mid_step(field, value):
    """A resolve() hook that sets the second body's `field` to `value` (what a buggy student hook might do)."""
    def resolve(a, b, normal, point):
        setattr(b, field, value)
    return resolve


@pytest.mark.parametrize("order", ["solve-first", "move-first"])
@pytest.mark.parametrize("field, value", [("vel", None), ("vel", (1, 2)), ("vel", [0.0, 5.0]), ("omega", None),
                                          ("omega", "0.5")])
def test_a_hook_that_breaks_vel_or_omega_mid_step_is_named_not_a_library_line(order, field, value):
    """Hard input: resolve() sets b.vel or b.omega to something the next line of the step cannot use.

    Without World.name_bad_motion this surfaced as a raw TypeError or AttributeError on a
    library line (response.separate's `None * float`, the end-of-step sum's `.x`): the
    step must instead say, in one ValueError line, which body and what it became.
    """
    world = World([Body(box_points(400, 40), (200, 300), 0), Body(box_points(40, 40), (200, 265), 1.0)],
                  order=order)
    world.resolve = set_mid_step(field, value)
    message = refused(lambda: [world.step() for _ in range(10)], "body 1's vel or omega became", repr(value))
    assert "hook" in message


def test_a_hooks_own_type_error_is_left_as_it_is():
    """A TypeError the hook raises itself, with every body still sound, reaches the caller unchanged."""
    def resolve(a, b, normal, point):
        raise TypeError("the hook's own mistake")
    world = World([Body(box_points(400, 40), (200, 300), 0), Body(box_points(40, 40), (200, 265), 1.0)])
    world.resolve = resolve
    with pytest.raises(TypeError, match="the hook's own mistake"):
        for _ in range(10):
            world.step()


@pytest.mark.parametrize("order", ["solve-first", "move-first"])
@pytest.mark.parametrize("value", [NAN, INF])
def test_a_hook_that_makes_a_body_non_finite_mid_step_is_named(order, value):
    """Hard input: resolve() writes NaN or inf into b.vel.y in place, on a stack of two crates.

    The NaN body's corners give the next sub-step's SAT no normal, and the push-out
    used to fail there with a raw TypeError (`None * float` in response.separate);
    now the step names the body, as the end-of-step check does.
    """
    def resolve(a, b, normal, point):
        b.vel.y = value
    world = World([Body(box_points(400, 40), (200, 300), 0), Body(box_points(40, 40), (200, 265), 1.0),
                   Body(box_points(40, 40), (200, 225), 1.0)], order=order)
    world.resolve = resolve
    refused(lambda: [world.step() for _ in range(50)], "became non-finite", "check its mass, the step and the hooks")
