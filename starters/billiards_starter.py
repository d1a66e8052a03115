"""Billiards: a Lesson 11 lab (written by `python -m checker new-lab`; make it yours).

Two crates fall onto the floor. The HUD shows the fastest approach along a
contact normal seen so far, read with normal_speed(): how fast B moves
relative to A along the contact's normal (px/s), negative while the two
approach, as the lesson's resolve() reads it before an impulse.

The comments "Step 1" to "Step 3" follow the exercise's steps. Step 2 is the
code between the lines `# --- step 2: ... ---` and `# --- end of step 2 ---`:
yours to write in the starter, done in the solution (where the step opens
with the starter's text for it, between `# BEGIN PROMPT` and `# END PROMPT`).
The step's comment names the section of the lesson (lesson11/README.md) that
explains it. In the starter the step holds a placeholder line, marked
"replace this placeholder", that keeps the file running until you write the
step: replace that line with your code. Code written above a placeholder left
in place is wasted: a placeholder `return` hands back its stand-in value
unless your code returned first.

Controls: left click drops a crate (up to 20), R resets.
"""
import random

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import Body, World, box_points
from lesson11.physics2d.draw import draw_text

WIDTH, HEIGHT = 900, 600
MAX_CRATES = 20
STATIC_BODIES = 1    # the floor
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)

# Step 1: run this file. Until you write step 2 the HUD reads 0.0 px/s, however hard the crates land.


def normal_speed(va, vb, normal):
    """How fast B moves relative to A along the unit normal (px/s): (vB - vA) · n.

    va, vb: the two bodies' velocities (px/s); normal: the contact's unit
    normal, from A to B. Negative while the bodies approach, positive while
    they separate, 0 when they slide past each other.
    """
    # --- step 2: the speed along the normal ---
    # Step 2 (lesson: "5. Impulses that spin, and friction"): return B's velocity relative to A's,
    # projected on the normal (a dot product); it is negative while the two approach.
    return 0.0  # until you write step 2, every contact reads 0.0 px/s: replace this placeholder
    # --- end of step 2 ---


def build(item):
    """One crate from {"w", "h", "pos", optional "angle", "vel", "omega"} (mass w·h/1000)."""
    return Body(box_points(item["w"], item["h"]), item["pos"], mass=item["w"] * item["h"] / 1000,
                angle=item.get("angle", 0.0), vel=item.get("vel", (0, 0)), omega=item.get("omega", 0.0),
                color=item.get("color", (214, 150, 86)))


def make_scene():
    """The floor and two crates dropped onto it, from 300 px and 400 px above it."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    return [floor, build({"w": 60, "h": 40, "pos": [300, 240]}), build({"w": 60, "h": 40, "pos": [600, 140]})]


def fastest_approach(world):
    """The fastest approach along a normal among the world's contacts (px/s, 0 when none approaches)."""
    return max([0.0] + [-normal_speed(c.a.vel, c.b.vel, c.normal) for c in world.contacts])


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("Billiards")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = World(lab.scene(make_scene(), build=build))  # lab runtime: scene()
    panel = LabPanel()  # solver panel
    fastest = 0.0
    running = True
    # Step 3: watch the crates land, then click to drop more and read the fastest approach.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                if len(world.bodies) - STATIC_BODIES < MAX_CRATES:
                    world.add(build({"w": rng.randint(36, 56), "h": rng.randint(28, 44), "pos": list(event.pos)}))
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = World(make_scene())
                fastest = 0.0
        panel.advance(world, dt)  # solver panel: fixed steps, long frames clamped
        lab.record(world.bodies, world.contacts)  # lab runtime: record()
        fastest = max(fastest, fastest_approach(world))

        screen.fill(BACKGROUND)
        for body in world.bodies:
            pygame.draw.polygon(screen, body.color, body.world_points())
        draw_text(screen, font, f"crates {len(world.bodies) - STATIC_BODIES}/{MAX_CRATES} | fastest approach "
                                f"{fastest:.1f} px/s | [click] drop  [R] reset")
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()
    print(f"fastest approach along a normal: {fastest:.1f} px/s")


if __name__ == "__main__":
    main()
