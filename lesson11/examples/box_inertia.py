"""Moment of inertia of a 30 × 20 box of mass 2, two ways.

The box formula        I = m (w² + h²) / 12
and the general polygon_inertia (lesson11/physics2d/shapes.py), which cuts the
polygon into triangles around its centre, must agree: both give 216.67.
A Body built from the same corners stores that I as `inertia`.

Run: python -m lesson11.examples.box_inertia
"""
from lesson11.physics2d import Body, box_points, polygon_inertia

W, H, MASS = 30, 20, 2


def main():
    by_formula = MASS * (W ** 2 + H ** 2) / 12
    by_polygon = polygon_inertia(box_points(W, H), MASS)
    body = Body(box_points(W, H), (0, 0), MASS)
    print(f"box formula m (w² + h²) / 12:  I = {by_formula:.2f}")
    print(f"polygon_inertia(corners, m):   I = {by_polygon:.2f}")
    print(f"Body(...).inertia:             I = {body.inertia:.2f}, inv_inertia = {body.inv_inertia:.6f}")


if __name__ == "__main__":
    main()
