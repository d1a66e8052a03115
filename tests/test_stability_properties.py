"""Stability suite, properties: invariants of the collision code on random convex polygons and poses.

Polygons are random points on a circle (always convex) stretched by up to 3 : 1,
turned and placed at random; degenerate ones (two corners closer than 0.5 px,
or rejected by Polygon) are skipped with assume(). 200 examples per property.
"""
import math

import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from lesson11.physics2d import (TOUCH_TOLERANCE, Polygon, Vector2, circle_toi, closest_on_segment, edge_normals,
                                inside, polygon_inertia, project, sat)

SETTINGS = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


@st.composite
def convex_local(draw):
    """A convex polygon in local space (Polygon.points, centred on its centroid), 3 to 8 corners."""
    n = draw(st.integers(3, 8))
    angles = sorted(draw(st.lists(st.floats(0, 2 * math.pi, exclude_max=True), min_size=n, max_size=n)))
    radius = draw(st.floats(5, 60))
    stretch = draw(st.floats(1 / 3, 3))
    points = [Vector2(radius * math.cos(a) * stretch, radius * math.sin(a)) for a in angles]
    assume(all(points[i].distance_to(points[i - 1]) > 0.5 for i in range(n)))
    try:
        shape = Polygon(points)
    except ValueError:
        assume(False)
    assume(shape.area() > 1.0)
    return shape.points


@st.composite
def posed(draw):
    """World points of a random convex polygon at a random position (within 80 px) and angle."""
    local = draw(convex_local())
    pos = Vector2(draw(st.floats(-80, 80)), draw(st.floats(-80, 80)))
    angle = draw(st.floats(0, 2 * math.pi))
    return [pos + p.rotate_rad(angle) for p in local]


def overlap_on(axis, pa, pb):
    """How far B must move along ±axis to leave A (px): min(max_a - min_b, max_b - min_a), sat's depth on that axis."""
    min_a, max_a = project(pa, axis)
    min_b, max_b = project(pb, axis)
    return min(max_a - min_b, max_b - min_a)


@SETTINGS
@given(posed(), posed())
def test_sat_is_symmetric(pa, pb):
    """Property: sat(A, B) and sat(B, A) agree: both apart or both hit, same depth, opposite normals.

    When two axes tie for the smallest overlap the two orders may pick different
    ones; then each normal must still give the same depth for the other order.
    """
    ab, ba = sat(pa, pb), sat(pb, pa)
    assert (ab is None) == (ba is None)
    if ab is None:
        return
    assert ab[1] == pytest.approx(ba[1], abs=1e-9)
    if (ab[0] + ba[0]).length() > 1e-9:
        assert overlap_on(ba[0], pa, pb) == pytest.approx(ab[1], abs=1e-9)


NEAR_TWIN_A = [Vector2(58.1878, -12.7776), Vector2(30.6059, 12.4665), Vector2(-26.7811, 14.5013),
               Vector2(-61.2118, -8.54399)]
NEAR_TWIN_B = NEAR_TWIN_A[:3] + [Vector2(-61.2118, -8.544)]


@SETTINGS
@given(posed(), posed())
@example(NEAR_TWIN_A, NEAR_TWIN_B)  # found by a CI run: two ways out 1e-5 px apart
def test_sat_depth_is_positive_and_the_mtv_separates(pa, pb):
    """Property: a hit has depth > TOUCH_TOLERANCE and a unit normal A→B; moving B by normal × depth separates.

    Deep hits included: physics2d's sat takes the shorter way out on each axis,
    so one shadow containing the other no longer under-reports the depth (the
    lesson's plain overlap formula did, in 41 % of random hits).
    """
    hit = sat(pa, pb)
    assume(hit is not None)
    normal, depth = hit
    assert depth > TOUCH_TOLERANCE
    assert normal.length() == pytest.approx(1.0, abs=1e-12)
    moved = [p + normal * depth for p in pb]
    # Exactly the depth leaves a shadow overlap of rounding size (measured |overlap| <= 2.8e-14 px): apart.
    assert sat(pa, moved) is None
    # Moving the other way must not separate them (the normal points A→B), unless both ways
    # out are nearly equally long on this axis. Near-twins (CI found one whose ways differed by
    # 1e-5 px) have a second, nearly parallel edge normal whose leftover overlap can reach zero,
    # so the property is asserted only where the longer way is longer by a visible 1e-3 px.
    min_a, max_a = project(pa, normal)
    min_b, max_b = project(pb, normal)
    if (max_b - min_a) - (max_a - min_b) > 1e-3:
        assert sat(pa, [p - normal * depth for p in pb]) is not None


@SETTINGS
@given(posed(), st.floats(-150, 150), st.floats(-150, 150))
def test_inside_agrees_with_closest_on_segment(points, x, y):
    """Property: inside() and the nearest outline point from closest_on_segment() tell the same story.

    - a point on the outline (closest_on_segment of any point) is inside;
    - a point not inside is farther than TOUCH_TOLERANCE from the outline;
    - the path from a point to its nearest outline point stays on the same side.
    """
    p = Vector2(x, y)
    edges = [(points[i], points[(i + 1) % len(points)]) for i in range(len(points))]
    q = min((closest_on_segment(p, a, b) for a, b in edges), key=p.distance_to)
    assert inside(q, points)
    distance = p.distance_to(q)
    if not inside(p, points):
        assert distance > TOUCH_TOLERANCE
    if distance > 1e-3:
        assert inside((p + q) / 2, points) == inside(p, points)


@SETTINGS
@given(st.floats(-300, 300), st.floats(-300, 300), st.floats(-3000, 3000), st.floats(-3000, 3000),
       st.floats(-3000, 3000), st.floats(-3000, 3000), st.floats(0.5, 40), st.floats(0.5, 40))
def test_circle_toi_root_makes_the_circles_touch(x, y, v1x, v1y, v2x, v2y, r1, r2):
    """Property: circle_toi's t puts the circles exactly at distance r1 + r2, and not earlier.

    Circle 1 starts at the origin, circle 2 at (x, y); dt = 1/10 s.
    """
    p1, p2 = Vector2(), Vector2(x, y)
    v1, v2 = Vector2(v1x, v1y), Vector2(v2x, v2y)
    assume(p1.distance_to(p2) > r1 + r2 + 1e-6)  # apart at the start (t = 0 is the touching case)
    t = circle_toi(p1, v1, r1, p2, v2, r2, 0.1)
    if t is None:
        # No touch in [0, dt]: at 200 sample times the circles stay apart.
        for k in range(201):
            s = 0.1 * k / 200
            assert (p2 + v2 * s).distance_to(p1 + v1 * s) > r1 + r2 - 1e-6
        return
    assert 0 <= t <= 0.1
    gap = (p2 + v2 * t).distance_to(p1 + v1 * t) - (r1 + r2)
    assert abs(gap) < 1e-6  # measured worst |gap| 7.4e-12 px over 2000 examples; bound 1e-6
    earlier = t * (1 - 1e-3)
    assert (p2 + v2 * earlier).distance_to(p1 + v1 * earlier) > r1 + r2 - 1e-9


def triangle_quadrature(a, b, c, f):
    """∫ f over triangle abc by the 3-point rule at the edge midpoints (exact for quadratics)."""
    area = abs((b - a).cross(c - a)) / 2
    return area * (f((a + b) / 2) + f((b + c) / 2) + f((c + a) / 2)) / 3


@SETTINGS
@given(convex_local(), st.floats(0.1, 50))
def test_polygon_inertia_equals_numerical_integration(points, mass):
    """Property: polygon_inertia equals ∫ ρ r² dA, integrated numerically over a fan from corner 0.

    The quadrature uses a different triangulation (a fan from a corner, not from
    the centroid) and finds the centroid numerically too, so it shares no formula
    with polygon_inertia.
    """
    fan = [(points[0], points[i], points[i + 1]) for i in range(1, len(points) - 1)]
    area = sum(triangle_quadrature(a, b, c, lambda p: 1.0) for a, b, c in fan)
    cx = sum(triangle_quadrature(a, b, c, lambda p: p.x) for a, b, c in fan) / area
    cy = sum(triangle_quadrature(a, b, c, lambda p: p.y) for a, b, c in fan) / area
    centre = Vector2(cx, cy)
    assert centre.length() < 1e-9 * max(p.length() for p in points)  # Polygon centred it on the centroid
    integral = sum(triangle_quadrature(a, b, c, lambda p: (p - centre).length_squared()) for a, b, c in fan)
    # measured relative difference at most 6.7e-16 over 1000 examples; bound 1e-9
    assert polygon_inertia(points, mass) == pytest.approx(mass * integral / area, rel=1e-9)


def test_polygon_inertia_matches_a_grid_integration():
    """Property, cross-check by brute force: a 400 × 400 midpoint grid over a pentagon gives the same I within 0.5 %."""
    points = Polygon([Vector2(30 * math.cos(a), 18 * math.sin(a))
                      for a in (0.1, 1.4, 2.6, 3.9, 5.2)]).points
    xs = [p.x for p in points]
    ys = [p.y for p in points]
    n = 400
    hx, hy = (max(xs) - min(xs)) / n, (max(ys) - min(ys)) / n
    normals = edge_normals(points)
    slabs = [project(points, axis) for axis in normals]  # the polygon is the intersection of its edge slabs
    total = count = 0
    for i in range(n):
        x = min(xs) + (i + 0.5) * hx
        for j in range(n):
            p = Vector2(x, min(ys) + (j + 0.5) * hy)
            if all(low <= p.dot(axis) <= high for axis, (low, high) in zip(normals, slabs)):
                total += p.length_squared()
                count += 1
    grid = total / count  # I / m for a uniform density
    # measured relative difference 0.003 %; bound 0.5 %
    assert polygon_inertia(points, 1.0) == pytest.approx(grid, rel=5e-3)
