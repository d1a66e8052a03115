"""Issue 34 items 2 and 3: Body and World settings checked when set, derived fields kept in step, one phase list
per solver, and the docstrings' examples run."""
import doctest
import inspect
import math
import re

import pytest

from lesson11.physics2d import Body, Circle, Vector2, World, box_points, polygon_inertia
from lesson11.physics2d import bodies, settings, sleep, world as world_module


def crate(mass=2.0, **kwargs):
    kwargs.setdefault("pos", (100, 50))
    return Body(box_points(40, 20), mass=mass, **kwargs)


# ---------------------------------------------------------------- mass keeps the derived fields in step

def test_mass_zero_after_construction_makes_the_body_static_in_every_derived_field():
    body = crate(2.0, vel=(30, 0), omega=1.0)
    body.mass = 0
    assert (body.mass, body.inv_mass, body.inertia, body.inv_inertia) == (0.0, 0.0, 0.0, 0.0)
    assert body.is_static
    floor = Body(box_points(400, 20), (100, 200), 0)
    world = World([floor, body])
    for _ in range(30):
        world.step()
    assert body.pos == Vector2(100, 50) and body.angle == 0.0   # static: not integrated, not pushed


def test_setting_mass_recomputes_inverse_mass_and_the_shapes_inertia():
    body = crate(0)
    body.mass = 3
    assert body.inv_mass == 1 / 3
    assert body.inertia == polygon_inertia(box_points(40, 20), 3.0)   # as Body(..., 3) computes it
    assert body.inv_inertia == 1 / body.inertia
    fresh = crate(3.0)
    assert {k: v for k, v in vars(body).items() if k != "shape"} == {k: v for k, v in vars(fresh).items() if
                                                                       k != "shape"}   # as if made with mass 3


def test_a_refused_mass_leaves_every_field_as_it_was():
    body = crate(2.0)
    before = dict(vars(body))
    for bad, message in ((-1, "body mass must be >= 0"), (math.nan, "body mass must be finite"),
                         ("heavy", "body mass must be a number")):
        with pytest.raises(ValueError, match=message):
            body.mass = bad
    assert vars(body) == before


def test_inertia_keeps_its_inverse_and_accepts_infinity_for_a_body_that_cannot_turn():
    body = crate(2.0)
    body.inertia = 500.0
    assert body.inv_inertia == 1 / 500
    body.inertia = math.inf   # the Ball on the Ramp starter's disc_inertia placeholder
    assert body.inv_inertia == 0.0
    static = crate(0)
    static.inertia = 0.0      # a static body's own value: accepted
    with pytest.raises(ValueError, match="a static body"):
        static.inertia = 10.0
    assert static.inertia == 0.0


# ---------------------------------------------------------------- every setting checked as in __init__

BAD = [
    ("pos", (math.nan, 0)), ("pos", "here"), ("pos", None), ("angle", math.inf), ("angle", "left"), ("angle", [1]),
    ("mass", -1), ("mass", math.nan), ("restitution", 5), ("restitution", -0.1), ("restitution", math.nan),
    ("friction", -1), ("friction", math.inf), ("inertia", 0.0), ("inertia", -3.0), ("inertia", math.nan),
    ("inertia", "heavy"),
]


@pytest.mark.parametrize("name, bad", BAD)
def test_a_bad_setting_is_the_same_one_line_error_set_later_as_in_body(name, bad):
    with pytest.raises(ValueError) as made:
        crate(**{name: bad}) if name != "mass" else crate(bad)
    body = crate()
    before = dict(vars(body))
    with pytest.raises(ValueError) as set_later:
        setattr(body, name, bad)
    assert str(set_later.value) == str(made.value)
    assert "\n" not in str(made.value) and name.split("_")[0] in str(made.value)
    assert vars(body) == before   # nothing of the bad value spread into the body


@pytest.mark.parametrize("name, bad, message", [("vel", (0, math.inf), "body velocity must be finite"),
                                               ("vel", None, "body velocity must be a pair"),
                                               ("omega", math.nan, "body omega must be finite")])
def test_vel_and_omega_are_checked_by_body_and_by_the_world(name, bad, message):
    """vel and omega stay plain attributes (set ~7,000 times a step): Body() checks them, and so does the World."""
    with pytest.raises(ValueError, match=message):
        crate(**{name: bad})
    body = crate()
    world = World([body], gravity=(0, 0))
    setattr(body, name, Vector2(0, math.inf) if name == "vel" else math.nan)
    with pytest.raises(ValueError, match="finite") as caught:   # the step's check, or angle's as it turns
        world.step()
    assert "\n" not in str(caught.value)


def test_a_vector_set_is_the_bodys_own_copy_and_in_place_changes_keep_it():
    a, b = crate(), crate()
    a.pos = b.pos
    assert a.pos == b.pos and a.pos is not b.pos   # two bodies never share one position
    own = a.pos
    a.pos += Vector2(1, 0)
    assert a.pos is own and own == Vector2(101, 50)
    a.pos = (5, 6)
    assert isinstance(a.pos, Vector2) and a.pos == Vector2(5, 6)


def test_integers_and_floats_store_as_before():
    body = crate(2, omega=2)
    body.angle, body.restitution, body.friction = 1, 1, 0
    assert [type(v) for v in (body.angle, body.omega, body.restitution, body.friction, body.mass)] == [float] * 5


# ---------------------------------------------------------------- docstrings: what, unit, default; examples run

def settings_of(cls):
    return {name: value for name, value in vars(cls).items() if isinstance(value, property)}


@pytest.mark.parametrize("cls, names", [
    (Body, {"pos", "angle", "mass", "inertia", "restitution", "friction"}),
    (World, {"gravity", "step_seconds", "iterations", "substeps", "slop", "percent", "resting_speed", "max_frame",
             "max_steps", "contact_rule", "solver", "effects", "order", "broad_phase", "warm_starting",
             "circle_circle", "circle_polygon", "circle_point", "sleep_speed", "sleep_spin", "sleep_after", "sleep_timer", "moves",
             "wake_pair"}),
])
def test_every_setting_has_its_own_docstring_with_its_default(cls, names):
    found = settings_of(cls)
    assert names <= set(found)
    for name in names:
        doc = inspect.getdoc(found[name]) or ""
        assert "checked when set" not in doc.splitlines()[0], name
        assert "Default" in doc or "default" in doc, f"{cls.__name__}.{name}: no default in {doc!r}"
        assert len(doc) > 60, f"{cls.__name__}.{name}: {doc!r}"


def test_help_world_slop_says_what_it_is_its_unit_and_default():
    import pydoc
    text = pydoc.render_doc(World.slop, renderer=pydoc.plaintext)
    assert "Overlap (px)" in text and "0.5 px" in text and "push-out" in text


def _doctests(module):
    """The module's doctests (DocTestFinder also reads the docstrings of its classes' properties: the settings)."""
    return [test for test in doctest.DocTestFinder().find(module, module.__name__) if test.examples]


@pytest.mark.parametrize("module", [settings, bodies, world_module, sleep], ids=lambda m: m.__name__)
def test_the_docstring_examples_run(module):
    tests = _doctests(module)
    assert tests, f"{module.__name__} has no examples"
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for test in tests:
        runner.run(test)
    assert runner.summarize(verbose=False).failed == 0


# ---------------------------------------------------------------- one phase list per solver

def test_world_step_dispatches_in_under_30_lines():
    lines = inspect.getsource(World.step).splitlines()
    assert len(lines) < 30
    for phase_list in ("step_solve_first", "step_move_first", "step_accumulated", "end_step"):
        assert f"self.{phase_list}(dt)" in "\n".join(lines)


@pytest.mark.parametrize("method", ["step_solve_first", "lesson_solve_first", "step_move_first",
                                    "step_accumulated"])
def test_each_solver_step_has_a_comment_per_phase(method):
    source = inspect.getsource(getattr(World, method))
    comments = [line.strip() for line in source.splitlines() if line.strip().startswith("#")]
    assert len(comments) >= 2, comments


def test_the_sleep_rules_are_sleep_modules():
    assert World.moves_of_world is sleep.moves and World.wake_of_world is sleep.wake_pair
    assert World().sleep_timer_of_world(0.25, 1.0, 0.0, 0.5) == sleep.timer(0.25, 1.0, 0.0, 0.5) == 0.75
    ball = Body(Circle(5), (0, 0), 1.0, vel=(3, 4), omega=2.0)
    World().fall_asleep([ball])
    assert ball.asleep and ball.vel == Vector2() and ball.omega == 0.0 and ball.island == [ball]


@pytest.mark.parametrize("field, value, words", [
    ("vel", "x", "body 0's vel must be a pair of numbers"),
    ("vel", Vector2(float("nan"), 0.0), "body 0's vel must be finite"),
    ("omega", "x", "body 0's omega must be a number"),
    ("omega", float("inf"), "body 0's omega must be finite"),
])
def test_a_bad_vel_or_omega_set_between_steps_stops_the_next_step_in_one_line(field, value, words):
    """vel and omega are plain attributes (checking each set costs 1.3-1.4x a lab step): the next step checks them."""
    crate = Body(box_points(20, 20), (100, 100), 1.0)
    world = World([crate])
    setattr(crate, field, value)
    with pytest.raises(ValueError, match=re.escape(words)) as caught:
        world.step()
    assert "\n" not in str(caught.value)
    assert world.time == 0.0, "the step must stop before it moves anything"


def test_a_pair_or_an_int_set_between_steps_is_taken_as_a_vector_and_a_float():
    """b.vel = (3, 4) and b.omega = 2 are what a student writes: the step takes them as Vector2 and float."""
    crate = Body(box_points(20, 20), (100, 100), 1.0)
    world = World([crate], gravity=(0, 0))
    crate.vel, crate.omega = (120, 0), 2
    world.step()
    assert isinstance(crate.vel, Vector2) and crate.vel.x == 120.0
    assert isinstance(crate.omega, float) and crate.omega == 2.0
