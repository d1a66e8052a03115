"""The fast paths (vectors.FAST_PATHS, collision.FAST_PATHS) change no number the World computes.

Every lab's default scene (every lab in checker/labs/: its solution's make_world(rng), seed 11;
Bullets with bullets fired in plain and "ccd" mode has its own test) and the Tumbling Crates 12-crate clicked pile (in
the default setting, 1 × 6, move-first, all-pairs and the accumulated solver) run
twice side by side, one world with the fast paths and one with the readable
reference forms, switched around each step. After every step the float.hex of
every body's pos, angle, vel and omega must be the same: bit for bit, not "close".
"""
import importlib.util
import math
import os
import random

import pytest

import labs_found
from lesson11.bench import energy
from lesson11.physics2d import collision, vectors
from lesson11.physics2d.vectors import Vector2

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
fast_paths = collision.fast_paths  # both switches: collision.FAST_PATHS and vectors.FAST_PATHS


def solution(name):
    """solutions/<name>.py as a module (its main() does not run)."""
    spec = importlib.util.spec_from_file_location(f"fast_paths_{name}", os.path.join(ROOT, "solutions", f"{name}.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def state(world):
    """Every body's pos, angle, vel and omega as float.hex strings."""
    return [tuple(v.hex() for v in (b.pos.x, b.pos.y, b.angle, b.vel.x, b.vel.y, b.omega)) for b in world.bodies]


def lockstep(make, steps, drops=None):
    """Build the scene twice (make() -> world), step both `steps` times, fast and reference; assert every state equal.

    drops: {step: function(world) -> bodies to add before that step} (called once per world).
    Returns the number of contact points seen, so a test can tell the scene had contacts.
    """
    fast, slow = make(), make()
    seen = 0
    for k in range(steps):
        for world in (fast, slow):
            for body in (drops or {}).get(k, lambda w: ())(world):
                world.add(body)
        with fast_paths(True):
            fast.step()
        with fast_paths(False):
            slow.step()
        assert state(fast) == state(slow), f"step {k}: the fast paths changed a body's state"
        assert [(c.point.x.hex(), c.point.y.hex()) for c in fast.contacts] == \
            [(c.point.x.hex(), c.point.y.hex()) for c in slow.contacts], f"step {k}: contact points differ"
        seen += len(fast.contacts)
    assert fast.counters == slow.counters
    return seen


@pytest.mark.parametrize("lab", labs_found.IDS)
def test_every_labs_default_scene_is_bit_identical(lab):
    module = solution(lab)
    assert lockstep(lambda: module.make_world(random.Random(11)), 360) > 0


@pytest.mark.parametrize("mode", ["plain", "ccd"])
def test_bullets_default_scene_with_shots_is_bit_identical(mode):
    module = solution("bullets")
    shots = {10 * k: (lambda w, k=k: [module.make_bullet(module.GUN, Vector2(1, 0.05 * k - 0.1).normalize() * 6000)])
             for k in range(5)}
    assert lockstep(lambda: module.make_world(random.Random(11), mode), 120, shots) > 0


@pytest.mark.parametrize("settings", [{}, {"substeps": 1, "iterations": 6}, {"order": "move-first"},
                                      {"broad_phase": "all-pairs"}, {"solver": "accumulated"}],
                         ids=["default", "1x6", "move-first", "all-pairs", "accumulated"])
def test_the_12_crate_clicked_pile_is_bit_identical(settings):
    def make():
        world, clicks = energy.scene("pile", settings)  # the lab's world and its 12 clicked crates, by step
        world.clicks = clicks
        return world
    drops = {step: (lambda world, step=step: world.clicks[step]) for step in make().clicks}
    assert lockstep(make, 600, drops) > 0


def test_the_quick_forms_agree_with_the_readable_ones_on_random_input():
    """project, spin_velocity, center_of, contact_points and the search's boxes against their references, on random
    polygons and spins."""
    from lesson11.physics2d import Body, box_points, regular_polygon, world
    rng = random.Random(5)
    for _ in range(3000):
        a, b = (Body(rng.choice([box_points(rng.uniform(5, 90), rng.uniform(5, 90)),  # boxes, and the generic loop
                                 regular_polygon(rng.randint(3, 6), rng.uniform(5, 50))]),
                     (rng.uniform(0, 50), rng.uniform(0, 50)), 1,
                     angle=rng.choice([0.0, math.pi / 2, rng.uniform(-7, 7)])) for _ in range(2))
        pa, pb = a.world_points(), b.world_points()
        axis = Vector2(rng.uniform(-1, 1), rng.uniform(-1, 1))
        assert collision.project(pa, axis) == collision.project_reference(pa, axis)
        assert collision.project(pa, tuple(axis)) == collision.project_reference(pa, tuple(axis))  # a lab's tuple axis
        omega, r = rng.choice([0.0, -0.0, rng.uniform(-9, 9)]), pa[0] - a.pos
        fast, slow = vectors.spin_velocity(omega, r), vectors.spin_velocity_reference(omega, r)
        assert (fast.x.hex(), fast.y.hex()) == (slow.x.hex(), slow.y.hex())
        with fast_paths(False):
            centre = collision.center_of(pa)
        assert collision.center_of(pa) == centre and collision.center_of(pa) is not pa.center
        assert [v.hex() for v in world._polygon_box(pa)] == [v.hex() for v in a.aabb(pa)]
        hit = collision.sat(pa, pb)
        if hit is not None:
            assert collision.contact_points(pa, pb, hit[0]) == collision.contact_points_reference(pa, pb, hit[0])
    assert collision.centre_of is collision.center_of  # the name the labs import still works


def test_separate_skips_only_moves_that_change_nothing():
    """separate() returns early for a push of 0 only when pos -/+ n * 0 is pos bit for bit: signed zeros in a position,
    a NaN or infinite normal and a NaN depth all take the reference's two moves."""
    import copy
    from lesson11.physics2d import Body, box_points, response
    rng = random.Random(3)
    values = [0.0, -0.0, 1.5, -2.25, 1e-300]
    normals = [Vector2(0.6, -0.8), Vector2(-0.0, 1.0), Vector2(0.0, -1.0), Vector2(math.nan, 0), Vector2(math.inf, 0)]
    for _ in range(5000):
        a, b = (Body(box_points(10, 10), (rng.choice(values + [rng.uniform(-9, 9)]),
                                          rng.choice(values + [rng.uniform(-9, 9)])), rng.choice([0, 1.0, 2.5]))
                for _ in range(2))
        normal, depth = rng.choice(normals), rng.choice([0.0, -0.0, 0.5, 0.3, 0.7, math.nan, -3.0])
        a2, b2 = copy.deepcopy(a), copy.deepcopy(b)
        response.separate(a, b, normal, depth)
        response.separate_reference(a2, b2, normal, depth)
        assert [v.hex() for v in (a.pos.x, a.pos.y, b.pos.x, b.pos.y)] == \
            [v.hex() for v in (a2.pos.x, a2.pos.y, b2.pos.x, b2.pos.y)]


def test_the_quick_move_keeps_the_setters_errors_and_a_subclass_s_properties():
    """integrate_positions' fast path: a non-finite angle gets the angle setter's own error, and a Body subclass
    with its own angle property is moved through it, as the reference does."""
    from lesson11.physics2d import Body, World, box_points
    for on in (True, False):
        crate = Body(box_points(10, 10), (0, 0), 1, omega=1e308)
        world = World([crate], effects={"rotation"})
        crate.omega = math.inf
        with fast_paths(on), pytest.raises(ValueError, match="body angle must be finite"):
            world.integrate_positions(1.0)

    class Logged(Body):
        seen = []

        @property
        def angle(self):
            return self._angle

        @angle.setter
        def angle(self, value):
            Logged.seen.append(value)
            self._angle = value
    for on in (True, False):
        Logged.seen = []
        with fast_paths(on):
            World([Logged(box_points(10, 10), (0, 0), 1, omega=2.0)]).integrate_positions(0.5)
        assert Logged.seen == [0.0, 1.0]



def test_the_summed_finite_check_raises_what_the_loop_raises():
    """end_step's fast finite check (one sum over every body) lets through exactly the worlds the readable loop lets
    through: a NaN or inf in any field, anywhere, gets the loop's error naming that body; finite values whose sum
    overflows, a vel that does not add to a float and a subclass's own is_finite are judged by the loop too."""
    from lesson11.physics2d import Body, World, box_points

    class Judged(Body):
        verdict = True

        def is_finite(self):
            return Judged.verdict

    def outcome(field, value, on, kind=Body):
        crates = [kind(box_points(10, 10), (5.0 * k, 0), 1) for k in range(4)]
        world = World(crates, effects=set())
        if field in ("x", "y"):
            setattr(crates[2].pos, field, value)  # in place, as a student's edit could leave it
        elif field == "angle":
            crates[2]._angle = value  # past the setter, likewise
        else:
            setattr(crates[2], field, value)
        with fast_paths(on):
            try:
                world.end_step(0.01)
            except ValueError as error:
                return str(error)
        return "ok"
    cases = [(field, value) for field in ("x", "y", "angle", "omega") for value in (math.nan, math.inf, -math.inf)]
    cases += [("vel", Vector2(math.nan, 0)), ("vel", Vector2(0, -math.inf)), ("x", 1e308), ("omega", 1e308),
              ("vel", Vector2(1e308, 1e308)), ("omega", 0), ("vel", (0, 0)), ("angle", 1.5)]
    for field, value in cases:
        expected = outcome(field, value, False) if field != "vel" or isinstance(value, Vector2) else "TypeError"
        if expected == "TypeError":  # vel as a tuple: both forms fail alike (is_finite reads vel.x)
            for on in (True, False):
                with pytest.raises(AttributeError):
                    outcome(field, value, on)
            continue
        assert outcome(field, value, True) == expected, (field, value)
        finite = all(map(math.isfinite, [value.x, value.y] if field == "vel" else [value]))
        assert (expected == "ok") == finite and (finite or "body 2 " in expected), (field, value, expected)
    for on in (True, False):
        Judged.verdict = True  # World.add asks too
        world = World([Judged(box_points(10, 10), (0, 0), 1)], effects=set())
        Judged.verdict = False
        with fast_paths(on), pytest.raises(ValueError, match="body 0 "):
            world.end_step(0.01)
