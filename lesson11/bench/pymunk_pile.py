"""The pile scenes rebuilt in pymunk, for a side-by-side run with physics2d.

Same floor, crate sizes, masses, gravity (0, 980) with y down, step 1/120 s
and solver iterations as scenes.py. pymunk has no "up": y down with gravity
(0, 980) behaves exactly like y up with (0, -980).

Two material rules differ and are matched here:
  friction     physics2d uses √(μA μB); pymunk multiplies μA μB. Each pymunk
               shape gets √0.6, so a pair gets 0.6 in both engines.
  restitution  physics2d uses min(eA, eB); pymunk multiplies eA eB. Each shape
               gets √0.2, so a pair gets 0.2 in both.
What is NOT the same, and cannot be made the same: pymunk keeps impulses across
iterations and steps (accumulated, warm-started) and removes overlap with a
velocity bias (collision_slop 0.1 px, collision_bias = share of the overlap
left after one second, default 0.9^60), where the lesson's World pushes
positions by 40 % of (depth - 0.5 px) per pass.
"""
import math

import pymunk

from .scenes import BOX, BOX_MASS, FLOOR_TOP, FLOOR_WIDTH, FLOOR_X, pile_positions

FRICTION = math.sqrt(0.6)     # per shape; a pair gets 0.6
ELASTICITY = math.sqrt(0.2)   # per shape; a pair gets 0.2


class PymunkPile:
    """A pymunk Space holding the floor and the crates of scenes.pile_positions(name)."""

    def __init__(self, name, iterations=6, step=1 / 120):
        self.space = pymunk.Space()
        self.space.gravity = (0, 980)
        self.space.iterations = iterations
        self.step_seconds = step
        half_w, half_h, centre_y = FLOOR_WIDTH / 2, 20, FLOOR_TOP + 20
        floor = pymunk.Poly(self.space.static_body,
                            [(FLOOR_X - half_w, centre_y - half_h), (FLOOR_X + half_w, centre_y - half_h),
                             (FLOOR_X + half_w, centre_y + half_h), (FLOOR_X - half_w, centre_y + half_h)])
        floor.friction, floor.elasticity = FRICTION, ELASTICITY
        self.space.add(floor)
        self.crates = []
        for centre in pile_positions(name):
            body = pymunk.Body(BOX_MASS, pymunk.moment_for_box(BOX_MASS, (BOX, BOX)))
            body.position = centre
            shape = pymunk.Poly.create_box(body, (BOX, BOX))
            shape.friction, shape.elasticity = FRICTION, ELASTICITY
            self.space.add(body, shape)
            self.crates.append((body, shape))

    def step(self):
        """One fixed step of 1/120 s."""
        self.space.step(self.step_seconds)

    def crate_corners(self):
        """World corners (px) of every crate, as (x, y) objects with .y."""
        return [[body.local_to_world(v) for v in shape.get_vertices()] for body, shape in self.crates]

    def top_position(self):
        """Centre (px) of the last crate, the top of the pile."""
        return self.crates[-1][0].position

    def kinetic_energy(self):
        """½ m |v|² + ½ I ω² summed over the crates (pymunk's own kinetic_energy leaves out the ½)."""
        return sum(0.5 * b.mass * (b.velocity.x ** 2 + b.velocity.y ** 2) + 0.5 * b.moment * b.angular_velocity ** 2
                   for b, _ in self.crates)
