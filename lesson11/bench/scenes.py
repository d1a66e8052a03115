"""The benchmark's scenes and the accuracy figures measured on them.

Every scene is built fresh for each run, so runs never share state. Units: px,
s, rad; y grows downward; the floor's top face is at y = FLOOR_TOP. Boxes are
40 px, mass 1, friction 0.6, restitution 0.2 (the Body defaults), so that the
pymunk twin (pymunk_pile.py) can copy them exactly.
"""
import math

from lesson11.physics2d import Body, Circle, LESSON_EFFECTS, World, box_points
from lesson11.physics2d.vectors import Vector2

FLOOR_TOP = 600.0   # px, y of the floor's top face
FLOOR_WIDTH = 800.0  # px
FLOOR_X = 400.0     # px, x of the floor's centre
BOX = 40.0          # px, side of a crate
BOX_MASS = 1.0

WALL_X = 400.0      # px, x of the thin wall's centre (tunnelling study)
WALL_WIDTH = 4.0    # px, the wall is this thin...
WALL_HEIGHT = 400.0  # px, ...and this tall, so gravity cannot take a shot over it
BULLET_RADIUS = 3.0  # px
BULLET_MASS = 0.1


def floor():
    """A static floor, 40 px thick, whose top face is at y = FLOOR_TOP."""
    return Body(box_points(FLOOR_WIDTH, 40), (FLOOR_X, FLOOR_TOP + 20), 0)


def pile_positions(name):
    """Centres (px) of the crates of a pile scene, bottom row first, all exactly touching.

    "pyramid4": 4 + 3 + 2 + 1 = 10 crates; "stackN" (e.g. "stack4"): N crates in one column.
    """
    if name.startswith("pyramid"):
        base = int(name[len("pyramid"):])
        centres = []
        for row in range(base):
            count = base - row
            left = FLOOR_X - (count - 1) * BOX / 2
            centres += [(left + k * BOX, FLOOR_TOP - BOX / 2 - row * BOX) for k in range(count)]
        return centres
    if name.startswith("stack"):
        count = int(name[len("stack"):])
        return [(FLOOR_X, FLOOR_TOP - BOX / 2 - level * BOX) for level in range(count)]
    raise ValueError(f"unknown pile scene {name!r}; use 'pyramidN' or 'stackN'")


def pile_world(name, **settings):
    """A World holding the floor and the crates of pile_positions(name); settings go to World()."""
    crates = [Body(box_points(BOX, BOX), centre, BOX_MASS) for centre in pile_positions(name)]
    return World([floor()] + crates, **settings)


def floor_penetration(crate_corners):
    """How far (px) the lowest crate corner is below the floor's top face, or 0: max(y) - FLOOR_TOP."""
    lowest = max(p.y for corners in crate_corners for p in corners)
    return max(lowest - FLOOR_TOP, 0.0)


def settling_balls_world(effects, bullets=False, count=24):
    """A closed 400 × 300 px box of static walls with `count` frictionless balls (radius 12 px) thrown in.

    Restitution 0.5: the balls bounce, then settle in layers on the floor.
    Circles touch along the line through their centres and friction is 0, so
    the scene needs only "gravity", "restitution" and "correction": declaring
    "friction" and "rotation" as well changes nothing but the time.
    bullets=True marks every ball as a bullet (swept tests when "ccd" is declared).
    """
    walls = [Body(box_points(440, 20), (200, -10), 0), Body(box_points(440, 20), (200, 310), 0),
             Body(box_points(20, 300), (-10, 150), 0), Body(box_points(20, 300), (410, 150), 0)]
    for wall in walls:
        wall.restitution, wall.friction = 0.5, 0.0
    balls = []
    for k in range(count):
        x, y = 30 + 45 * (k % 8), 40 + 50 * (k // 8)
        velocity = (23 * k - 150, 31 * (k % 7) - 120)
        balls.append(Body(Circle(12), (x, y), 1.0, vel=velocity, restitution=0.5, friction=0.0, bullet=bullets))
    return World(walls + balls, effects=effects)


def bullet_world(start_x, speed, ccd, step):
    """A thin static wall and one small fast circle flying at it along +x.

    ccd=True declares "ccd" and marks the circle as a bullet (swept test);
    otherwise the world only checks where the circle is after each step.
    substeps=1: World's default solve-first order would split every step in 4
    (LESSON_SUBSTEPS), so a "1/120 s" step would really be four of 1/480 s; the
    study's sub-stepping rows do that splitting themselves, by `step`.
    """
    wall = Body(box_points(WALL_WIDTH, WALL_HEIGHT), (WALL_X, 300), 0)
    bullet = Body(Circle(BULLET_RADIUS), (start_x, 300), BULLET_MASS, vel=(speed, 0), bullet=ccd)
    effects = LESSON_EFFECTS | {"ccd"} if ccd else LESSON_EFFECTS
    return World([wall, bullet], step_seconds=step, effects=effects, substeps=1), bullet


def tunnelled(bullet):
    """True when the bullet's centre ended past the middle of the wall, on the far side (x > WALL_X)."""
    return bullet.pos.x > WALL_X


def state_of(world):
    """Every body's position (x, y) in px, to compare two runs of the same scene."""
    return [(b.pos.x, b.pos.y) for b in world.bodies]


def largest_difference(state_a, state_b):
    """Largest distance (px) between the same body's positions in two state_of() lists."""
    return max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(state_a, state_b))


__all__ = ["FLOOR_TOP", "BOX", "BOX_MASS", "WALL_X", "WALL_WIDTH", "BULLET_RADIUS", "Vector2",
           "floor", "pile_positions", "pile_world", "floor_penetration", "settling_balls_world",
           "bullet_world", "tunnelled", "state_of", "largest_difference"]
