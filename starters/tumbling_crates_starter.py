"""Tumbling Crates: the Lesson 11 practice exercise (lesson11/README.md, "Practice exercise").

Run it: python starters/tumbling_crates_starter.py  (click drops a crate, R resets,
D hides the contact normals; the panel's P pauses and O steps).
Write steps 2 to 6 between the `# --- step N` and `# --- end of step N ---` lines and
change nothing else. Where a step holds a line marked "replace this placeholder",
replace that line with your code: code written above it is wasted.
Check it: python -m checker starters/tumbling_crates_starter.py  (a mark and a hint
per step; add --show to see the first failure in a window).
"""
import math
import random

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import Body, World, box_points, centre_of, cross, edge_normals, project, spin_velocity
from lesson11.physics2d.draw import draw_body, draw_contacts, draw_text

WIDTH, HEIGHT = 900, 600
RESTING_SPEED = 30   # px/s: slower impacts do not bounce (stops resting jitter)
FAST_MOVER = 30      # px/s: a crate faster than this at the end counts as a fast mover
MAX_CRATES = 14
STATIC_BODIES = 3    # floor, ramp, wall
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)

# Step 1: run this file and watch the crates fall.


def sat(pa, pb):
    """Separating Axis Test for two convex polygons (lists of world points, px).

    Returns None when they are apart, else (normal, depth): the unit normal
    pointing from A to B and the overlap in px along it.
    """
    best_axis, best_depth = None, math.inf
    # --- step 2: the SAT loop ---
    # Step 2 (lesson: "2. The Separating Axis Theorem: the flashlight picture"): loop over the
    # edge normals of both polygons (edge_normals); project pa and pb onto each axis (project).
    # A gap on any axis means they are apart: return None. Otherwise keep the axis with the
    # smallest overlap in best_axis and its overlap in best_depth.
    return None  # until you write step 2, nothing ever collides: replace this placeholder
    # --- end of step 2 ---
    # --- step 3: make the normal point from A to B ---
    # Step 3 (lesson: "3. Depth, direction and contact points"): the axis may point either
    # way, whichever body's edge it came from. If it points from B towards A (its dot product
    # with centre_of(pb) - centre_of(pa) is negative), turn it round: best_axis = -best_axis.
    # --- end of step 3 ---
    return best_axis, best_depth


def apply_impulse(a, b, impulse, ra, rb):
    """Equal and opposite impulse at the contact: changes velocity AND spin."""
    a.vel -= impulse * a.inv_mass
    b.vel += impulse * b.inv_mass
    # --- step 6: the two spin updates ---
    # Step 6 (lesson: "5. Impulses that spin, and friction"): the impulse also changes the
    # spin. Update a.omega and b.omega with cross(ra, impulse) and cross(rb, impulse) times
    # each inverse inertia, with the same signs as the two velocity lines above (A -=, B +=).
    # --- end of step 6 ---


def resolve(a, b, normal, point):
    """Normal impulse with restitution, then Coulomb friction, at one contact point."""
    ra, rb = point - a.pos, point - b.pos
    rel = (b.vel + spin_velocity(b.omega, rb)) - (a.vel + spin_velocity(a.omega, ra))
    vn = rel.dot(normal)
    if vn >= 0:
        return  # the contact points are already separating
    ran, rbn = cross(ra, normal), cross(rb, normal)
    k = a.inv_mass + b.inv_mass
    # --- step 4: the spin terms of the effective mass ---
    # Step 4 (lesson: "5. Impulses that spin, and friction"): add each body's spin term
    # to k: (ra × n)² / I_A and (rb × n)² / I_B. Dividing by I is multiplying by inv_inertia
    # (1 / I, and 0 for a static body): ran * ran * a.inv_inertia, and the same for b.
    # --- end of step 4 ---
    e = min(a.restitution, b.restitution) if vn < -RESTING_SPEED else 0.0
    j = -(1 + e) * vn / k
    apply_impulse(a, b, normal * j, ra, rb)

    rel = (b.vel + spin_velocity(b.omega, rb)) - (a.vel + spin_velocity(a.omega, ra))
    tangent = rel - normal * rel.dot(normal)
    if tangent.length_squared() > 1e-12:
        t = tangent.normalize()
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt  # the impulse that would stop the sliding
        mu = math.sqrt(a.friction * b.friction)
        # --- step 5: Coulomb's law, |jt| <= mu * j ---
        # Step 5 (lesson: "5. Impulses that spin, and friction"): Coulomb's law. Friction may
        # never be bigger than mu times the normal impulse j: keep jt between -mu * j and mu * j.
        # --- end of step 5 ---
        apply_impulse(a, b, t * jt, ra, rb)


def make_crate(rng, pos):
    """A crate of random size (40-90 × 30-70 px) and angle at pos; mass = area / 1000."""
    w, h = rng.randint(40, 90), rng.randint(30, 70)
    color = (rng.randint(170, 240), rng.randint(110, 170), rng.randint(60, 110))
    return Body(box_points(w, h), pos, mass=w * h / 1000, angle=rng.uniform(0, math.pi), color=color)


def make_scene(rng):
    """Floor, a 22° ramp, a wall just off the right edge, and four falling crates."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    ramp = Body(box_points(420, 24), (230, 380), 0, angle=math.radians(22), color=GREY)
    wall = Body(box_points(30, HEIGHT), (WIDTH + 10, HEIGHT / 2), 0, color=GREY)
    crates = [make_crate(rng, (150 + i * 180, 80 + 40 * i)) for i in range(4)]
    return [floor, ramp, wall] + crates


def make_world(rng):
    """A World that runs this file's sat() and resolve() at 1/120 s steps."""
    return World(lab.scene(make_scene(rng)), sat=sat, resolve=resolve)  # lab runtime: scene()


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("Tumbling Crates")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = make_world(rng)
    debug = True
    simulated = 0.0
    running = True
    panel = LabPanel()  # solver panel
    # Step 7: click to drop more crates on the ramp and on the pile, and watch them settle.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                if len(world.bodies) - STATIC_BODIES < MAX_CRATES:
                    world.add(make_crate(rng, event.pos))
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = make_world(rng)
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_d:
                debug = not debug
        simulated += panel.advance(world, dt) * world.step_seconds  # solver panel: fixed steps, long frames clamped
        lab.record(world.bodies, world.contacts)  # lab runtime: record()

        screen.fill(BACKGROUND)
        for body in world.bodies:
            draw_body(screen, body)
        if debug:
            draw_contacts(screen, world.contacts)
        crates = len(world.bodies) - STATIC_BODIES
        hud = f"crates {crates} | contacts {len(world.contacts)} | [click] drop crate  [R] reset  [D] debug"
        draw_text(screen, font, hud)
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()
    moving = sum(1 for body in world.bodies if body.inv_mass > 0 and body.vel.length() > FAST_MOVER)
    print(f"Simulated {simulated:.1f} s with {len(world.bodies) - STATIC_BODIES} crates; fast movers now: {moving}")


if __name__ == "__main__":
    main()
