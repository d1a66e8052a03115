"""Debug drawing with pygame: bodies, contact points and normals, a HUD line.

"Physics bugs are invisible in numbers and obvious in pictures": draw every
contact as a dot and every normal as a short line.
"""
import pygame

OUTLINE = (20, 20, 20)
CONTACT = (255, 80, 80)
TEXT = (230, 230, 230)


def draw_body(surface, body, outline=OUTLINE):
    """Fill and outline one body (polygon corners, or a circle with a radius line showing its angle)."""
    if body.shape.kind == "circle":
        pygame.draw.circle(surface, body.color, body.pos, body.radius)
        pygame.draw.circle(surface, outline, body.pos, body.radius, 2)
        spoke = pygame.Vector2(body.radius, 0).rotate_rad(body.angle)
        pygame.draw.line(surface, outline, body.pos, body.pos + spoke, 2)
        return
    points = body.world_points()
    pygame.draw.polygon(surface, body.color, points)
    pygame.draw.polygon(surface, outline, points, 2)


def draw_contacts(surface, contacts, length=20, color=CONTACT):
    """A dot at each contact point and a line `length` px long along its normal (A→B)."""
    for contact in contacts:
        pygame.draw.circle(surface, color, contact.point, 4)
        pygame.draw.line(surface, color, contact.point, contact.point + contact.normal * length, 2)


def draw_text(surface, font, text, pos=(10, 10), color=TEXT):
    """Render one line of text at pos (px)."""
    surface.blit(font.render(text, True, color), pos)
