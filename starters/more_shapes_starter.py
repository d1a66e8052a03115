"""More Shapes: a Lesson 11 "Going further" exercise.

Triangles, pentagons, hexagons and little houses join the crates of the
lesson's project, on the same floor, 22° ramp and wall. The physics is the lesson's:
polygon_inertia works for any convex polygon as long as its points are
centred on the centroid, and SAT works for any convex polygon if it tests
every edge direction of both shapes. This file makes both true for the new
shapes: it builds regular polygons, centres any convex outline on its
area-weighted centroid, computes the moment of inertia by the triangle-fan
sum, and gives SAT each edge direction once. build() makes every body from
these functions, so the simulation runs on them.

The comments "Step 1" to "Step 6" follow the exercise's six steps. Steps 2 to
5 are the code between the lines `# --- step N: ... ---` and
`# --- end of step N ---`: yours to write in the starter, done in the solution
(where each step opens with the starter's text for it, between
`# BEGIN PROMPT` and `# END PROMPT`). Each step's comment names the section of
the lesson (lesson11/README.md) or of this lab's page (lesson11/labs/more_shapes.md)
that explains it. In the starter some steps
hold a placeholder line, marked "replace this placeholder", that keeps the
file running until you write the step: replace that line with your code. Code
written above a placeholder left in place is wasted: a placeholder `return`
hands back its stand-in value unless your code returned first, and a
placeholder move or assignment runs again after yours.

Controls: left click drops the next shape (box, triangle, pentagon, hexagon,
house, in turn), R resets, D shows contact points, normals and each body's
centre of mass. The solver panel (lesson11/panel.py, lines marked
`# solver panel`) lists its own keys on screen. Lines marked `# lab runtime`
let the checker run this file headless; they change nothing when you run it
yourself.
"""
import math
import random

import pygame
from pygame import Vector2

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import Body, Polygon, World, box_points, centre_of, cross, edge_normals, project
from lesson11.physics2d.draw import draw_body, draw_contacts, draw_text

WIDTH, HEIGHT = 900, 600
FAST_MOVER = 30      # px/s: a shape faster than this at the end counts as a fast mover
MAX_SHAPES = 14
STATIC_BODIES = 3    # floor, ramp, wall
PARALLEL = 1e-6      # |sin| of the angle below which two axes count as parallel
DENSITY = 1 / 1000   # mass per px², as for the crates (mass = area / 1000)
KINDS = ("box", "triangle", "pentagon", "hexagon", "house")
SIDES = {"triangle": 3, "pentagon": 5, "hexagon": 6}
COLORS = {"box": (214, 150, 86), "triangle": (110, 190, 150), "pentagon": (120, 160, 220),
          "hexagon": (220, 200, 100), "house": (200, 120, 150)}
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)

# Step 1: run this file. Until you write steps 2-5 every shape is a square that hardly turns.


def regular_polygon(sides, radius):
    """The corners (px) of a regular polygon centred on (0, 0), on a circle of `radius` px.

    Corner k sits at angle θk = 2πk / sides: (radius cos θk, radius sin θk), so
    corner 0 is at (radius, 0) and the corners run clockwise on screen (y down).
    """
    if isinstance(sides, bool) or not isinstance(sides, int) or sides < 3:
        raise ValueError(f"a regular polygon needs a whole number of sides >= 3, got {sides!r}")
    if not isinstance(radius, (int, float)) or not 0 < radius < math.inf:
        raise ValueError(f"a regular polygon needs a positive radius in px, got {radius!r}")
    # --- step 2: a regular polygon's corners ---
    # Step 2 (lesson: "The regular polygon"): return the `sides` corners of a
    # regular polygon centred on (0, 0): corner k at angle θk = 2πk / sides (radians), that is
    # Vector2(radius * math.cos(θk), radius * math.sin(θk)), for k = 0, 1, ..., sides - 1.
    return box_points(radius, radius)  # until you write step 2, every shape is a square: replace this placeholder
    # --- end of step 2 ---


def polygon_area(points):
    """Signed area (px²) by the shoelace formula: A = ½ Σ p_i × p_i+1 (positive for clockwise on screen)."""
    points = [Vector2(p) for p in points]
    return 0.5 * sum(cross(a, points[(i + 1) % len(points)]) for i, a in enumerate(points))


def polygon_centroid(points):
    """The area-weighted centroid (px) of a convex polygon (either winding).

    C = Σ (p_i + p_i+1) (p_i × p_i+1) / (6 A), with A the signed shoelace area.
    This is the centre of mass of the solid shape, not the average of its corners.
    """
    points = [Vector2(p) for p in points]
    if len(points) < 3:
        raise ValueError(f"a polygon needs at least 3 points, got {len(points)}")
    area = polygon_area(points)
    if abs(area) < 1e-9:
        raise ValueError("a polygon needs a non-zero area; these points lie on one line")
    # --- step 3: the area-weighted centroid ---
    # Step 3 (lesson: "The centroid": polygon_inertia needs
    # the points centred on the centroid): add up (a + b) * cross(a, b) over the edges a -> b
    # (the last edge runs from the last point back to the first) and return the sum / (6 * area).
    # Not the average of the corners: each edge's term is weighted by its triangle's area.
    return Vector2()  # until you write step 3, no outline is centred: replace this placeholder
    # --- end of step 3 ---


def centred(points):
    """The points (px) moved so that their centroid is at (0, 0): p - polygon_centroid(points)."""
    centre = polygon_centroid(points)
    return [Vector2(p) - centre for p in points]


def polygon_inertia(points, mass):
    """Moment of inertia (mass·px²) of a solid convex polygon about (0, 0), its centroid.

    The polygon is a fan of triangles (0, a, b), one per edge a→b, and
        I = m Σ |a × b| (a·a + a·b + b·b) / (6 Σ |a × b|).
    For a w × h box this is m (w² + h²) / 12; for a regular n-gon of
    circumradius r it is m r² (2 + cos(2π/n)) / 6.
    """
    points = [Vector2(p) for p in points]
    if len(points) < 3:
        raise ValueError(f"a polygon needs at least 3 points, got {len(points)}")
    if not isinstance(mass, (int, float)) or not 0 < mass < math.inf:
        raise ValueError(f"polygon_inertia needs a positive mass, got {mass!r}")
    # --- step 4: the triangle-fan sum ---
    # Step 4 (lesson: "4. Spin: angular velocity and moment of inertia", the convex polygon
    # row): the triangle-fan sum. For each edge a -> b, the triangle (0, a, b) weighs
    # area2 = |a × b| and adds area2 * (a·a + a·b + b·b); return mass * (that sum) / (6 * the
    # sum of the weights).
    return 1e9  # until you write step 4, shapes hardly turn: replace this placeholder
    # --- end of step 4 ---


def separating_axes(pa, pb):
    """The axes SAT must test for two convex polygons (world points, px): every edge normal
    of both, each direction once.

    Two edges whose normals are parallel (|n1 × n2| <= PARALLEL, pointing the same way
    or opposite) give the same overlap, so only the first of them is kept: a box
    has 2 directions, a hexagon 3, a triangle 3, a regular pentagon 5.
    """
    axes = []
    # --- step 5: skip parallel axes ---
    # Step 5 (lesson: "Parallel axes"): go through
    # edge_normals(pa) + edge_normals(pb) and append an axis to `axes` only if it is not
    # parallel to any axis already there: abs(cross(axis, kept)) > PARALLEL for every kept.
    # Parallel normals (pointing the same way or opposite) give the same overlap. Replace the
    # placeholder below: left in, it throws away the axes you collected.
    axes = edge_normals(pa) + edge_normals(pb)  # until you write step 5, every edge is tested: replace this placeholder
    # --- end of step 5 ---
    return axes


def sat(pa, pb):
    """Separating Axis Test for two convex polygons (lists of world points, px).

    Returns None when they are apart, else (normal, depth): the unit normal
    pointing from A to B and the smallest overlap in px, over separating_axes().
    """
    best_axis, best_depth = None, math.inf
    for axis in separating_axes(pa, pb):
        min_a, max_a = project(pa, axis)
        min_b, max_b = project(pb, axis)
        overlap = min(max_a, max_b) - max(min_a, min_b)
        if overlap <= 0:
            return None  # found a gap: not touching
        if overlap < best_depth:
            best_axis, best_depth = axis, overlap
    if best_axis is None:
        return None
    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:
        best_axis = -best_axis  # always from A to B
    return best_axis, best_depth


def outline(item):
    """The corners (px) of one shape, not yet centred: a box {"w", "h"}, a regular polygon
    {"size": circumradius}, or a house {"w", "h"} (a box with a gable roof, its corner at (0, 0))."""
    kind = item.get("kind", "box")
    if kind not in KINDS:
        raise ValueError(f"unknown shape kind {kind!r}; known: {', '.join(KINDS)}")
    needs = ("size",) if kind in SIDES else ("w", "h")
    if any(not isinstance(item.get(key), (int, float)) or not item[key] > 0 for key in needs):
        raise ValueError(f"a {kind} needs {' and '.join(repr(key) for key in needs)} in px (> 0), got {item!r}")
    if kind in SIDES:
        return regular_polygon(SIDES[kind], item["size"])
    w, h = item["w"], item["h"]
    if kind == "box":
        return box_points(w, h)
    return [Vector2(0, 0), Vector2(0, -0.6 * h), Vector2(w / 2, -h), Vector2(w, -0.6 * h), Vector2(w, 0)]


def build(item):
    """One Body from a shape description {"kind", "pos", size keys, optional "angle", "vel", "omega"}.

    The corners are centred with polygon_centroid, the mass is area × DENSITY and
    the moment of inertia comes from polygon_inertia: the lab's own functions.
    """
    local = centred(outline(item))
    mass = abs(polygon_area(local)) * DENSITY
    return Body(Polygon(local, recentre=False), item["pos"], mass, angle=item.get("angle", 0.0),
                vel=item.get("vel", (0, 0)), omega=item.get("omega", 0.0), inertia=polygon_inertia(local, mass),
                color=COLORS.get(item.get("kind", "box"), GREY))


def random_shape(rng, kind, pos):
    """A shape description of `kind` at pos with a random size and angle."""
    item = {"kind": kind, "pos": list(pos), "angle": rng.uniform(0, math.pi)}
    if kind in SIDES:
        item["size"] = rng.randint(24, 38)
    else:
        item["w"], item["h"] = rng.randint(40, 80), rng.randint(30, 60)
    return item


def make_scene(rng):
    """Floor, a 22° ramp, a wall just off the right edge, and four falling shapes."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    ramp = Body(box_points(420, 24), (230, 380), 0, angle=math.radians(22), color=GREY)
    wall = Body(box_points(30, HEIGHT), (WIDTH + 10, HEIGHT / 2), 0, color=GREY)
    shapes = [build(random_shape(rng, KINDS[i + 1], (150 + i * 180, 80 + 40 * i))) for i in range(4)]
    return [floor, ramp, wall] + shapes


def make_world(rng):
    """A World that runs this file's sat() at 1/120 s steps; every shape comes from build()."""
    return World(lab.scene(make_scene(rng), build=build), sat=sat)  # lab runtime: scene()


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("More Shapes")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = make_world(rng)
    debug = True
    simulated = 0.0
    drops = 0
    running = True
    panel = LabPanel()  # solver panel
    # Step 6: click to drop every kind of shape on the ramp and on the pile, and watch them settle.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                if len(world.bodies) - STATIC_BODIES < MAX_SHAPES:
                    world.add(build(random_shape(rng, KINDS[drops % len(KINDS)], event.pos)))
                    drops += 1
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
            for body in world.bodies[STATIC_BODIES:]:
                pygame.draw.circle(screen, (30, 30, 30), body.pos, 3)  # the centre of mass
        shapes = len(world.bodies) - STATIC_BODIES
        hud = (f"shapes {shapes} | next {KINDS[drops % len(KINDS)]} | contacts {len(world.contacts)} | "
               "[click] drop shape  [R] reset  [D] debug")
        draw_text(screen, font, hud)
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()
    moving = sum(1 for body in world.bodies if body.inv_mass > 0 and body.vel.length() > FAST_MOVER)
    print(f"Simulated {simulated:.1f} s with {len(world.bodies) - STATIC_BODIES} shapes; fast movers now: {moving}")


if __name__ == "__main__":
    main()
