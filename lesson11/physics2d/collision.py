"""Collision detection: is there an overlap, along which normal, how deep, and where?

Every test here works on world-space points (lists of Vector2, px). Each
answer that has a direction gives the normal pointing from A to B, so that
moving B by normal * depth (or A by the opposite) separates the pair.

Exact touching counts as apart: an overlap of at most TOUCH_TOLERANCE px is
reported as no contact, so a pair pushed out by exactly its depth stays apart
despite rounding.
"""
import contextlib
import math
from collections import namedtuple
from math import sqrt
from operator import itemgetter

from . import vectors
from .shapes import WorldPoints
from .vectors import Vector2

TOUCH_TOLERANCE = 1e-6  # px: overlaps this small are "touching", i.e. apart
CORNER_MERGE = 0.5      # px: corners closer than this are one contact point (corner_manifold)
SAME_POINT = Vector2().epsilon  # px: pygame's Vector2 == counts points this close on both axes as one (1e-6)
READABLE = False        # True: corner_manifold, clip_manifold and the reference solver (its Arbiter, its
                        # float contact search and sub-steps in world.py) run their readable Vector2 versions
                        # (arbiter.readable_versions sets it, with the fast paths off, for a block)

# Fast paths: True runs the quicker forms of project, center_of, contact_points and collide (and the World's
# contact search), which compute the same floats in the same order; False runs the readable reference forms.
# tests/test_fast_paths.py steps every lab's scene both ways and compares every float bit for bit.
FAST_PATHS = True


@contextlib.contextmanager
def fast_paths(on):
    """Run a block with the fast paths on (True) or the readable reference forms (False), here and in vectors.py."""
    old = FAST_PATHS, vectors.FAST_PATHS
    _switch(on, on)
    try:
        yield
    finally:
        _switch(*old)


def _switch(here, in_vectors):
    global FAST_PATHS
    FAST_PATHS, vectors.FAST_PATHS = here, in_vectors


def edge_normals(points):
    """Unit normals (-e.y, e.x) / |e| of each edge e = p[i+1] - p[i]; zero-length edges are skipped.

    For a body's WorldPoints (Body.world_points()) the normals are worked out
    once and kept with the points; each call returns fresh copies, so a caller
    that changes a normal in place changes only its own.
    """
    kept = isinstance(points, WorldPoints)
    known = points.normals if kept else None
    if known is None:
        known = []
        for i, a in enumerate(points):
            edge = points[(i + 1) % len(points)] - a
            if edge.length_squared() > 0:
                known.append(Vector2(-edge.y, edge.x).normalize())
        if kept:
            points.normals = known
    return list(map(Vector2, known))  # fresh copies: Vector2(normal) of each


def project(points, axis):
    """The shadow of the points on a unit axis: (min p·axis, max p·axis), in px (project_reference)."""
    if FAST_PATHS and len(points) == 4:  # a box: the reference's loop unrolled, the same comparisons in order
        p0, p1, p2, p3 = points
        lowest = highest = p0.dot(axis)
        d = p1.dot(axis)
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
        d = p2.dot(axis)
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
        d = p3.dot(axis)
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
        return lowest, highest
    return project_reference(points, axis)


def project_reference(points, axis):
    """The readable project: (min p·axis, max p·axis) over the points, in px."""
    lowest = highest = points[0].dot(axis)
    for p in points:
        d = p.dot(axis)
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
    return lowest, highest


def center_of(points):
    """Average of the points (px): the center the lesson uses to orient normals.

    For a body's WorldPoints it is worked out once and kept with the points (as
    edge_normals are); each call returns a fresh copy.
    """
    if FAST_PATHS and isinstance(points, WorldPoints):
        if points.center is None:
            points.center = sum(points, Vector2()) / len(points)
        return Vector2(points.center)
    return sum(points, Vector2()) / len(points)


centre_of = center_of  # the name the labs import (British spelling); the lesson says "center"


def sat(pa, pb, margin=0.0):
    """Separating Axis Test for two convex polygons given as world points.

    Projects both onto every edge normal of both. One axis whose shadows do not
    overlap, min(max_a, max_b) - max(min_a, min_b) <= TOUCH_TOLERANCE, means
    apart: returns None. Otherwise returns (normal, depth), the minimum
    translation vector: moving B by normal * depth separates the pair.

    On each axis B can leave forwards, by max_a - min_b, or backwards, by
    max_b - min_a; the shorter way is that axis's depth and direction. This is
    the lesson's overlap whenever neither shadow contains the other; when one
    does (a deep hit), the lesson's overlap is too short to separate the pair.
    When both ways are equally long, the normal points from A's center to B's.

    margin (px, default 0) also reports pairs less than `margin` apart, with a
    negative depth (minus the gap): the accumulated solver's speculative contacts.
    """
    best_axis, best_depth = None, math.inf
    for axis in edge_normals(pa) + edge_normals(pb):
        min_a, max_a = project(pa, axis)
        min_b, max_b = project(pb, axis)
        overlap = min(max_a, max_b) - max(min_a, min_b)
        if overlap <= TOUCH_TOLERANCE - margin:
            return None  # a gap (or exact touching): apart
        forwards, backwards = max_a - min_b, max_b - min_a
        depth = min(forwards, backwards)
        if depth < best_depth:
            if abs(forwards - backwards) <= TOUCH_TOLERANCE:
                best_axis = orient_a_to_b(axis, pa, pb)
            else:
                best_axis = axis if forwards < backwards else -axis
            best_depth = depth
    return best_axis, best_depth


def orient_a_to_b(axis, pa, pb):
    """Flip the axis if needed so it points from A's center to B's: (cB - cA)·axis >= 0.

    When the centers coincide along the axis, the middles of the two shadows
    decide; when those coincide too (the pair is symmetric), the axis is made
    to point right, or down if vertical, so the answer is still well defined.
    """
    along = (center_of(pb) - center_of(pa)).dot(axis)
    if abs(along) <= TOUCH_TOLERANCE:
        min_a, max_a = project(pa, axis)
        min_b, max_b = project(pb, axis)
        along = (min_b + max_b) - (min_a + max_a)
    if abs(along) <= TOUCH_TOLERANCE:
        along = axis.x if abs(axis.x) > TOUCH_TOLERANCE else axis.y
    return -axis if along < 0 else Vector2(axis)


def inside(point, points):
    """True if point is inside or on the outline of a convex polygon (either winding).

    For each edge a→b the signed distance cross(b - a, point - a) / |b - a|
    must have the same sign for every edge; distances within TOUCH_TOLERANCE px
    of an edge count as on it.
    """
    return inside_edges(point, polygon_edges(points))


def polygon_edges(points):
    """Each edge of the outline once, for inside_edges: [(a, b - a, TOUCH_TOLERANCE |b - a|), ...] (px, px, px²).

    For a body's WorldPoints the list is worked out once and kept with the
    points (like edge_normals); it is read-only: inside_edges only reads it.
    """
    kept = isinstance(points, WorldPoints)
    if kept and points.edges is not None:
        return points.edges
    edges = []
    for i, a in enumerate(points):
        edge = points[(i + 1) % len(points)] - a
        edges.append((a, edge, TOUCH_TOLERANCE * edge.length()))
    if kept:
        points.edges = edges
    return edges


def inside_edges(point, edges):
    """inside() with the polygon's edges worked out already (polygon_edges): test many points, edges computed once."""
    left = right = False
    for a, edge, limit in edges:
        side = edge.cross(point - a)  # Vector2.cross is the same 2D cross product as cross()
        if side > limit:
            left = True
        elif side < -limit:
            right = True
        if left and right:
            return False  # on the outer side of some edge
    return True


def closest_on_segment(p, a, b):
    """The point of segment a–b nearest to p: a + (b - a) t with t = clamp((p - a)·(b - a) / |b - a|², 0, 1)."""
    ab = b - a
    length_squared = ab.dot(ab)
    if length_squared == 0:
        return Vector2(a)  # a zero-length edge is a point
    t = max(0.0, min(1.0, (p - a).dot(ab) / length_squared))
    return a + ab * t


def circle_polygon(center, radius, points, margin=0.0):
    """Circle (center px, radius px) against a convex polygon (world points).

    Finds the closest point q on the outline. Outside and |q - center| < radius:
    normal = (q - center) / |q - center|, depth = radius - |q - center|.
    Center inside: the push goes the other way, depth = radius + |q - center|.
    Center on the outline: normal points from the center to the polygon's middle.
    Returns None when apart (touching counts as apart), else (normal from the
    circle into the polygon, depth px). A margin (px) also reports a circle up
    to `margin` outside, with a negative depth (minus the gap).
    """
    closest = min((closest_on_segment(center, points[i], points[(i + 1) % len(points)])
                   for i in range(len(points))), key=lambda q: center.distance_squared_to(q))
    offset = closest - center
    dist = offset.length()
    if dist <= TOUCH_TOLERANCE:  # center on the outline: push away from the middle
        return (center_of(points) - center).normalize(), radius
    if inside(center, points):  # center already inside: push out the other way
        return -offset / dist, radius + dist
    if dist >= radius + margin - TOUCH_TOLERANCE:
        return None
    return offset / dist, radius - dist


def circle_contact_point(center, radius, normal, depth):
    """Where a circle (center px, radius px) touches along the unit normal pointing out of it: world px.

    Halfway into the overlap, center + normal (radius - depth / 2), so the point
    lies on the circle's surface when the depth is 0. The World's default
    `circle_point` hook; a lab may hand in its own (e.g. center + normal radius).
    """
    return center + normal * (radius - depth / 2)


def circle_circle(center_a, radius_a, center_b, radius_b, margin=0.0):
    """Two circles (centers px, radii px): None if apart, else (unit normal from A to B, depth px).

    normal = (cB - cA) / |cB - cA|, depth = ra + rb - |cB - cA|; touching counts
    as apart. Coincident centers get the normal (1, 0). The World's default
    `circle_circle` hook. A margin (px) also reports circles up to `margin`
    apart, with a negative depth.
    """
    offset = center_b - center_a
    dist = offset.length()
    depth = radius_a + radius_b - dist
    if depth <= TOUCH_TOLERANCE - margin:
        return None
    normal = offset / dist if dist > TOUCH_TOLERANCE else Vector2(1, 0)
    return normal, depth


def contact_points(pa, pb, normal):
    """The lesson's contact rule: corners of A inside B, then corners of B inside A, at most two.

    If edges cross with no corner inside, the deepest corner of B along the
    normal (smallest p·normal) stands in. (contact_points_reference is the
    readable form; this one runs the same tests on plain floats.)
    """
    if not FAST_PATHS:
        return contact_points_reference(pa, pb, normal)
    corners = []
    edges_a, edges_b = flat_edges(pa), flat_edges(pb)
    for points, own, other in ((pa, edges_a, edges_b), (pb, edges_b, edges_a)):
        four = len(other) == 4
        if four:  # a box: the edge loop below unrolled (the same sides, the same comparisons)
            (a0x, a0y, e0x, e0y, l0), (a1x, a1y, e1x, e1y, l1), (a2x, a2y, e2x, e2y, l2), \
                (a3x, a3y, e3x, e3y, l3) = other
        for p, (px, py, _, _, _) in zip(points, own):  # own[i] starts at corner i: its x and y
            if four:
                side = e0x * (py - a0y) - e0y * (px - a0x)
                left, right = side > l0, side < -l0  # at most one: limits are >= 0 (or NaN: neither)
                side = e1x * (py - a1y) - e1y * (px - a1x)
                if side > l1:
                    left = True
                elif side < -l1:
                    right = True
                if left and right:
                    continue
                side = e2x * (py - a2y) - e2y * (px - a2x)
                if side > l2:
                    left = True
                elif side < -l2:
                    right = True
                if left and right:
                    continue
                side = e3x * (py - a3y) - e3y * (px - a3x)
                if side > l3:
                    left = True
                elif side < -l3:
                    right = True
                if left and right:
                    continue
            else:
                left = right = False
                for ax, ay, ex, ey, limit in other:  # inside_edges on floats: side = e × (p - a)
                    side = ex * (py - ay) - ey * (px - ax)
                    if side > limit:
                        left = True
                    elif side < -limit:
                        right = True
                    if left and right:
                        break
                if left and right:
                    continue
            for q in corners:  # p == q for Vector2: closer than SAME_POINT on both axes
                if abs(px - q.x) < SAME_POINT and abs(py - q.y) < SAME_POINT:
                    break
            else:
                corners.append(p)
                if len(corners) == 2:
                    return corners  # the reference keeps the first two as well
    if not corners:
        corners = [min(pb, key=lambda p: p.dot(normal))]
    return corners


def flat_edges(points):
    """polygon_edges as plain floats: [(a.x, a.y, e.x, e.y, TOUCH_TOLERANCE |e|), ...], e = b - a (px).

    Kept with a body's WorldPoints once worked out; |e| is sqrt(e.x² + e.y²), as Vector2.length computes it.
    """
    kept = isinstance(points, WorldPoints)
    if kept and points.flat_edges is not None:
        return points.flat_edges
    if len(points) == 4:  # a box: the loop below unrolled, the same floats
        (ax, ay), (bx, by), (cx, cy), (dx, dy) = points
        e0x, e0y, e1x, e1y, e2x, e2y, e3x, e3y = bx - ax, by - ay, cx - bx, cy - by, dx - cx, dy - cy, ax - dx, ay - dy
        edges = [(ax, ay, e0x, e0y, TOUCH_TOLERANCE * sqrt(e0x * e0x + e0y * e0y)),
                 (bx, by, e1x, e1y, TOUCH_TOLERANCE * sqrt(e1x * e1x + e1y * e1y)),
                 (cx, cy, e2x, e2y, TOUCH_TOLERANCE * sqrt(e2x * e2x + e2y * e2y)),
                 (dx, dy, e3x, e3y, TOUCH_TOLERANCE * sqrt(e3x * e3x + e3y * e3y))]
        if kept:
            points.flat_edges = edges
        return edges
    coords = [(p.x, p.y) for p in points]
    edges = []
    for (ax, ay), (bx, by) in zip(coords, coords[1:] + coords[:1]):
        ex, ey = bx - ax, by - ay
        edges.append((ax, ay, ex, ey, TOUCH_TOLERANCE * sqrt(ex * ex + ey * ey)))
    if kept:
        points.flat_edges = edges
    return edges


def contact_points_reference(pa, pb, normal):
    """The readable contact_points: every corner tested with inside_edges, Vector2 throughout."""
    corners = []
    edges_a, edges_b = polygon_edges(pa), polygon_edges(pb)
    for p in [p for p in pa if inside_edges(p, edges_b)] + [p for p in pb if inside_edges(p, edges_a)]:
        if p not in corners:  # a repeated corner is one contact, not two
            corners.append(p)
    if not corners:
        corners = [min(pb, key=lambda p: p.dot(normal))]
    return corners[:2]


def _best_edge(points, direction):
    """The edge (v1, v2) whose outward face looks most along `direction`, and its farthest corner."""
    points = [p for i, p in enumerate(points) if p != points[i - 1]] or points[:1]  # no zero-length edges
    n = len(points)
    i = max(range(n), key=lambda k: points[k].dot(direction))
    v, before, after = points[i], points[i - 1], points[(i + 1) % n]
    to_before = v - before
    to_after = v - after
    if to_before.length_squared() > 0 and to_after.length_squared() > 0 and \
            abs(to_before.normalize().dot(direction)) <= abs(to_after.normalize().dot(direction)):
        return before, v, v
    return v, after, v


def _clip(v1, v2, direction, offset):
    """Keep the part of segment v1–v2 where p·direction >= offset (Sutherland–Hodgman, one plane)."""
    d1, d2 = v1.dot(direction) - offset, v2.dot(direction) - offset
    kept = [p for p, d in ((v1, d1), (v2, d2)) if d >= 0]
    if d1 * d2 < 0:
        kept.append(v1 + (v2 - v1) * (d1 / (d1 - d2)))
    return kept


def clip_manifold_reference(pa, pb, normal, margin=0.0):
    """Contact points by edge clipping, each with its own depth: [(point, depth px), ...], up to two.

    The reference edge is the face most perpendicular to the normal (of A along
    +normal or of B along -normal); the other shape's facing edge (incident) is
    clipped to the reference edge's side planes, and points behind the
    reference face are kept, with depth = how far behind the face they are.
    Falls back to the corners rule (with the pair's depth) if clipping keeps nothing.
    With a margin (px), points up to `margin` in front of the face are kept too, with negative depth.
    The readable reference of clip_manifold (which the World runs).
    """
    a1, a2, a_far = _best_edge(pa, normal)
    b1, b2, b_far = _best_edge(pb, -normal)
    if abs((a2 - a1).normalize().dot(normal)) <= abs((b2 - b1).normalize().dot(normal)):
        ref1, ref2, ref_far, inc1, inc2, ref_normal = a1, a2, a_far, b1, b2, normal
    else:
        ref1, ref2, ref_far, inc1, inc2, ref_normal = b1, b2, b_far, a1, a2, -normal
    side = (ref2 - ref1).normalize()
    kept = _clip(inc1, inc2, side, side.dot(ref1))
    if len(kept) == 2:
        kept = _clip(kept[0], kept[1], -side, -side.dot(ref2))
    face = ref_normal.dot(ref_far)
    manifold = [(p, face - ref_normal.dot(p)) for p in kept if ref_normal.dot(p) <= face + TOUCH_TOLERANCE + margin]
    return manifold or _corners_fallback(pa, pb, normal, margin)


def _corners_fallback(pa, pb, normal, margin):
    """clip_manifold's answer when clipping keeps nothing: the corners rule, every point with the pair's depth."""
    hit = sat(pa, pb, margin)
    depth = hit[1] if hit is not None else 0.0
    return [(p, depth) for p in contact_points(pa, pb, normal)]


def clip_contact_points(pa, pb, normal):
    """Contact points by edge clipping, as production engines compute them (up to two): clip_manifold's points."""
    return [point for point, _ in clip_manifold(pa, pb, normal)]


def circle_toi(p1, v1, r1, p2, v2, r2, dt):
    """Time in [0, dt] (s) when two moving circles first touch, or None.

    Solves |dp + dv t| = r1 + r2 with dp = p2 - p1, dv = v2 - v1:
    a t² + b t + c = 0 with a = dv·dv, b = 2 dp·dv, c = dp·dp - (r1 + r2)²,
    and takes the earlier root t = (-b - √(b² - 4ac)) / 2a. Returns 0.0 when
    already touching.
    """
    dp, dv = p2 - p1, v2 - v1
    radius = r1 + r2
    c = dp.dot(dp) - radius * radius
    if c <= 0:
        return 0.0  # already touching
    a = dv.dot(dv)
    b = 2 * dp.dot(dv)
    disc = b * b - 4 * a * c
    if a == 0 or disc < 0:
        return None  # not moving relative to each other, or the paths miss
    t = (-b - math.sqrt(disc)) / (2 * a)  # the earlier root: first contact
    return t if 0 <= t <= dt else None


def circle_polygon_toi(center, vel, radius, points, dt):
    """Swept test of a circle moving at vel (px/s) against a still convex polygon, over dt s.

    The circle first touches either an edge face, when its center reaches the
    edge's line moved out by radius, t = (radius - (c - a)·n) / (v·n) with n the
    outward normal, or a corner, found by circle_toi against a circle of radius 0.
    Returns (t, normal from the circle into the polygon) for the earliest t in
    [0, dt], or None.
    """
    hit = circle_polygon(center, radius, points)
    if hit is not None:
        return 0.0, hit[0]
    middle = center_of(points)
    best = None
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        edge = b - a
        if edge.length_squared() == 0:
            continue
        normal = Vector2(-edge.y, edge.x).normalize()
        if (a - middle).dot(normal) < 0:
            normal = -normal  # outward
        if vel.dot(normal) < 0:  # moving towards this face
            t = (radius - (center - a).dot(normal)) / vel.dot(normal)
            foot = center + vel * t - normal * radius
            on_edge = closest_on_segment(foot, a, b).distance_to(foot) <= TOUCH_TOLERANCE * 1e3
            if 0 <= t <= dt and on_edge and (best is None or t < best[0]):
                best = (t, -normal)
        t = circle_toi(center, vel, radius, a, Vector2(), 0.0, dt)
        if t is not None and (best is None or t < best[0]):
            touch = center + vel * t
            best = (t, (a - touch).normalize())
    return best


def separation(point, points):
    """Signed distance (px) of a point outside a convex polygon: max over edges of (p - v)·n_out.

    Negative inside (minus the distance to the nearest edge line), positive
    outside (at most the true distance, which it equals in front of an edge).
    """
    return separation_faces(point, outward_faces(points))


def outward_faces(points):
    """Each edge's first corner v and outward unit normal n_out, for separation_faces: [(v, n_out), ...].

    n = (-e.y, e.x) / |e| for the edge e from v to the next corner, turned
    round if it points towards the polygon's centre; zero-length edges are skipped.
    """
    middle = centre_of(points)
    faces = []
    for i, v in enumerate(points):
        edge = points[(i + 1) % len(points)] - v
        if edge.length_squared() == 0:
            continue
        n = Vector2(-edge.y, edge.x).normalize()
        if (v - middle).dot(n) < 0:
            n = -n  # outward
        faces.append((v, n))
    return faces


def separation_faces(point, faces):
    """separation() with the polygon's faces worked out already (outward_faces): many points, faces computed once."""
    worst = -math.inf
    for v, n in faces:
        distance = (point - v).dot(n)
        if distance > worst:
            worst = distance
    return worst


def corner_manifold_reference(pa, pb, normal, margin=0.0):
    """The lesson's corners rule with a depth per corner: [(point, depth px), ...], up to two.

    A corner of A counts when it is inside B, or less than `margin` px outside
    it (separation <= margin); so does a corner of B against A. Each corner's
    depth is how far it is behind the other body's face that looks most along
    the normal (B's face towards -n for a corner of A, A's face towards +n for a
    corner of B); a corner short of that face has a negative depth (a
    speculative contact). The deepest corner is kept, then the deepest one
    more than CORNER_MERGE px away from it ACROSS the normal, |(p - q)·t| with
    t the tangent: two boxes of equal width have their corners on top of each
    other, one above the other by the overlap; those are one contact, not two
    (lesson11/bench/README.md has what measuring along the whole distance did).
    Equal depths keep the earlier corner, so rounding cannot swap the answer.
    The readable reference of corner_manifold (which the World runs).
    """
    found = []
    for corners, other, towards in ((pa, pb, -normal), (pb, pa, normal)):
        v1, v2, _ = _best_edge(other, towards)
        face = Vector2(-(v2 - v1).y, (v2 - v1).x).normalize()
        if face.dot(towards) < 0:
            face = -face  # outward
        faces = outward_faces(other)
        for p in corners:
            if separation_faces(p, faces) < margin - TOUCH_TOLERANCE:
                found.append((p, -(p - v1).dot(face)))
    found.sort(key=lambda pd: -pd[1])  # stable: ties keep their order
    kept = found[:1]
    tangent = Vector2(normal.y, -normal.x)
    for p, depth in found[1:]:
        if abs((p - kept[0][0]).dot(tangent)) > CORNER_MERGE:
            kept.append((p, depth))
            break
    return kept


# ---------------------------------------------------------------- the same manifolds on plain floats
# The World's versions of corner_manifold_reference and clip_manifold_reference: every line computes what
# the reference computes, in the same order (Vector2's arithmetic is IEEE doubles too), so the answers agree
# to the last bit; only the Vector2 objects and method calls are gone. tests/test_arbiter_fast.py holds them.

def _xy(points):
    """The points as (x, y) float pairs (px)."""
    return [(p.x, p.y) for p in points]


def _unit(x, y):
    """(x, y) / |(x, y)|, as Vector2.normalize computes it (ValueError for a zero vector, as it raises)."""
    length = math.sqrt(x * x + y * y)
    if length == 0:
        Vector2().normalize()  # raises pygame's own ValueError
    return x / length, y / length


def axes_xy(points, normals):
    """Each unit normal (nx, ny) with project() of the (x, y) pairs on it: [(nx, ny, min p·n, max p·n), ...] px,
    the same comparisons in the same order (a box's loop unrolled, as project's fast path)."""
    if len(points) != 4:
        return [(nx, ny, *_shadow_xy(points, nx, ny)) for nx, ny in normals]
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = points
    axes = []
    for ax, ay in normals:
        lowest = highest = x0 * ax + y0 * ay
        d = x1 * ax + y1 * ay
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
        d = x2 * ax + y2 * ay
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
        d = x3 * ax + y3 * ay
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
        axes.append((ax, ay, lowest, highest))
    return axes


def _shadow_xy(points, ax, ay):
    """project() on (x, y) pairs, any number of them: (min p·axis, max p·axis) px."""
    lowest = highest = points[0][0] * ax + points[0][1] * ay
    for x, y in points:
        d = x * ax + y * ay
        if d < lowest:
            lowest = d
        elif d > highest:
            highest = d
    return lowest, highest


FlatOutline = namedtuple("FlatOutline", "xy normals axes faces distinct regular")
FlatOutline.__doc__ = """A polygon's corners on plain floats, for sat_xy and corner_manifold_xy (worked out once per
body per contact search): (x, y) pairs; edge_normals' unit normals (nx, ny), zero-length edges skipped; each of
those normals with the polygon's shadow (project) on it, (nx, ny, min, max); outward_faces as (vx, vy, nx, ny);
the corners without repeats as _best_edge drops them (_distinct_xy); and `regular`: no corner dropped (so no
zero-length edge), so normals[i] is edge i's (corner i to i + 1) and _best_face can read it."""


_new_tuple = tuple.__new__  # _new_tuple(cls, values): a namedtuple cls's _make, in C


def flat_outline(points, xy=None):
    """The FlatOutline of a polygon's world corners (Vector2, px; xy: the same as (x, y) pairs, if made already),
    in one pass over the edges.

    Each normal is _unit(-e.y, e.x) written out ((-e.y)² is e.y², the same float), each face the normal
    turned outward as _outward_faces_xy turns it (about the mean of the corners, added up in order).
    """
    if xy is None:
        xy = [(p.x, p.y) for p in points]
    n = len(xy)
    if n == 4:  # a box: the mean's sums written out, and each corner's next one named
        (x0, y0), (x1, y1), (x2, y2), (x3, y3) = xy
        mx, my = ((((0.0 + x0) + x1) + x2) + x3) / 4, ((((0.0 + y0) + y1) + y2) + y3) / 4
        edges = zip(xy, (xy[1], xy[2], xy[3], xy[0]))
    else:
        mx = my = 0.0
        for x, y in xy:  # one addition after another, as sum(points, Vector2()) adds
            mx += x
            my += y
        mx, my = mx / n, my / n
        edges = zip(xy, xy[1:] + xy[:1])
    normals, faces, regular = [], [], True
    for (vx, vy), (wx, wy) in edges:  # each corner and the next
        ex, ey = wx - vx, wy - vy
        if -SAME_POINT < ex < SAME_POINT and -SAME_POINT < ey < SAME_POINT:
            regular = False  # _distinct_xy drops a corner here
        squared = ey * ey + ex * ex  # = ex² + ey² (a sum of two floats does not depend on their order)
        if squared == 0:
            continue  # a zero-length edge has no normal
        length = sqrt(squared)
        nx, ny = -ey / length, ex / length
        normals.append((nx, ny))
        faces.append((vx, vy, -nx, -ny) if (vx - mx) * nx + (vy - my) * ny < 0 else (vx, vy, nx, ny))
    return _new_tuple(FlatOutline, (xy, normals, axes_xy(xy, normals), faces, xy if regular else _distinct_xy(xy),
                                    regular))  # FlatOutline(...) without its Python-level __new__


def _best_face(outline, dx, dy):
    """_best_edge_distinct's edge on a regular FlatOutline, by index: (k, i), edge k (corner k to k + 1, normal
    normals[k]) and the farthest corner i; the same choice, from the same floats.

    Edge i's unit direction e / |e| is (n.y, -n.x) of its normal n = (-e.y, e.x) / |e| (exactly: the same
    quotients), so the two edges at the farthest corner are compared without a square root.
    """
    points, normals = outline.xy, outline.normals
    if len(points) == 4:  # a box: the loop below unrolled, the same comparisons in order
        (x0, y0), (x1, y1), (x2, y2), (x3, y3) = points
        i, top = 0, x0 * dx + y0 * dy
        along = x1 * dx + y1 * dy
        if along > top:
            i, top = 1, along
        along = x2 * dx + y2 * dy
        if along > top:
            i, top = 2, along
        if x3 * dx + y3 * dy > top:
            i = 3
    else:
        i, top = 0, points[0][0] * dx + points[0][1] * dy
        for k in range(1, len(points)):  # the first corner farthest along the direction, as max() picks it
            along = points[k][0] * dx + points[k][1] * dy
            if along > top:
                i, top = k, along
    (bx, by), (ax, ay) = normals[i - 1], normals[i]  # the edge into corner i, and the edge out of it
    if abs(by * dx + -bx * dy) <= abs(-ay * dx + ax * dy):  # |(v - before)/|..|·d| <= |(v - after)/|..|·d|
        return i - 1, i
    return i, i


def sat_xy(pa, a, pb, b, margin):
    """sat(pa, pb, margin) on plain floats, for the reference solver's speculative contacts: the same answer.

    a, b are the polygons' FlatOutlines (each one's shadow on its own normals
    worked out once per body, not once per pair; the other's shadow is projected
    axis by axis, as sat projects it); pa, pb the same corners as Vector2, used
    only where sat turns to orient_a_to_b (both ways out equally long). sat stays
    the readable reference (the students' lesson); tests/test_arbiter_fast.py
    holds the two equal.
    """
    best_x = best_y = None
    best_depth = math.inf
    limit = TOUCH_TOLERANCE - margin
    # A's normals, then B's, as sat takes them
    for axes, other, own_is_a in ((a.axes, b.xy, True), (b.axes, a.xy, False)):
        four = len(other) == 4
        if four:
            (x0, y0), (x1, y1), (x2, y2), (x3, y3) = other
        for ax, ay, own_min, own_max in axes:
            if four:  # project() of the other polygon, its box loop unrolled (the same comparisons in order)
                low = high = x0 * ax + y0 * ay
                d = x1 * ax + y1 * ay
                if d < low:
                    low = d
                elif d > high:
                    high = d
                d = x2 * ax + y2 * ay
                if d < low:
                    low = d
                elif d > high:
                    high = d
                d = x3 * ax + y3 * ay
                if d < low:
                    low = d
                elif d > high:
                    high = d
            else:
                low, high = _shadow_xy(other, ax, ay)
            if own_is_a:
                min_a, max_a = own_min, own_max
                min_b, max_b = low, high
            else:
                min_a, max_a = low, high
                min_b, max_b = own_min, own_max
            # min() and max() as conditionals: each keeps its first argument unless the second is smaller (larger)
            if (max_b if max_b < max_a else max_a) - (min_b if min_b > min_a else min_a) <= limit:
                return None  # a gap (or exact touching): apart
            forwards, backwards = max_a - min_b, max_b - min_a
            depth = backwards if backwards < forwards else forwards
            if depth < best_depth:
                if abs(forwards - backwards) <= TOUCH_TOLERANCE:
                    best_x, best_y = orient_a_to_b(Vector2(ax, ay), pa, pb)
                elif forwards < backwards:
                    best_x, best_y = ax, ay
                else:
                    best_x, best_y = -ax, -ay
                best_depth = depth
    return (None if best_x is None else Vector2(best_x, best_y)), best_depth


def _distinct_xy(points):
    """The corners _best_edge keeps: each one not equal to the corner before it (or the first, if none is)."""
    distinct, (lx, ly) = [], points[-1]
    for p in points:  # p != the corner before it, as Vector2's == compares (each coordinate within 1e-6)
        ex, ey = p[0] - lx, p[1] - ly
        if not (-SAME_POINT < ex < SAME_POINT and -SAME_POINT < ey < SAME_POINT):
            distinct.append(p)
        lx, ly = p
    return distinct or points[:1]


def _best_edge_distinct(points, dx, dy):
    """_best_edge on (x, y) pairs that _distinct_xy has kept and a direction (dx, dy): (v1, v2, the farthest
    corner)."""
    n = len(points)
    i, top = 0, points[0][0] * dx + points[0][1] * dy
    for k in range(1, n):  # the first corner farthest along the direction, as max() picks it
        along = points[k][0] * dx + points[k][1] * dy
        if along > top:
            i, top = k, along
    v, before, after = points[i], points[i - 1], points[(i + 1) % n]
    bx, by, ax, ay = v[0] - before[0], v[1] - before[1], v[0] - after[0], v[1] - after[1]
    to_before, to_after = bx * bx + by * by, ax * ax + ay * ay  # |v - before|², |v - after|²
    if to_before > 0 and to_after > 0:
        to_before, to_after = math.sqrt(to_before), math.sqrt(to_after)
        if abs(bx / to_before * dx + by / to_before * dy) <= abs(ax / to_after * dx + ay / to_after * dy):
            return before, v, v
    return v, after, v


def corner_manifold(pa, pb, normal, margin=0.0):
    """corner_manifold_reference on plain floats (the World's version): the same [(point, depth px), ...]."""
    if READABLE:
        return corner_manifold_reference(pa, pb, normal, margin)
    return corner_manifold_xy(pa, flat_outline(pa), pb, flat_outline(pb), normal, margin)


_depth = itemgetter(1)


def corner_manifold_xy(pa, a, pb, b, normal, margin):
    """corner_manifold with each polygon's FlatOutline worked out already (pa, pb: the same corners, whose
    objects the answer's points are)."""
    nx, ny = normal
    limit = margin - TOUCH_TOLERANCE
    found = []
    for corners, xy, outline, faces, dx, dy in ((pa, a.xy, b, b.faces, -nx, -ny), (pb, b.xy, a, a.faces, nx, ny)):
        within = _within_faces(corners, xy, faces, limit)
        if not within and outline.regular:
            continue  # no corner to measure from the face: skip _best_face (which has no other effect)
        if outline.regular:
            k, _ = _best_face(outline, dx, dy)
            (v1x, v1y), (fx, fy) = outline.xy[k], outline.normals[k]
        else:
            (v1x, v1y), (v2x, v2y), _ = _best_edge_distinct(outline.distinct, dx, dy)
            fx, fy = _unit(-(v2y - v1y), v2x - v1x)
        if fx * dx + fy * dy < 0:
            fx, fy = -fx, -fy  # outward
        for p, px, py in within:
            found.append((p, -((px - v1x) * fx + (py - v1y) * fy), px, py))
    found.sort(key=_depth, reverse=True)  # deepest first; stable (reverse too): ties keep their order
    if not found:
        return []
    kept = [found[0][:2]]
    kx, ky = found[0][2], found[0][3]
    for p, depth, px, py in found[1:]:
        if abs((px - kx) * ny + (py - ky) * -nx) > CORNER_MERGE:
            kept.append((p, depth))
            break
    return kept


def _within_faces(corners, xy, faces, limit):
    """[(p, px, py), ...] for each corner (p, and its (px, py) in xy) whose separation from every face
    (vx, vy, nx, ny) is less than limit px: (p - v)·n < limit, in the faces' order (a box's four unrolled)."""
    if len(faces) != 4:
        within = []
        for p, (px, py) in zip(corners, xy):
            for vx, vy, ex, ey in faces:
                if (px - vx) * ex + (py - vy) * ey >= limit:
                    break
            else:
                within.append((p, px, py))
        return within
    (ax, ay, aex, aey), (bx, by, bex, bey), (cx, cy, cex, cey), (dx, dy, dex, dey) = faces
    within = []
    for p, (px, py) in zip(corners, xy):  # a loop, not a comprehension: the faces stay fast locals, not cells
        if ((px - ax) * aex + (py - ay) * aey >= limit or (px - bx) * bex + (py - by) * bey >= limit
                or (px - cx) * cex + (py - cy) * cey >= limit or (px - dx) * dex + (py - dy) * dey >= limit):
            continue  # as the loop above breaks
        within.append((p, px, py))
    return within


def _clip_xy(v1, v2, dx, dy, offset):
    """_clip on (x, y) pairs: the part of v1–v2 where p·(dx, dy) >= offset."""
    d1, d2 = v1[0] * dx + v1[1] * dy - offset, v2[0] * dx + v2[1] * dy - offset
    kept = [p for p, d in ((v1, d1), (v2, d2)) if d >= 0]
    if d1 * d2 < 0:
        t = d1 / (d1 - d2)
        kept.append((v1[0] + (v2[0] - v1[0]) * t, v1[1] + (v2[1] - v1[1]) * t))
    return kept


def clip_manifold(pa, pb, normal, margin=0.0):
    """clip_manifold_reference on plain floats (the World's version): the same [(point, depth px), ...]."""
    if READABLE:
        return clip_manifold_reference(pa, pb, normal, margin)
    return clip_manifold_xy(pa, _distinct_xy(_xy(pa)), pb, _distinct_xy(_xy(pb)), normal, margin)


def clip_manifold_xy(pa, distinct_a, pb, distinct_b, normal, margin):
    """clip_manifold with each polygon's corners as (x, y) pairs that _distinct_xy has kept (a FlatOutline's
    `distinct`); pa, pb the same polygons as Vector2, for the rare fallback to the corners rule."""
    nx, ny = normal
    return (_clip_edges(normal, margin, _clip_edge(distinct_a, nx, ny), _clip_edge(distinct_b, -nx, -ny))
            or _corners_fallback(pa, pb, normal, margin))


def clip_manifold_outlines(pa, a, pb, b, normal, depth, margin):
    """clip_manifold_xy with each polygon's FlatOutline, and the pair's depth from sat(pa, pb, margin) (sat_xy's):
    a regular outline's edge and its unit direction are read off its corners and normals (_best_face), without
    the square roots, and the fallback to the corners rule takes the depth given (_corners_fallback would work
    it out again); the same floats."""
    nx, ny = normal
    return (_clip_edges(normal, margin, _outline_edge(a, nx, ny), _outline_edge(b, -nx, -ny))
            or [(p, depth) for p in contact_points(pa, pb, normal)])


def _clip_edge(distinct, dx, dy):
    """_best_edge_distinct's (v1, v2, farthest corner) with the edge's unit direction (v2 - v1) / |v2 - v1|."""
    v1, v2, far = _best_edge_distinct(distinct, dx, dy)
    return v1, v2, far, _unit(v2[0] - v1[0], v2[1] - v1[1])


def _outline_edge(outline, dx, dy):
    """_clip_edge(outline.distinct, dx, dy) of a FlatOutline; for a regular one, the unit direction of edge k is
    (n.y, -n.x) of its normal n (the same quotients as _unit's, as _best_face says)."""
    if not outline.regular:
        return _clip_edge(outline.distinct, dx, dy)
    k, i = _best_face(outline, dx, dy)
    points, (ex, ey) = outline.xy, outline.normals[k]
    return points[k], points[k + 1 - len(points)], points[i], (ey, -ex)  # k + 1 - n: corner k + 1, from the end


def _clip_edges(normal, margin, a_edge, b_edge):
    """clip_manifold_xy's clipping, from each polygon's best edge (v1, v2, farthest corner, unit v1 → v2): the
    points kept, [(point, depth px), ...], possibly none (the caller then falls back to the corners rule)."""
    nx, ny = normal
    a1, a2, a_far, ua = a_edge
    b1, b2, b_far, ub = b_edge
    if abs(ua[0] * nx + ua[1] * ny) <= abs(ub[0] * nx + ub[1] * ny):
        ref1, ref2, ref_far, (sx, sy), inc1, inc2, rx, ry = a1, a2, a_far, ua, b1, b2, nx, ny
    else:
        ref1, ref2, ref_far, (sx, sy), inc1, inc2, rx, ry = b1, b2, b_far, ub, a1, a2, -nx, -ny
    kept = _clip_xy(inc1, inc2, sx, sy, sx * ref1[0] + sy * ref1[1])  # (sx, sy): the reference edge's direction
    if len(kept) == 2:
        kept = _clip_xy(kept[0], kept[1], -sx, -sy, -(sx * ref2[0] + sy * ref2[1]))
    face = rx * ref_far[0] + ry * ref_far[1]
    return [(Vector2(x, y), face - (rx * x + ry * y)) for x, y in kept
            if rx * x + ry * y <= face + TOUCH_TOLERANCE + margin]


def _circle_answer(hit, test):
    """A circle test's answer as (Vector2 normal, float depth), or None; a one-line ValueError if it is neither."""
    if hit is None:
        return None
    try:
        normal, depth = hit
        return Vector2(normal), float(depth)
    except (TypeError, ValueError):
        name = getattr(test, "__name__", "the circle test")
        raise ValueError(f"{name}() must return None or (normal, depth), got {hit!r}") from None


Manifold = namedtuple("Manifold", "normal depth points depths")
Manifold.__doc__ = """One pair's narrow-phase answer: unit normal A→B, the pair's depth (px),
the contact points (world px) and each point's own depth (px; negative = a gap, a speculative contact)."""


def collide(a, b, pa, pb, contact_rule="corners", polygon_test=sat, margin=0.0, circle_test=circle_polygon,
            circle_point=circle_contact_point, circles_test=None):
    """Narrow phase for one pair of bodies (with world points pa, pb): a Manifold, or None when apart.

    Polygons: polygon_test(pa, pb) (the lab's sat, if hooked) gives normal and
    depth; the contact rule gives the points:
      "corners"  the lesson's contact_points, every point with the pair's depth;
                 with a margin, corner_manifold (each corner its own depth);
      "clip"     clip_manifold, edge clipping, each point its own depth.
    Circles: circles_test(ca, ra, cb, rb) for two circles (the lab's
    circle_circle, if hooked; None: this module's circle_circle), or
    circle_test(center, radius, points) for a circle and a polygon (the lab's
    circle_polygon, if hooked), giving the normal out of the circle and the
    depth; circle_point(center, radius, d, depth) places the one contact point,
    d being the direction from the circle's center (default
    circle_contact_point: halfway into the overlap, c + d (r - depth/2)).
    A margin (px) asks for speculative contacts: pairs closer than that count,
    with a negative depth; polygons and circles then use this module's sat,
    circle_circle, circle_polygon and circle_contact_point (which know about margins).
    """
    kind = (a.shape.kind, b.shape.kind)
    if kind == ("polygon", "polygon"):
        hit = sat(pa, pb, margin) if margin else polygon_test(pa, pb)
        if hit is None:
            return None
        normal, depth = hit
        if contact_rule == "clip":
            pairs = clip_manifold(pa, pb, normal, margin)
        elif margin:
            pairs = corner_manifold(pa, pb, normal, margin) or [(p, depth) for p in contact_points(pa, pb, normal)]
        else:
            pairs = [(p, depth) for p in contact_points(pa, pb, normal)]
        return Manifold(normal, depth, [p for p, _ in pairs], [d for _, d in pairs])
    if kind == ("circle", "circle"):
        if circles_test is None or circles_test is circle_circle or margin:
            hit = circle_circle(a.pos, a.radius, b.pos, b.radius, margin)
        else:  # the lab's test, on copies of the centres
            hit = _circle_answer(circles_test(Vector2(a.pos), a.radius, Vector2(b.pos), b.radius), circles_test)
    elif margin:
        if kind == ("circle", "polygon"):
            hit = circle_polygon(a.pos, a.radius, pb, margin)
        else:
            hit = circle_polygon(b.pos, b.radius, pa, margin)
            hit = None if hit is None else (-hit[0], hit[1])
        circle_point = circle_contact_point
    elif kind == ("circle", "polygon"):
        hit = _circle_answer(circle_test(Vector2(a.pos), a.radius, [Vector2(p) for p in pb]), circle_test)
    else:
        hit = _circle_answer(circle_test(Vector2(b.pos), b.radius, [Vector2(p) for p in pa]), circle_test)
        hit = None if hit is None else (-hit[0], hit[1])
    if hit is None:
        return None
    normal, depth = hit
    circle, direction = (a, normal) if a.shape.kind == "circle" else (b, -normal)
    point = circle_point(Vector2(circle.pos), circle.radius, Vector2(direction), depth)
    return Manifold(normal, depth, [point], [depth])
