"""Solver probe: the same scenes in the lesson solver, the reference solver and pymunk, side by side.

    python -m lesson11.bench.solver_probe          # prints a Markdown table (pymunk rows skipped if missing)
    python -m lesson11.bench.solver_probe --speed  # the reference solver, readable against float, side by side

Every engine runs 1/120 s steps with the work of 6 passes per step: the lesson
solver in the lesson text's order (order="move-first") 6 iterations, the reference
("accumulated") solver 3 sub-steps of 1 pass plus 1 relax pass, pymunk 6 iterations.
The lesson solver in its default order (order="solve-first") does more: 4 sub-steps
of 1 + 6 resolve passes and 1 push-out (contacts found once per sub-step, not per pass, plus
once at the end of the step). Units px, s; y down, gravity 980 px/s².
  flat e     a 40 px box dropped flat from 100 px: rebound speed / impact speed, and its spin (rad/s)
  stack      10 boxes (40 px) for 20 s: largest drift of any box (px)
  100:1      a 100× heavier box on a light one for 5 s: deepest overlap (px), and whether the heavy one stays on top
  ramp       a 40 px crate at rest on a 22° slope, μ 0.6, for 3 s: distance moved (px)
and, against the analytic answer (relative error, %), from rest unless said:
  fall       a box falling freely for 1 s: y = ½ g t²
  slide      a box sliding down a 30° slope, μ 0.2, for 1 s: s = ½ g (sin θ - μ cos θ) t²
  roll       a disc (r 20 px, I = ½ m r²) rolling down a 20° slope, μ 0.6, for 1 s: s = ½ (2/3) g sin θ t²
  stop       a box sliding at 300 px/s on the floor, μ 0.5, until it stops: d = v0² / (2 μ g)
  far pile   12 crates (60 × 40 px, rows of 4, 3, 3, 2) settling 2 s at (10⁶, 10⁶) px and at the
             origin: largest difference of any crate's position relative to the start, / 10⁶ px

The scene measurements (flat_bounce, disc_bounce, stack, heavy_on_light, ramp_rest) also come
as generators (flat_bounce_run, ...) that yield the scene after each step and return the same
figures: accuracy_cost's "solvers" study advances them in lockstep, and every scene counts the
steps it took and the seconds spent inside them (scene.steps, scene.seconds).

--speed times the reference solver's two versions on the brick pile in one run: the readable one
(arbiter.ReferenceArbiter, collision.sat and corner_manifold_reference / clip_manifold_reference, the
World's Vector2 sub-steps, every fast path off: arbiter.readable_versions) and the float one the World
runs. The two piles step in turn, one step each, the first alternating, each step timed by the process's
CPU clock (the switch into the readable versions is outside the timing); each repeat starts both piles
afresh and the median of the repeats is kept. It also prints how far apart the two piles end. Its last
row is the Tumbling Crates lab's 12-crate clicked pile (energy.scene("pile"), the issue's pile) in the
World's default 1×6 setting: both versions run the clicks, and the steps after the last one are timed.
"""
import math
import statistics
import sys
import time

from lesson11.physics2d import Body, Circle, Vector2, World, box_points
from lesson11.physics2d.arbiter import readable_versions

try:
    import pymunk
except ImportError:  # the probe still runs our rows
    pymunk = None

FLOOR = 600.0
G = 980.0  # px/s²
FAR = 1e6  # px: the far pile's offset along x and y
ENGINES = {"lesson move-first": dict(solver="lesson", order="move-first", iterations=6),
           "lesson solve-first": dict(solver="lesson", order="solve-first", iterations=6),
           "reference corners": dict(solver="accumulated", contact_rule="corners", substeps=3, iterations=1),
           "reference clip": dict(solver="accumulated", contact_rule="clip", substeps=3, iterations=1)}


class Ours:
    """A physics2d World with one static floor (or ramp) and boxes; bodies addressed by index.

    The floor is a 2000 × 40 px box whose top face is at y = FLOOR (+ offset), turned
    by `angle` about its centre; μ between two bodies is √(μA μB), so the floor gets
    the same friction as the bodies to make the pair's μ that value.
    """

    def __init__(self, settings, angle=0.0, offset=(0, 0), friction=0.6):
        self.offset = Vector2(offset)
        floor = Body(box_points(2000, 40), Vector2(400, FLOOR + 20) + self.offset, 0, angle=angle,
                     friction=friction)
        self.world = World([floor], **settings)
        self.steps, self.seconds = 0, 0.0

    def box(self, size, pos, mass=1.0, e=0.2, angle=0.0, friction=0.6, vel=(0, 0), height=None):
        shape = box_points(size, size if height is None else height)
        body = Body(shape, Vector2(pos) + self.offset, mass, angle=angle, restitution=e, friction=friction,
                    vel=vel)
        self.world.add(body)
        return lambda: (Vector2(body.pos) - self.offset, Vector2(body.vel), body.omega)

    def disc(self, radius, pos, mass=1.0, friction=0.6, e=0.2):
        body = Body(Circle(radius), Vector2(pos) + self.offset, mass, friction=friction, restitution=e)
        self.world.add(body)
        return lambda: (Vector2(body.pos) - self.offset, Vector2(body.vel), body.omega)

    def step(self):
        """One 1/120 s step; counts it and the seconds spent in it."""
        start = time.perf_counter()
        self.world.step()
        self.seconds += time.perf_counter() - start
        self.steps += 1


class Pymunk:
    """The same scene in pymunk (same units), 6 iterations; pymunk multiplies the two μ, so the floor has μ 1."""

    def __init__(self, angle=0.0, offset=(0, 0)):
        self.offset = Vector2(offset)
        self.space = pymunk.Space()
        self.space.gravity = (0, G)
        self.space.iterations = 6
        floor = pymunk.Body(body_type=pymunk.Body.STATIC)
        floor.position = tuple(Vector2(400, FLOOR + 20) + self.offset)
        floor.angle = angle
        shape = pymunk.Poly.create_box(floor, (2000, 40))
        shape.friction, shape.elasticity = 1.0, 1.0  # pymunk multiplies: μ = μ_box × 1.0, e = e_box × 1.0
        self.space.add(floor, shape)
        self.steps, self.seconds = 0, 0.0

    def _add(self, body, shape, pos, e, friction):
        body.position = tuple(Vector2(pos) + self.offset)
        shape.friction, shape.elasticity = friction, e
        self.space.add(body, shape)
        return lambda: (Vector2(tuple(body.position)) - self.offset, Vector2(tuple(body.velocity)),
                        body.angular_velocity)

    def box(self, size, pos, mass=1.0, e=0.2, angle=0.0, friction=0.6, vel=(0, 0), height=None):
        dims = (size, size if height is None else height)
        body = pymunk.Body(mass, pymunk.moment_for_box(mass, dims))
        body.angle, body.velocity = angle, tuple(vel)
        return self._add(body, pymunk.Poly.create_box(body, dims), pos, e, friction)

    def disc(self, radius, pos, mass=1.0, friction=0.6, e=0.2):
        body = pymunk.Body(mass, pymunk.moment_for_circle(mass, 0, radius))
        return self._add(body, pymunk.Circle(body, radius), pos, e, friction)

    def step(self):
        """One 1/120 s step; counts it and the seconds spent in it."""
        start = time.perf_counter()
        self.space.step(1 / 120)
        self.seconds += time.perf_counter() - start
        self.steps += 1


def make(engine, angle=0.0, offset=(0, 0), friction=0.6):
    """The scene for one engine; `friction` is the floor's μ in ours (pymunk's floor has μ 1, see Pymunk).

    engine: a name in ENGINES, "pymunk", a dict of World settings, or {"pymunk": n} (pymunk, n iterations).
    """
    if engine == "pymunk":
        return Pymunk(angle, offset)
    if isinstance(engine, dict) and "pymunk" in engine:
        scene = Pymunk(angle, offset)
        scene.space.iterations = engine["pymunk"]
        return scene
    return Ours(ENGINES[engine] if isinstance(engine, str) else engine, angle, offset, friction)


def to_end(run):
    """Run a measurement generator (flat_bounce_run, ...) to its end; the figures it returns."""
    while True:
        try:
            next(run)
        except StopIteration as done:
            return done.value


def flat_bounce_run(engine, e):
    """Generator form of flat_bounce: yields the scene after each step."""
    scene = make(engine)
    if not isinstance(scene, Pymunk):
        scene.world.bodies[0].restitution = 1.0
    state = scene.box(40, (400, FLOOR - 120), e=e)
    for _ in range(240):
        before = state()[1].y
        scene.step()
        yield scene
        pos, vel, omega = state()
        if before > 0 and vel.y <= 0:
            return -vel.y / before, abs(omega)
    return float("nan"), float("nan")


def flat_bounce(engine, e):
    """Rebound speed / impact speed of a flat 40 px box dropped from 100 px, and the spin as it leaves (rad/s)."""
    return to_end(flat_bounce_run(engine, e))


def disc_bounce_run(engine, e, height=200.0, seconds=6.0):
    """Generator form of disc_bounce: yields the scene after each step."""
    scene = make(engine)
    if not isinstance(scene, Pymunk):
        scene.world.bodies[0].restitution = 1.0  # e of a pair is min(eA, eB) here; pymunk's floor has e 1 already
    state = scene.disc(10, (400, FLOOR - 10 - height), e=e)
    energy = lambda: 0.5 * state()[1].length_squared() + G * (FLOOR - 10 - state()[0].y)
    start, apexes, rebounds, rising = energy(), [], [], False
    for _ in range(round(seconds * 120)):
        before = state()[1].y
        scene.step()
        yield scene
        vy = state()[1].y
        if before > 30 and vy < 0:
            rebounds.append(-vy / before)
        if vy < 0:
            rising = True
        elif rising:
            apexes.append(energy() / start)
            rising = False
    return apexes, rebounds


def disc_bounce(engine, e, height=200.0, seconds=6.0):
    """A 10 px disc dropped `height` px on the floor: (energy at each apex / at the start, rebound ratios).

    Energy = ½ v² + g·(height above the rest position) per unit mass; a rebound ratio is the
    upward speed after the step / the downward speed before it, for impacts faster than 30 px/s.
    """
    return to_end(disc_bounce_run(engine, e, height, seconds))


def stack_run(engine, seconds=20):
    """Generator form of stack: yields the scene after each step."""
    scene = make(engine)
    states = [scene.box(40, (400, FLOOR - 20 - 40 * k)) for k in range(10)]
    start = [s()[0] for s in states]
    worst = 0.0
    for _ in range(int(seconds * 120)):
        scene.step()
        yield scene
        worst = max(worst, max((s()[0] - p).length() for s, p in zip(states, start)))
    return worst


def stack(engine, seconds=20):
    """10 boxes (40 px) stacked on the floor for `seconds`: the largest drift of any box (px)."""
    return to_end(stack_run(engine, seconds))


def heavy_on_light_run(engine, seconds=5):
    """Generator form of heavy_on_light: yields the scene after each step."""
    scene = make(engine)
    light = scene.box(40, (400, FLOOR - 20), 1.0)
    heavy = scene.box(40, (400, FLOOR - 60), 100.0)
    worst = 0.0
    for _ in range(int(seconds * 120)):
        scene.step()
        yield scene
        worst = max(worst, 40 - (light()[0].y - heavy()[0].y))
    on_top = abs(heavy()[0].x - light()[0].x) < 20 and heavy()[0].y < light()[0].y
    return worst, on_top


def heavy_on_light(engine, seconds=5):
    """A 100× heavier box on a light one: (deepest overlap (px), whether the heavy one stays on top)."""
    return to_end(heavy_on_light_run(engine, seconds))


def ramp_rest_run(engine, seconds=3):
    """Generator form of ramp_rest: yields the scene after each step."""
    angle = math.radians(22)
    scene = make(engine, angle)
    up = Vector2(0, -1).rotate_rad(angle)
    centre = Vector2(400, FLOOR + 20) + up * 40.0
    state = scene.box(40, centre, angle=angle)
    start = state()[0]
    for _ in range(int(seconds * 120)):
        scene.step()
        yield scene
    return (state()[0] - start).length()


def ramp_rest(engine, seconds=3):
    """A 40 px crate set at rest on a 22° slope (μ 0.6) for `seconds`: how far it moved (px)."""
    return to_end(ramp_rest_run(engine, seconds))


def on_slope(degrees, lift):
    """(angle rad, the point `lift` px above the slope's top face over the floor's centre, unit vector down the slope)."""
    angle = math.radians(degrees)
    up = Vector2(0, -1).rotate_rad(angle)
    return angle, Vector2(400, FLOOR + 20) + up * (20 + lift), Vector2(1, 0).rotate_rad(angle)


def free_fall(engine, seconds=1.0):
    """Relative error of the distance fallen from rest in `seconds` against ½ g t² (far above the floor)."""
    scene = make(engine)
    state = scene.box(40, (400, FLOOR - 2000))
    start = state()[0].y
    for _ in range(round(seconds * 120)):
        scene.step()
    exact = 0.5 * G * seconds ** 2
    return (state()[0].y - start - exact) / exact


def slide(engine, degrees=30.0, mu=0.2, seconds=1.0):
    """Relative error of a box's slide from rest down a slope against ½ g (sin θ - μ cos θ) t²."""
    angle, centre, down = on_slope(degrees, 20)
    scene = make(engine, angle, friction=mu)
    state = scene.box(40, centre, angle=angle, friction=mu)
    start = state()[0]
    for _ in range(round(seconds * 120)):
        scene.step()
    exact = 0.5 * G * (math.sin(angle) - mu * math.cos(angle)) * seconds ** 2
    return ((state()[0] - start).dot(down) - exact) / exact


def disc_roll(engine, degrees=20.0, seconds=1.0, radius=20.0):
    """Relative error of a disc rolling from rest down a slope (μ 0.6) against ½ (2/3) g sin θ t²."""
    angle, centre, down = on_slope(degrees, radius)
    scene = make(engine, angle)
    state = scene.disc(radius, centre)
    start = state()[0]
    for _ in range(round(seconds * 120)):
        scene.step()
    exact = 0.5 * (2 / 3) * G * math.sin(angle) * seconds ** 2
    return ((state()[0] - start).dot(down) - exact) / exact


def stopping(engine, speed=300.0, mu=0.5):
    """Relative error of a box's stopping distance on the floor against v0² / (2 μ g)."""
    scene = make(engine, friction=mu)
    state = scene.box(40, (0, FLOOR - 20), friction=mu, vel=(speed, 0))
    start = state()[0].x
    for _ in range(round(2 * speed / (mu * G) * 120)):  # twice the time it needs to stop
        scene.step()
    exact = speed ** 2 / (2 * mu * G)
    return (state()[0].x - start - exact) / exact


def brick_pile(scene):
    """12 crates of 60 × 40 px laid like bricks (rows of 4, 3, 3, 2, 2 px gaps) on the floor; their states."""
    states = []
    y = FLOOR - 22
    for count, shift in ((4, 0.0), (3, 31.0), (3, 31.0), (2, 62.0)):
        states += [scene.box(60, (300 + shift + 62 * k, y), mass=2.4, height=40) for k in range(count)]
        y -= 42
    return states


def far_pile(engine, seconds=2.0):
    """The brick pile settled at the origin and at (FAR, FAR) px: largest position difference / FAR."""
    ends = []
    for offset in ((0, 0), (FAR, FAR)):
        scene = make(engine, offset=offset)
        states = brick_pile(scene)
        for _ in range(round(seconds * 120)):
            scene.step()
        ends.append([state()[0] for state in states])
    return max((p - q).length() for p, q in zip(*ends)) / FAR


SPEED_SETTINGS = {"World default 1×6, corners": dict(solver="accumulated"),
                  "World default 1×6, clip": dict(solver="accumulated", contact_rule="clip"),
                  "probe's 3×1, corners": ENGINES["reference corners"],
                  "probe's 3×1, clip": ENGINES["reference clip"]}


def side_by_side(worlds, steps, timed_from=0, drops=None):
    """Step worlds = [readable, float] `steps` times, one step each in turn (the first alternating), the readable
    one inside readable_versions(); the CPU seconds of each one's steps from step `timed_from` on (the switch into
    the readable versions is not timed). drops: {step: function(world) -> bodies to add before that step}."""
    spent = [0.0, 0.0]
    for k in range(steps):
        for which in ((0, 1) if k % 2 == 0 else (1, 0)):
            world = worlds[which]
            for body in (drops or {}).get(k, lambda _: ())(world):
                world.add(body)
            if which == 0:
                with readable_versions():
                    start = time.process_time()
                    world.step()
                    took = time.process_time() - start
            else:
                start = time.process_time()
                world.step()
                took = time.process_time() - start
            if k >= timed_from:
                spent[which] += took
    return spent


def gap_px(worlds):
    """Largest distance (px) between the same body's positions in the two worlds."""
    return max((p.pos - q.pos).length() for p, q in zip(worlds[0].bodies, worlds[1].bodies))


def reference_speed(settings, steps=300, repeats=3):
    """The brick pile in the reference solver, readable and float versions side by side:
    (readable CPU ms per step, float CPU ms per step, largest difference of any body's position, px)."""
    runs = []
    for _ in range(repeats):
        piles = [make(settings), make(settings)]  # [readable, float]
        for pile in piles:
            brick_pile(pile)
        worlds = [pile.world for pile in piles]
        spent = side_by_side(worlds, steps)
        runs.append((1000 * spent[0] / steps, 1000 * spent[1] / steps, gap_px(worlds)))
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs), max(r[2] for r in runs)


def clicked_pile_speed(settings, settle=240, repeats=3):
    """Tumbling Crates' 12-crate clicked pile (energy.scene("pile"): the lab's world, its crates clicked in every
    20 frames) in the reference solver, readable and float side by side; the `settle` steps after the last click
    are timed: (readable CPU ms per step, float CPU ms per step, largest position difference, px)."""
    from . import energy  # the lab's scene: imported here, the accuracy tables do not need it
    runs = []
    for _ in range(repeats):
        made = [energy.scene("pile", settings) for _ in range(2)]  # [readable, float], each with its own crates
        worlds = [world for world, _ in made]
        last = max(made[0][1])
        drops = {step: (lambda world, step=step: made[worlds.index(world)][1][step]) for step in made[0][1]}
        spent = side_by_side(worlds, last + 1 + settle, timed_from=last + 1, drops=drops)
        runs.append((1000 * spent[0] / settle, 1000 * spent[1] / settle, gap_px(worlds)))
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs), max(r[2] for r in runs)


def speed_main(steps=300, repeats=3, settle=240):
    """--speed: the table of reference_speed for each of SPEED_SETTINGS, and the lab's clicked pile."""
    print(f"Reference solver on the 12-crate brick pile, {steps} steps of 1/120 s, median of {repeats} repeats "
          f"(CPU ms per step):")
    print()
    print("| setting | readable (Vector2) | float | readable / float | positions apart at the end |")
    print("|---|---:|---:|---:|---:|")
    rows = [(name, lambda settings=settings: reference_speed(settings, steps, repeats))
            for name, settings in SPEED_SETTINGS.items()]
    rows.append((f"lab's 12-crate clicked pile, 1×6 corners ({settle} steps after the last click)",
                 lambda: clicked_pile_speed(dict(solver="accumulated"), settle, repeats)))
    for name, measure in rows:
        readable, fast, gap = measure()
        print(f"| {name} | {readable:.3f} ms | {fast:.3f} ms | {readable / fast:.2f}× | {gap:.1e} px |", flush=True)


def main():
    if "--speed" in sys.argv[1:]:
        return speed_main(*([30, 1, 30] if "--quick" in sys.argv[1:] else []))
    engines = list(ENGINES) + (["pymunk"] if pymunk else [])
    print("| engine | flat e=0.5 rebound (spin) | flat e=0.9 rebound (spin) | 10-stack drift 20 s | 100:1 overlap 5 s (on top) | ramp rest 3 s |")
    print("|---|---|---|---|---|---|")
    for engine in engines:
        b5, b9 = flat_bounce(engine, 0.5), flat_bounce(engine, 0.9)
        worst, on_top = heavy_on_light(engine)
        print(f"| {engine} | {b5[0]:.3f} ({b5[1]:.2f}) | {b9[0]:.3f} ({b9[1]:.2f}) | {stack(engine):.2f} px | "
              f"{worst:.2f} px ({'yes' if on_top else 'no'}) | {ramp_rest(engine):.2f} px |", flush=True)
    print()
    print("| engine | fall 1 s | slide 30° μ 0.2 | disc roll 20° | stop 300 px/s μ 0.5 | far pile |")
    print("|---|---|---|---|---|---|")
    for engine in engines:
        print(f"| {engine} | {100 * free_fall(engine):+.2f} % | {100 * slide(engine):+.2f} % | "
              f"{100 * disc_roll(engine):+.2f} % | {100 * stopping(engine):+.2f} % | {far_pile(engine):.1e} |",
              flush=True)
    if not pymunk:
        print("(pymunk is not installed: its rows are skipped)")


if __name__ == "__main__":
    main()
