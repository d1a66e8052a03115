"""The reference solver: accumulated impulses, warm starting, soft contacts and sub-steps.

Method: sequential impulses with accumulated, clamped impulses and warm
starting, as Box2D-Lite's Arbiter (Erin Catto, GDC 2006), run as the "soft
step" of Box2D v3 (Catto, Solver2D, 2024): the step is split into sub-steps,
each contact is a stiff damped spring (a soft constraint) while it pushes
overlap out, and a relax pass then removes the push-out speed again, so
correcting the overlap adds no energy. Our own code after the published ideas.

The lesson's solver (world.py with response.resolve) starts every pass from
scratch: easy to read, good enough for a few crates, but a tall stack or a
heavy box on a light one sinks: the support is rebuilt from nothing each step.

Phases of one fixed step dt, with h = dt / substeps (world.py calls them in order):
  1. collide   once per step: manifolds with speculative contacts (pairs less
               than a margin apart count, with a negative depth = the gap);
               points matched with last step's keep their impulses (update)
  2. prepare   anchors ra, rb, effective masses, the approach speed for restitution
  then, for each sub-step:
  3. v += g h, then warm start: apply the kept impulses P = Pn n + Pt t again
  4. solve     `iterations` passes with the soft push-out (use_bias=True):
                 s  = current separation (px), followed as the bodies move
                 s > 0 (a gap): bias = s / h, the contact may close the gap, no more
                 s <= 0:        bias = max(β s, -MAX_PUSH), soft: mass and impulse scaled
                 Pn <- max(Pn - mass_n·m_scale·(vn + bias) - i_scale·Pn, 0)
                 Pt <- clamp(Pt - mass_t·vt, -μ Pn, μ Pn)        (Coulomb on the total)
  5. x += v h, angle += ω h
  6. relax     one pass without the push-out (use_bias=False), taking its speed away again
  after the sub-steps:
  7. restitution: contacts that approached faster than resting_speed and
     pushed get vn = -e·vn(approach), with the total still clamped Pn >= 0

Two versions of the same formulas: ReferenceArbiter (readable, with Vector2)
and Arbiter (plain floats, what the World runs); inside readable_versions()
the World runs the readable one, and collision's readable manifolds.
"""
import contextlib
import math

from . import collision
from .response import apply_impulse, effective_mass_inverse, relative_velocity
from .vectors import Vector2

MATCH_DISTANCE = 2.0      # px: a contact within this distance of last step's (on body A) is the same contact
SPECULATIVE_MARGIN = 1.0  # px: pairs closer than this (plus how far they can move in a step) are contacts
CONTACT_HERTZ = 120.0     # Hz: stiffness of the soft contact, capped at a quarter of the sub-step rate
DAMPING_RATIO = 10.0      # ζ of the soft contact (heavily over-damped: no bounce from the push-out)
MAX_PUSH = 300.0          # px/s: the push-out never separates faster than this
RESTITUTION_PASSES = 4    # passes of the restitution phase (two bouncing corners need a few to agree)


def soft_constants(hertz, damping_ratio, h):
    """A soft contact for a sub-step h (s): (bias_rate 1/s, mass_scale, impulse_scale).

        ω = 2π·hertz,  a1 = 2ζ + h ω,  a2 = h ω a1,  a3 = 1 / (1 + a2)
        bias_rate = ω / a1,  mass_scale = a2 a3,  impulse_scale = a3
    (a spring-damper solved implicitly: stable for any stiffness and step).
    """
    omega = 2 * math.pi * hertz
    a1 = 2 * damping_ratio + h * omega
    a2 = h * omega * a1
    a3 = 1 / (1 + a2)
    return omega / a1, a2 * a3, a3


class ContactPoint:
    """One persistent contact point and the impulses accumulated on it (mass·px/s)."""
    __slots__ = ("point", "depth", "local_a", "local_xy", "normal_impulse", "friction_impulse", "ra", "rb", "anchors",
                 "mass_normal", "mass_tangent", "approach", "max_normal_impulse")

    def __init__(self, point, depth, local_a):
        self.point = point        # world point (px)
        self.depth = depth        # how far this point is inside the other body (px; negative: a gap)
        self.local_a = local_a    # the point in A's frame, to recognise it next step
        self.normal_impulse = 0.0
        self.friction_impulse = 0.0


class ReferenceArbiter:
    """The contact between two bodies, kept from step to step: the readable version, with Vector2.

    The documented reference of the solver's formulas. The World runs Arbiter,
    the same formulas on plain floats (lesson11/bench/README.md has the times);
    tests/test_arbiter_fast.py holds the two within 1e-9 px, and
    readable_versions() runs this one.
    """

    def __init__(self, a, b):
        self.a, self.b = a, b
        self.points = []
        self.normal = Vector2(0, 1)

    def update(self, manifold):
        """Take this step's manifold, carrying over the impulses of points that persist (within MATCH_DISTANCE px)."""
        old = self.points
        self.points = []
        for point, depth in zip(manifold.points, manifold.depths):
            local_a = (point - self.a.pos).rotate_rad(-self.a.angle)
            contact = ContactPoint(point, depth, local_a)
            match = min(old, key=lambda c: c.local_a.distance_squared_to(local_a), default=None)
            if match is not None and match.local_a.distance_to(local_a) <= MATCH_DISTANCE:
                contact.normal_impulse = match.normal_impulse
                contact.friction_impulse = match.friction_impulse
            self.points.append(contact)
        self.normal = manifold.normal

    def prepare(self, world, warm_starting=True):
        """Once per step: anchors ra = p - xA, rb = p - xB (px), mass_n = 1/k(n), mass_t = 1/k(t), approach speed.

        The solve follows each point's separation as the bodies move:
        s = -depth + n·(ΔB(rb) - ΔA(ra)), from the bodies' motion since now (separation()).
        """
        a, b, n = self.a, self.b, self.normal
        tangent = Vector2(n.y, -n.x)
        spin = "rotation" in world.effects
        self.mu = math.sqrt(a.friction * b.friction) if "friction" in world.effects else 0.0
        self.restitution = min(a.restitution, b.restitution) if "restitution" in world.effects else 0.0
        for c in self.points:
            c.ra, c.rb = (c.point - a.pos, c.point - b.pos) if spin else (Vector2(), Vector2())
            c.anchors = (c.ra.x, c.ra.y, c.rb.x, c.rb.y)
            c.mass_normal = 1 / effective_mass_inverse(a, b, c.ra, c.rb, n)
            c.mass_tangent = 1 / effective_mass_inverse(a, b, c.ra, c.rb, tangent)
            c.approach = relative_velocity(a, b, c.ra, c.rb).dot(n)  # vn before this step (px/s)
            c.max_normal_impulse = 0.0
            if not warm_starting:
                c.normal_impulse = c.friction_impulse = 0.0
            if self.mu == 0:
                c.friction_impulse = 0.0

    def separation(self, c, motion):
        """Current separation (px) of point c along the normal: -depth plus how far the two anchors moved apart.

        motion[id(body)] = (dx, dy, cos Δθ, sin Δθ): how far each body moved and
        turned since prepare() (World.body_motion, one cos/sin per body per sub-step).
        The anchor r moved by d + R(Δθ) r - r.
        """
        dax, day, ca, sa = motion[id(self.a)]
        dbx, dby, cb, sb = motion[id(self.b)]
        rax, ray, rbx, rby = c.anchors
        mx = (dbx + cb * rbx - sb * rby - rbx) - (dax + ca * rax - sa * ray - rax)
        my = (dby + sb * rbx + cb * rby - rby) - (day + sa * rax + ca * ray - ray)
        return mx * self.normal.x + my * self.normal.y - c.depth

    def warm_start(self):
        """Apply the accumulated impulses again: P = Pn n + Pt t at each point."""
        n = self.normal
        tangent = Vector2(n.y, -n.x)
        for c in self.points:
            apply_impulse(self.a, self.b, n * c.normal_impulse + tangent * c.friction_impulse, c.ra, c.rb)

    def solve(self, h, soft, use_bias, motion):
        """One pass over the points: normal impulses (soft push-out if use_bias), then Coulomb friction.

        soft = (bias_rate, mass_scale, impulse_scale) from soft_constants;
        motion as in separation(). Only the change of each clamped total is
        applied, P = ΔPn n + ΔPt t at the point. Written with plain floats (the
        same formulas as response.relative_velocity and apply_impulse): this
        loop is where a tall stack spends its time.
        """
        a, b = self.a, self.b
        nx, ny = self.normal.x, self.normal.y
        tx, ty = ny, -nx
        ima, iia, imb, iib = a.inv_mass, a.inv_inertia, b.inv_mass, b.inv_inertia
        vax, vay, wa = a.vel.x, a.vel.y, a.omega
        vbx, vby, wb = b.vel.x, b.vel.y, b.omega
        bias_rate, soft_mass, soft_impulse = soft
        for c in self.points:
            rax, ray, rbx, rby = c.anchors
            s = self.separation(c, motion)
            if s > 0:
                bias, mass_scale, impulse_scale = s / h, 1.0, 0.0  # speculative: close the gap, no more
            elif use_bias:
                bias, mass_scale, impulse_scale = max(bias_rate * s, -MAX_PUSH), soft_mass, soft_impulse
            else:
                bias, mass_scale, impulse_scale = 0.0, 1.0, 0.0
            # vn = ((vB + ωB × rb) - (vA + ωA × ra))·n, with ω × r = (-ω r.y, ω r.x)
            vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny
            old = c.normal_impulse
            change = -c.mass_normal * mass_scale * (vn + bias) - impulse_scale * old
            c.normal_impulse = max(old + change, 0.0)
            c.max_normal_impulse = max(c.max_normal_impulse, c.normal_impulse - old)
            p = c.normal_impulse - old
            px, py = nx * p, ny * p
            vax -= px * ima
            vay -= py * ima
            wa -= (rax * py - ray * px) * iia
            vbx += px * imb
            vby += py * imb
            wb += (rbx * py - rby * px) * iib
        if self.mu != 0:
            for c in self.points:
                rax, ray, rbx, rby = c.anchors
                vt = (vbx - wb * rby - vax + wa * ray) * tx + (vby + wb * rbx - vay - wa * rax) * ty
                old = c.friction_impulse
                limit = self.mu * c.normal_impulse
                c.friction_impulse = max(-limit, min(limit, old - c.mass_tangent * vt))
                p = c.friction_impulse - old
                px, py = tx * p, ty * p
                vax -= px * ima
                vay -= py * ima
                wa -= (rax * py - ray * px) * iia
                vbx += px * imb
                vby += py * imb
                wb += (rbx * py - rby * px) * iib
        a.vel.update(vax, vay)
        a.omega = wa
        b.vel.update(vbx, vby)
        b.omega = wb

    def bounce(self, resting_speed):
        """Restitution, after the sub-steps: a point that approached at vn0 < -resting_speed and pushed
        gets vn = -e·vn0, by Pn <- max(Pn - mass_n (vn + e·vn0), 0)."""
        if self.restitution == 0:
            return
        a, b, n = self.a, self.b, self.normal
        for c in self.points:
            if c.approach >= -resting_speed or c.max_normal_impulse == 0:
                continue
            vn = relative_velocity(a, b, c.ra, c.rb).dot(n)
            old = c.normal_impulse
            c.normal_impulse = max(old - c.mass_normal * (vn + self.restitution * c.approach), 0.0)
            apply_impulse(a, b, n * (c.normal_impulse - old), c.ra, c.rb)


class Arbiter(ReferenceArbiter):
    """The contact between two bodies, as the World runs it: ReferenceArbiter's formulas on plain floats.

    Each line computes what the reference computes, in the same order of
    operations (Vector2's arithmetic is IEEE doubles too), so the two agree to
    the last bit; only the Vector2 objects and calls are gone from the loops.
    The bodies do not move between the passes of one sub-step, so what each
    point's passes read (separation, bias, scaled mass) is worked out once per
    sub-step (pass_groups), and solve_passes runs every contact's passes (after
    warm_start_floats) on the bodies' velocities as plain lists (World.step_accumulated).
    solve and bounce are the reference's (bounce with the anchors made Vector2
    where it reads them; warm_start, which reads them at every point, is not
    called after the float prepare). Inside readable_versions() every method runs the reference's.
    """
    def update(self, manifold):
        if collision.READABLE:
            return super().update(manifold)
        old = self.points
        self.points = []
        pos, turn = self.a.pos, -self.a.angle
        new_point = ContactPoint.__new__
        for point, depth in zip(manifold.points, manifold.depths):
            local_a = (point - pos).rotate_rad(turn)  # pygame's rotation, as the reference (exact quarter turns)
            contact = new_point(ContactPoint)  # ContactPoint(point, depth, local_a), its __init__ written out
            contact.point, contact.depth, contact.local_a = point, depth, local_a
            contact.normal_impulse = contact.friction_impulse = 0.0
            lx, ly = contact.local_xy = local_a.x, local_a.y  # local_a's floats, for the next step's matching
            nearest, match = math.inf, None
            for c in old:  # the first nearest, as min() picks it
                ox, oy = c.local_xy
                dx, dy = ox - lx, oy - ly
                distance_squared = dx * dx + dy * dy
                if distance_squared < nearest:
                    nearest, match = distance_squared, c
            if match is not None and math.sqrt(nearest) <= MATCH_DISTANCE:
                contact.normal_impulse = match.normal_impulse
                contact.friction_impulse = match.friction_impulse
            self.points.append(contact)
        self.normal = manifold.normal

    def prepare(self, world, warm_starting=True):
        if collision.READABLE:
            return super().prepare(world, warm_starting)
        a, b = self.a, self.b
        nx, ny = self.normal
        tx, ty = ny, -nx
        effects = world.effects
        spin = "rotation" in effects
        self.mu = math.sqrt(a.friction * b.friction) if "friction" in effects else 0.0
        self.restitution = min(a.restitution, b.restitution) if "restitution" in effects else 0.0
        ima, iia, imb, iib = a.inv_mass, a.inv_inertia, b.inv_mass, b.inv_inertia
        (apx, apy), (bpx, bpy), (vax, vay), (vbx, vby) = a.pos, b.pos, a.vel, b.vel
        wa, wb = a.omega, b.omega
        self.anchored = False
        for c in self.points:
            if spin:
                px, py = c.point
                rax, ray, rbx, rby = px - apx, py - apy, px - bpx, py - bpy
            else:
                rax = ray = rbx = rby = 0.0
            c.anchors = (rax, ray, rbx, rby)
            c.ra = None  # ra and rb as Vector2: made by bounce() for the points it uses them at
            # 1 / k for n and t, k = 1/mA + 1/mB + (ra × d)² / IA + (rb × d)² / IB (effective_mass_inverse)
            an, bn, at, bt = rax * ny - ray * nx, rbx * ny - rby * nx, rax * ty - ray * tx, rbx * ty - rby * tx
            c.mass_normal = 1 / (ima + imb + an * an * iia + bn * bn * iib)
            c.mass_tangent = 1 / (ima + imb + at * at * iia + bt * bt * iib)
            # vn before this step: ((vB + ωB × rb) - (vA + ωA × ra))·n, as relative_velocity adds it up
            c.approach = ((vbx + -wb * rby) - (vax + -wa * ray)) * nx + ((vby + wb * rbx) - (vay + wa * rax)) * ny
            c.max_normal_impulse = 0.0
            if not warm_starting:
                c.normal_impulse = c.friction_impulse = 0.0
            if self.mu == 0:
                c.friction_impulse = 0.0

    anchored = True  # False after the float prepare until bounce has made the Vector2 anchors it reads

    def bounce(self, resting_speed):
        if not self.anchored and self.restitution != 0:
            self.anchored = True  # which points bounce does not change between its passes
            for c in self.points:  # the anchors as Vector2 where the reference's bounce reads them
                if c.ra is None and c.approach < -resting_speed and c.max_normal_impulse != 0:
                    rax, ray, rbx, rby = c.anchors
                    c.ra, c.rb = Vector2(rax, ray), Vector2(rbx, rby)
        super().bounce(resting_speed)

    def bounces(self, resting_speed):
        """Whether bounce() changes anything: restitution, and a point that approached faster than resting_speed
        and pushed (what bounce reads of them does not change between its passes)."""
        if self.restitution != 0:
            for c in self.points:
                if c.approach < -resting_speed and c.max_normal_impulse != 0:
                    return True
        return False


def pass_groups(contacts, motion, h, soft, use_bias):
    """What solve_passes reads of each contact for one sub-step's passes, [(ka, kb, nx, ny, 1/mA, 1/IA, 1/mB, 1/IB,
    μ, rows), ...] for contacts = [(ka, kb, arbiter), ...] (ka and kb: A's and B's places in solve_passes' lists
    and in motion, a list of each body's (dx, dy, cos Δθ, sin Δθ) as ReferenceArbiter.separation reads it).

    rows has, per point, (point, rax, ray, rbx, rby, bias px/s, -mass_n × the mass scale, the impulse scale,
    mass_t), from the separation s as separation() works it out and the bias solve() picks for it (the bodies
    do not move between the passes of a sub-step).
    """
    bias_rate, soft_mass, soft_impulse = soft
    groups = []
    for ka, kb, arbiter in contacts:
        a, b = arbiter.a, arbiter.b
        nx, ny = arbiter.normal
        dax, day, ca, sa = motion[ka]
        dbx, dby, cb, sb = motion[kb]
        rows = []
        for c in arbiter.points:
            rax, ray, rbx, rby = c.anchors
            mx = (dbx + cb * rbx - sb * rby - rbx) - (dax + ca * rax - sa * ray - rax)
            my = (dby + sb * rbx + cb * rby - rby) - (day + sa * rax + ca * ray - ray)
            s = mx * nx + my * ny - c.depth
            if s > 0:
                bias, mass_scale, impulse_scale = s / h, 1.0, 0.0  # speculative: close the gap, no more
            elif use_bias:
                bias = bias_rate * s
                if -MAX_PUSH > bias:  # max(bias_rate s, -MAX_PUSH), compared as max() compares
                    bias = -MAX_PUSH
                mass_scale, impulse_scale = soft_mass, soft_impulse
            else:
                bias, mass_scale, impulse_scale = 0.0, 1.0, 0.0
            rows.append((c, rax, ray, rbx, rby, bias, -c.mass_normal * mass_scale, impulse_scale, c.mass_tangent))
        groups.append((ka, kb, nx, ny, a.inv_mass, a.inv_inertia, b.inv_mass, b.inv_inertia, arbiter.mu, rows))
    return groups


def warm_start_floats(groups, vx, vy, w):
    """ReferenceArbiter.warm_start for every contact on plain floats (lists as in solve_passes): P = Pn n + Pt t
    applied at each point as response.apply_impulse applies it, the same floats."""
    for ka, kb, nx, ny, ima, iia, imb, iib, _, rows in groups:
        for c, rax, ray, rbx, rby, *_ in rows:
            normal, friction = c.normal_impulse, c.friction_impulse
            px, py = nx * normal + ny * friction, ny * normal + -nx * friction  # tangent t = (n.y, -n.x)
            vx[ka] -= px * ima
            vy[ka] -= py * ima
            w[ka] -= (rax * py - ray * px) * iia  # cross(ra, P)
            vx[kb] += px * imb
            vy[kb] += py * imb
            w[kb] += (rbx * py - rby * px) * iib


def solve_passes(groups, vx, vy, w, passes):
    """ReferenceArbiter.solve for every contact, `passes` times over, on plain floats: the same impulses and velocities.

    groups: pass_groups' answer, in the World's order; vx, vy, w: every
    body's velocity (px/s) and spin (rad/s) as lists, read and written in place
    (the World copies them from the bodies and back: between two contacts'
    solves a body's velocity is the same float either way). Each line computes
    what ReferenceArbiter.solve computes, in the same order.
    """
    for _ in range(passes):
        for ka, kb, nx, ny, ima, iia, imb, iib, mu, rows in groups:
            vax = vx[ka]  # one statement each: a six-name assignment would build and unpack a tuple
            vay = vy[ka]
            wa = w[ka]
            vbx = vx[kb]
            vby = vy[kb]
            wb = w[kb]
            for c, rax, ray, rbx, rby, bias, scaled_mass, impulse_scale, _ in rows:
                vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny
                old = c.normal_impulse
                new = old + (scaled_mass * (vn + bias) - impulse_scale * old)
                if 0.0 > new:  # max(new, 0.0)
                    new = 0.0
                c.normal_impulse = new
                p = new - old
                if p > c.max_normal_impulse:
                    c.max_normal_impulse = p
                px, py = nx * p, ny * p
                vax -= px * ima
                vay -= py * ima
                wa -= (rax * py - ray * px) * iia
                vbx += px * imb
                vby += py * imb
                wb += (rbx * py - rby * px) * iib
            if mu != 0:
                tx, ty = ny, -nx
                for c, rax, ray, rbx, rby, _, _, _, mass_tangent in rows:
                    vt = (vbx - wb * rby - vax + wa * ray) * tx + (vby + wb * rbx - vay - wa * rax) * ty
                    old = c.friction_impulse
                    limit = mu * c.normal_impulse
                    new = old - mass_tangent * vt
                    if not new < limit:  # clamp(new, -limit, limit), as max(-limit, min(limit, new)) picks
                        new = limit
                    if not new > -limit:
                        new = -limit
                    c.friction_impulse = new
                    p = new - old
                    px, py = tx * p, ty * p
                    vax -= px * ima
                    vay -= py * ima
                    wa -= (rax * py - ray * px) * iia
                    vbx += px * imb
                    vby += py * imb
                    wb += (rbx * py - rby * px) * iib
            vx[ka] = vax
            vy[ka] = vay
            w[ka] = wa
            vx[kb] = vbx
            vy[kb] = vby
            w[kb] = wb


@contextlib.contextmanager
def readable_versions():
    """Inside the block, the reference solver runs its readable versions: ReferenceArbiter's methods,
    collision's sat, corner_manifold_reference / clip_manifold_reference, World.readable_substeps, and
    collision.fast_paths(False) (the test and the bench compare them with the float versions).

    A world keeps one version for all its steps: the float Arbiter keeps what its passes read between them.
    """
    before = collision.READABLE
    collision.READABLE = True
    try:
        with collision.fast_paths(False):
            yield
    finally:
        collision.READABLE = before
