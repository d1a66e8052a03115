"""Sleeping Crates: a Lesson 11 "Going further" exercise.

Forty crates in a pile cost the World a contact search over every pair, five
times a step, even when nothing in the pile moves. Sleeping stops paying for
that: a crate whose speed and spin stay under small thresholds for half a
second falls asleep (with every crate it touches: the pile sleeps as one
island). A sleeping crate is not integrated, and the broad phase never looks
at a pair in which neither body moves (two sleeping crates, or a sleeping crate
and the floor). An awake crate that touches a sleeping one wakes it, and the
island it fell asleep with.

physics2d's World runs the "sleep" effect; this file hands it three functions,
as the lesson's project hands in sat():
    sleep_timer(timer, speed, spin, dt)   after every step, for every awake crate
    moves(body)                           which bodies are integrated and tested
    wake_on_contact(a, b)                 for every touching pair: which bodies to wake

The comments "Step 1" to "Step 5" follow the exercise's five steps. Steps 2 to
4 are the code between the lines `# --- step N: ... ---` and
`# --- end of step N ---`: yours to write in the starter, done in the solution
(where each step opens with the starter's text for it, between
`# BEGIN PROMPT` and `# END PROMPT`). Each step's comment names the section of
the lesson (lesson11/README.md) or of this lab's page (lesson11/labs/sleeping_crates.md)
that explains it. In the starter some steps
hold a placeholder line, marked "replace this placeholder", that keeps the
file running until you write the step: replace that line with your code. Code
written above a placeholder left in place is wasted: a placeholder `return`
hands back its stand-in value unless your code returned first.

Controls: left click drops a crate (up to 40), R resets, D shows contact points
and normals. Sleeping crates are drawn dimmed; the HUD counts awake and
sleeping crates and shows the physics time per frame (ms). The solver panel
(lesson11/panel.py, lines marked `# solver panel`) lists its own keys on
screen. Lines marked `# lab runtime` let the checker run this file headless;
they change nothing when you run it yourself.
"""
import random

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import LESSON_EFFECTS, Body, World, box_points
from lesson11.physics2d.draw import draw_contacts, draw_text

WIDTH, HEIGHT = 900, 600
SLEEP_SPEED = 5.0    # px/s: slower than this ...
SLEEP_SPIN = 0.1     # rad/s: ... and spinning slower than this ...
SLEEP_AFTER = 0.5    # s: ... for this long, and a crate may fall asleep
MAX_CRATES = 40
STATIC_BODIES = 3    # floor, left wall, right wall
FAST_MOVER = 30      # px/s: a crate faster than this at the end counts as a fast mover
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)
DIM = 0.45           # a sleeping crate's colour is this share of its awake colour

# Step 1: run this file. Until you write steps 2-4 no crate ever sleeps: the HUD says 0 asleep.


def sleep_timer(timer, speed, spin, dt):
    """How long (s) a crate has been calm after this step of dt s.

    `timer` is the value after the last step, `speed` the crate's speed (px/s)
    and `spin` its angular velocity (rad/s, either sign). While the crate is
    slower than SLEEP_SPEED and spins slower than SLEEP_SPIN the timer grows by
    dt; one step above either threshold starts it again from 0. The World puts
    a crate to sleep once its timer (and that of every crate it touches)
    reaches SLEEP_AFTER.
    """
    # --- step 2: the sleep timer ---
    # Step 2 (lesson: "Sleeping"): while the crate is calm (speed < SLEEP_SPEED
    # and |spin| < SLEEP_SPIN) return timer + dt; one step above either threshold starts the
    # timer again from 0.
    return 0.0  # until you write step 2, no crate ever falls asleep: replace this placeholder
    # --- end of step 2 ---


def moves(body):
    """True if the World must move this body and test its pairs: it is dynamic and awake.

    A static body (inv_mass 0) never moves, and a sleeping one (body.asleep)
    stays where it fell asleep. World.integrate_velocities and
    World.integrate_positions skip a body for which this is False, and the
    World skips every pair in which neither body moves, so a sleeping pile on
    the floor costs no contact tests.
    """
    # --- step 3: skip sleeping bodies ---
    # Step 3 (lesson: "Sleeping"): static bodies (inv_mass 0) never move, and a
    # sleeping body (body.asleep) must not move either: return False for both.
    return body.inv_mass != 0  # until you write step 3, sleeping crates still move: replace this placeholder
    # --- end of step 3 ---


def wake_on_contact(a, b):
    """The bodies to wake when a and b touch: a list, empty if none.

    A sleeping body is woken when the other body of the pair is dynamic and
    awake (it moves, so it can push). The floor and the walls never wake
    anything, and two sleeping bodies leave each other asleep. The World wakes
    each body returned together with the island it fell asleep with.
    """
    # --- step 4: wake on contact ---
    # Step 4 (lesson: "Sleeping"): return a list of the bodies of the pair to
    # wake: a sleeping body whose partner is dynamic and awake. The floor and walls wake
    # nothing; [] if nothing wakes.
    return []  # until you write step 4, no contact wakes a sleeping crate: replace this placeholder
    # --- end of step 4 ---


def build(item):
    """One crate from {"w", "h", "pos", optional "angle", "vel", "omega", "asleep"} (mass w·h/1000)."""
    body = Body(box_points(item["w"], item["h"]), item["pos"], mass=item["w"] * item["h"] / 1000,
                angle=item.get("angle", 0.0), vel=item.get("vel", (0, 0)), omega=item.get("omega", 0.0),
                color=item.get("color", (214, 150, 86)))
    body.asleep = bool(item.get("asleep", False))
    return body


def random_crate(rng, pos):
    """A crate description at pos with a random size, angle and colour."""
    shade = rng.randint(-30, 30)
    return {"w": rng.randint(36, 56), "h": rng.randint(28, 44), "pos": list(pos), "angle": rng.uniform(-0.4, 0.4),
            "color": (200 + shade // 2, 140 + shade, 80 + shade)}


def make_scene(rng):
    """Floor, two walls, and eight crates falling into the bin between them."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    left = Body(box_points(30, HEIGHT), (15, HEIGHT / 2), 0, color=GREY)
    right = Body(box_points(30, HEIGHT), (WIDTH - 15, HEIGHT / 2), 0, color=GREY)
    crates = [build(random_crate(rng, (200 + 70 * i, 120 + 35 * (i % 3)))) for i in range(8)]
    return [floor, left, right] + crates


def make_world(rng):
    """A World with the "sleep" effect running this file's three functions, 1/120 s steps."""
    world = World(lab.scene(make_scene(rng), build=build), effects=LESSON_EFFECTS | {"sleep"},  # lab runtime: scene()
                  sleep_after=SLEEP_AFTER, sleep_timer=sleep_timer, moves=moves, wake=wake_on_contact)
    world.fall_asleep([body for body in world.bodies if body.asleep])  # crates set asleep sleep as one island
    return world


def draw_crate(screen, body):
    """A crate filled with its colour, dimmed while it sleeps."""
    colour = [int(c * DIM) for c in body.color] if body.asleep else body.color
    points = body.world_points()
    pygame.draw.polygon(screen, colour, points)
    pygame.draw.polygon(screen, (20, 20, 20), points, 2)


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("Sleeping Crates")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = make_world(rng)
    debug = False
    simulated = 0.0
    running = True
    panel = LabPanel()  # solver panel
    # Step 5: click until there are 40 crates, and watch the physics ms fall as the pile goes dim.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                if len(world.bodies) - STATIC_BODIES < MAX_CRATES:
                    world.add(build(random_crate(rng, event.pos)))
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = make_world(rng)
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_d:
                debug = not debug
        simulated += panel.advance(world, dt) * world.step_seconds  # solver panel: fixed steps, long frames clamped
        lab.record(world.bodies, world.contacts)  # lab runtime: record()

        screen.fill(BACKGROUND)
        for body in world.bodies:
            draw_crate(screen, body)
        if debug:
            draw_contacts(screen, world.contacts)
        crates = world.bodies[STATIC_BODIES:]
        asleep = sum(1 for body in crates if body.asleep)
        hud = (f"crates {len(crates)}/{MAX_CRATES} | awake {len(crates) - asleep} | asleep {asleep} | "
               f"physics {panel.measure(world)['ms']:.1f} ms/frame | [click] drop  [R] reset  [D] debug")
        draw_text(screen, font, hud)
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()
    moving = sum(1 for body in world.bodies if body.inv_mass > 0 and body.vel.length() > FAST_MOVER)
    asleep = sum(1 for body in world.bodies if body.asleep)
    print(f"Simulated {simulated:.1f} s with {len(world.bodies) - STATIC_BODIES} crates; asleep now: {asleep}; "
          f"fast movers now: {moving}")


if __name__ == "__main__":
    main()
