"""The two physics2d hooks the More Shapes lab uses: Polygon(points, recentre=False) and Body(..., inertia=I).

The lab centres its shapes with the student's polygon_centroid and computes their
moment of inertia with the student's polygon_inertia, so both must reach the Body
unchanged; bad values are one-line ValueErrors like every other Body setting.
"""
import pytest
from pygame import Vector2

from lesson11.physics2d import Body, Polygon, box_points, polygon_inertia

WEDGE = [Vector2(0, 0), Vector2(60, 0), Vector2(0, 40)]  # a right triangle, centroid (20, 13.33)


def test_polygon_recentres_by_default_and_keeps_the_points_when_asked():
    assert tuple(Polygon(WEDGE).points[0]) == pytest.approx((-20, -40 / 3))
    kept = Polygon(WEDGE, recentre=False)
    assert kept.points == WEDGE
    assert kept.radius == pytest.approx(60.0)  # bounding radius about (0, 0), the body's pos


def test_polygon_without_recentring_still_validates():
    with pytest.raises(ValueError, match="convex"):
        Polygon([(0, 0), (10, 0), (2, 2), (0, 10)], recentre=False)
    with pytest.raises(ValueError, match="at least 3 distinct points"):
        Polygon([(0, 0), (1, 1)], recentre=False)
    with pytest.raises(ValueError, match="recentre must be True or False"):
        Polygon(WEDGE, recentre="no")


def test_body_takes_a_given_inertia():
    body = Body(box_points(30, 20), (0, 0), 2.0, inertia=500.0)
    assert body.inertia == 500.0 and body.inv_inertia == pytest.approx(1 / 500)
    default = Body(box_points(30, 20), (0, 0), 2.0)
    assert default.inertia == pytest.approx(polygon_inertia(box_points(30, 20), 2.0))  # 216.67, as before


@pytest.mark.parametrize("inertia, message", [
    (0.0, "body inertia must be > 0"),
    (-3.0, "body inertia must be > 0"),
    (float("nan"), "body inertia must be finite"),
    ("heavy", "body inertia must be a number"),
])
def test_body_rejects_a_bad_inertia_in_one_line(inertia, message):
    with pytest.raises(ValueError, match=message) as caught:
        Body(box_points(30, 20), (0, 0), 2.0, inertia=inertia)
    assert "\n" not in str(caught.value)


def test_a_static_body_takes_no_inertia():
    with pytest.raises(ValueError, match="static body"):
        Body(box_points(30, 20), (0, 0), 0, inertia=10.0)


def test_the_solver_panel_says_a_lab_that_hooks_only_sat_runs_its_sat():
    """More Shapes hands the World its sat() but not resolve(): the panel says whose functions run."""
    from lesson11.panel import LabPanel
    from lesson11.physics2d import World, sat

    world = World([Body(box_points(60, 40), (0, 0), 1.0)], sat=lambda pa, pb: sat(pa, pb))
    panel = LabPanel()
    panel.adopt(world)
    assert "runs your sat() and physics2d's resolve()" in repr(panel.lines(world))
    assert "runs physics2d's sat() and resolve()" in repr(panel.lines(World([])))
