"""The Separating Axis Test on three pairs of 40 × 40 boxes.

Box A sits at the origin, unrotated. Each B is another 40 × 40 box:
  1. side by side, shifted 30 px right and 5 px down: they overlap by 10 px;
  2. a diamond (turned 45°) near A's corner: the bounding boxes overlap, but
     the diamond's own edge normal shows a gap, so SAT says apart;
  3. the same diamond pushed closer: a real overlap along the diagonal.

sat() lives in lesson11/physics2d/collision.py. It returns None when some axis
shows a gap, else (normal from A to B, depth in px): the minimum translation
vector.

Run: python -m lesson11.examples.sat_three_pairs
"""
import math

from lesson11.physics2d import Body, box_points, sat

PAIRS = [
    # name, centre of B (px), angle of B (degrees)
    ("side by side, 10 px overlap", (30, 5), 0),
    ("diamond near a corner", (45, 45), 45),
    ("diamond pushed closer", (30, 30), 45),
]


def world_box(w, h, centre, angle_degrees=0.0):
    """World corners (px) of a w × h box at `centre`, turned by angle_degrees (clockwise on screen)."""
    body = Body(box_points(w, h), centre, mass=0, angle=math.radians(angle_degrees))
    return body.world_points()


def describe(name, hit):
    """One line in the lesson's format: 'apart' or 'overlap D px along (nx, ny)'."""
    if hit is None:
        return f"{name}: apart"
    normal, depth = hit
    # + 0.0 turns a printed -0.00 into 0.00
    return f"{name}: overlap {depth:.2f} px along ({normal.x + 0.0:.2f}, {normal.y + 0.0:.2f})"


def main():
    a = world_box(40, 40, (0, 0))
    for name, centre, angle in PAIRS:
        b = world_box(40, 40, centre, angle)
        print(describe(name, sat(a, b)))


if __name__ == "__main__":
    main()
