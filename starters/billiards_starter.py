"""Billiards: a Lesson 11 lab, balls that meet on a table seen from above.

You write the contact between two balls: circle_circle() finds whether they overlap and along which normal,
bounce() gives both the impulse that makes them bounce apart, cloth_slowing() lets the cloth slow each ball
to a stop. The World (lesson11.physics2d) calls your circle_circle() for every pair of balls and your
bounce() for every contact, cushions included (a ball against a cushion: the library's circle_polygon()).
Seen from above, the World has no gravity: the scene declares only the effects it needs (EFFECTS); g is
used by the cloth only. The balls do not spin, so the impulse has no spin term.

The comments "Step 1" to "Step 5" follow the exercise's steps. Steps 2 to 4 are the code between the lines
`# --- step N: ... ---` and `# --- end of step N ---`: yours to write in the starter, done in the solution
(where each step opens with the starter's text for it, between `# BEGIN PROMPT` and `# END PROMPT`). Each
step's comment names the section of the lesson (lesson11/README.md) that explains it. In the starter each
step holds a placeholder line, marked "replace this placeholder", that keeps the file running until you
write the step: replace that line with your code. Code written above a placeholder left in place is
wasted: a placeholder `return` hands back its stand-in value unless your code returned first.

Controls: left click shoots the white ball towards the mouse, harder the further away you click; R racks
the balls again, in a new order. Lines marked `# lab runtime` let the checker run this file headless, and
`# solver panel` lines add the solver panel. Units: px, s; y grows downward.
"""
import random

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import Body, Circle, World, box_points
from lesson11.physics2d.draw import draw_text

WIDTH, HEIGHT = 900, 600
TABLE = pygame.Rect(60, 150, 780, 400)  # px: the cloth inside the cushions (below the solver panel)
CUSHION = 40                            # px: each cushion's thickness
RADIUS = 14.0                           # px: every ball
MASS = 1.0                              # every ball
RESTITUTION = 0.95                      # e of every contact, ball or cushion
G = 980.0                               # px/s²: g, used only by the cloth (the table is seen from above)
ROLLING = 0.15                          # the cloth's rolling resistance μ_r (a real cloth: about 0.01)
MAX_SHOT = 900.0                        # px/s: the hardest shot
EFFECTS = {"restitution", "correction"}  # seen from above: no gravity; balls that do not spin: no rotation
CLOTH, GREY, WHITE = (30, 110, 60), (90, 60, 40), (240, 240, 235)
COLORS = [(230, 190, 40), (40, 80, 200), (210, 50, 40), (120, 50, 160), (240, 130, 30), (230, 110, 160),
          (140, 30, 40), (30, 30, 30), (200, 170, 60), (60, 110, 210)]

# Step 1: run this file and watch the break: until steps 2 and 3 nothing bounces, and until step 4 nothing slows.


def circle_circle(ca, ra, cb, rb):
    """Two balls: None when apart, else (unit normal from A's centre to B's, depth px).

    ca, cb: the centres (px); ra, rb: the radii (px). d = cb - ca;
    depth = ra + rb - |d|, the overlap; touching (depth <= 0) is apart;
    normal = d / |d|. Centres that coincide have no direction: the normal is
    then (1, 0).
    """
    # --- step 2: do two balls overlap? ---
    # Step 2 (lesson: "6. Circles, polygons and fast objects"): return None when the balls do not overlap; otherwise
    # the unit normal from A's centre to B's and the depth ra + rb - |cb - ca| (normal (1, 0) if the centres coincide).
    return None  # until you write step 2, balls pass through each other: replace this placeholder
    # --- end of step 2 ---


def bounce(a, b, normal, e):
    """The bounce impulse along the unit normal n (from A to B), restitution e.

    vn = (vB - vA) · n, the closing speed (px/s); nothing when vn >= 0 (the
    balls already separate). Else j = -(1 + e) vn / (1/mA + 1/mB), and
    vA -= j n / mA, vB += j n / mB, with inv_mass = 1/m (0 for a cushion).
    No spin term: the balls do not spin.
    """
    # --- step 3: the bounce impulse ---
    # Step 3 (lesson: "5. Impulses that spin, and friction"): when the balls close along the normal, give B the
    # impulse +j n and A -j n, j = -(1 + e) vn / (1/mA + 1/mB), each changing its velocity by its inverse mass.
    return  # until you write step 3, balls touch without bouncing: replace this placeholder
    # --- end of step 3 ---


def cloth_slowing(vel, mu, dt):
    """A ball's velocity (px/s) after dt s on a cloth of rolling resistance mu.

    The speed drops by mu g dt along -v, and never past zero: a ball slower
    than that stops (the velocity becomes exactly (0, 0)).
    """
    # --- step 4: the cloth slows the ball ---
    # Step 4 (lesson: "5. Impulses that spin, and friction"): lower the speed by mu * G * dt without turning the
    # velocity round: a ball slower than that stops at exactly (0, 0).
    return vel  # until you write step 4, the balls roll for ever: replace this placeholder
    # --- end of step 4 ---


def resolve(a, b, normal, point):
    """The World's resolve hook: every contact bounces with the table's restitution."""
    bounce(a, b, normal, RESTITUTION)


def build(item):
    """One ball from {"pos", optional "vel", "color", "rolling" (the cloth's μ_r under it)}."""
    ball = Body(Circle(RADIUS), item["pos"], MASS, vel=item.get("vel", (0, 0)), color=tuple(item.get("color", WHITE)))
    ball.rolling = item.get("rolling", ROLLING)
    return ball


def make_scene(rng):
    """The four cushions, ten balls racked in a triangle (colours shuffled by rng) and the cue ball breaking them."""
    t, c = TABLE, CUSHION
    cushions = [Body(box_points(w, h), pos, 0, color=GREY) for w, h, pos in (
        (t.width + 2 * c, c, (t.centerx, t.top - c / 2)), (t.width + 2 * c, c, (t.centerx, t.bottom + c / 2)),
        (c, t.height, (t.left - c / 2, t.centery)), (c, t.height, (t.right + c / 2, t.centery)))]
    gap = 2 * RADIUS + 0.5   # px between racked balls' centres: touching, not overlapping
    spots = [(t.left + 0.7 * t.width + row * gap * 0.866, t.centery + (k - row / 2) * gap)
             for row in range(4) for k in range(row + 1)]
    cue = build({"pos": (t.left + t.width / 4, t.centery), "vel": (MAX_SHOT, rng.uniform(-20, 20))})
    return cushions + [cue] + [
        build({"pos": spot, "color": color}) for spot, color in zip(spots, rng.sample(COLORS, len(spots)))]


def make_world(rng):
    """The table in a World with its effects, calling this file's circle_circle() and, through resolve(), bounce()."""
    return World(lab.scene(make_scene(rng), build=build), effects=EFFECTS,  # lab runtime: scene()
                 circle_circle=circle_circle, resolve=resolve)


def balls_of(world):
    """The world's balls (its moving bodies), the cue ball first."""
    return [body for body in world.bodies if body.inv_mass != 0]


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("Billiards")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = make_world(rng)
    panel = LabPanel()  # solver panel
    running = True
    # Step 5: watch the break bounce the balls apart and the cloth stop them; click to shoot the white ball again.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                cue = balls_of(world)[0]
                aim = pygame.Vector2(event.pos) - cue.pos
                if aim.length() > 0:
                    cue.vel = aim.normalize() * min(MAX_SHOT, 3 * aim.length())
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = make_world(rng)
        steps = panel.advance(world, dt)  # solver panel: fixed steps, long frames clamped
        balls = balls_of(world)
        for ball in balls:
            ball.vel = cloth_slowing(ball.vel, ball.rolling, steps * world.step_seconds)
        lab.record(world.bodies, world.contacts)  # lab runtime: record()

        screen.fill(GREY)
        pygame.draw.rect(screen, CLOTH, TABLE)
        for ball in balls:
            pygame.draw.circle(screen, ball.color, ball.pos, RADIUS)
        moving = sum(1 for ball in balls if ball.vel.length() > 0)
        draw_text(screen, font, f"balls rolling {moving}/{len(balls)} | [click] shoot the white ball  [R] rack")
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()
    print(f"balls still rolling at the end: {sum(1 for ball in balls_of(world) if ball.vel.length() > 0)}")


if __name__ == "__main__":
    main()
