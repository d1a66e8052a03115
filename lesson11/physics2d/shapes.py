"""Shapes in local space: convex polygons and circles, centered on (0, 0).

A shape only knows its outline; a Body (bodies.py) gives it a position, an
angle and a mass. Polygons are stored with their centroid at (0, 0), so the
body's position is its center of mass.
"""
import math

from .vectors import Vector2, cross, finite_number, finite_vector

# Two points closer than this (px) are one point; an area below this (px²) is no area.
POINT_TOLERANCE = 1e-9


def box_points(w, h):
    """The four corners (px) of a w × h box centered on (0, 0), in screen order.

    Corners: (-w/2, -h/2), (w/2, -h/2), (w/2, h/2), (-w/2, h/2).
    """
    w = finite_number(w, "box width")
    h = finite_number(h, "box height")
    if w <= 0 or h <= 0:
        raise ValueError(f"a box needs a positive width and height, got {w} × {h}")
    return [Vector2(-w / 2, -h / 2), Vector2(w / 2, -h / 2), Vector2(w / 2, h / 2), Vector2(-w / 2, h / 2)]


def regular_polygon(sides, radius, angle=0.0):
    """Corners (px) of a regular polygon with `sides` corners on a circle of `radius` px.

    Corner k sits at radius * (cos θk, sin θk) with θk = angle + 2πk / sides.
    """
    if not isinstance(sides, int) or sides < 3:
        raise ValueError(f"a regular polygon needs a whole number of sides >= 3, got {sides!r}")
    radius = finite_number(radius, "polygon radius")
    if radius <= 0:
        raise ValueError(f"a regular polygon needs a positive radius, got {radius}")
    return [Vector2(radius * math.cos(angle + 2 * math.pi * k / sides),
                    radius * math.sin(angle + 2 * math.pi * k / sides)) for k in range(sides)]


def polygon_area(points):
    """Signed area (px²) by the shoelace formula: ½ Σ cross(p_i, p_i+1).

    Positive when the points run clockwise on screen (y down), negative otherwise.
    """
    return 0.5 * sum(cross(a, points[(i + 1) % len(points)]) for i, a in enumerate(points))


def polygon_centroid(points):
    """Centroid (px) of a simple polygon: Σ (p_i + p_i+1) cross(p_i, p_i+1) / (6 A)."""
    area = polygon_area(points)
    total = Vector2()
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        total += (a + b) * cross(a, b)
    return total / (6 * area)


def polygon_inertia(points, mass):
    """Moment of inertia (kg·px², with mass in the course's mass units) of a solid convex polygon.

    The points must be centered on the centroid. The polygon is cut into triangles
    (0, a, b) and their inertias are summed:
        I = m Σ |a × b| (a·a + a·b + b·b) / (6 Σ |a × b|)
    For a w × h box this equals the box formula m (w² + h²) / 12.
    """
    num = den = 0.0
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        area2 = abs(cross(a, b))
        num += area2 * (a.dot(a) + a.dot(b) + b.dot(b))
        den += area2
    return mass * num / (6 * den)


def convex_polygon(points, recentre=True):
    """Validate a convex polygon and return its corners re-centered on the centroid.

    With recentre=False the corners are validated but kept where they are (a
    lab that centers them with its own centroid function passes them this way).
    Accepts either winding. Duplicate consecutive points are dropped. Raises
    ValueError when `points` is not a list of points, there are fewer than 3
    distinct points, a point is not finite, the area is zero, the outline turns
    both ways (not convex), or it goes round more than once (a star).
    """
    try:
        points = list(points)
    except TypeError:
        raise ValueError(f"a polygon needs a list of (x, y) points, got {points!r}") from None
    pts = [finite_vector(p, f"polygon point {i}") for i, p in enumerate(points)]
    distinct = []
    for p in pts:
        if not distinct or (p - distinct[-1]).length() > POINT_TOLERANCE:
            distinct.append(p)
    if len(distinct) > 1 and (distinct[0] - distinct[-1]).length() <= POINT_TOLERANCE:
        distinct.pop()
    if len(distinct) < 3:
        raise ValueError(f"a polygon needs at least 3 distinct points, got {len(distinct)}")
    area = polygon_area(distinct)
    scale = max(max(abs(p.x), abs(p.y)) for p in distinct)
    if abs(area) <= POINT_TOLERANCE * max(1.0, scale * scale):
        raise ValueError("a polygon needs a non-zero area; these points lie on one line or the outline crosses itself")
    turns = [cross(distinct[(i + 1) % len(distinct)] - a,
                   distinct[(i + 2) % len(distinct)] - distinct[(i + 1) % len(distinct)])
             for i, a in enumerate(distinct)]
    tolerance = POINT_TOLERANCE * max(1.0, scale * scale)
    if any(t > tolerance for t in turns) and any(t < -tolerance for t in turns):
        raise ValueError("a polygon must be convex (no dents); split a concave shape into convex pieces")
    edges = [distinct[(i + 1) % len(distinct)] - a for i, a in enumerate(distinct)]
    winding = sum(math.atan2(cross(e, edges[(i + 1) % len(edges)]), e.dot(edges[(i + 1) % len(edges)]))
                  for i, e in enumerate(edges))
    if abs(abs(winding) - 2 * math.pi) > 1e-6:  # a star turns one way but goes round more than once
        raise ValueError("a polygon must be convex (no dents); this outline goes round more than once and crosses itself")
    if not recentre:
        return distinct
    center = polygon_centroid(distinct)
    return [p - center for p in distinct]


class WorldPoints(list):
    """A polygon's corners in world space (a list of Vector2, px), as Body.world_points() returns them.

    A plain list that also keeps the edge normals once collision.edge_normals
    has worked them out (attribute `normals`, None until then), and the edges
    once collision.polygon_edges has (attribute `edges`), and the same for the
    center (collision.center_of) and the edges as plain floats (`flat_edges`,
    collision's fast contact points): a body tested against several others in
    one contact search computes them once.
    It is a snapshot: the world makes new ones after the bodies move, and the
    normals and edges describe the corners as they were when first asked for.
    """
    # None until worked out: class-level defaults, so making one is list's own __init__ (in C), twice as quick
    # as setting four slots in a Python __init__; the first store puts the value on the instance
    normals = edges = center = flat_edges = None


class Polygon:
    """A convex polygon shape: `points` (list of Vector2, px) centered on its centroid.

    Polygon(points, recentre=False) keeps the points as given (validated, not
    moved): the body's pos is then their (0, 0), which is its center of mass
    only if the caller centered them on their centroid (the More Shapes lab
    does this with the student's polygon_centroid).
    """

    kind = "polygon"

    def __init__(self, points, recentre=True):
        if not isinstance(recentre, bool):
            raise ValueError(f"Polygon recentre must be True or False, got {recentre!r}")
        self.points = convex_polygon(points, recentre)
        self.radius = max(p.length() for p in self.points)  # bounding circle (px)

    def area(self):
        """Area in px² (always positive)."""
        return abs(polygon_area(self.points))

    def inertia(self, mass):
        """Moment of inertia for `mass`: polygon_inertia(points, mass)."""
        return polygon_inertia(self.points, mass)


class Circle:
    """A circle shape of `radius` px centered on (0, 0)."""

    kind = "circle"

    def __init__(self, radius):
        radius = finite_number(radius, "circle radius")
        if radius <= 0:
            raise ValueError(f"a circle needs a positive radius, got {radius}")
        self.radius = radius

    def area(self):
        """Area in px²: π r²."""
        return math.pi * self.radius ** 2

    def inertia(self, mass):
        """Moment of inertia of a solid disc: I = ½ m r²."""
        return 0.5 * mass * self.radius ** 2
