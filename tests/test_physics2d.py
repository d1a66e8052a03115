"""physics2d holds the lesson's own numbers, its invariants, and rejects bad input at the API."""
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from lesson11.physics2d import (Body, Circle, EFFECTS, LESSON_EFFECTS, Polygon, Vector2, World, apply_impulse,
                                box_points, circle_circle, circle_polygon, circle_toi, clip_contact_points,
                                closest_on_segment, contact_points, convex_polygon, cross, edge_normals, inside,
                                polygon_inertia, project, regular_polygon, resolve, sat, separate,
                                spin_velocity)
from lesson11.physics2d.collision import inside_edges, polygon_edges
from lesson11.physics2d.vectors import cross_reference


def placed_box(w, h, centre, angle_deg=0.0):
    """World corners of a w × h box at centre, turned by angle_deg (as in the lesson's SAT listing)."""
    return [Vector2(centre) + p.rotate(angle_deg) for p in box_points(w, h)]


# ---- the lesson's numbers -------------------------------------------------------------------------

def test_box_inertia_matches_box_formula_and_lesson_value():
    by_formula = 2 * (30 ** 2 + 20 ** 2) / 12
    assert polygon_inertia(box_points(30, 20), 2) == pytest.approx(by_formula, rel=1e-12)
    assert round(by_formula, 2) == 216.67
    assert Body(box_points(30, 20), (0, 0), 2).inertia == pytest.approx(216.6667, abs=1e-4)


def test_disc_inertia_is_half_m_r_squared():
    assert Body(Circle(10), (0, 0), 3).inertia == pytest.approx(0.5 * 3 * 100)


def test_sat_side_by_side_overlap_10_px_along_x():
    normal, depth = sat(placed_box(40, 40, (0, 0)), placed_box(40, 40, (30, 5)))
    assert depth == pytest.approx(10.0, abs=1e-9)
    assert normal.x == pytest.approx(1.0) and normal.y == pytest.approx(0.0, abs=1e-12)


def test_sat_diamond_near_corner_is_apart_although_bounding_boxes_overlap():
    a, b = placed_box(40, 40, (0, 0)), placed_box(40, 40, (45, 45), 45)
    assert max(p.x for p in a) > min(p.x for p in b) and max(p.y for p in a) > min(p.y for p in b)
    assert sat(a, b) is None


def test_sat_diamond_pushed_closer_5_86_px_along_diagonal():
    normal, depth = sat(placed_box(40, 40, (0, 0)), placed_box(40, 40, (30, 30), 45))
    assert round(depth, 2) == 5.86
    assert (round(normal.x, 2), round(normal.y, 2)) == (0.71, 0.71)


def test_ball_on_ramp_normal_depth_and_apart_after_push():
    ramp_points = [Vector2(0, 100), Vector2(200, 40), Vector2(200, 100)]
    normal, depth = circle_polygon(Vector2(100, 62), 12, ramp_points)
    assert (round(normal.x, 2), round(normal.y, 2)) == (0.29, 0.96)
    assert round(depth, 2) == 4.34
    ball = Body(Circle(12), (100, 62), 2)
    ramp = Body.from_world_points(ramp_points, 0)
    flat = [c for p in ramp.world_points() for c in p]
    assert flat == pytest.approx([c for p in ramp_points for c in p], abs=1e-9)
    separate(ball, ramp, normal, depth, slop=0, percent=1)
    assert ramp.pos == Body.from_world_points(ramp_points, 0).pos  # static: never moves
    assert circle_polygon(ball.pos, 12, ramp_points) is None  # exactly touching counts as apart


def test_bullet_discrete_misses_swept_hits_at_17_67_ms():
    bullet, speed, target, dt = Vector2(0, 0), Vector2(3000, 0), Vector2(60, 0), 1 / 30
    end = bullet + speed * dt
    assert end.x == pytest.approx(100) and end.distance_to(target) >= 7  # discrete: no overlap at the end
    t = circle_toi(bullet, speed, 2, target, Vector2(), 5, dt)
    assert round(t * 1000, 2) == 17.67
    assert round((bullet + speed * t).x, 1) == 53.0


# ---- invariants ------------------------------------------------------------------------------------

@pytest.mark.parametrize("centre,angle", [((30, 5), 0), ((30, 30), 45), ((-12, 25), 17), ((5, -31), 80)])
def test_sat_is_antisymmetric_and_mtv_separates(centre, angle):
    a, b = placed_box(40, 40, (0, 0), 10), placed_box(50, 30, centre, angle)
    normal_ab, depth_ab = sat(a, b)
    normal_ba, depth_ba = sat(b, a)
    assert depth_ab == pytest.approx(depth_ba, abs=1e-9)
    assert (normal_ab + normal_ba).length() < 1e-9
    assert depth_ab > 0 and normal_ab.length() == pytest.approx(1.0)
    moved = [p + normal_ab * (depth_ab + 1e-6) for p in b]
    assert sat(a, moved) is None


def test_cross_spin_velocity_and_projection():
    assert cross(Vector2(1, 0), Vector2(0, 1)) == 1  # (0, 1) is clockwise of (1, 0) on screen
    v = spin_velocity(2.0, Vector2(3, 0))
    assert (v.x, v.y) == (0, 6) and v.dot(Vector2(3, 0)) == 0
    assert project(box_points(4, 2), Vector2(1, 0)) == (-2, 2)
    assert len(edge_normals([Vector2(0, 0), Vector2(0, 0), Vector2(4, 0), Vector2(0, 4)])) == 3


def test_inside_closest_and_circle_circle():
    square = box_points(10, 10)
    assert inside(Vector2(0, 0), square) and inside(Vector2(5, 0), square)
    assert not inside(Vector2(5.1, 0), square)
    assert inside(Vector2(0, 0), list(reversed(square)))
    assert closest_on_segment(Vector2(3, 7), Vector2(0, 0), Vector2(10, 0)) == Vector2(3, 0)
    assert closest_on_segment(Vector2(-3, 7), Vector2(0, 0), Vector2(10, 0)) == Vector2(0, 0)
    normal, depth = circle_circle(Vector2(0, 0), 5, Vector2(8, 0), 5)
    assert normal == Vector2(1, 0) and depth == pytest.approx(2)
    assert circle_circle(Vector2(0, 0), 5, Vector2(10, 0), 5) is None  # touching is apart


def test_contact_rules_one_corner_on_tip_two_when_flat():
    floor = placed_box(200, 20, (0, 10))
    tip = placed_box(20, 20, (0, -13), 45)  # lowest corner 1.14 px into the floor
    normal, _ = sat(floor, tip)
    assert len(contact_points(floor, tip, normal)) == 1
    flat = placed_box(20, 20, (0, -9))  # resting flat, 1 px deep
    normal, _ = sat(floor, flat)
    for rule in (contact_points, clip_contact_points):
        points = rule(floor, flat, normal)
        assert len(points) == 2
        assert sorted(round(p.x) for p in points) == [-10, 10]


def test_apply_impulse_signs_a_minus_b_plus():
    a = Body(box_points(20, 20), (0, 0), 1)
    b = Body(box_points(20, 20), (30, 0), 1)
    impulse, ra, rb = Vector2(0, 5), Vector2(10, 0), Vector2(-10, 0)
    apply_impulse(a, b, impulse, ra, rb)
    assert a.vel == Vector2(0, -5) and b.vel == Vector2(0, 5)
    assert a.omega == pytest.approx(-cross(ra, impulse) * a.inv_inertia)
    assert b.omega == pytest.approx(cross(rb, impulse) * b.inv_inertia)
    assert a.omega < 0 and b.omega < 0


def test_resolve_stops_approach_and_clamps_friction():
    floor = Body(box_points(400, 20), (0, 10), 0, friction=0.5)
    crate = Body(box_points(20, 20), (0, -10), 1, vel=(500, 200), friction=0.5)  # μ = √(0.5·0.5)  # glancing: fast slide
    normal = Vector2(0, -1)  # floor (A) → crate (B) points up
    j = resolve(floor, crate, normal, Vector2(0, 0), spin=False)
    assert j == pytest.approx(200 * (1 + 0.2))  # e = 0.2: vn = -200 becomes +40
    assert crate.vel.y == pytest.approx(-40)
    assert crate.vel.x == pytest.approx(500 - 0.5 * j)  # Coulomb: friction capped at μ j, not a dead stop


def test_resting_speed_cutoff_means_no_bounce():
    floor = Body(box_points(400, 20), (0, 10), 0)
    crate = Body(box_points(20, 20), (0, -10), 1, vel=(0, 20), restitution=1)
    resolve(floor, crate, Vector2(0, -1), Vector2(0, 0))
    assert crate.vel.y == pytest.approx(0)


def test_static_body_never_moves_under_impulse_or_push():
    ground = Body(box_points(100, 10), (0, 0), 0)
    box = Body(box_points(10, 10), (0, -7), 3)
    for _ in range(5):
        apply_impulse(ground, box, Vector2(30, -1000), Vector2(3, -5), Vector2(1, 2))
        apply_impulse(box, ground, Vector2(-30, 1000), Vector2(1, 2), Vector2(3, -5))
        separate(ground, box, Vector2(0, -1), 3.0, slop=0, percent=1)
        separate(box, ground, Vector2(0, 1), 3.0, slop=0, percent=1)
    assert (ground.pos, ground.vel, ground.omega, ground.angle) == (Vector2(0, 0), Vector2(0, 0), 0.0, 0.0)


def test_separate_splits_push_by_inverse_mass():
    light = Body(box_points(10, 10), (0, 0), 1)
    heavy = Body(box_points(10, 10), (9, 0), 3)
    separate(light, heavy, Vector2(1, 0), 4.5, slop=0.5, percent=1)
    assert light.pos.x == pytest.approx(-3.0) and heavy.pos.x == pytest.approx(9 + 1.0)


def test_free_fall_gives_v_equals_g_t():
    world = World([Body(box_points(10, 10), (0, 0), 1)])
    for _ in range(120):
        world.step()
    assert world.bodies[0].vel.y == pytest.approx(980 * 1.0, rel=1e-12)
    assert world.time == pytest.approx(1.0)


def test_world_accumulator_and_clamped_long_frame():
    world = World([Body(box_points(10, 10), (0, 0), 1)])
    assert world.advance(1 / 60) == 2
    assert world.advance(0.004) == 0 and world.advance(0.005) == 1  # remainder carried
    world.max_steps = None
    assert world.advance(10.0) == 30  # clamped to 0.25 s = 30 steps of 1/120 s


def test_world_caps_catch_up_steps_and_drops_the_backlog():
    """A long frame runs at most max_steps steps; the backlog beyond one step is dropped, not carried into a spiral."""
    world = World([Body(box_points(10, 10), (0, 0), 1)])
    assert world.max_steps == 4
    assert world.advance(0.1) == 4            # 12 steps' worth of time, 4 run
    assert world.accumulator < world.step_seconds
    assert world.dropped == pytest.approx(0.1 - 4 / 120 - world.accumulator)
    assert world.advance(1 / 60) == 2         # the next ordinary frame is ordinary again
    assert world.time == pytest.approx(6 / 120)
    world.max_steps = 1
    assert world.advance(1 / 60) == 1
    for bad in (0, -1, 2.5, True, "4"):
        with pytest.raises(ValueError, match="max_steps"):
            world.max_steps = bad


def test_world_runs_a_students_functions():
    calls = {"sat": 0, "resolve": 0}

    def my_sat(pa, pb):
        calls["sat"] += 1
        return sat(pa, pb)

    def my_resolve(a, b, normal, point):
        calls["resolve"] += 1
        return resolve(a, b, normal, point)

    floor = Body(box_points(400, 20), (0, 10), 0)
    world = World([floor, Body(box_points(20, 20), (0, -15), 1)], sat=my_sat, resolve=my_resolve)
    for _ in range(60):
        world.step()
    assert calls["sat"] > 0 and calls["resolve"] > 0
    assert world.bodies[1].pos.y == pytest.approx(-10, abs=1.0)  # resting on the floor


def test_declared_effects_only_those_run():
    """A frictionless, non-rotating scene never turns a body; no swept tests without "ccd"."""
    floor = Body(box_points(400, 20), (0, 10), 0)
    crate = Body(box_points(20, 20), (0, -30), 1, angle=0.3, vel=(200, 0))
    world = World([floor, crate], effects={"gravity", "correction"})
    for _ in range(120):
        world.step()
    assert crate.angle == 0.3 and crate.omega == 0.0
    assert crate.vel.x == pytest.approx(200)  # no friction ran
    assert world.counters["swept_tests"] == 0
    assert world.counters["contacts"] > 0
    with pytest.raises(ValueError, match="unknown effects"):
        World(effects={"gravity", "magnetism"})
    with pytest.raises(ValueError, match="not the string 'gravity'"):
        World(effects="gravity")  # a bare string would otherwise be read letter by letter
    assert LESSON_EFFECTS < set(EFFECTS)


def test_swept_bullet_stops_at_thin_wall_discrete_tunnels():
    def shoot(effects):
        wall = Body(box_points(4, 200), (100, 0), 0, restitution=0)
        bullet = Body(Circle(3), (0, 0), 0.1, vel=(6000, 0), bullet=True, restitution=0)
        world = World([wall, bullet], gravity=(0, 0), effects=effects)
        for _ in range(12):
            world.step()
        return bullet.pos.x
    assert shoot(LESSON_EFFECTS) > 200  # tunnelled straight through
    assert shoot(LESSON_EFFECTS | {"ccd"}) == pytest.approx(95, abs=0.5)  # wall face 98 minus radius 3


# ---- bad input ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs,message", [
    ({"pos": (math.nan, 0)}, "position must be finite"),
    ({"vel": (0, math.inf)}, "velocity must be finite"),
    ({"mass": math.nan}, "mass must be finite"),
    ({"mass": -1}, "mass must be >= 0"),
    ({"angle": math.inf}, "angle must be finite"),
    ({"pos": "here"}, "position must be a pair"),
])
def test_body_rejects_bad_numbers(kwargs, message):
    settings = {"pos": (0, 0), "mass": 1}
    settings.update(kwargs)
    with pytest.raises(ValueError, match=message):
        Body(box_points(10, 10), **settings)


@pytest.mark.parametrize("points,message", [
    ([(0, 0), (1, 0)], "at least 3 distinct points"),
    ([(0, 0), (0, 0), (0, 0), (5, 5)], "at least 3 distinct points"),
    ([(0, 0), (1, 1), (2, 2)], "non-zero area"),
    ([(0, 0), (10, 0), (2, 2), (0, 10)], "convex"),
    ([(0, 0), (math.nan, 0), (0, 1)], "must be finite"),
])
def test_polygon_rejects_degenerate_input(points, message):
    with pytest.raises(ValueError, match=message):
        convex_polygon(points)


def test_polygon_is_recentred_on_centroid_either_winding():
    for pts in ([(0, 0), (6, 0), (0, 6)], [(0, 0), (0, 6), (6, 0)]):
        poly = Polygon(pts)
        centroid = sum(poly.points, Vector2()) / 3
        assert centroid.length() < 1e-12
    assert len(regular_polygon(6, 10)) == 6


def test_world_rejects_bad_dt_and_settings():
    world = World()
    for bad in (math.nan, math.inf, -1):
        with pytest.raises(ValueError, match="frame time"):
            world.advance(bad)
    with pytest.raises(ValueError, match="step dt must be"):
        world.step(0)
    with pytest.raises(ValueError, match="iterations"):
        World(iterations=0)
    with pytest.raises(ValueError, match="contact_rule"):
        World(contact_rule="magic")


def test_nan_set_by_hand_is_caught_before_it_spreads():
    floor = Body(box_points(400, 20), (0, 10), 0)
    crate = Body(box_points(20, 20), (0, -12), 1)
    world = World([floor, crate])
    crate.vel = Vector2(math.nan, 0)
    with pytest.raises(ValueError, match="body 1's vel must be finite"):
        world.step()                     # World.check_motion, before the step moves anything
    crate.vel = Vector2()
    crate.vel.x = math.nan               # in place, mid-run: the same check at the next step
    with pytest.raises(ValueError, match="body 1's vel must be finite"):
        world.step()
    bad = Body(box_points(5, 5), (0, 0), 1)
    with pytest.raises(ValueError, match="body position must be finite"):
        bad.pos = Vector2(math.inf, 0)   # a checked setting refuses it at once
    bad.pos.x = math.inf                 # written inside the body's own vector: no setting sees it
    with pytest.raises(ValueError, match="cannot add"):
        world.add(bad)


# ---- the accumulated solver (arbiter.py) ----------------------------------------------------------------

def test_clip_manifold_gives_each_point_its_own_depth():
    from lesson11.physics2d.collision import clip_manifold
    floor = placed_box(200, 20, (0, 10))
    tilted = placed_box(40, 20, (0, -9.5), 1)  # 1° tilt: one corner deeper than the other
    normal, _ = sat(floor, tilted)
    depths = sorted(d for _, d in clip_manifold(floor, tilted, normal))
    assert len(depths) == 2 and depths[0] < depths[1]
    one = math.radians(1)
    assert depths[1] == pytest.approx(-9.5 + 10 * math.cos(one) + 20 * math.sin(one), abs=1e-9)  # lower corner
    assert depths[0] == pytest.approx(-9.5 + 10 * math.cos(one) - 20 * math.sin(one), abs=1e-9)


def test_accumulated_solver_rests_without_creep_and_respects_effects():
    """A crate on the 22° slope of a static ramp: the accumulated solver holds it (solve, then move)."""
    ramp = Body(box_points(600, 40), (0, 0), 0, angle=math.radians(22))
    normal = Vector2(0, -1).rotate_rad(math.radians(22))
    crate = Body(box_points(40, 40), normal * 40.2, 1, angle=math.radians(22))
    world = World([ramp, crate], solver="accumulated", contact_rule="clip", iterations=10)
    start = crate.pos.copy()
    for _ in range(360):
        world.step()
    assert (crate.pos - start).length() < 1.0  # measured 0.2 px in 3 s; the lesson's solver creeps 3.1 px/s
    frictionless = World([Body(box_points(600, 40), (0, 0), 0, angle=math.radians(22)),
                          Body(box_points(40, 40), normal * 40.2, 1, angle=math.radians(22))],
                         solver="accumulated", effects=LESSON_EFFECTS - {"friction"})
    for _ in range(120):
        frictionless.step()
    assert frictionless.bodies[1].vel.length() > 300  # slides: g sin 22° ≈ 367 px/s after 1 s
    assert all(c.friction_impulse == 0 for arb in frictionless.arbiters.values() for c in arb.points)
    with pytest.raises(ValueError, match="solver must be"):
        World(solver="magic")


def test_world_settings_are_checked_when_set_later_and_switching_is_safe():
    """Settings set after World(...) go through the same validators; switching solver or rule drops kept contacts."""
    world = World()
    for name, bad in (("iterations", 0), ("substeps", 0), ("step_seconds", 0), ("slop", -1), ("percent", 2),
                      ("resting_speed", -1), ("max_frame", 0), ("max_steps", 0), ("contact_rule", "magic"), ("solver", "magic"),
                      ("effects", "gravity"), ("warm_starting", 1), ("gravity", (math.nan, 0))):
        with pytest.raises(ValueError):
            setattr(world, name, bad)
    floor = Body(box_points(400, 20), (0, 10), 0)
    crate = Body(box_points(20, 20), (0, -10), 1)
    world = World([floor, crate], solver="accumulated", substeps=2)
    world.step()
    assert world.arbiters
    world.contact_rule = "clip"
    assert not world.arbiters
    world.step()
    world.solver = "lesson"
    assert not world.arbiters
    world.step()
    assert world.step_seconds == pytest.approx(1 / 120)


# ---------------------------------------------------------------- work done once, not twice (issue 13)

def test_world_points_keep_their_edge_normals_and_hand_out_copies():
    box = Body(box_points(40, 20), (100, 50), 1, angle=0.3)
    points = box.world_points()
    plain = [Vector2(p) for p in points]             # a plain list: normals computed every call
    first = edge_normals(points)
    assert points.normals is not None and first == edge_normals(plain)
    first[0] *= -1                                    # the caller changes its copy in place...
    assert edge_normals(points) == edge_normals(plain)  # ...the kept normals are unchanged
    assert edge_normals(points)[0] is not edge_normals(points)[0]


def test_world_points_keep_their_edges_once_worked_out():
    box = Body(box_points(40, 20), (100, 50), 1, angle=0.3)
    points = box.world_points()
    plain = [Vector2(p) for p in points]
    assert points.edges is None
    edges = polygon_edges(points)
    assert points.edges is edges and polygon_edges(points) is edges  # worked out once per snapshot
    assert edges == polygon_edges(plain)                              # the same as computed afresh
    moved = box.world_points()                                        # a new snapshot starts empty
    assert moved.edges is None and moved.normals is None


@given(st.floats(-300, 300), st.floats(-300, 300), st.floats(-7, 7))
def test_inside_edges_is_inside_with_edges_worked_out_once(x, y, angle):
    shape = Body(Polygon([(0, 0), (60, 10), (50, 70), (-10, 40)], recentre=False), (20, 30), 1, angle=angle)
    points = shape.world_points()
    edges = polygon_edges(points)
    for corner in points + [Vector2(x, y), Vector2(20, 30)]:
        assert inside_edges(corner, edges) == inside(corner, points)


finite = st.floats(-1e6, 1e6, allow_nan=False)


@given(finite, finite, finite, finite)
def test_fast_cross_and_project_agree_with_their_readable_forms(ax, ay, bx, by):
    """cross is pygame's Vector2.cross; cross_reference is the formula; project's loop is min/max of the dots."""
    a, b = Vector2(ax, ay), Vector2(bx, by)
    assert math.isclose(cross(a, b), cross_reference(a, b), rel_tol=1e-12, abs_tol=1e-6)  # exact on x86-64
    points = [a, b, a + b, a - b]
    axis = Vector2(1, 2).normalize()
    assert project(points, axis) == (min(p.dot(axis) for p in points), max(p.dot(axis) for p in points))
