"""Draw assets/contact_picture.png: one crate corner touching the floor, with ra, rb, n, t and the relative
velocity labelled, the numbers of the lesson's worked k and j (lesson11/README.md, section 5).

    python tests/contact_shot.py

The crate is 60 × 40 px, mass 2.4 (its area / 1000, as the lab makes crates), turned by atan(5/12) (22.6°) so
that its lowest corner is at rb = (20, 30) from its centre; it moves at (60, 200) px/s without spin. The floor
is body A (static), the crate body B. tests/test_worked_impulse.py checks the numbers the text gives.
"""
import math
import os
import sys

import pygame
from pygame import Vector2

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from lesson11.physics2d import Body, box_points, spin_velocity  # noqa: E402

CRATE_W, CRATE_H, CRATE_MASS = 60, 40, 2.4
CRATE_ANGLE = math.atan2(5, 12)           # rad: cos = 12/13, sin = 5/13
CRATE_VEL = Vector2(60, 200)              # px/s
FLOOR_TOP = 300                           # px, in the picture
PATH = os.path.join(ROOT, "assets", "contact_picture.png")


def scene():
    """(floor, crate, contact point, normal): the crate's lowest corner resting on the floor's top."""
    floor = Body(box_points(520, 40), (260, FLOOR_TOP + 20), 0)
    crate = Body(box_points(CRATE_W, CRATE_H), (0, 0), CRATE_MASS, angle=CRATE_ANGLE)
    corner = max(crate.world_points(), key=lambda p: p.y)
    crate.pos = Vector2(330, FLOOR_TOP) - corner          # move the crate so that corner touches the floor
    crate.vel = Vector2(CRATE_VEL)
    point = Vector2(330, FLOOR_TOP)
    return floor, crate, point, Vector2(0, -1)


def arrow(surface, colour, start, end, width=3):
    pygame.draw.line(surface, colour, start, end, width)
    direction = (Vector2(end) - Vector2(start)).normalize()
    side = Vector2(-direction.y, direction.x)
    tip = Vector2(end)
    pygame.draw.polygon(surface, colour, [tip, tip - direction * 12 + side * 6, tip - direction * 12 - side * 6])


def draw(path=PATH, scale=2.0):
    pygame.init()
    surface = pygame.Surface((640, 440))
    surface.fill((250, 250, 247))
    font = pygame.font.Font(None, 26)
    small = pygame.font.Font(None, 22)
    floor, crate, point, normal = scene()
    origin = Vector2(330, 250)                            # where the contact point is drawn

    def at(p):                                            # scene px -> picture px, `scale` times larger
        return origin + (Vector2(p) - point) * scale

    ink, red, blue, green, purple = (30, 30, 30), (200, 40, 40), (40, 80, 200), (20, 130, 60), (130, 50, 160)
    for body, fill in ((floor, (190, 192, 200)), (crate, (222, 170, 110))):
        corners = [at(p) for p in body.world_points()]
        pygame.draw.polygon(surface, fill, corners)
        pygame.draw.polygon(surface, ink, corners, 2)

    def label(text, pos, colour, f=font):
        surface.blit(f.render(text, True, colour), pos)

    rb = point - crate.pos
    rel = crate.vel + spin_velocity(crate.omega, rb)      # the floor's point does not move
    tangent = (rel - normal * rel.dot(normal)).normalize()
    # the centres and the offsets from them to the contact point
    pygame.draw.circle(surface, ink, at(floor.pos), 5)
    label("A: the floor (static)", at(floor.pos) + Vector2(-150, 12), ink)
    pygame.draw.circle(surface, ink, at(crate.pos), 5)
    label("B: the crate", at(crate.pos) + Vector2(-130, -14), ink)
    arrow(surface, blue, at(floor.pos), origin)
    label("ra", (at(floor.pos) + origin) / 2 + Vector2(-30, -4), blue)
    arrow(surface, blue, at(crate.pos), origin)
    label("rb", (at(crate.pos) + origin) / 2 + Vector2(-30, -2), blue)
    arrow(surface, red, origin, origin + normal * 90)
    label("n", origin + normal * 90 + Vector2(8, -6), red)
    arrow(surface, green, origin, origin + tangent * 110)
    label("t", origin + tangent * 110 + Vector2(6, -22), green)
    arrow(surface, purple, origin, origin + rel / 2)
    label("rel", origin + rel / 2 + Vector2(10, -8), purple)
    pygame.draw.circle(surface, red, origin, 6)
    label("red dot: the contact point, where B's corner touches A; black dots: the centres", (14, 410), ink, small)
    label(f"rb = ({rb.x:.0f}, {rb.y:.0f}) px from B's centre;  n = (0, -1), from A to B;  t = (1, 0)", (14, 12), ink, small)
    label(f"rel = ({rel.x:.0f}, {rel.y:.0f}) px/s, how B's corner moves relative to A's (drawn at half length)", (14, 34), ink, small)
    label(f"vn = rel . n = {rel.dot(normal):.0f} px/s < 0: closing", (14, 56), ink, small)
    label("the crate: 60 x 40 px, mass 2.4, I = 1040, turned 22.6 degrees", (14, 78), ink, small)
    pygame.image.save(surface, path)
    return path


if __name__ == "__main__":
    print(draw())
