"""What lesson11/README.md section 3 says about the flip is true: each box axis arrives twice, the first wins,
so only the centres can say which way is A to B.

An unflipped sat() (the lesson's loop with strict `<`, no flip) is run on random overlapping box pairs. The
axis it keeps points from B to A in a large share of the pairs, whether it came from one of A's edges or one
of B's, so no rule by ownership can replace the test against the centres. Measured with seed 41 on 4000
pairs: from an A edge the unflipped normal points A to B in about 51 %, from a B edge in about 57 %.
"""
import math
import random

from pygame import Vector2

from lesson11.physics2d import box_points, centre_of, edge_normals, project


def unflipped_sat(pa, pb):
    """The lesson's step-2 loop (first smallest overlap wins): (axis, depth, from_a), or None when apart."""
    best = None
    normals_a = edge_normals(pa)
    for index, axis in enumerate(normals_a + edge_normals(pb)):
        min_a, max_a = project(pa, axis)
        min_b, max_b = project(pb, axis)
        overlap = min(max_a, max_b) - max(min_a, min_b)
        if overlap <= 0:
            return None
        if best is None or overlap < best[1]:
            best = (axis, overlap, index < len(normals_a))
    return best


def box(w, h, pos, angle):
    return [Vector2(pos) + p.rotate_rad(angle) for p in box_points(w, h)]


def test_each_axis_arrives_twice_with_the_same_overlap_pointing_opposite_ways():
    a, b = box(60, 40, (0, 0), 0.3), box(50, 30, (30, 20), -0.7)
    normals = edge_normals(a)
    for first, opposite in ((0, 2), (1, 3)):     # a box's opposite edges
        assert (normals[first] + normals[opposite]).length() < 1e-12
        lo, hi = project(a, normals[first]), project(b, normals[first])
        lo2, hi2 = project(a, normals[opposite]), project(b, normals[opposite])
        assert math.isclose(min(lo[1], hi[1]) - max(lo[0], hi[0]), min(lo2[1], hi2[1]) - max(lo2[0], hi2[0]))


def test_the_lessons_example_an_axis_of_a_that_already_points_from_a_to_b():
    a, b = box(40, 40, (30, 5), 0.0), box(40, 40, (0, 0), 0.0)
    axis, depth, from_a = unflipped_sat(a, b)
    assert from_a and math.isclose(depth, 10.0)
    assert (centre_of(b) - centre_of(a)).dot(axis) > 0     # from A to B without any flip


def test_floor_contacts_are_won_on_the_floors_top_edge_pointing_into_the_floor():
    floor = box(900, 40, (450, 580), 0.0)
    crate = box(60, 40, (450, 541), 0.4)
    axis, _, from_a = unflipped_sat(floor, crate)
    assert from_a and axis == Vector2(0, 1)                 # down, into the floor: from B to A


def test_unflipped_normal_is_wrong_in_a_large_share_from_either_bodys_edges():
    rng = random.Random(41)
    right = {True: 0, False: 0}
    total = {True: 0, False: 0}
    while sum(total.values()) < 4000:
        pa = box(rng.uniform(20, 90), rng.uniform(20, 90), (0, 0), rng.uniform(0, math.pi))
        pb = box(rng.uniform(20, 90), rng.uniform(20, 90), (rng.uniform(-70, 70), rng.uniform(-70, 70)),
                 rng.uniform(0, math.pi))
        hit = unflipped_sat(pa, pb)
        if hit is None:
            continue
        axis, _, from_a = hit
        total[from_a] += 1
        right[from_a] += (centre_of(pb) - centre_of(pa)).dot(axis) > 0
    shares = {owner: right[owner] / total[owner] for owner in total}
    print(f"unflipped normal points A to B: from A's edges {shares[True]:.0%} of {total[True]}, "
          f"from B's edges {shares[False]:.0%} of {total[False]}")
    assert all(0.35 < share < 0.65 for share in shares.values())   # wrong in 35-65 % whoever owns the edge
