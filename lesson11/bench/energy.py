"""Energy books for the solver settings: does any setting make energy from nothing?

    python -m lesson11.bench.energy [--seconds S]   # prints one row per solver setting and scene

A scene is stepped at 1/120 s; before and after every step the total energy
E = Σ ½ m v² + ½ I ω² - m g·y + ½ m h g·v (y down, so a body that rises gains
m g per px) is taken. The last term is what the integrator (v += g h, then
x += v h, h the sub-step) keeps exactly in free flight: without it a bouncing
body seems to gain g h |v| at every bounce (5 px of height for a disc dropped
from 200 px) and to lose it again on its way. A step may lose energy (impacts, friction) and the push-out may lift
a body a fraction of a px; what it must not do is add more. Figures are given
in px of the scene's weight: ΔE / Σ m g, "as if the whole scene rose by".
  rise     the largest energy gain in one step (px)
  climb    the largest gain over any stretch of steps, clicks not counted (px)
  excess   the most the scene ever held above what it was given: its energy at the
           start plus that of each clicked crate as it was added (px; below 0 is a loss)
  speed    the fastest body at any step (px/s)
  outside  bodies that left the 900 × 600 px window (0, 0)-(900, 600)
The scenes are the Tumbling Crates lab's own (its solution's make_scene,
make_crate, sat and resolve, seed 11, clicks at 60 fps frames), a 10-box
stack between two walls and an e = 1 disc dropped from 200 px.
"""
import argparse
import importlib.util
import math
import os
import random
import time

from lesson11 import crate_scenes
from lesson11.physics2d import Body, Circle, World, box_points

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LAB_FILE = os.path.join(ROOT, "solutions", "tumbling_crates.py")
WINDOW = (0.0, 0.0, 900.0, 600.0)   # px: x0, y0, x1, y1 of the lab window
STEPS_PER_FRAME = 2                 # 1/120 s steps in a 60 fps frame
PILE_DROPS = crate_scenes.PILE_DROPS   # the lab's 12-crate pile: clicked every 20 frames from frame 10
OWN_DROPS = crate_scenes.DROPS   # the checker's clicks in the lab's own scene: (frame, position)
SOLVERS = {  # name: World settings
    "lesson solve-first": {"solver": "lesson", "order": "solve-first"},
    "lesson move-first": {"solver": "lesson", "order": "move-first"},
    "reference": {"solver": "accumulated"},
}
_lab = None


def lab():
    """The Tumbling Crates solution as a module (loaded once; its main() is not run)."""
    global _lab
    if _lab is None:
        spec = importlib.util.spec_from_file_location("tumbling_crates_solution", LAB_FILE)
        _lab = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(_lab)
    return _lab


def lab_world(settings, crates=True):
    """The lab's world (floor, ramp, wall; its four crates unless crates=False) with `settings`, and its rng."""
    module = lab()
    rng = random.Random(11)
    bodies = module.make_scene(rng)
    if not crates:
        bodies = [body for body in bodies if body.inv_mass == 0]
    return World(bodies, sat=module.sat, resolve=module.resolve, **settings), rng


def scene(name, settings):
    """(world, {step: [bodies to add before it]}) for one of SCENES."""
    module = lab()
    if name == "pile":
        world, rng = lab_world(settings, crates=False)
        clicks = {}
        for k, pos in enumerate(PILE_DROPS):
            clicks.setdefault((10 + 20 * k) * STEPS_PER_FRAME, []).append(module.make_crate(rng, pos))
        return world, clicks
    if name == "own":
        world, rng = lab_world(settings)
        return world, {frame * STEPS_PER_FRAME: [module.make_crate(rng, pos)] for frame, pos in OWN_DROPS}
    if name == "bricks":
        world, _ = lab_world(settings, crates=False)
        y = 560 - 22
        for count, shift in ((4, 0.0), (3, 31.0), (3, 31.0), (2, 62.0)):
            for k in range(count):
                world.add(Body(box_points(60, 40), (520 + shift + 62 * k, y), mass=2.4))
            y -= 42
        return world, {}
    if name == "stack":
        # the lab window's floor with a wall at each side: a toppled box stays in view
        walls = [Body(box_points(900, 40), (450, 580), 0), Body(box_points(30, 600), (-15, 300), 0),
                 Body(box_points(30, 600), (915, 300), 0)]
        boxes = [Body(box_points(40, 40), (450, 540 - 40 * k), 1.0) for k in range(10)]
        return World(walls + boxes, **settings), {}
    if name == "disc":
        floor = Body(box_points(800, 40), (450, 580), 0, restitution=1.0)
        disc = Body(Circle(10), (450, 550 - 200), 1.0, restitution=1.0)
        return World([floor, disc], **settings), {}
    raise ValueError(f"unknown scene {name!r}; choose from {', '.join(SCENES)}")


SCENES = ("pile", "own", "bricks", "stack", "disc")


def energy(world):
    """Total energy (mass·px²/s²): Σ ½ m v² + ½ I ω² - m g·x + ½ m h g·v over the dynamic bodies,
    h = step_seconds / substeps (s), g the gravity vector (px/s²): constant in free flight."""
    g, h = world.gravity, world.step_seconds / world.substeps
    return sum(body.kinetic_energy() - body.mass * g.dot(body.pos) + 0.5 * body.mass * h * g.dot(body.vel)
               for body in world.bodies if body.inv_mass)


def weight(world):
    """Σ m g of the dynamic bodies (mass·px/s²): one px of the whole scene's height, in energy."""
    return sum(body.mass for body in world.bodies if body.inv_mass) * world.gravity.length()


def outside(body):
    """True if the body's centre is out of the lab window."""
    x0, y0, x1, y1 = WINDOW
    return not (x0 <= body.pos.x <= x1 and y0 <= body.pos.y <= y1)


def books(name, settings, seconds):
    """Run scene `name` for `seconds` with World `settings`: {"rise", "climb", "excess" (px), "speed" (px/s), "outside",
    "finite" (False if a body became non-finite: the World raises), "steps", "cpu" (s of process time)}."""
    world, clicks = scene(name, settings)
    rise = climb = speed = 0.0
    total = lowest = 0.0     # sum of the steps' energy changes so far, and its lowest value
    given = None             # energy given so far (start + clicks), and the most above it
    excess = -math.inf
    left = set()
    steps = round(seconds * 120)
    finite = True
    start = time.process_time()
    for k in range(steps):
        start_energy = energy(world)
        for body in clicks.get(k, ()):
            world.add(body)
        scale = weight(world) or 1.0
        before = energy(world)
        given = before if given is None else given + before - start_energy
        try:
            world.step()
        except ValueError:
            finite = False
            break
        after = energy(world)
        excess = max(excess, (after - given) / scale)
        change = (after - before) / scale
        rise = max(rise, change)
        total += change
        lowest = min(lowest, total)
        climb = max(climb, total - lowest)
        for index, body in enumerate(world.bodies):
            if body.inv_mass:
                speed = max(speed, math.hypot(body.vel.x, body.vel.y))
                if outside(body):
                    left.add(index)
    return {"rise": rise, "climb": climb, "excess": excess, "speed": speed, "outside": len(left), "finite": finite, "steps": k + 1,
            "cpu": time.process_time() - start}


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m lesson11.bench.energy", description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=2.0, help="simulated seconds per run (default 2)")
    parser.add_argument("--grid", default="1x1,1x6,2x4,4x6,16x1,1x50",
                        help="sub-steps x iterations, comma-separated (default %(default)s)")
    args = parser.parse_args(argv)
    print("| solver | sub-steps × iterations | scene | rise (px) | climb (px) | excess (px) | top speed (px/s) "
          "| outside | CPU s |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|")
    for solver, base in SOLVERS.items():
        for cell in args.grid.split(","):
            substeps, iterations = (int(v) for v in cell.split("x"))
            for name in SCENES:
                r = books(name, dict(base, substeps=substeps, iterations=iterations), args.seconds)
                print(f"| {solver} | {substeps} × {iterations} | {name} | {r['rise']:.3f} | {r['climb']:.3f} | "
                      f"{r['excess']:.3f} | {r['speed']:.0f} | {r['outside']}{'' if r['finite'] else ' NaN'} | "
                      f"{r['cpu']:.2f} |", flush=True)


if __name__ == "__main__":
    main()
