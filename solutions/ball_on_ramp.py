"""Ball on the Ramp: a Lesson 11 lab ("Going further").

A solid ball rolls down the crates lab's 22° ramp, drops onto the floor
and knocks crates over. Your circle_polygon() finds where the ball touches a
polygon (the ramp, the floor, a crate), separate() pushes overlapping bodies
apart, disc_inertia() says how hard the ball is to spin, contact_point() says
where on the ball a contact pushes, and the friction in resolve() turns the
slide into a roll. Crates against crates use the library's sat(); everything
else (bodies, the fixed-step world, drawing) comes from lesson11.physics2d.

The comments "Step 1" to "Step 8" follow the exercise's eight steps. Steps 2
to 7 are the code between the lines `# --- step N: ... ---` and
`# --- end of step N ---`: yours to write in the starter, done in the solution
(where each step opens with the starter's text for it, between
`# BEGIN PROMPT` and `# END PROMPT`). Each step's comment names the section of
the lesson (lesson11/README.md) or of this lab's page (lesson11/labs/ball_on_ramp.md)
that explains it. In the starter some steps
hold a placeholder line, marked "replace this placeholder", that keeps the
file running until you write the step: replace that line with your code. Code
written above a placeholder left in place is wasted: a placeholder `return`
hands back its stand-in value unless your code returned first.

Controls: left click drops a ball, right click drops a crate, R resets, D shows
contact points and normals. The solver panel (lesson11/panel.py, lines marked
`# solver panel`) lists its own keys on screen. Lines marked `# lab runtime`
let the checker run this file headless; they change nothing when you run it
yourself.

Units: px, s, rad; y grows downward; a positive angle (and a positive spin)
turns clockwise on screen, so a ball rolling to the right has omega > 0.
"""
import math
import random

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import (Body, Circle, World, apply_impulse, box_points, centre_of, cross, inside,
                                relative_velocity)
from lesson11.physics2d.draw import draw_body, draw_contacts, draw_text

WIDTH, HEIGHT = 900, 600
RESTING_SPEED = 30   # px/s: slower impacts do not bounce (stops resting jitter)
SLOP = 0.5           # px of overlap the push-out leaves alone
PERCENT = 0.4        # share of the remaining overlap pushed out per push
BALL_RADIUS = 20     # px
MAX_DYNAMIC = 14     # balls and crates together
STATIC_BODIES = 3    # floor, ramp, wall
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)
BALL_COLOR = (90, 170, 230)

# Step 1: run this file and watch the ball.


def closest_on_segment(p, a, b):
    """The point of the segment a–b (px) nearest to the point p (px).

    With ab = b - a, the point is a + ab t where t = (p - a)·ab / (ab·ab),
    clamped to [0, 1] so that it stays on the segment (0 at a, 1 at b).
    """
    ab = b - a
    # --- step 2: the closest point on one edge ---
    # BEGIN PROMPT
    # Step 2 (lesson: "A ball against a polygon"): project p onto the edge's line,
    # t = (p - a)·ab / (ab·ab), then clamp t to [0, 1] so the point stays between a and b,
    # and return a + ab * t.
    # starter: return pygame.Vector2(math.inf, math.inf)  # until you write step 2, the ball falls through: replace this placeholder
    # END PROMPT
    t = (p - a).dot(ab) / ab.dot(ab)
    t = max(0.0, min(1.0, t))
    return a + ab * t
    # --- end of step 2 ---


def circle_polygon(center, radius, points):
    """A circle (center px, radius px) against a convex polygon (world points, px).

    Returns None when they are apart, else (normal, depth): the unit normal
    pointing from the circle into the polygon, and the overlap in px. With q the
    point of the outline closest to the center and d = |q - center|:
      center outside, d < radius:  normal = (q - center) / d, depth = radius - d
      center inside:               normal = (center - q) / d, depth = radius + d
    """
    closest = min((closest_on_segment(center, points[i], points[(i + 1) % len(points)])
                   for i in range(len(points))), key=center.distance_squared_to)
    offset = closest - center
    dist = offset.length()
    if dist < 1e-9:  # the center exactly on the outline: push away from the polygon's middle
        return (centre_of(points) - center).normalize(), radius
    # --- step 3: the center inside the polygon ---
    # BEGIN PROMPT
    # Step 3 (lesson: "A ball against a polygon"): if the center is already inside the polygon
    # (inside(center, points)), the nearest edge is the ball's way out, so the push must go the
    # other way: return the normal -offset / dist and the depth radius + dist (the ball leaves
    # through that edge).
    # END PROMPT
    if inside(center, points):
        return -offset / dist, radius + dist
    # --- end of step 3 ---
    if dist >= radius:
        return None
    return offset / dist, radius - dist


def separate(a, b, normal, depth):
    """Push overlapping bodies apart along the normal (A to B), split by inverse mass.

    push = max(depth - SLOP, 0) * PERCENT px in all; A moves back by
    push * (1/mA) / (1/mA + 1/mB), B forward by push * (1/mB) / (1/mA + 1/mB),
    so a static body (1/m = 0) never moves and a light body moves more.
    """
    total = a.inv_mass + b.inv_mass
    if total == 0:
        return  # two static bodies
    push = max(depth - SLOP, 0.0) * PERCENT
    # --- step 4: split the push-out by inverse mass ---
    # BEGIN PROMPT
    # Step 4 (lesson: "5. Impulses that spin, and friction", the push-out): split the push by
    # inverse mass. Move A back along the normal by push * a.inv_mass / total and B forward by
    # push * b.inv_mass / total, so a static body never moves and a light body moves more than
    # a heavy one.
    # END PROMPT
    a.pos -= normal * (push * a.inv_mass / total)
    b.pos += normal * (push * b.inv_mass / total)
    # --- end of step 4 ---


def disc_inertia(mass, radius):
    """Moment of inertia (mass·px²) of a solid disc about its center: I = ½ m r²."""
    # --- step 5: the ball's moment of inertia ---
    # BEGIN PROMPT
    # Step 5 (lesson: "4. Spin: angular velocity and moment of inertia"): return the moment of
    # inertia of a solid disc of this mass and radius, I = ½ m r².
    # starter: return math.inf  # until you write step 5, the ball cannot turn: replace this placeholder
    # END PROMPT
    return 0.5 * mass * radius ** 2
    # --- end of step 5 ---


def contact_point(center, radius, normal, depth):
    """Where a contact pushes on a ball (world px): the point of its surface along the normal.

    The normal (unit) points out of the ball into the other body, so the
    point is center + normal * radius. depth (px) is the overlap there.
    """
    # --- step 6: the contact point on the ball's surface ---
    # BEGIN PROMPT
    # Step 6 (lesson: "A ball against a polygon"): a contact pushes on the ball's
    # surface, not at its center: return the point radius px from the center along the normal.
    # starter: return center  # until you write step 6, every push acts at the center (no turning): replace this placeholder
    # END PROMPT
    return center + normal * radius
    # --- end of step 6 ---


def resolve(a, b, normal, point):
    """Normal impulse with restitution, then Coulomb friction, at one contact point (world px).

    Normal: j = -(1 + e) vn / k with k = 1/mA + 1/mB + (ra × n)²/IA + (rb × n)²/IB.
    Friction along the slip direction t: jt = -rel·t / kt (kt: k with t for n),
    clamped to [-mu j, mu j]; both impulses act at the contact point, so they
    change the spin as well as the velocity.
    """
    ra, rb = point - a.pos, point - b.pos
    rel = relative_velocity(a, b, ra, rb)
    vn = rel.dot(normal)
    if vn >= 0:
        return  # the contact points are already separating
    ran, rbn = cross(ra, normal), cross(rb, normal)
    k = a.inv_mass + b.inv_mass + ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia
    e = min(a.restitution, b.restitution) if vn < -RESTING_SPEED else 0.0
    j = -(1 + e) * vn / k
    apply_impulse(a, b, normal * j, ra, rb)

    rel = relative_velocity(a, b, ra, rb)
    tangent = rel - normal * rel.dot(normal)
    if tangent.length_squared() <= 1e-12:
        return  # no slip: no friction needed
    t = tangent.normalize()
    mu = math.sqrt(a.friction * b.friction)
    # --- step 7: friction at the contact point makes the ball roll ---
    # BEGIN PROMPT
    # Step 7 (lesson: "5. Impulses that spin, and friction"): the friction impulse. Compute kt
    # like k but along t (with both spin terms), jt = -rel·t / kt, clamp it to [-mu * j, mu * j]
    # (Coulomb), and apply t * jt at the contact with apply_impulse, so it turns the ball.
    # END PROMPT
    rat, rbt = cross(ra, t), cross(rb, t)
    kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
    jt = -rel.dot(t) / kt  # the impulse that would stop the slip
    jt = max(-mu * j, min(mu * j, jt))  # Coulomb: |friction| <= mu * normal impulse
    apply_impulse(a, b, t * jt, ra, rb)
    # --- end of step 7 ---


def make_ball(pos, radius=BALL_RADIUS, friction=0.6, vel=(0, 0), omega=0.0):
    """A solid ball of radius px at pos (px); mass = area / 1000 = π r² / 1000, I = disc_inertia(m, r)."""
    mass = math.pi * radius ** 2 / 1000
    ball = Body(Circle(radius), pos, mass, vel=vel, omega=omega, friction=friction, color=BALL_COLOR)
    inertia = disc_inertia(mass, radius)
    if not inertia > 0:
        raise ValueError(f"disc_inertia({mass:.4g}, {radius:g}) returned {inertia!r}; a moment of inertia is > 0")
    ball.inertia, ball.inv_inertia = inertia, 1 / inertia  # 1 / inf = 0: a ball that cannot turn
    return ball


def make_crate(rng, pos):
    """A crate of random size (30-70 × 30-90 px) at pos, standing upright; mass = area / 1000."""
    w, h = rng.randint(30, 70), rng.randint(30, 90)
    color = (rng.randint(170, 240), rng.randint(110, 170), rng.randint(60, 110))
    return Body(box_points(w, h), pos, mass=w * h / 1000, color=color)


def build(item):
    """One body for the checker's scenario: a ball if the item has "r" (px), else a crate ("w", "h" px).

    A ball item may give "friction" (mu), "vel" (px/s) and "omega" (rad/s); a crate
    item is made by the lab runtime's crate() (mass w·h/1000, "angle", "vel", "omega").
    """
    if "r" in item:
        return make_ball(item["pos"], item["r"], item.get("friction", 0.6), item.get("vel", (0, 0)),
                         item.get("omega", 0.0))
    return lab.crate(item)


def make_scene(rng):
    """Floor, the 22° ramp, a wall just off the right edge, a ball at the top of the ramp and two crates."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    ramp = Body(box_points(420, 24), (230, 380), 0, angle=math.radians(22), color=GREY)
    wall = Body(box_points(30, HEIGHT), (WIDTH + 10, HEIGHT / 2), 0, color=GREY)
    ball = make_ball((70, 278))
    tall = Body(box_points(24, 90), (600, HEIGHT - 85), 24 * 90 / 1000, color=(220, 140, 80))
    return [floor, ramp, wall, ball, tall, make_crate(rng, (760, 400))]


def make_world(rng):
    """A World that runs this file's circle_polygon(), contact_point(), resolve() and separate() at 1/120 s steps."""
    return World(lab.scene(make_scene(rng), build=build), resolve=resolve, separate=separate,  # lab runtime: scene()
                 circle_polygon=circle_polygon, circle_point=contact_point)


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("Ball on the Ramp")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = make_world(rng)
    debug = True
    running = True
    panel = LabPanel()  # solver panel
    # Step 8: left-click to drop a ball and right-click to drop a crate on the ramp; watch a ball roll and knock
    # crates over.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button in (1, 3):
                if len(world.bodies) - STATIC_BODIES < MAX_DYNAMIC:
                    world.add(make_ball(event.pos) if event.button == 1 else make_crate(rng, event.pos))
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = make_world(rng)
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_d:
                debug = not debug
        panel.advance(world, dt)  # solver panel: fixed steps, long frames clamped
        lab.record(world.bodies, world.contacts)  # lab runtime: record()

        screen.fill(BACKGROUND)
        for body in world.bodies:
            draw_body(screen, body)
        if debug:
            draw_contacts(screen, world.contacts)
        balls = sum(1 for body in world.bodies if body.shape.kind == "circle")
        crates = len(world.bodies) - STATIC_BODIES - balls
        hud = (f"balls {balls} | crates {crates} | contacts {len(world.contacts)} | "
               "[click] ball  [right click] crate  [R] reset  [D] debug")
        draw_text(screen, font, hud)
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()


if __name__ == "__main__":
    main()
