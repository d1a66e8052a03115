"""Solver probe: the same scenes in the lesson solver, the reference solver and pymunk, side by side.

    python -m lesson11.bench.solver_probe          # prints a Markdown table (pymunk rows skipped if missing)

Every engine runs 1/120 s steps with the work of 6 passes per step: the lesson
solver 6 iterations, the reference ("accumulated") solver 3 sub-steps of
1 pass plus 1 relax pass, pymunk 6 iterations. Units px, s; y down, gravity 980 px/s².
  flat e     a 40 px box dropped flat from 100 px: rebound speed / impact speed, and its spin (rad/s)
  stack      10 boxes (40 px) for 20 s: largest drift of any box (px)
  100:1      a 100× heavier box on a light one for 5 s: deepest overlap (px), and whether the heavy one stays on top
  ramp       a 40 px crate at rest on a 22° slope, μ 0.6, for 3 s: distance moved (px)
"""
import math

from lesson11.physics2d import Body, Vector2, World, box_points

try:
    import pymunk
except ImportError:  # the probe still runs our rows
    pymunk = None

FLOOR = 600.0
ENGINES = {"lesson": dict(solver="lesson", iterations=6),
           "reference corners": dict(solver="accumulated", contact_rule="corners", substeps=3, iterations=1),
           "reference clip": dict(solver="accumulated", contact_rule="clip", substeps=3, iterations=1)}


class Ours:
    """A physics2d World with one static floor (or ramp) and boxes; bodies addressed by index."""

    def __init__(self, settings, angle=0.0):
        floor = Body(box_points(2000, 40), Vector2(400, FLOOR + 20).rotate_rad(0), 0, angle=angle)
        self.world = World([floor], **settings)

    def box(self, size, pos, mass=1.0, e=0.2, angle=0.0):
        body = Body(box_points(size, size), pos, mass, angle=angle, restitution=e)
        self.world.add(body)
        return lambda: (Vector2(body.pos), Vector2(body.vel), body.omega)

    def step(self):
        self.world.step()


class Pymunk:
    """The same scene in pymunk (same units), 6 iterations."""

    def __init__(self, angle=0.0):
        self.space = pymunk.Space()
        self.space.gravity = (0, 980)
        self.space.iterations = 6
        floor = pymunk.Body(body_type=pymunk.Body.STATIC)
        floor.position = (400, FLOOR + 20)
        floor.angle = angle
        shape = pymunk.Poly.create_box(floor, (2000, 40))
        shape.friction, shape.elasticity = 1.0, 1.0  # pymunk multiplies: μ = 0.6 × 1.0, e = e_box × 1.0
        self.space.add(floor, shape)

    def box(self, size, pos, mass=1.0, e=0.2, angle=0.0):
        body = pymunk.Body(mass, pymunk.moment_for_box(mass, (size, size)))
        body.position, body.angle = tuple(pos), angle
        shape = pymunk.Poly.create_box(body, (size, size))
        shape.friction, shape.elasticity = 0.6, e
        self.space.add(body, shape)
        return lambda: (Vector2(tuple(body.position)), Vector2(tuple(body.velocity)), body.angular_velocity)

    def step(self):
        self.space.step(1 / 120)


def make(engine, angle=0.0):
    return Pymunk(angle) if engine == "pymunk" else Ours(ENGINES[engine], angle)


def flat_bounce(engine, e):
    """Rebound speed / impact speed of a flat 40 px box dropped from 100 px, and the spin as it leaves (rad/s)."""
    scene = make(engine)
    if engine != "pymunk":
        scene.world.bodies[0].restitution = 1.0
    state = scene.box(40, (400, FLOOR - 120), e=e)
    impact = None
    for _ in range(240):
        before = state()[1].y
        scene.step()
        pos, vel, omega = state()
        if before > 0 and vel.y <= 0:
            impact = before
            return -vel.y / impact, abs(omega)
    return float("nan"), float("nan")


def stack(engine, seconds=20):
    scene = make(engine)
    states = [scene.box(40, (400, FLOOR - 20 - 40 * k)) for k in range(10)]
    start = [s()[0] for s in states]
    worst = 0.0
    for _ in range(int(seconds * 120)):
        scene.step()
        worst = max(worst, max((s()[0] - p).length() for s, p in zip(states, start)))
    return worst


def heavy_on_light(engine, seconds=5):
    scene = make(engine)
    light = scene.box(40, (400, FLOOR - 20), 1.0)
    heavy = scene.box(40, (400, FLOOR - 60), 100.0)
    worst = 0.0
    for _ in range(int(seconds * 120)):
        scene.step()
        worst = max(worst, 40 - (light()[0].y - heavy()[0].y))
    on_top = abs(heavy()[0].x - light()[0].x) < 20 and heavy()[0].y < light()[0].y
    return worst, on_top


def ramp_rest(engine, seconds=3):
    angle = math.radians(22)
    scene = make(engine, angle)
    up = Vector2(0, -1).rotate_rad(angle)
    centre = Vector2(400, FLOOR + 20) + up * 40.0
    state = scene.box(40, centre, angle=angle)
    start = state()[0]
    for _ in range(int(seconds * 120)):
        scene.step()
    return (state()[0] - start).length()


def main():
    engines = list(ENGINES) + (["pymunk"] if pymunk else [])
    print("| engine | flat e=0.5 rebound (spin) | flat e=0.9 rebound (spin) | 10-stack drift 20 s | 100:1 overlap 5 s (on top) | ramp rest 3 s |")
    print("|---|---|---|---|---|---|")
    for engine in engines:
        b5, b9 = flat_bounce(engine, 0.5), flat_bounce(engine, 0.9)
        worst, on_top = heavy_on_light(engine)
        print(f"| {engine} | {b5[0]:.3f} ({b5[1]:.2f}) | {b9[0]:.3f} ({b9[1]:.2f}) | {stack(engine):.2f} px | "
              f"{worst:.2f} px ({'yes' if on_top else 'no'}) | {ramp_rest(engine):.2f} px |", flush=True)
    if not pymunk:
        print("(pymunk is not installed: its row is skipped)")


if __name__ == "__main__":
    main()
