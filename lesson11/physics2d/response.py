"""Collision response: impulses that change velocity and spin, friction, and the push-out.

Notation (as in the lesson): ra and rb are the offsets (px) from each body's
centre to the contact point, n the unit normal from A to B, and a body's
"inverse mass" 1/m and "inverse inertia" 1/I are 0 for static bodies.
"""
import math

from . import vectors
from .vectors import Vector2, cross, spin_velocity

RESTING_SPEED = 30.0  # px/s: slower impacts get e = 0, so resting bodies do not bounce
SLOP = 0.5            # px of overlap the push-out tolerates
PERCENT = 0.4         # share of the remaining overlap removed per push
_INF = math.inf


def apply_impulse(a, b, impulse, ra, rb):
    """Equal and opposite impulse P (mass·px/s) at the contact: A gets -P, B gets +P.

        vA -= P / mA        ωA -= (ra × P) / IA
        vB += P / mB        ωB += (rb × P) / IB
    """
    a.vel -= impulse * a.inv_mass
    a.omega -= cross(ra, impulse) * a.inv_inertia
    b.vel += impulse * b.inv_mass
    b.omega += cross(rb, impulse) * b.inv_inertia


def relative_velocity(a, b, ra, rb):
    """Velocity of B's contact point relative to A's (px/s): (vB + ωB × rb) - (vA + ωA × ra)."""
    return (b.vel + spin_velocity(b.omega, rb)) - (a.vel + spin_velocity(a.omega, ra))


def effective_mass_inverse(a, b, ra, rb, direction):
    """k = 1/mA + 1/mB + (ra × d)² / IA + (rb × d)² / IB for a unit direction d (normal or tangent)."""
    rad, rbd = cross(ra, direction), cross(rb, direction)
    return a.inv_mass + b.inv_mass + rad * rad * a.inv_inertia + rbd * rbd * b.inv_inertia


def resolve(a, b, normal, point, resting_speed=RESTING_SPEED, friction=True, restitution=True,
            spin=True):
    """Normal impulse with restitution, then Coulomb friction, at one contact point (world px).

    Normal: with vn = rel·n < 0 (closing),
        j = -(1 + e) vn / k,  e = min(eA, eB), or 0 if |vn| <= resting_speed.
    Friction along the sliding direction t:
        jt = -rel·t / kt, clamped to [-μ j, μ j] with μ = √(μA μB).
    Both go through apply_impulse. The switches turn effects off for scenes that
    do not need them: spin=False treats the contact as if at the centres (no
    turning), friction=False skips the tangent impulse, restitution=False uses e = 0.
    Returns the normal impulse j (0 if the points were separating).
    """
    ra, rb = (point - a.pos, point - b.pos) if spin else (Vector2(), Vector2())
    rel = relative_velocity(a, b, ra, rb)
    vn = rel.dot(normal)
    if vn >= 0:
        return 0.0  # already separating: nothing to do
    k = effective_mass_inverse(a, b, ra, rb, normal)
    if k == 0:
        return 0.0  # two static bodies
    e = min(a.restitution, b.restitution) if restitution and vn < -resting_speed else 0.0
    j = -(1 + e) * vn / k
    apply_impulse(a, b, normal * j, ra, rb)
    if friction:
        rel = relative_velocity(a, b, ra, rb)
        tangent = rel - normal * rel.dot(normal)
        if tangent.length_squared() > 1e-12:
            t = tangent.normalize()
            kt = effective_mass_inverse(a, b, ra, rb, t)
            jt = -rel.dot(t) / kt  # the impulse that would stop the sliding
            mu = math.sqrt(a.friction * b.friction)
            jt = max(-mu * j, min(mu * j, jt))  # Coulomb: |friction| <= mu * normal impulse
            apply_impulse(a, b, t * jt, ra, rb)
    return j


def separate(a, b, normal, depth, slop=SLOP, percent=PERCENT):
    """Push overlapping bodies apart along the normal (A→B), split by inverse mass.

        push = max(depth - slop, 0) * percent / (1/mA + 1/mB)
        posA -= n * push / mA,   posB += n * push / mB
    A static body (1/m = 0) never moves; a light body moves more than a heavy
    one. slop=0, percent=1 removes the whole overlap at once.
    (separate_reference is the readable form: it always does the two moves.)
    """
    total = a.inv_mass + b.inv_mass
    if total > 0:
        push = max(depth - slop, 0.0) * percent / total
        if push == 0.0 and vectors.FAST_PATHS and _moves_nothing(a.pos, b.pos, normal):
            return  # a resting contact (depth <= slop): pos -/+ n * 0 would be pos itself
        a.pos -= normal * (push * a.inv_mass)
        b.pos += normal * (push * b.inv_mass)


def _moves_nothing(pos_a, pos_b, normal):
    """True if pos -/+ normal * (±0.0) leaves both positions as they are, bit for bit.

    It does unless the normal is not a finite Vector2 (n * 0 is NaN, or a tuple
    raises), or a coordinate is ±0.0 (-0.0 - 0.0 and 0.0 + -0.0 flip the sign of zero).
    """
    return (type(normal) is Vector2 and -_INF < normal.x < _INF and -_INF < normal.y < _INF
            and pos_a.x != 0.0 and pos_a.y != 0.0 and pos_b.x != 0.0 and pos_b.y != 0.0)


def separate_reference(a, b, normal, depth, slop=SLOP, percent=PERCENT):
    """The readable separate: push = max(depth - slop, 0) percent / (1/mA + 1/mB), both bodies moved."""
    total = a.inv_mass + b.inv_mass
    if total > 0:
        push = max(depth - slop, 0.0) * percent / total
        a.pos -= normal * (push * a.inv_mass)
        b.pos += normal * (push * b.inv_mass)
