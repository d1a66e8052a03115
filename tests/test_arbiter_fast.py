"""The reference solver's float versions against its readable ones (issue 31 item 3).

The World runs arbiter.Arbiter and collision.corner_manifold / clip_manifold: the
formulas of arbiter.ReferenceArbiter and the *_reference manifolds written on plain
floats. Inside arbiter.readable_versions() the World runs the readable ones. Each
scene runs once in each version and every body must end within 1e-9 px of its twin
(the float versions keep the reference's order of operations, so today they end
exactly equal); the manifold functions must give exactly the reference's answers.
"""
import importlib
import math
import random

import pytest

import labs_found
from lesson11 import runtime
from lesson11.bench import accuracy_cost, scenes as bench_scenes, solver_probe
from lesson11.physics2d import World, collision
from lesson11.physics2d.arbiter import readable_versions
from lesson11.physics2d.vectors import Vector2

TOLERANCE = 1e-9  # px


def stepped(step, readable):
    """Call step() once, in the readable versions if `readable`."""
    if readable:
        with readable_versions():
            return step()
    return step()


def gap(bodies_a, bodies_b):
    """Largest distance (px) between the same body's positions in two runs."""
    return max(math.hypot(p.pos.x - q.pos.x, p.pos.y - q.pos.y) for p, q in zip(bodies_a, bodies_b))


def run_world(make_world, steps, readable):
    world = make_world()
    for _ in range(steps):
        stepped(world.step, readable)
    return world


def run_probe(measurement, readable):
    """Run a solver_probe measurement generator to its end: (its figures, the scene's bodies)."""
    run, scene = measurement(), None
    while True:
        try:
            scene = stepped(lambda: next(run), readable)
        except StopIteration as done:
            return done.value, scene.world.bodies


# ---------------------------------------------------------------- the accuracy scenes

@pytest.mark.parametrize("rule", ["corners", "clip"])
@pytest.mark.parametrize("pile", ["pyramid4", "stack4", "stack8"])
def test_accuracy_piles_end_within_1e_9_px(pile, rule):
    """accuracy_cost's piles (studies 2, 3, 5) in the reference solver, 1 s: readable and float end together."""
    make = lambda: bench_scenes.pile_world(pile, solver="accumulated", contact_rule=rule)
    readable, fast = (run_world(make, 120, flag) for flag in (True, False))
    assert fast.arbiters, "the scene must have contacts, or it tests nothing"
    assert gap(readable.bodies, fast.bodies) <= TOLERANCE


SETTINGS = accuracy_cost.FULL


@pytest.mark.slow  # 14 cases, about 25 CPU s: the published durations
@pytest.mark.parametrize("engine", ["reference corners", "reference clip"])
@pytest.mark.parametrize("scene", [key for key, *_ in accuracy_cost.solver_scenes(SETTINGS)])
def test_accuracy_solver_scenes_give_the_same_figures(engine, scene):
    """accuracy_cost's study 6 (solver_probe's scenes, the published durations): the same figures, bodies within 1e-9 px."""
    measurement = next(m for key, _, m, _ in accuracy_cost.solver_scenes(SETTINGS) if key == scene)
    (figures_r, bodies_r), (figures_f, bodies_f) = (run_probe(lambda: measurement(engine), flag)
                                                   for flag in (True, False))
    assert figures_f == figures_r
    assert gap(bodies_r, bodies_f) <= TOLERANCE


def test_brick_pile_ends_within_1e_9_px():
    """The frontier's 12-crate brick pile, World default 1 × 6, 2.5 s; and the bench's --speed gap is 0 px."""
    def make():
        scene = solver_probe.make(dict(solver="accumulated"))
        solver_probe.brick_pile(scene)
        return scene.world
    readable, fast = (run_world(make, 300, flag) for flag in (True, False))
    assert gap(readable.bodies, fast.bodies) <= TOLERANCE
    assert solver_probe.reference_speed(dict(solver="accumulated"), steps=20, repeats=1)[2] <= TOLERANCE


def test_the_labs_clicked_pile_ends_within_1e_9_px():
    """--speed's last row, the Tumbling Crates 12-crate clicked pile (all 12 clicks, then 20 steps): the readable
    and float versions end within 1e-9 px of each other."""
    readable, fast, apart = solver_probe.clicked_pile_speed(dict(solver="accumulated"), settle=20, repeats=1)
    assert apart <= TOLERANCE
    assert readable > 0 and fast > 0


# ---------------------------------------------------------------- the lab scenes

# every scene of every lab in checker/labs/ (tests/labs_found.py), by its registry name
SCENES = [pytest.param(lab, name, id=f"{lab.id}-{name}") for lab in labs_found.LABS for name in lab.scenarios()]


def lab_world(lab, scenario):
    """The lab's own statics and the checker's scenario bodies (built by the lab's own build()), in the
    reference solver with the lab's effects (its solution's make_world(rng): lint-lab's world_factories rule)."""
    module = importlib.import_module(f"solutions.{lab.id}")
    build = getattr(module, "build", runtime.crate)
    runtime.configure(scenario, "test scenario")
    try:
        bodies = runtime.scene(module.make_scene(random.Random(scenario["seed"])), build=build)
    finally:
        runtime.reset()
    effects = module.make_world(random.Random(scenario["seed"])).effects
    return World(bodies, solver="accumulated", effects=effects)


@pytest.mark.parametrize("lab, name", SCENES)
def test_lab_scenes_end_within_1e_9_px(lab, name):
    """Every lab's checker scenes, as far as 2 s, in the reference solver: readable and float end together."""
    scenario = lab.scenarios()[name]
    steps = min(240, 2 * scenario["frames"])  # two 1/120 s steps a 60 fps frame
    readable, fast = (run_world(lambda: lab_world(lab, scenario), steps, flag) for flag in (True, False))
    assert len(fast.bodies) > 3
    assert gap(readable.bodies, fast.bodies) <= TOLERANCE


# ---------------------------------------------------------------- the manifolds, case by case

def polygon(rng, centre, sides, radius, duplicate=False):
    """A random convex polygon (a regular one, stretched and turned) at centre; duplicate repeats a corner
    within 1e-7 px (a zero-length edge by Vector2's ==) or 2e-6 px (a real one)."""
    turn, stretch = rng.uniform(0, math.pi), rng.uniform(0.5, 1.5)
    points = [Vector2(centre) + Vector2(radius * math.cos(2 * math.pi * k / sides) * stretch,
                                        radius * math.sin(2 * math.pi * k / sides)).rotate_rad(turn)
              for k in range(sides)]
    if duplicate:
        points.insert(1, points[0] + Vector2(rng.choice([1e-7, 2e-6, 0.0]), rng.choice([-1e-7, 0.0])))
    return points


def clip_with_outlines(pa, pb, normal, margin):
    """clip_manifold_outlines (the World's search: edges read off each FlatOutline, the pair's depth from sat_xy)
    with the outlines made here."""
    a, b = collision.flat_outline(pa), collision.flat_outline(pb)
    depth = collision.sat_xy(pa, a, pb, b, margin)[1]
    return collision.clip_manifold_outlines(pa, a, pb, b, normal, depth, margin)


def test_manifolds_give_exactly_the_reference_answers():
    """2000 random pairs of touching, overlapping and nearly touching polygons, with margins: the same lists."""
    rng = random.Random(31)
    compared = 0
    for _ in range(2000):
        pa = polygon(rng, (0, 0), rng.choice([3, 4, 5, 6]), rng.uniform(10, 40), rng.random() < 0.2)
        pb = polygon(rng, (rng.uniform(-60, 60), rng.uniform(-60, 60)), rng.choice([3, 4, 6]), rng.uniform(10, 40),
                     rng.random() < 0.2)
        margin = rng.choice([0.0, 1.0, 3.5])
        hit = collision.sat(pa, pb, margin)
        if hit is None:
            continue
        normal = hit[0]
        for fast, reference in ((collision.corner_manifold, collision.corner_manifold_reference),
                                (collision.clip_manifold, collision.clip_manifold_reference),
                                (clip_with_outlines, collision.clip_manifold_reference)):
            expected = [(tuple(p), d) for p, d in reference(pa, pb, normal, margin)]
            assert [(tuple(p), d) for p, d in fast(pa, pb, normal, margin)] == expected
        compared += 1
    assert compared > 500


def sat_answer(hit):
    """sat's answer as plain values: None, or ((nx, ny), depth)."""
    return None if hit is None else (tuple(hit[0]), hit[1])


def test_sat_xy_gives_exactly_sat_answers():
    """sat_xy (the reference solver's float sat) against sat, the students' reference: 3000 random pairs
    (corners repeated in some, margins 0 to 3.5 px), each both ways round; mirror-image pairs (both ways out
    equally long, where sat orients the axis from A's centre to B's); apart ones. The same answers."""
    rng = random.Random(3131)
    hits = apart = 0
    for _ in range(3000):
        pa = polygon(rng, (0, 0), rng.choice([3, 4, 5, 6]), rng.uniform(10, 40), rng.random() < 0.2)
        pb = polygon(rng, (rng.uniform(-60, 60), rng.uniform(-60, 60)), rng.choice([3, 4, 6]), rng.uniform(10, 40),
                     rng.random() < 0.2)
        margin = rng.choice([0.0, 1.0, 3.5])
        for first, second in ((pa, pb), (pb, pa)):
            expected = sat_answer(collision.sat(first, second, margin))
            fast = collision.sat_xy(first, collision.flat_outline(first), second, collision.flat_outline(second),
                                    margin)
            assert sat_answer(fast) == expected
            hits, apart = hits + (expected is not None), apart + (expected is None)
    box = [Vector2(x, y) for x, y in ((-20, -20), (20, -20), (20, 20), (-20, 20))]
    for shift in ((30, 0), (0, 30), (-30, 0), (0, 0), (39.9999995, 0)):  # centred: both ways equally long
        other = [p + Vector2(shift) for p in box]
        for margin in (0.0, 1.0):
            expected = sat_answer(collision.sat(box, other, margin))
            fast = collision.sat_xy(box, collision.flat_outline(box), other, collision.flat_outline(other), margin)
            assert sat_answer(fast) == expected, shift
    assert hits > 1000 and apart > 1000


def test_equal_boxes_merge_corners_as_the_reference_does():
    """Two equal boxes, the upper one turned ±0.01 rad and shifted across in 0.5 mm steps, so its lower corner
    passes the lower box's upper one at about CORNER_MERGE (0.5 px) across the normal: the same lists."""
    lower = [Vector2(x, y) for x, y in ((0, 0), (40, 0), (40, 40), (0, 40))]
    for turn in (0.01, -0.01):
        for k in range(400):
            centre = Vector2(20 + 0.5 + k / 2000, -20 + 0.3)
            upper = [centre + (p - Vector2(20, 20)).rotate_rad(turn) for p in lower]
            normal = collision.sat(lower, upper, 1.0)[0]
            for fast, reference in ((collision.corner_manifold, collision.corner_manifold_reference),
                                    (collision.clip_manifold, collision.clip_manifold_reference),
                                    (clip_with_outlines, collision.clip_manifold_reference)):
                expected = [(tuple(p), d) for p, d in reference(lower, upper, normal, 1.0)]
                assert [(tuple(p), d) for p, d in fast(lower, upper, normal, 1.0)] == expected, (turn, k)


def test_readable_versions_restores_the_float_ones():
    """The switch holds only inside the block, also when the block raises; inside it the fast paths are off
    too (collision.FAST_PATHS, vectors.FAST_PATHS), so the block runs the readable step throughout."""
    from lesson11.physics2d import vectors
    with pytest.raises(RuntimeError):
        with readable_versions():
            assert collision.READABLE
            assert not collision.FAST_PATHS and not vectors.FAST_PATHS
            raise RuntimeError("inside")
    assert not collision.READABLE
    assert collision.FAST_PATHS and vectors.FAST_PATHS
