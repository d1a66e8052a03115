"""Tunnelling: a 3000 px/s bullet (radius 2 px) and a still target (radius 5 px) 60 px away.

At 30 frames per second the bullet jumps 100 px per frame. The discrete test
only looks at where the bullet lands, x = 100, and sees no overlap: the
bullet went straight through. The swept test, circle_toi
(lesson11/physics2d/collision.py), solves |dp + dv t| = r1 + r2 for the first
t and finds the hit 17.67 ms into the frame, at x = 53.0 (60 - 2 - 5).

Run: python -m lesson11.examples.bullet_swept
"""
from lesson11.physics2d import Vector2, circle_toi

BULLET_START = Vector2(0, 0)
BULLET_VELOCITY = Vector2(3000, 0)  # px/s
BULLET_RADIUS = 2
TARGET = Vector2(60, 0)
TARGET_RADIUS = 5
FRAME = 1 / 30  # s


def main():
    end = BULLET_START + BULLET_VELOCITY * FRAME
    overlaps = end.distance_to(TARGET) < BULLET_RADIUS + TARGET_RADIUS
    print(f"discrete: bullet jumps from x={BULLET_START.x:.0f} to x={end.x:.0f}; overlaps at the end? {overlaps}")
    t = circle_toi(BULLET_START, BULLET_VELOCITY, BULLET_RADIUS, TARGET, Vector2(), TARGET_RADIUS, FRAME)
    hit_x = (BULLET_START + BULLET_VELOCITY * t).x
    print(f"swept: first contact at t = {t * 1000:.2f} ms, bullet at x = {hit_x:.1f}")
    for substeps in (2, 4, 8):
        caught = any((BULLET_START + BULLET_VELOCITY * (FRAME * k / substeps)).distance_to(TARGET)
                     < BULLET_RADIUS + TARGET_RADIUS for k in range(1, substeps + 1))
        print(f"sub-stepping x{substeps}: checks every {3000 * FRAME / substeps:.1f} px; catches the hit? {caught}")


if __name__ == "__main__":
    main()
