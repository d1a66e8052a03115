"""Bullets: a Lesson 11 lab ("Going further").

A gun on the left fires small, fast circles at a 4 px wall and at crates on
the floor. Checked only where they are once per step, the bullets jump
straight through the wall; this lab makes them stop. Your circle_toi() finds
the moment two moving circles first touch (a quadratic in t),
bounding_radius() and time_of_impact() skip every body whose bounding circle
the bullet cannot reach this step before the exact swept test against its
outline, and swept_move() moves a bullet to its time of impact, resolves the
hit there and spends the rest of the step with the new velocity. Everything
else (bodies, the fixed-step world, the swept face-and-corner test
circle_polygon_toi, drawing) comes from lesson11.physics2d.

The comments "Step 1" to "Step 6" follow the exercise's six steps. Steps 2 to
5 are the code between the lines `# --- step N: ... ---` and
`# --- end of step N ---`: yours to write in the starter, done in the solution
(where each step opens with the starter's text for it, between
`# BEGIN PROMPT` and `# END PROMPT`). Each step's comment names the section of
the lesson (lesson11/README.md) or of this lab's page (lesson11/labs/bullets.md)
that explains it. In the starter some steps
hold a placeholder line, marked "replace this placeholder", that keeps the
file running until you write the step: replace that line with your code. Code
written above a placeholder left in place is wasted: a placeholder `return`
hands back its stand-in value unless your code returned first, and a
placeholder move or assignment runs again after yours.

Controls: click fires a bullet from the gun towards the mouse. Keys 1-5 choose
how bullets move: 1 plain steps, 2 / 3 / 4 sub-stepping ×2 / ×4 / ×8, 5
continuous collision detection (CCD). V changes the bullet speed, R resets,
D shows contact points and normals. The HUD counts the bullets fired and the
bullets that tunnelled through the wall, and the physics ms per frame. The
solver panel (lesson11/panel.py, lines marked `# solver panel`) lists its own
keys on screen. Lines marked `# lab runtime` let the checker run this file
headless; they change nothing when you run it yourself.

Units: px, s, rad; y grows downward; gravity (0, 980) px/s², step 1/120 s.
"""
import math
import random
import time

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import LESSON_EFFECTS, Body, Circle, Vector2, World, box_points, circle_polygon_toi
from lesson11.physics2d.draw import draw_body, draw_contacts, draw_text

WIDTH, HEIGHT = 900, 600
GUN = Vector2(40, 250)       # px, where bullets start
WALL_X = 470.0               # px, the centre line of the thin wall
WALL_WIDTH = 4.0             # px: thinner than one step of a fast bullet
WALL_TOP, WALL_BOTTOM = 40.0, 440.0   # px, the wall's vertical extent
BULLET_RADIUS = 3.0          # px
BULLET_MASS = 0.05           # a crate of w × h px has mass w·h/1000
SPEEDS = (3000, 6000, 12000)  # px/s, the V key cycles through them
MAX_BULLETS = 40             # older bullets are removed first
MODES = {"plain": 1, "x2": 2, "x4": 4, "x8": 8, "ccd": 1}   # mode: sub-steps per 1/120 s step
MODE_KEYS = {pygame.K_1: "plain", pygame.K_2: "x2", pygame.K_3: "x4", pygame.K_4: "x8", pygame.K_5: "ccd"}
MODE_NAMES = {"plain": "plain steps", "x2": "sub-steps x2", "x4": "sub-steps x4", "x8": "sub-steps x8",
              "ccd": "CCD (swept)"}
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)
BULLET_COLOR = (250, 220, 90)

# Step 1: run this file, press 1 (plain steps) and click to the right of the wall: watch the bullets pass it.


def circle_toi(p1, v1, r1, p2, v2, r2, dt):
    """The time (s, in [0, dt]) at which two circles moving in straight lines first touch, or None.

    With dp = p2 - p1 and dv = v2 - v1 the gap vector at time t is dp + dv t,
    and the circles touch when |dp + dv t| = r1 + r2. Squared, that is
    a t² + b t + c = 0 with a = dv·dv, b = 2 dp·dv, c = dp·dp - (r1 + r2)².
    Already touching (c <= 0): 0.0. No relative motion (a = 0) or a negative
    discriminant (the paths miss): None. Otherwise the earlier root
    t = (-b - √(b² - 4ac)) / 2a, if it lies in [0, dt] (a negative root means
    the circles are moving apart: their touching lies in the past).
    """
    dp, dv = p2 - p1, v2 - v1
    reach = r1 + r2
    # --- step 2: the time of impact of two circles ---
    # BEGIN PROMPT
    # Step 2 (lesson: "Tunnelling, sub-stepping and continuous collision detection"):
    # c = dp·dp - reach²; return 0.0 when c <= 0 (already touching). Then a = dv·dv,
    # b = 2 dp·dv and the discriminant b² - 4ac: return None when a == 0 (no relative motion)
    # or the discriminant is negative (the paths miss). Otherwise take the EARLIER root
    # t = (-b - √(b² - 4ac)) / 2a and return it only if 0 <= t <= dt, else None.
    # starter: return None  # until you write step 2, nothing is ever hit under CCD: replace this placeholder
    # END PROMPT
    c = dp.dot(dp) - reach * reach
    if c <= 0:
        return 0.0  # already touching
    a = dv.dot(dv)
    b = 2 * dp.dot(dv)
    disc = b * b - 4 * a * c
    if a == 0 or disc < 0:
        return None  # no relative motion, or the paths miss
    t = (-b - math.sqrt(disc)) / (2 * a)  # the earlier root: first contact
    return t if 0 <= t <= dt else None
    # --- end of step 2 ---


def bounding_radius(points, centre):
    """The radius (px) of the smallest circle around `centre` that holds every point of the outline."""
    # --- step 3: the crate's bounding circle ---
    # BEGIN PROMPT
    # Step 3 (lesson: "A circle against a polygon, swept"): the bounding circle around `centre` must hold
    # every point: return the largest distance from centre to a point of the outline
    # (centre.distance_to(p)).
    # starter: return math.inf  # until you write step 3, every bounding circle is endless: replace this placeholder
    # END PROMPT
    return max(centre.distance_to(p) for p in points)
    # --- end of step 3 ---


def time_of_impact(bullet, other, dt):
    """When (s, in [0, dt]) the bullet first touches `other` (held still), and the normal: (t, normal) or None.

    The normal is a unit vector from the bullet into the other body. A circle
    is one circle_toi() call. A polygon is first tested cheaply: if the bullet
    cannot reach even the polygon's bounding circle this step, it cannot hit
    the polygon, and the exact swept test (circle_polygon_toi, the polygon's
    faces and corners) is skipped.
    """
    if other.shape.kind == "circle":
        t = circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(), other.radius, dt)
        if t is None:
            return None
        gap = other.pos - (bullet.pos + bullet.vel * t)
        return t, (gap.normalize() if gap.length_squared() > 0 else Vector2(1, 0))
    points = other.world_points()
    # --- step 4: the broad test against the bounding circle ---
    # BEGIN PROMPT
    # Step 4 (lesson: "A circle against a polygon, swept"): the broad test. Call circle_toi() for the
    # bullet (pos, vel, radius) against the crate's bounding circle: centre other.pos, not
    # moving (Vector2()), radius bounding_radius(points, other.pos), over dt. If it finds no
    # contact (None, not merely 0.0), the bullet cannot reach the crate this step: return None
    # at once, before the exact swept test below.
    # END PROMPT
    if circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(), bounding_radius(points, other.pos),
                  dt) is None:
        return None  # out of reach of the bounding circle: no polygon test needed
    # --- end of step 4 ---
    return circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius, points, dt)


def swept_move(world, bullet, dt):
    """Move a bullet through dt s without skipping anything: to its first impact, resolve, then the rest.

    The earliest time_of_impact() against every other body (each held still
    during the sweep) wins. No impact: the bullet moves v dt. An impact at t:
    the bullet moves v t to where it touches, world.resolve() changes the
    velocities at the contact point (on the bullet's surface along the normal),
    and the bullet spends the remaining dt - t moving with its new velocity.
    One impact per step: that remaining move is not swept, so after a rebound
    the bullet can pass into or through a second body within the same step
    unseen (the next step's sweep starts from wherever it ended).
    """
    first = None
    for other in world.bodies:
        if other is bullet:
            continue
        world.counters["swept_tests"] += 1
        hit = time_of_impact(bullet, other, dt)
        if hit is not None and (first is None or hit[0] < first[0]):
            first = (hit[0], hit[1], other)
    if first is None:
        bullet.pos += bullet.vel * dt
        return
    t, normal, other = first
    # --- step 5: move to the impact, resolve there, spend the rest of the step ---
    # BEGIN PROMPT
    # Step 5 (lesson: "The swept move"): move the
    # bullet to its time of impact (bullet.pos += bullet.vel * t), resolve the hit there with
    # world.resolve(bullet, other, normal, point), the point being on the bullet's surface
    # (bullet.pos + normal * bullet.radius), then spend the rest of the step, dt - t, moving with
    # the bullet's NEW velocity. Replace the placeholder below: left in, it moves the bullet again.
    # starter: bullet.pos += bullet.vel * dt  # until you write step 5, the bullet ignores the impact: replace this placeholder
    # END PROMPT
    bullet.pos += bullet.vel * t
    world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
    bullet.pos += bullet.vel * (dt - t)
    # --- end of step 5 ---


class BulletWorld(World):
    """physics2d's World whose bullets (with the "ccd" effect) move by this file's swept_move()."""

    def swept_move(self, bullet, dt):
        swept_move(self, bullet, dt)


def apply_mode(world, mode):
    """Set the world up for one of MODES: its sub-steps, and the "ccd" effect only for "ccd"."""
    world.substeps = MODES[mode]
    world.effects = world.effects | {"ccd"} if mode == "ccd" else world.effects - {"ccd"}


def make_bullet(pos, vel):
    """A bullet: a circle of BULLET_RADIUS px and BULLET_MASS at pos (px) moving at vel (px/s)."""
    return Body(Circle(BULLET_RADIUS), pos, BULLET_MASS, vel=vel, color=BULLET_COLOR, bullet=True)


def make_wall():
    """The static 4 px wall, from WALL_TOP to WALL_BOTTOM, centred on x = WALL_X."""
    return Body(box_points(WALL_WIDTH, WALL_BOTTOM - WALL_TOP), (WALL_X, (WALL_TOP + WALL_BOTTOM) / 2), 0, color=GREY)


def build(item):
    """One body for the checker's scenario: a bullet if the item has "r" (px; "vel" px/s), else a crate."""
    if "r" in item:
        return Body(Circle(item["r"]), item["pos"], item.get("mass", BULLET_MASS), vel=item.get("vel", (0, 0)),
                    color=BULLET_COLOR, bullet=True)
    return lab.crate(item)


def make_scene(rng):
    """The floor, the thin wall and three crates on the floor between the gun and the wall."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    crates = []
    for x, (w, h) in zip((250, 320, 390), ((40, 40), (50, 70), (36, 100))):
        color = (rng.randint(170, 240), rng.randint(110, 170), rng.randint(60, 110))
        crates.append(Body(box_points(w, h), (x, HEIGHT - 40 - h / 2), w * h / 1000, color=color))
    return [floor, make_wall()] + crates


def make_world(rng, mode="plain"):
    """A BulletWorld at 1/120 s steps in the given mode (the window starts in "plain"); bullets move by this
    file's swept_move() under CCD."""
    world = BulletWorld(lab.scene(make_scene(rng), build=build), effects=LESSON_EFFECTS)  # lab runtime: scene()
    apply_mode(world, mode)
    return world


def crossed_wall(before, after):
    """True when a bullet went from left of the wall's centre line to right of it, at the wall's height."""
    if not (before.x < WALL_X <= after.x):
        return False
    y = before.y + (after.y - before.y) * (WALL_X - before.x) / (after.x - before.x)
    return WALL_TOP <= y <= WALL_BOTTOM


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("Bullets")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    mode, speed = "plain", SPEEDS[-1]
    world = make_world(rng, mode)
    fired = tunnelled = 0
    seen = set()   # ids of the bullets already counted as tunnelled
    marks = []     # heights (px) where bullets went through the wall, drawn as red ticks
    streaks = []   # (from, to) of every bullet's move in the last frame
    spent = []     # physics ms of the last frames
    debug = True
    running = True
    panel = LabPanel()  # solver panel
    # Step 6: fire at the wall in each mode (keys 1-5) and at 12000 px/s (V): count the tunnelled bullets
    # and read the physics ms: sub-stepping costs ×n and still misses some, CCD misses none.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                aim = Vector2(event.pos) - GUN
                if aim.length_squared() > 0:
                    world.add(make_bullet(GUN, aim.normalize() * speed))
                    fired += 1
            elif event.type == pygame.KEYDOWN and event.key in MODE_KEYS:
                mode = MODE_KEYS[event.key]
                apply_mode(world, mode)
                panel.change("substeps", MODES[mode])  # solver panel: shows the mode's sub-steps
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_v:
                speed = SPEEDS[(SPEEDS.index(speed) + 1) % len(SPEEDS)]
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = make_world(rng, mode)
                fired = tunnelled = 0
                seen.clear()
                marks.clear()
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_d:
                debug = not debug
        bullets = [body for body in world.bodies if body.bullet]
        before = {id(body): Vector2(body.pos) for body in bullets}
        start = time.perf_counter()
        panel.advance(world, dt)  # solver panel: fixed steps, long frames clamped
        spent = (spent + [(time.perf_counter() - start) * 1000])[-30:]
        for body in bullets:
            if id(body) not in seen and crossed_wall(before[id(body)], body.pos):
                seen.add(id(body))
                tunnelled += 1
                marks.append(before[id(body)].y + (body.pos.y - before[id(body)].y)
                             * (WALL_X - before[id(body)].x) / (body.pos.x - before[id(body)].x))
        streaks = [(before[id(body)], Vector2(body.pos)) for body in bullets]
        for body in bullets[:-MAX_BULLETS] + [b for b in bullets if not -50 < b.pos.x < WIDTH + 50
                                              or not -50 < b.pos.y < HEIGHT + 50]:
            if body in world.bodies:
                world.remove(body)
        lab.record(world.bodies, world.contacts)  # lab runtime: record()

        screen.fill(BACKGROUND)
        for body in world.bodies:
            draw_body(screen, body)
        pygame.draw.circle(screen, BULLET_COLOR, GUN, 8, 2)
        for start, end in streaks:  # where each bullet went this frame
            pygame.draw.line(screen, BULLET_COLOR, start, end, 1)
        for y in marks[-50:]:  # where bullets tunnelled
            pygame.draw.line(screen, (235, 80, 80), (WALL_X - 8, y), (WALL_X + 8, y), 2)
        if debug:
            draw_contacts(screen, world.contacts)
        hud = (f"{MODE_NAMES[mode]} | {speed} px/s | fired {fired} | tunnelled {tunnelled} | "
               f"physics {sum(spent) / max(len(spent), 1):.2f} ms/frame")
        draw_text(screen, font, hud)
        draw_text(screen, font, "[click] fire  [1] plain [2] x2 [3] x4 [4] x8 [5] CCD  [V] speed  [R] reset  "
                  "[D] debug", (10, HEIGHT - 30))
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()


if __name__ == "__main__":
    main()
