"""Accumulated impulses with warm starting: the solver production engines use.

The lesson's solver (world.solve_contacts + response.resolve) starts every
pass from scratch: each pass computes a fresh impulse, clamps friction by that
pass's normal impulse, and forgets it all at the end of the step. That is easy
to read, and good enough for a few crates, but a tall stack or a heavy box on a
light one sinks: the support has to be rebuilt from nothing every step.

This module keeps each contact's total impulse across passes and across steps,
as Box2D-Lite's Arbiter does (Erin Catto, GDC 2006):
  * the total normal impulse Pn is clamped, Pn >= 0 (a contact only pushes);
  * the total friction impulse Pt is clamped, |Pt| <= μ Pn (Coulomb on the total);
  * a contact found again next step starts from last step's Pn, Pt (warm start);
  * overlap is removed by a velocity bias, bias = β/dt · max(depth - slop, 0),
    instead of moving positions directly;
  * pairs less than SPECULATIVE_MARGIN apart are contacts too (speculative
    contacts): a gap g lets the points close at up to g/dt, bias = -g/dt, so a
    box resting on another is held from the first step instead of falling in.
The World uses it when a scene declares solver="accumulated".
"""
from .response import apply_impulse, effective_mass_inverse, relative_velocity
from .vectors import Vector2

BIAS_FACTOR = 0.2     # β: share of the overlap turned into separating speed per step
MATCH_DISTANCE = 2.0  # px: a contact within this distance of last step's (on body A) is the same contact
SPECULATIVE_MARGIN = 1.0  # px: pairs closer than this are contacts already (negative depth = gap)


class ContactPoint:
    """One persistent contact point and the impulses accumulated on it (mass·px/s)."""

    def __init__(self, point, depth, local_a):
        self.point = point        # world point (px)
        self.depth = depth        # how far this point is inside the other body (px)
        self.local_a = local_a    # the point in A's frame, to recognise it next step
        self.normal_impulse = 0.0
        self.friction_impulse = 0.0


class Arbiter:
    """The contact between two bodies, kept from step to step."""

    def __init__(self, a, b):
        self.a, self.b = a, b
        self.points = []
        self.normal = Vector2(0, 1)

    def update(self, normal, points, depths):
        """Take this step's contact points (and each one's depth, px), carrying over the impulses of points that persist."""
        old = self.points
        self.points = []
        for point, depth in zip(points, depths):
            local_a = (point - self.a.pos).rotate_rad(-self.a.angle)
            contact = ContactPoint(point, depth, local_a)
            match = min(old, key=lambda c: c.local_a.distance_squared_to(local_a), default=None)
            if match is not None and match.local_a.distance_to(local_a) <= MATCH_DISTANCE:
                contact.normal_impulse = match.normal_impulse
                contact.friction_impulse = match.friction_impulse
            self.points.append(contact)
        self.normal = normal

    def prepare(self, world, dt):
        """Per step, before any warm start: offsets, effective masses and the bias speed.

        mass_n = 1 / k(n), mass_t = 1 / k(t) with k from effective_mass_inverse;
        bias = β/dt · max(depth - slop, 0), or the bounce speed -e·vn when the
        contact closes faster than resting_speed and that is larger.
        """
        a, b, n = self.a, self.b, self.normal
        tangent = Vector2(n.y, -n.x)
        spin = "rotation" in world.effects
        for c in self.points:
            c.ra, c.rb = (c.point - a.pos, c.point - b.pos) if spin else (Vector2(), Vector2())
            c.mass_normal = 1 / effective_mass_inverse(a, b, c.ra, c.rb, n)
            c.mass_tangent = 1 / effective_mass_inverse(a, b, c.ra, c.rb, tangent)
            c.bias = 0.0
            if c.depth < 0:
                c.bias = c.depth / dt  # speculative: may close the gap this step, no further
            elif "correction" in world.effects:
                c.bias = BIAS_FACTOR / dt * max(c.depth - world.slop, 0.0)
            vn = relative_velocity(a, b, c.ra, c.rb).dot(n)
            if "restitution" in world.effects and vn < -world.resting_speed:
                c.bias = max(c.bias, -min(a.restitution, b.restitution) * vn)
            if "friction" not in world.effects:
                c.friction_impulse = 0.0

    def warm_start(self):
        """Apply last step's accumulated impulses again: P = Pn n + Pt t at each point."""
        n = self.normal
        tangent = Vector2(n.y, -n.x)
        for c in self.points:
            apply_impulse(self.a, self.b, n * c.normal_impulse + tangent * c.friction_impulse, c.ra, c.rb)

    def apply(self, world):
        """One pass: change each point's total impulses by what its velocities still need, then clamp.

        Pn ← max(Pn + mass_n (-vn + bias), 0);  Pt ← clamp(Pt + mass_t (-vt), -μ Pn, μ Pn).
        Only the change of each total is applied (through apply_impulse).
        """
        a, b, n = self.a, self.b, self.normal
        tangent = Vector2(n.y, -n.x)
        mu = (a.friction * b.friction) ** 0.5
        for c in self.points:
            vn = relative_velocity(a, b, c.ra, c.rb).dot(n)
            old = c.normal_impulse
            c.normal_impulse = max(old + c.mass_normal * (-vn + c.bias), 0.0)
            apply_impulse(a, b, n * (c.normal_impulse - old), c.ra, c.rb)
            if "friction" in world.effects:
                vt = relative_velocity(a, b, c.ra, c.rb).dot(tangent)
                old = c.friction_impulse
                limit = mu * c.normal_impulse
                c.friction_impulse = max(-limit, min(limit, old + c.mass_tangent * -vt))
                apply_impulse(a, b, tangent * (c.friction_impulse - old), c.ra, c.rb)
