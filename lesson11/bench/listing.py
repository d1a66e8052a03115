"""The lesson's example solver, as a module the benchmark can run on any pile of crates.

Lesson 11's Tumbling Crates listing carries its own little physics engine:
a `step_world` that moves every body, then makes ITERATIONS passes in which it
recomputes every body's corners and bounding box, tests every pair with SAT,
and at each contact point applies a normal impulse (restitution) and a
clamped friction impulse, then pushes the pair apart. This module does the
same thing, in the same order, with the same numbers (1/120 s, 6 passes,
slop 0.5 px, 40 % push-out, no bounce below 30 px/s), in plain Python with
pygame's Vector2 and FRect, so its time is the listing's own time.

It does not use lesson11.physics2d: the point is to measure the listing, not
the library. Differences from physics2d's World in behaviour, all of them the
listing's:
  - the order is "move first" (gravity, move, then the passes), one step per
    1/120 s, no sub-steps (World's default lesson solver runs 4 sub-steps);
  - corners and boxes are computed once per pass, so a body pushed by one
    pair is tested against the next pair at its old corners;
  - every pair of boxes is tested (all pairs, only static-static skipped).

Units: px, s, rad; y grows downward; a positive angle turns clockwise on screen.

    bodies = from_snapshot(snapshot)      # snapshot: see speed.py's Snapshot
    step_world(bodies, STEP)
"""
import math

import pygame
from pygame import Vector2

GRAVITY = Vector2(0, 980)  # px/s², y down
STEP = 1 / 120             # s, the fixed step
ITERATIONS = 6             # passes over every pair per step
SLOP = 0.5                 # px of overlap the push-out leaves alone
PERCENT = 0.4              # share of the rest of the overlap pushed out per pass
RESTING_SPEED = 30         # px/s: impacts slower than this do not bounce
INSIDE_TOLERANCE = 1e-9    # the corner test's allowance for round-off


# ---------------------------------------------------------------- small vector helpers

def cross(u, v):
    """The z part of the 3-D cross product of two plane vectors: u.x v.y - u.y v.x."""
    return u.x * v.y - u.y * v.x


def point_velocity_from_spin(omega, offset):
    """Velocity (px/s) that a spin omega (rad/s) gives a point `offset` px from the centre: ω × r."""
    return Vector2(-omega * offset.y, omega * offset.x)


def box_points(width, height):
    """The four corners of a width × height box around (0, 0), clockwise on screen."""
    half_w, half_h = width / 2, height / 2
    return [Vector2(-half_w, -half_h), Vector2(half_w, -half_h), Vector2(half_w, half_h), Vector2(-half_w, half_h)]


def polygon_inertia(points, mass):
    """Moment of inertia (mass·px²) of a convex polygon of `mass` about (0, 0), from its triangles' fan."""
    weighted = total = 0.0
    count = len(points)
    for index in range(count):
        p, q = points[index], points[(index + 1) % count]
        twice_area = abs(cross(p, q))
        weighted += twice_area * (p.dot(p) + p.dot(q) + q.dot(q))
        total += twice_area
    return mass * weighted / (6 * total)


# ---------------------------------------------------------------- bodies

class Crate:
    """A convex polygon body: local corners, position, velocity, angle, spin and its material.

    mass 0 means static: both inverse masses are 0, so nothing moves or turns it.
    """

    def __init__(self, points, pos, mass, angle=0.0, vel=(0, 0), omega=0.0, restitution=0.2, friction=0.6):
        self.local = [Vector2(p) for p in points]
        self.pos = Vector2(pos)
        self.vel = Vector2(vel)
        self.angle = float(angle)
        self.omega = float(omega)
        self.restitution = restitution
        self.friction = friction
        if mass == 0:
            self.inv_mass = 0.0
            self.inv_inertia = 0.0
        else:
            self.inv_mass = 1 / mass
            self.inv_inertia = 1 / polygon_inertia(self.local, mass)

    def world_points(self):
        """The corners in world px: each local corner turned by the angle, then moved to pos."""
        return [self.pos + corner.rotate_rad(self.angle) for corner in self.local]


def from_snapshot(snapshot):
    """Fresh Crates from a snapshot's bodies (dicts with points, pos, vel, angle, omega, mass, restitution,
    friction): the same starting state as every other engine of the benchmark."""
    return [Crate(b["points"], b["pos"], b["mass"], b["angle"], b["vel"], b["omega"], b["restitution"],
                  b["friction"]) for b in snapshot]


# ---------------------------------------------------------------- collision detection

def edge_normals(points):
    """Unit normals of the polygon's edges (zero-length edges skipped)."""
    normals = []
    count = len(points)
    for index in range(count):
        edge = points[(index + 1) % count] - points[index]
        if edge.length_squared() > 0:
            normals.append(Vector2(-edge.y, edge.x).normalize())
    return normals


def project(points, axis):
    """The polygon's shadow on `axis`: (smallest, largest) dot product of its corners."""
    shadow = [point.dot(axis) for point in points]
    return min(shadow), max(shadow)


def sat(pa, pb):
    """Separating Axis Test of two convex polygons (world corners).

    None when some edge normal of either polygon shows a gap; otherwise
    (normal, depth): the axis of least overlap, turned to point from A's
    centre towards B's, and that overlap in px.
    """
    best_axis, best_depth = None, math.inf
    for axis in edge_normals(pa) + edge_normals(pb):
        low_a, high_a = project(pa, axis)
        low_b, high_b = project(pb, axis)
        overlap = min(high_a, high_b) - max(low_a, low_b)
        if overlap <= 0:
            return None
        if overlap < best_depth:
            best_axis, best_depth = axis, overlap
    centre_a = sum(pa, Vector2()) / len(pa)
    centre_b = sum(pb, Vector2()) / len(pb)
    if (centre_b - centre_a).dot(best_axis) < 0:
        best_axis = -best_axis
    return best_axis, best_depth


def inside(point, points):
    """True when `point` is inside the convex polygon or on its edge (the same side of every edge)."""
    count = len(points)
    sides = [cross(points[(k + 1) % count] - points[k], point - points[k]) for k in range(count)]
    return all(s >= -INSIDE_TOLERANCE for s in sides) or all(s <= INSIDE_TOLERANCE for s in sides)


def contact_points(pa, pb, normal):
    """The lesson's "corners inside" rule: A's corners inside B, then B's inside A, at most two.

    With none (edges crossing, no corner in), B's corner furthest against the normal stands in.
    """
    found = [p for p in pa if inside(p, pb)] + [p for p in pb if inside(p, pa)]
    if not found:
        found = [min(pb, key=lambda p: p.dot(normal))]
    return found[:2]


def bounding_box(points):
    """The axis-aligned box around the corners, a pygame.FRect.

    Written as the listing writes it: the left and top edges are found again
    for the width and height, so this costs what the listing's does.
    """
    return pygame.FRect(min(p.x for p in points), min(p.y for p in points),
                        max(p.x for p in points) - min(p.x for p in points),
                        max(p.y for p in points) - min(p.y for p in points))


# ---------------------------------------------------------------- collision response

def apply_impulse(a, b, impulse, ra, rb):
    """Impulse (mass·px/s) on B at offset rb and its opposite on A at ra: velocities and spins change."""
    a.vel -= impulse * a.inv_mass
    a.omega -= cross(ra, impulse) * a.inv_inertia
    b.vel += impulse * b.inv_mass
    b.omega += cross(rb, impulse) * b.inv_inertia


def resolve(a, b, normal, point):
    """One contact point: a normal impulse (bouncing only above RESTING_SPEED), then Coulomb friction.

    Nothing happens when the points already separate along the normal. The
    friction impulse is the one that would stop the sliding, clamped to μ
    times the normal impulse, μ = √(μA μB); restitution is min(eA, eB).
    """
    ra = point - a.pos
    rb = point - b.pos
    # velocity of B's contact point relative to A's, spin included (written out, as the listing does)
    rel = (b.vel + point_velocity_from_spin(b.omega, rb)) - (a.vel + point_velocity_from_spin(a.omega, ra))
    approach = rel.dot(normal)
    if approach >= 0:
        return
    ra_n, rb_n = cross(ra, normal), cross(rb, normal)
    mass_term = a.inv_mass + b.inv_mass + ra_n * ra_n * a.inv_inertia + rb_n * rb_n * b.inv_inertia
    bounce = min(a.restitution, b.restitution) if approach < -RESTING_SPEED else 0.0
    j = -(1 + bounce) * approach / mass_term
    apply_impulse(a, b, normal * j, ra, rb)

    slide = (b.vel + point_velocity_from_spin(b.omega, rb)) - (a.vel + point_velocity_from_spin(a.omega, ra))
    tangent = slide - normal * slide.dot(normal)
    if tangent.length_squared() <= 1e-12:
        return
    t = tangent.normalize()
    ra_t, rb_t = cross(ra, t), cross(rb, t)
    tangent_term = a.inv_mass + b.inv_mass + ra_t * ra_t * a.inv_inertia + rb_t * rb_t * b.inv_inertia
    jt = -slide.dot(t) / tangent_term
    mu = math.sqrt(a.friction * b.friction)
    jt = max(-mu * j, min(mu * j, jt))
    apply_impulse(a, b, t * jt, ra, rb)


def separate(a, b, normal, depth):
    """Push the pair apart along the normal by PERCENT of the overlap beyond SLOP, shared by inverse mass."""
    shares = a.inv_mass + b.inv_mass
    if shares <= 0:
        return
    push = max(depth - SLOP, 0) * PERCENT / shares
    a.pos -= normal * (push * a.inv_mass)
    b.pos += normal * (push * b.inv_mass)


# ---------------------------------------------------------------- the step

def step_world(bodies, dt=STEP, contacts=None):
    """One fixed step: gravity and motion for every dynamic body, then ITERATIONS passes over all pairs.

    Each pass recomputes every body's corners and box once, then for every pair
    (static-static skipped) whose boxes overlap and whose SAT finds a hit:
    resolve() at each contact point, then separate(). With a `contacts` list,
    it holds (point, normal) of the last pass's contacts afterwards.
    """
    for body in bodies:
        if body.inv_mass > 0:
            body.vel += GRAVITY * dt
            body.pos += body.vel * dt
            body.angle += body.omega * dt
    count = len(bodies)
    for _ in range(ITERATIONS):
        if contacts is not None:
            contacts.clear()
        corners = [body.world_points() for body in bodies]
        boxes = [bounding_box(points) for points in corners]
        for i in range(count):
            for j in range(i + 1, count):
                a, b = bodies[i], bodies[j]
                if a.inv_mass == 0 and b.inv_mass == 0:
                    continue
                if not boxes[i].colliderect(boxes[j]):
                    continue
                hit = sat(corners[i], corners[j])
                if hit is None:
                    continue
                normal, depth = hit
                for point in contact_points(corners[i], corners[j], normal):
                    resolve(a, b, normal, point)
                    if contacts is not None:
                        contacts.append((point, normal))
                separate(a, b, normal, depth)
