"""The "sleep" effect: calm islands of touching bodies stop being simulated until something wakes them.

A World whose effects include "sleep" runs, after each step, update(world, dt):
every awake dynamic body's `sleep_time` (s) becomes world.sleep_timer(sleep_time,
speed, spin, dt) (the library's: timer below), and an island of touching dynamic
bodies whose sleep_time are all >= world.sleep_after falls asleep together:
`asleep` True, velocity and spin zeroed, `island` the list of its members.
During a step, bodies for which world.moves(body) is False (the library's: moves)
are not integrated, and a pair in which neither moves is never visited by the
broad phase; for every touching pair found, world.wake_pair(a, b) (the library's:
wake_pair) names the bodies to wake, and wake() wakes each with its island.

The thresholds are the World settings sleep_speed, sleep_spin and sleep_after;
their defaults are SLEEP_SPEED, SLEEP_SPIN and SLEEP_AFTER below.
"""
from .vectors import Vector2, finite_number

SLEEP_SPEED = 5.0   # px/s: a body slower than this (and spinning slower than SLEEP_SPIN) ...
SLEEP_SPIN = 0.1    # rad/s
SLEEP_AFTER = 0.5   # s ... for this long, with every body it touches, falls asleep


def timer(sleep_time, speed, spin, dt, sleep_speed=SLEEP_SPEED, sleep_spin=SLEEP_SPIN):
    """The library's sleep timer (s): sleep_time + dt while speed < sleep_speed and |spin| < sleep_spin, else 0.

    >>> timer(0.25, 1.0, 0.0, 0.5)     # calm: the timer runs
    0.75
    >>> timer(0.25, 6.0, 0.0, 0.5)     # 6 px/s is not calm: back to 0
    0.0
    """
    return sleep_time + dt if speed < sleep_speed and abs(spin) < sleep_spin else 0.0


def moves(body):
    """The library's rule: a body is integrated (and its pairs tested) if it is dynamic and awake."""
    return body.inv_mass != 0 and not body.asleep


def wake_pair(a, b):
    """The library's rule: of a touching pair, the sleeping body is woken if the other is dynamic and awake."""
    return [sleeper for sleeper, other in ((a, b), (b, a))
            if sleeper.asleep and other.inv_mass != 0 and not other.asleep]


def wake(body):
    """Wake `body` and every body that fell asleep in the same island (timers back to 0)."""
    for other in getattr(body, "island", None) or [body]:
        if other.asleep:
            other.asleep = False
            other.sleep_time = 0.0
            other.island = None
    body.asleep = False
    body.sleep_time = 0.0


def fall_asleep(bodies):
    """Put these dynamic bodies to sleep together, as one island: no velocity, no spin."""
    island = list(bodies)
    for body in island:
        body.asleep = True
        body.vel = Vector2()
        body.omega = 0.0
        body.island = island


def update(world, dt):
    """After a step of dt s: each awake dynamic body's sleep_time = world.sleep_timer(...); calm islands sleep.

    An island is a group of awake dynamic bodies joined by the pairs that
    touched in any contact search of this step (world.touched: (id(a), id(b));
    static bodies join no island). It falls asleep when every member's
    sleep_time >= world.sleep_after, so a pile sleeps as one (and wake() wakes
    it as one). world.touched is emptied for the next step.
    """
    awake = [body for body in world.bodies if body.inv_mass != 0 and not body.asleep]
    for body in awake:
        body.sleep_time = finite_number(world.sleep_timer(body.sleep_time, body.vel.length(), body.omega, dt),
                                        "sleep_timer's result")
    islands = _islands(awake, world.touched)
    world.touched = set()
    for members in islands:
        if all(body.sleep_time >= world.sleep_after for body in members):
            fall_asleep(members)


def _islands(bodies, touched):
    """`bodies` grouped by the pairs (id(a), id(b)) in `touched` (union-find), each group in `bodies`' order."""
    parent = {id(body): id(body) for body in bodies}

    def root(key):
        while parent[key] != key:
            parent[key] = parent[parent[key]]
            key = parent[key]
        return key
    for ka, kb in touched:
        if ka in parent and kb in parent:
            parent[root(ka)] = root(kb)
    islands = {}
    for body in bodies:
        islands.setdefault(root(id(body)), []).append(body)
    return list(islands.values())
