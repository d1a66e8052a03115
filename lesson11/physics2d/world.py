"""The World: bodies advanced with a fixed step, gravity, and an iterative contact solver.

A scene declares the effects it needs in `effects`; the world runs those and
nothing else (no friction pass for a frictionless scene, no swept tests unless
"ccd" is asked for). Settings are plain attributes with documented defaults.
A lab can hand in its own `sat`, `resolve` and `separate`, and the world calls
them inside its loop, so a student's functions run the whole simulation.
"""
from collections import namedtuple

from . import collision, response
from .arbiter import SPECULATIVE_MARGIN, Arbiter
from .vectors import Vector2, finite_number, finite_vector

EFFECTS = ("gravity", "rotation", "friction", "restitution", "correction", "ccd")
SOLVERS = ("lesson", "accumulated")
LESSON_EFFECTS = frozenset({"gravity", "rotation", "friction", "restitution", "correction"})

Contact = namedtuple("Contact", "a b point normal depth")
Contact.__doc__ = "One contact: bodies a and b, the world point (px), the unit normal A→B, the depth (px)."


class World:
    """A collection of bodies stepped with a fixed time step.

    Settings (attributes; defaults are the lesson's):
      gravity        Vector2(0, 980) px/s²
      step           1/120 s, the fixed physics step
      iterations     6 solver passes over the contacts per step
      slop           0.5 px of overlap tolerated by the push-out
      percent        0.4, share of the remaining overlap pushed out per pass
      resting_speed  30 px/s; slower impacts do not bounce
      max_frame      0.25 s; longer frames are clamped (window drags, breakpoints)
      contact_rule   "corners" (the lesson's corners-inside rule) or "clip" (edge clipping)
      effects        which effects run, a subset of EFFECTS; LESSON_EFFECTS by default
      solver         "lesson" (fresh impulses every pass, push-out by separate) or
                     "accumulated" (arbiter.py: impulses kept across passes and steps,
                     warm started; for tall stacks and large mass ratios)
    Hooks: sat(pa, pb), resolve(a, b, normal, point), separate(a, b, normal, depth).
    After each step: `contacts` (list of Contact from the last solver pass) and
    `counters` (how many pair tests, contacts, swept tests ran in all).
    """

    def __init__(self, bodies=(), *, gravity=(0, 980), step=1 / 120, iterations=6,
                 slop=response.SLOP, percent=response.PERCENT, resting_speed=response.RESTING_SPEED,
                 max_frame=0.25, contact_rule="corners", effects=LESSON_EFFECTS, solver="lesson",
                 sat=None, resolve=None, separate=None):
        self.gravity = finite_vector(gravity, "world gravity")
        self.step_seconds = self._positive(step, "world step")
        if not isinstance(iterations, int) or iterations < 1:
            raise ValueError(f"world iterations must be a whole number >= 1, got {iterations!r}")
        self.iterations = iterations
        self.slop = finite_number(slop, "world slop")
        self.percent = finite_number(percent, "world percent")
        self.resting_speed = finite_number(resting_speed, "world resting_speed")
        if self.slop < 0:
            raise ValueError(f"world slop must be >= 0 px, got {self.slop}")
        if not 0 <= self.percent <= 1:
            raise ValueError(f"world percent must be between 0 and 1, got {self.percent}")
        if self.resting_speed < 0:
            raise ValueError(f"world resting_speed must be >= 0 px/s, got {self.resting_speed}")
        self.max_frame = self._positive(max_frame, "world max_frame")
        if contact_rule not in ("corners", "clip"):
            raise ValueError(f"contact_rule must be 'corners' or 'clip', got {contact_rule!r}")
        self.contact_rule = contact_rule
        if solver not in SOLVERS:
            raise ValueError(f"solver must be one of {list(SOLVERS)}, got {solver!r}")
        self.solver = solver
        self.arbiters = {}
        if isinstance(effects, str):
            raise ValueError(f"effects must be a set of names such as {{{effects!r}}}, not the string {effects!r}")
        unknown = set(effects) - set(EFFECTS)
        if unknown:
            raise ValueError(f"unknown effects {sorted(unknown)}; choose from {list(EFFECTS)}")
        self.effects = frozenset(effects)
        self.sat = sat or collision.sat
        self.resolve = resolve or self.lesson_resolve
        self.separate = separate or self.lesson_separate
        self.bodies = []
        self.contacts = []
        self.accumulator = 0.0
        self.time = 0.0
        self.counters = {"steps": 0, "pair_tests": 0, "narrow_tests": 0, "contacts": 0, "swept_tests": 0}
        for body in bodies:
            self.add(body)

    @staticmethod
    def _positive(value, name):
        value = finite_number(value, name)
        if value <= 0:
            raise ValueError(f"{name} must be > 0 s, got {value}")
        return value

    def add(self, body):
        """Add a body (checked to be finite) and return it."""
        if not body.is_finite():
            raise ValueError(f"cannot add {body!r}: its position, velocity, angle or omega is not finite")
        self.bodies.append(body)
        return body

    def remove(self, body):
        """Remove a body from the world."""
        self.bodies.remove(body)

    def lesson_resolve(self, a, b, normal, point):
        """The library's resolve() with this world's resting_speed and effects."""
        return response.resolve(a, b, normal, point, self.resting_speed,
                                friction="friction" in self.effects,
                                restitution="restitution" in self.effects,
                                spin="rotation" in self.effects)

    def lesson_separate(self, a, b, normal, depth):
        """The library's separate() with this world's slop and percent."""
        response.separate(a, b, normal, depth, self.slop, self.percent)

    def advance(self, frame_seconds):
        """Run as many fixed steps as fit in the frame's time (s), carrying the remainder.

        Frames longer than max_frame are clamped first. Returns the number of steps run.
        """
        frame_seconds = finite_number(frame_seconds, "frame time")
        if frame_seconds < 0:
            raise ValueError(f"frame time must be >= 0 s, got {frame_seconds}")
        self.accumulator += min(frame_seconds, self.max_frame)
        steps = 0
        while self.accumulator >= self.step_seconds:
            self.step()
            self.accumulator -= self.step_seconds
            steps += 1
        return steps

    def step(self, dt=None):
        """Advance every body by one step of dt seconds (default: the fixed step).

        The lesson's solver, in the lesson's order:
        1. integrate: v += g dt; then x += v dt and angle += ω dt (or a swept move for bullets)
        2. solve: `iterations` passes of broad phase, narrow phase, impulses, push-out.
        Moving before solving lets a crate resting on a slope creep down by
        g sin θ dt² per step (3.1 px/s on the 22° ramp): the impulses cancel the
        velocity, but not the move already made. The accumulated solver moves last.
        The accumulated solver: v += g dt; find contacts once; warm start and
        `iterations` passes of accumulated impulses; then x += v dt.
        Raises ValueError if any body ends the step with a non-finite state.
        """
        dt = self.step_seconds if dt is None else self._positive(dt, "step dt")
        if self.solver == "accumulated":
            self.step_accumulated(dt)
        else:
            self.integrate_velocities(dt)
            self.integrate_positions(dt)
            for _ in range(self.iterations):
                self.solve_contacts()
        self.time += dt
        self.counters["steps"] += 1
        for index, body in enumerate(self.bodies):
            if not body.is_finite():
                raise ValueError(f"body {index} {body!r} became non-finite at t = {self.time:.4f} s; "
                                 "check its mass, the step and the hooks")

    def integrate_velocities(self, dt):
        """Gravity for every dynamic body: v += g dt (only if the scene declares "gravity")."""
        if "gravity" not in self.effects:
            return
        for body in self.bodies:
            if body.inv_mass != 0:
                body.vel += self.gravity * dt

    def integrate_positions(self, dt):
        """Move every dynamic body: x += v dt, angle += ω dt (semi-implicit Euler, after the velocities)."""
        rotation = "rotation" in self.effects
        ccd = "ccd" in self.effects
        for body in self.bodies:
            if body.inv_mass == 0:
                continue
            if ccd and body.bullet and body.shape.kind == "circle":
                self.swept_move(body, dt)
            else:
                body.pos += body.vel * dt
            if rotation:
                body.angle += body.omega * dt

    def swept_move(self, bullet, dt):
        """Continuous collision detection for a circle bullet: move it to its first contact.

        Finds the earliest time of impact t in [0, dt] against every other body
        (held still during the sweep, so the contact point lies where both
        bodies are; circles by circle_toi, polygons by circle_polygon_toi),
        moves there, resolves the hit, and spends the rest of dt moving with the
        new velocity. A body that itself moves fast towards the bullet can
        still be missed: only the bullet is swept.
        """
        first = None
        for other in self.bodies:
            if other is bullet:
                continue
            self.counters["swept_tests"] += 1
            if other.shape.kind == "circle":
                t = collision.circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(),
                                         other.radius, dt)
                hit = None if t is None else (t, (other.pos - bullet.pos - bullet.vel * t).normalize())
            else:
                hit = collision.circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius,
                                                   other.world_points(), dt)
            if hit is not None and (first is None or hit[0] < first[0]):
                first = (hit[0], hit[1], other)
        if first is None:
            bullet.pos += bullet.vel * dt
            return
        t, normal, other = first
        bullet.pos += bullet.vel * t
        self.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        bullet.pos += bullet.vel * (dt - t)

    def world_shapes(self):
        """World points of every body (an empty list for circles), in body order."""
        return [body.world_points() for body in self.bodies]

    def collide(self, a, b, pa, pb, margin=0.0):
        """Narrow phase for one pair: None, or (normal A→B, depth, contact points, each point's depth).

        Only the clip rule measures a depth per point; otherwise each point gets the pair's depth.
        A margin (px) asks for speculative contacts: pairs closer than that count,
        with a negative depth; polygons then use physics2d's sat, not a hooked one.
        """
        kind = (a.shape.kind, b.shape.kind)
        if kind == ("polygon", "polygon"):
            hit = collision.sat(pa, pb, margin) if margin else self.sat(pa, pb)
            if hit is None:
                return None
            normal, depth = hit
            if self.contact_rule == "clip":
                manifold = collision.clip_manifold(pa, pb, normal, margin)
                return normal, depth, [p for p, _ in manifold], [d for _, d in manifold]
            points = collision.contact_points(pa, pb, normal)
            return normal, depth, points, [depth] * len(points)
        if kind == ("circle", "circle"):
            hit = collision.circle_circle(a.pos, a.radius, b.pos, b.radius)
        elif kind == ("circle", "polygon"):
            hit = collision.circle_polygon(a.pos, a.radius, pb)
        else:
            hit = collision.circle_polygon(b.pos, b.radius, pa)
            hit = None if hit is None else (-hit[0], hit[1])
        if hit is None:
            return None
        normal, depth = hit
        circle, direction = (a, normal) if a.shape.kind == "circle" else (b, -normal)
        return normal, depth, [circle.pos + direction * (circle.radius - depth / 2)], [depth]

    def hits(self, margin=0.0):
        """Every touching pair now: yields (a, b, normal A→B, depth, contact points, their depths).

        Broad phase first: pairs of static bodies and pairs whose bounding boxes
        are apart are skipped; the rest go to the narrow phase (collide).
        """
        bodies = self.bodies
        shapes = self.world_shapes()
        boxes = [body.aabb(points) for body, points in zip(bodies, shapes)]
        for i in range(len(bodies)):
            for j in range(i + 1, len(bodies)):
                a, b = bodies[i], bodies[j]
                if a.inv_mass == 0 and b.inv_mass == 0:
                    continue
                self.counters["pair_tests"] += 1
                box_a, box_b = boxes[i], boxes[j]
                if box_a[2] + margin < box_b[0] or box_b[2] + margin < box_a[0] or \
                        box_a[3] + margin < box_b[1] or box_b[3] + margin < box_a[1]:
                    continue  # broad phase: bounding boxes apart
                self.counters["narrow_tests"] += 1
                hit = self.collide(a, b, shapes[i], shapes[j], margin)
                if hit is not None:
                    self.counters["contacts"] += len(hit[2])
                    yield (a, b) + hit

    def solve_contacts(self):
        """One pass of the lesson's solver: for each touching pair, impulses at its points, then the push-out."""
        self.contacts = []
        correction = "correction" in self.effects
        for a, b, normal, depth, points, _ in self.hits():
            for point in points:
                self.resolve(a, b, normal, point)
                self.contacts.append(Contact(a, b, point, normal, depth))
            if correction:
                self.separate(a, b, normal, depth)

    def step_accumulated(self, dt):
        """One step of the accumulated solver (arbiter.py), in Box2D-Lite's order.

        v += g dt; contacts found once and matched with last step's; warm start;
        `iterations` passes of clamped accumulated impulses; x += v dt.
        """
        self.integrate_velocities(dt)
        arbiters = {}
        for a, b, normal, _, points, depths in self.hits(SPECULATIVE_MARGIN):
            arbiter = self.arbiters.get((id(a), id(b))) or Arbiter(a, b)
            arbiter.update(normal, points, depths)
            arbiters[(id(a), id(b))] = arbiter
        self.arbiters = arbiters
        for arbiter in arbiters.values():
            arbiter.prepare(self, dt)  # the bounce speeds must see the velocities before any warm start
        for arbiter in arbiters.values():
            arbiter.warm_start()
        for _ in range(self.iterations):
            for arbiter in arbiters.values():
                arbiter.apply(self)
        self.contacts = [Contact(arb.a, arb.b, c.point, arb.normal, c.depth)
                         for arb in arbiters.values() for c in arb.points]
        self.integrate_positions(dt)
