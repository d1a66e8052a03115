"""Scene builders shared by the stability tests (tests/test_stability_*.py).

Every builder returns plain physics2d objects. Units: px, s, rad; y grows
downward; the floor's top face is at y = FLOOR_TOP unless said otherwise.
"""
import math
import random

from lesson11.physics2d import Body, Circle, LESSON_EFFECTS, Polygon, Vector2, World, box_points

FLOOR_TOP = 600.0   # px, y of the floor's top face
BOX = 40.0          # px, side of the standard crate


def box(w, h, centre, angle=0.0):
    """World corners (px) of a w × h box centred at `centre`, turned by `angle` rad."""
    centre = Vector2(centre)
    return [centre + p.rotate_rad(angle) for p in box_points(w, h)]


def shifted(points, offset):
    """The same points moved by `offset` (px)."""
    offset = Vector2(offset)
    return [p + offset for p in points]


def floor(width=800.0, x=400.0, restitution=0.2, friction=0.6):
    """A static 40 px thick floor whose top face is at y = FLOOR_TOP."""
    return Body(box_points(width, 40), (x, FLOOR_TOP + 20), 0, restitution=restitution, friction=friction)


def box_stack(count, size=BOX, x=400.0):
    """A floor and `count` equal boxes of mass 1 stacked exactly touching, bottom first."""
    bodies = [floor(x=x)]
    for level in range(count):
        bodies.append(Body(box_points(size, size), (x, FLOOR_TOP - size / 2 - level * size), 1.0))
    return bodies


def box_pyramid(base, size=BOX, x=400.0):
    """A floor and a pyramid of boxes (mass 1), `base` on the bottom row, one fewer per row up."""
    bodies = [floor(x=x)]
    for row in range(base):
        count = base - row
        left = x - (count - 1) * size / 2
        for k in range(count):
            bodies.append(Body(box_points(size, size), (left + k * size, FLOOR_TOP - size / 2 - row * size), 1.0))
    return bodies


def crate_pile(seed=11, count=6):
    """A bin (floor and two walls, 200 px apart) and `count` randomly sized and turned crates above it."""
    rng = random.Random(seed)
    bodies = [Body(box_points(400, 40), (300, FLOOR_TOP + 20), 0),
              Body(box_points(20, 400), (190, 400), 0),
              Body(box_points(20, 400), (410, 400), 0)]
    for i in range(count):
        w, h = rng.randint(40, 60), rng.randint(30, 50)
        bodies.append(Body(box_points(w, h), (240 + 60 * (i % 3), 380 - 60 * (i // 3)), 1.0,
                           angle=rng.uniform(0, math.pi)))
    return bodies


def busy_box(width=400.0, height=300.0, iterations=3, substeps=2):
    """A closed 400 × 300 px container (4 static walls) with a spinning box, a ball and a bullet.

    Everything is frictionless with restitution 1, and the world is told not to
    damp slow impacts (resting_speed = 0), so the bodies keep hitting the walls
    and each other for as long as the test runs. Nothing rests here, so the
    scene declares 3 solver passes and 2 sub-steps (the lesson solver's
    solve-first default is 4). Measured over 10⁴ steps, deepest poke out of the
    walls and CPU time (one run, 2 busy cores): 1 sub-step 4.80 px in 7.4 s,
    2 sub-steps 0.61 px in 12.3 s, 4 sub-steps 0.26 px in 22.9 s; the
    move-first order 1.43 px in 10.0 s.
    """
    walls = [Body(box_points(width + 40, 20), (width / 2, -10), 0),
             Body(box_points(width + 40, 20), (width / 2, height + 10), 0),
             Body(box_points(20, height), (-10, height / 2), 0),
             Body(box_points(20, height), (width + 10, height / 2), 0)]
    bouncy = dict(restitution=1.0, friction=0.0)
    movers = [Body(box_points(40, 30), (100, 100), 1.0, vel=(180, -120), omega=2.0, **bouncy),
              Body(Circle(15), (250, 200), 1.0, vel=(-150, 90), **bouncy),
              Body(Circle(3), (200, 60), 0.2, vel=(2500, 700), bullet=True, **bouncy)]
    world = World(walls + movers, resting_speed=0.0, effects=LESSON_EFFECTS | {"ccd"}, iterations=iterations,
                  substeps=substeps)
    return world


def potential_energy(body, gravity=980.0, ground=FLOOR_TOP):
    """m g (ground - y) for a dynamic body (mass·px²/s²), 0 for static ones."""
    return body.mass * gravity * (ground - body.pos.y) if body.mass else 0.0


def total_energy(world, ground=FLOOR_TOP):
    """Kinetic plus gravitational potential energy of every body (mass·px²/s²)."""
    g = world.gravity.y
    return sum(b.kinetic_energy() + potential_energy(b, g, ground) for b in world.bodies)


def displacement(bodies, start):
    """Largest distance (px) any body has moved from its position in `start`."""
    return max((b.pos - p).length() for b, p in zip(bodies, start))


def positions(bodies):
    """Copies of every body's position."""
    return [Vector2(b.pos) for b in bodies]


__all__ = ["FLOOR_TOP", "BOX", "Polygon", "box", "shifted", "floor", "box_stack", "box_pyramid",
           "crate_pile", "busy_box", "potential_energy", "total_energy", "displacement", "positions"]
