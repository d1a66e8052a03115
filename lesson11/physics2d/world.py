"""The World: bodies advanced with a fixed step, gravity, and an iterative contact solver.

A scene declares the effects it needs in `effects`; the world runs those and
nothing else (no friction pass for a frictionless scene, no swept tests unless
"ccd" is asked for). Every setting is an attribute, checked whenever it is set
(in World(...) or later), with a one-line ValueError naming it and the value
(settings.py); help(World.slop) and the others say what each is, its unit and
default. A lab can hand in its own `sat`, `resolve` and `separate` (and, for
balls, `circle_circle`, `circle_polygon` and `circle_point`), and the world calls them inside
its loop, so a student's functions run the whole simulation.

World.step dispatches to one phase list per solver (step_solve_first,
step_move_first, step_accumulated), each read top to bottom like Box2D-Lite's
World::Step with a comment per phase, and all end with end_step. The "sleep"
effect's machinery is sleep.py; the measurements behind the choices made here
are in lesson11/bench/README.md ("physics2d's choices, measured").
"""
import math
from collections import deque as _deque
from collections import namedtuple
from functools import partial
from itertools import starmap as _starmap

from . import broadphase, collision, response, sleep
from .bodies import Body
from .arbiter import (CONTACT_HERTZ, DAMPING_RATIO, RESTITUTION_PASSES, SPECULATIVE_MARGIN, Arbiter,
                      pass_groups, soft_constants, solve_passes, warm_start_floats)
from .settings import (at_least_zero, effect_set, flag, fraction, hook, one_of, positive_seconds, setting,
                       vector, whole_number)
from .sleep import SLEEP_AFTER, SLEEP_SPEED, SLEEP_SPIN  # noqa: F401 (World's defaults, importable from here)
from .shapes import WorldPoints
from .vectors import Vector2, finite_number, finite_vector

GRAVITY = Vector2(0, 980)  # px/s², the course's gravity (y down)
STEP = 1 / 120             # s, the course's fixed physics step
EFFECTS = ("gravity", "rotation", "friction", "restitution", "correction", "ccd", "sleep")
SOLVERS = ("lesson", "accumulated")
ORDERS = ("move-first", "solve-first")
BROAD_PHASES = ("sweep-and-prune", "all-pairs")
LESSON_SUBSTEPS = 4        # the lesson solver's sub-steps in the solve-first order (see World.step_solve_first)
CONTACT_RULES = ("corners", "clip")
LESSON_EFFECTS = frozenset({"gravity", "rotation", "friction", "restitution", "correction"})
MAX_STEPS = 4              # fixed steps per advance() at most: two 60 fps frames' worth of 1/120 s steps

_body_world_points = Body.world_points  # _plain_manifolds inlines it for bodies that do not override it
Contact = namedtuple("Contact", "a b point normal depth")
Contact.__doc__ = "One contact: bodies a and b, the world point (px), the unit normal A→B, the depth (px)."
_contact = partial(tuple.__new__, Contact)  # Contact._make of a 5-tuple: the same Contact, made in C
_manifold = partial(tuple.__new__, collision.Manifold)  # collision.Manifold._make of a 4-tuple, the same way


class World:
    """A collection of bodies stepped with a fixed time step.

    Settings are keywords of World(...) and attributes, checked whenever they
    are set; help(World.<name>) says what each is, its unit and its default:
      the step       gravity, step_seconds, substeps, max_frame, max_steps
      the solver     solver, order, iterations, warm_starting, contact_rule, broad_phase, effects
      the push-out   slop, percent; bounces: resting_speed
      "sleep"        sleep_speed, sleep_spin, sleep_after, and the hooks sleep_timer, moves, wake_pair
                     (World(wake=...) sets wake_pair)
    Hooks (a lab's functions, called inside the loop; None gives the library's):
      sat(pa, pb), resolve(a, b, normal, point), separate(a, b, normal, depth);
      circle_circle(ca, ra, cb, rb), circle_polygon(center, radius, points) and
      circle_point(center, radius, normal, depth) for balls;
      sleep_timer(timer, speed, spin, dt), moves(body), wake(a, b) for "sleep" (sleep.py).
      Each must be a function: anything else is a one-line ValueError. Like sat, the
      circle hooks serve the lesson solver; the accumulated solver's speculative
      contacts use the library's.
    After each step: `contacts` (list of Contact the impulses used) and
    `counters`, totals since the world was made, each added once per contact search:
      steps          fixed steps run
      pair_tests     pairs whose bounding boxes the broad phase compared: with sweep-and-prune,
                     the pairs with a moving body whose boxes (grown by the margins) overlap
                     along x, i.e. the pairs the sweep met (a wide pile: a few per body);
                     with all-pairs every pair with a moving body, N (N - 1) / 2 at most.
                     A wake that sets new bodies moving runs the search again and counts again.
      narrow_tests   pairs handed to the narrow phase (collision.collide): boxes overlap
      contacts       contact points of the manifolds found (speculative ones included)
      swept_tests    "ccd": bodies a bullet was swept against
    `dropped` is the frame time (s) the max_steps cap has dropped, in all.

    >>> from lesson11.physics2d import Body, World, box_points
    >>> floor = Body(box_points(400, 40), (0, 20), mass=0)
    >>> crate = Body(box_points(40, 40), (0, -100), mass=1)
    >>> world = World([floor, crate])
    >>> for _ in range(240):       # 2 s of 1/120 s steps: the crate falls and lands
    ...     world.step()
    >>> round(crate.pos.y), round(crate.vel.y), world.counters["steps"]
    (-20, 0, 240)
    """

    gravity = setting("gravity", vector("gravity"),
                      """Acceleration (px/s²) of every dynamic body, a Vector2 (y grows downward).

        Applied only with the "gravity" effect. Two finite numbers.
        Default GRAVITY = (0, 980) px/s².""")
    step_seconds = setting("step_seconds", positive_seconds("step_seconds"), """The fixed physics step (s).

        step() runs one; advance(frame) runs as many as fit in the frame time.
        A number > 0. Default STEP = 1/120 s.""")
    iterations = setting("iterations", whole_number("iterations"),
                         """Solver passes over the contacts per (sub-)step, an int >= 1.

        More passes sink less and cost more (lesson11/bench/README.md,
        "Solver iterations"). Default 6.""")
    slop = setting("slop", at_least_zero("slop", "px"), """Overlap (px) the push-out leaves alone.

        separate() moves a pair apart by percent × (depth - slop) only, so
        bodies at rest stay in touch instead of being pushed out and falling
        back every step (jitter). A number >= 0. Default response.SLOP = 0.5 px.

        >>> World().slop
        0.5
        >>> World(slop=-1)
        Traceback (most recent call last):
        ...
        ValueError: world slop must be >= 0 px, got -1.0""")
    percent = setting("percent", fraction("percent"),
                      """Share of the overlap beyond slop that one push-out removes, 0 to 1.

        1 removes it at once (a visible jolt), small values let a pile sink.
        Default response.PERCENT = 0.4.""")
    resting_speed = setting("resting_speed", at_least_zero("resting_speed", "px/s"),
                            """Slowest impact (px/s) that bounces.

        An approach slower than this along the normal gets e = 0, so bodies at
        rest do not bounce on the speed one step of gravity gives them. A
        number >= 0. Default response.RESTING_SPEED = 30 px/s.""")
    max_frame = setting("max_frame", positive_seconds("max_frame"), """Longest frame (s) that advance() takes in.

        A longer frame (a window drag, a breakpoint) counts as this long.
        A number > 0. Default 0.25 s.""")
    max_steps = setting("max_steps", whole_number("max_steps", none_allowed=True),
                        """Fixed steps per advance() at most.

        An int >= 1, or None (no cap). The frame time that does not fit is
        dropped (added to `dropped`), so a frame whose physics runs long makes
        the simulation run slower than the clock instead of making the next
        frame longer still (the "spiral": 30 catch-up steps a frame, 3 fps).
        Default MAX_STEPS = 4, two 60 fps frames of 1/120 s steps.""")
    contact_rule = setting("contact_rule", one_of(CONTACT_RULES, "contact_rule", forget_arbiters=True),
                           """How two polygons' contact points are found.

        "corners": the lesson's rule, the corners of each inside the other;
        "clip": edge clipping (Box2D's). Changing it drops the accumulated
        solver's kept contacts (`arbiters`). Default "corners".""")
    solver = setting("solver", one_of(SOLVERS, "solver", forget_arbiters=True), """Which contact solver runs.

        "lesson": the labs' solver, fresh impulses every pass from resolve(),
        the push-out by separate() (order says when it moves the bodies);
        "accumulated": arbiter.py, impulses kept across passes and steps, soft
        contacts, for tall stacks and large mass ratios. Changing it drops the
        kept contacts (`arbiters`). Default "lesson".""")
    effects = setting("effects", effect_set(EFFECTS),
                      """The effects that run: a set of names from EFFECTS (kept as a frozenset).

        "gravity", "rotation", "friction", "restitution", "correction" (the
        push-out), "ccd" (swept tests for bodies with bullet=True), "sleep"
        (sleep.py). A scene pays only for what it declares. Default
        LESSON_EFFECTS: all but "ccd" and "sleep".

        >>> sorted(World(effects={"gravity", "sleep"}).effects)
        ['gravity', 'sleep']""")
    order = setting("order", one_of(ORDERS, "order"), """The lesson solver's order within a sub-step.

        "solve-first": Box2D-Lite's, contacts once, impulses, then the move
        and one push-out (step_solve_first); "move-first": the lesson text's
        step_world, gravity and the move first, then `iterations` passes of
        contacts, resolve() and separate() (step_move_first; a crate on the
        22° ramp creeps ~3 px/s). The accumulated solver ignores it.
        Default "solve-first".""")
    broad_phase = setting("broad_phase", one_of(BROAD_PHASES, "broad_phase"), """How the pairs to test are found.

        "sweep-and-prune" (broadphase.py: boxes sorted along x and swept) or
        "all-pairs" (every pair, box against box: the reference). Both give the
        same pairs in the same order, so the same motion to the last bit.
        Default "sweep-and-prune".""")
    warm_starting = setting("warm_starting", flag("warm_starting"),
                            """True: the accumulated solver starts from last step's impulses.

        It then needs fewer passes for a resting pile; the lesson solver
        ignores it. True or False. Default True.""")
    circle_polygon = setting("circle_polygon", hook("circle_polygon"),
                             """Hook: the test of every circle–polygon pair (lesson solver).

        circle_polygon(center, radius, points) -> None or (normal out of the
        circle into the polygon, depth px). A function; World(circle_polygon=None)
        uses the library's, collision.circle_polygon (the default).""")
    circle_circle = setting("circle_circle", hook("circle_circle"),
                            """Hook: the test of every pair of circles (lesson solver).

        circle_circle(ca, ra, cb, rb) -> None when apart, else (unit normal
        from A's centre to B's, depth = ra + rb - |cb - ca| px); centres in
        world px (copies), radii px. A function; World(circle_circle=None)
        uses the library's, collision.circle_circle (the default).""")
    circle_point = setting("circle_point", hook("circle_point"),
                           """Hook: the contact point of every circle pair (lesson solver).

        circle_point(center, radius, normal, depth) -> the contact point (world
        px), normal pointing out of that circle. A function; default
        collision.circle_contact_point (halfway into the overlap).""")
    sleep_speed = setting("sleep_speed", at_least_zero("sleep_speed", "px/s"),
                          """"sleep" effect: slower than this (px/s) is calm.

        A body calm in speed and spin (sleep_spin) for sleep_after s, with its
        island, falls asleep. A number >= 0. Default SLEEP_SPEED = 5 px/s.""")
    sleep_spin = setting("sleep_spin", at_least_zero("sleep_spin", "rad/s"),
                         """"sleep" effect: spinning slower than this (rad/s) is calm.

        A number >= 0. Default SLEEP_SPIN = 0.1 rad/s.""")
    sleep_after = setting("sleep_after", positive_seconds("sleep_after"),
                          """"sleep" effect: calm this long (s), an island falls asleep.

        Every member of the island must have been calm (sleep_time) this long.
        A number > 0. Default SLEEP_AFTER = 0.5 s.""")
    sleep_timer = setting("sleep_timer", hook("sleep_timer"),
                          """Hook, "sleep" effect: a body's new sleep timer after a step.

        sleep_timer(timer, speed, spin, dt) -> the new timer (s), for every
        awake dynamic body. A function; default sleep_timer_of_world (sleep.timer
        with this world's sleep_speed and sleep_spin).""")
    moves = setting("moves", hook("moves"), """Hook, "sleep" effect: moves(body) -> True if the body is integrated.

        A pair in which neither body moves is never tested. A function;
        default World.moves_of_world (dynamic and awake).""")
    wake_pair = setting("wake_pair", hook("wake"),
                        """Hook, "sleep" effect: wake_pair(a, b) -> the bodies to wake when a and b touch.

        Set by World(wake=...). A function; default World.wake_of_world (the
        sleeper of a pair whose other body is dynamic and awake).""")

    @property
    def substeps(self):
        """Equal sub-steps each fixed step is split into (h = step / substeps), an int >= 1.

        Set None for the default: LESSON_SUBSTEPS = 4 for the lesson solver's
        solve-first order, else 1; reading gives the number in use.
        """
        return self._substeps or (LESSON_SUBSTEPS if self.solver == "lesson" and self.order == "solve-first" else 1)

    @substeps.setter
    def substeps(self, value):
        self._substeps = whole_number("substeps", none_allowed=True)(self, value)

    def __init__(self, bodies=(), *, gravity=GRAVITY, step_seconds=STEP, iterations=6, substeps=None,
                 slop=response.SLOP, percent=response.PERCENT, resting_speed=response.RESTING_SPEED,
                 max_frame=0.25, max_steps=MAX_STEPS, contact_rule="corners", effects=LESSON_EFFECTS, solver="lesson",
                 warm_starting=True, order="solve-first", sat=None, resolve=None, separate=None,
                 circle_polygon=None, circle_point=None, circle_circle=None, sleep_speed=SLEEP_SPEED,
                 sleep_spin=SLEEP_SPIN, sleep_after=SLEEP_AFTER, sleep_timer=None, moves=None, wake=None,
                 broad_phase="sweep-and-prune"):
        self.arbiters = {}
        self.touched = set()  # "sleep": pairs (id(a), id(b)) that touched during this step
        self.gravity = gravity
        self.step_seconds = step_seconds
        self.iterations = iterations
        self.substeps = substeps
        self.slop = slop
        self.percent = percent
        self.resting_speed = resting_speed
        self.max_frame = max_frame
        self.max_steps = max_steps
        self.dropped = 0.0    # s of frame time dropped by the max_steps cap, in all
        self.contact_rule = contact_rule
        self.effects = effects
        self.solver = solver
        self.warm_starting = warm_starting
        self.order = order
        self.broad_phase = broad_phase
        self.sat = sat or collision.sat
        self.resolve = resolve or self.lesson_resolve
        self.separate = separate or self.lesson_separate
        self.circle_polygon = circle_polygon or collision.circle_polygon
        self.circle_point = circle_point or collision.circle_contact_point
        self.circle_circle = circle_circle or collision.circle_circle
        self.sleep_speed = sleep_speed
        self.sleep_spin = sleep_spin
        self.sleep_after = sleep_after
        self.sleep_timer = sleep_timer or self.sleep_timer_of_world
        self.moves = moves or self.moves_of_world
        self.wake_pair = wake or self.wake_of_world
        self.bodies = []
        self.contacts = []
        self.accumulator = 0.0
        self.time = 0.0
        self.counters = {"steps": 0, "pair_tests": 0, "narrow_tests": 0, "contacts": 0, "swept_tests": 0}
        for body in bodies:
            self.add(body)

    def add(self, body):
        """Add a body (checked to be finite) and return it."""
        if not body.is_finite():
            raise ValueError(f"cannot add {body!r}: its position, velocity, angle or omega is not finite")
        self.bodies.append(body)
        return body

    def remove(self, body):
        """Remove a body from the world (and the accumulated solver's contacts with it)."""
        self.bodies.remove(body)
        self.arbiters = {key: arb for key, arb in self.arbiters.items() if body not in (arb.a, arb.b)}

    def lesson_resolve(self, a, b, normal, point):
        """The library's resolve() with this world's resting_speed and effects."""
        return response.resolve(a, b, normal, point, self.resting_speed,
                                friction="friction" in self.effects,
                                restitution="restitution" in self.effects,
                                spin="rotation" in self.effects)

    def lesson_separate(self, a, b, normal, depth):
        """The library's separate() with this world's slop and percent."""
        response.separate(a, b, normal, depth, self.slop, self.percent)

    # ---------------------------------------------------------------- the "sleep" effect (sleep.py)

    moves_of_world = staticmethod(sleep.moves)
    wake_of_world = staticmethod(sleep.wake_pair)

    def sleep_timer_of_world(self, timer, speed, spin, dt):
        """The library's sleep timer (sleep.timer) with this world's sleep_speed and sleep_spin."""
        return sleep.timer(timer, speed, spin, dt, self.sleep_speed, self.sleep_spin)

    def wake(self, body):
        """Wake `body` and every body that fell asleep in the same island (sleep.wake)."""
        sleep.wake(body)

    def fall_asleep(self, bodies):
        """Put these dynamic bodies to sleep together, as one island (sleep.fall_asleep)."""
        sleep.fall_asleep(bodies)

    def update_sleep(self, dt):
        """After a step: sleep timers, then calm islands fall asleep (sleep.update)."""
        sleep.update(self, dt)

    # ---------------------------------------------------------------- time

    def advance(self, frame_seconds):
        """Run as many fixed steps as fit in the frame's time (s), carrying the remainder.

        Frames longer than max_frame are clamped first; at most max_steps steps run, and
        the time left beyond one step is dropped (added to `dropped`), so the simulation
        falls behind the clock rather than spiral. Returns the number of steps run.
        """
        frame_seconds = finite_number(frame_seconds, "frame time")
        if frame_seconds < 0:
            raise ValueError(f"frame time must be >= 0 s, got {frame_seconds}")
        self.accumulator += min(frame_seconds, self.max_frame)
        steps = 0
        while self.accumulator >= self.step_seconds:
            if self.max_steps is not None and steps == self.max_steps:
                # keep less than one step for the next frame; the rest of the backlog is dropped
                kept = math.fmod(self.accumulator, self.step_seconds)
                self.dropped += self.accumulator - kept
                self.accumulator = kept
                break
            self.step()
            self.accumulator -= self.step_seconds
            steps += 1
        return steps

    def step(self, dt=None):
        """Advance every body by one step of dt seconds (default: step_seconds) with the world's solver.

        Each solver's step is one phase list, in `substeps` sub-steps h = dt / substeps:
          solver "lesson", order "solve-first"   step_solve_first (the default: Box2D-Lite's order)
          solver "lesson", order "move-first"    step_move_first (the lesson text's step_world)
          solver "accumulated"                   step_accumulated (arbiter.py)
        and every step ends with end_step: sleep, the clock, the counters, and
        a ValueError if any body ends the step with a non-finite state.
        """
        dt = self.step_seconds if dt is None else positive_seconds("step dt")(self, dt)
        self.check_motion()
        try:
            if self.solver == "accumulated":
                self.step_accumulated(dt)
            elif self.order == "solve-first":
                self.step_solve_first(dt)
            else:
                self.step_move_first(dt)
            self.end_step(dt)
        except (TypeError, AttributeError) as error:
            self.name_bad_motion(error)
            raise

    def check_motion(self):
        """Check every body's vel (a Vector2 of finite px/s) and omega (a finite number of rad/s) once a step.

        They are plain attributes, not checked settings (bodies.py says why), so a
        bad value set between steps is caught here, in one line naming the body:
        a pair such as (3, 4) becomes a Vector2, anything else is a ValueError.
        """
        for index, body in enumerate(self.bodies):
            vel, omega = body.vel, body.omega
            if vel.__class__ is not Vector2 or not (math.isfinite(vel.x) and math.isfinite(vel.y)):
                body.vel = finite_vector(vel, f"body {index}'s vel")
            if omega.__class__ is not float or not math.isfinite(omega):
                body.omega = finite_number(omega, f"body {index}'s omega")

    def name_bad_motion(self, error):
        """After `error` (a TypeError or AttributeError) inside a step: a ValueError naming the body a hook broke,
        if there is one (else nothing, and the error stands).

        A hook (resolve, separate, ...) that sets b.vel = None or (1, 2) mid-step, or
        makes a body NaN (whose SAT then finds no normal), would otherwise surface as
        an error on a library line it never wrote (response.separate's `None * float`).
        """
        for index, body in enumerate(self.bodies):
            vel, omega = getattr(body, "vel", None), getattr(body, "omega", None)
            if vel.__class__ is not Vector2 or not isinstance(omega, (int, float)):
                raise ValueError(f"body {index}'s vel or omega became {vel!r}, {omega!r} during the step at "
                                 f"t = {self.time:.4f} s: a hook must keep vel a Vector2 (px/s) and omega a number "
                                 f"(rad/s)") from error
        self.name_non_finite(error)

    def name_non_finite(self, cause=None):
        """Raise a ValueError naming the first body whose pos, angle, vel or omega is NaN or infinite, if any."""
        for index, body in enumerate(self.bodies):
            if not body.is_finite():
                raise ValueError(f"body {index} {body!r} became non-finite at t = {self.time:.4f} s; "
                                 "check its mass, the step and the hooks") from cause

    def end_step(self, dt):
        """What ends every step of dt s: "sleep" (sleep.update), the clock, the step counter, the finite check."""
        if "sleep" in self.effects:
            self.update_sleep(dt)
        self.time += dt
        self.counters["steps"] += 1
        if collision.FAST_PATHS and _sum_is_finite(self.bodies):
            return  # every state finite (a NaN or inf anywhere makes the sum non-finite: then the loop names it)
        self.name_non_finite()

    # ---------------------------------------------------------------- one phase list per solver

    def step_solve_first(self, dt):
        """The lesson solver in Box2D-Lite's order, with the lab's sat, resolve and separate.

        Each sub-step (lesson_solve_first): contacts once, the push-out of the
        last move, resolve() passes, then the move. The step ends with one
        more contact search, where the bodies touch after the last move (what
        the lab draws), and that move's push-out.
        """
        h = dt / self.substeps
        touching = set()  # pairs that touched before the last move (none yet: the last step pushed them out)
        for _ in range(self.substeps):
            # 1-5. one sub-step: contacts, push-out, impact pass, resolve passes, move (lesson_solve_first)
            touching = self.lesson_solve_first(h, touching)
        # 6. contacts after the last move (what the lab draws), and that move's push-out
        found = list(self.manifolds())
        self.push_out(found, touching)
        self.contacts = [Contact(a, b, point, m.normal, m.depth) for a, b, m in found for point in m.points]

    def lesson_solve_first(self, h, touching):
        """One sub-step h (s) of step_solve_first; returns the pairs (id(a), id(b)) touching now.

        `touching` holds the pairs that touched before the last move. The bounce
        sits in the middle of the gravity kick, so an e = 1 disc leaves at exactly
        the speed it arrived with; friction stops a slide before the move, so a
        crate on the ramp does not creep. Why each phase sits where it does, and
        why 4 sub-steps: lesson11/bench/README.md, "physics2d's choices, measured".
        """
        # 1. contacts, found once: broad phase, the lab's sat, contact points
        found = list(self.manifolds())
        # 2. the push-out of the last move, for the pairs that touched before it too
        #    (a pair that met during the move waits for this sub-step's impulses)
        self.push_out(found, touching)
        # 3. half the gravity kick, the impact pass (resolve() once at every point), the other half
        #    (fast paths: the passes run over one flat list of resolve()'s arguments, made once)
        calls, run = ((_resolve_calls(found), self.resolve_calls) if collision.FAST_PATHS
                      else (found, self.resolve_pass))
        self.integrate_velocities(h / 2)
        run(calls, 0)
        self.integrate_velocities(h / 2)
        # 4. `iterations` passes of resolve() (forwards, backwards, ...): what is left is below resting_speed
        for index in range(self.iterations):
            run(calls, index)
        # 5. the move: x += v h, angle += ω h
        self.integrate_positions(h)
        return {(id(a), id(b)) for a, b, _ in found}

    def step_move_first(self, dt):
        """The lesson solver in the lesson text's order (step_world), with the lab's sat, resolve and separate.

        Moving before solving lets a crate resting on a slope creep down by
        g sin θ h² per step: the impulses cancel the velocity, but not the move
        already made (lesson11/README.md).
        """
        h = dt / self.substeps
        for _ in range(self.substeps):
            # 1. velocities: gravity
            self.integrate_velocities(h)
            # 2. positions: x += v h (a swept move for "ccd" bullets)
            self.integrate_positions(h)
            # 3. `iterations` passes, each: broad phase, the lab's sat, contact points,
            #    resolve() at every point (fresh impulses), then the push-out separate()
            for _ in range(self.iterations):
                self.contacts = []
                for a, b, m in self.manifolds():
                    for point in m.points:
                        self.resolve(a, b, m.normal, point)
                        self.contacts.append(Contact(a, b, point, m.normal, m.depth))
                    if "correction" in self.effects:
                        self.separate(a, b, m.normal, m.depth)

    def step_accumulated(self, dt):
        """The reference solver (arbiter.py's phases): impulses kept across passes and steps, soft contacts."""
        h = dt / self.substeps
        # 1. collide once per step: speculative manifolds, matched with last step's arbiters
        arbiters, kept = {}, self.arbiters
        for a, b, manifold in self.speculative_search(dt):
            key = (id(a), id(b))
            arbiter = kept.get(key) or Arbiter(a, b)
            arbiter.update(manifold)
            arbiters[key] = arbiter
        self.arbiters = arbiters
        # 2. prepare: anchors, effective masses, approach speeds (before any impulse)
        for arbiter in arbiters.values():
            arbiter.prepare(self, self.warm_starting)
        soft = soft_constants(min(CONTACT_HERTZ, 0.25 / h), DAMPING_RATIO, h)
        use_push = "correction" in self.effects
        if not collision.READABLE:  # the same phases with the passes on plain floats (arbiter.solve_passes)
            self.float_substeps(arbiters, h, soft, use_push)
        else:
            self.readable_substeps(arbiters, h, soft, use_push)
        # 7. restitution, from the approach speeds found in phase 2
        #    (the float version passes over the contacts whose bounce would change nothing)
        bouncing = (arbiters.values() if collision.READABLE
                    else [arbiter for arbiter in arbiters.values() if arbiter.bounces(self.resting_speed)])
        for _ in range(RESTITUTION_PASSES):
            for arbiter in bouncing:
                arbiter.bounce(self.resting_speed)
        self.contacts = [_contact((arb.a, arb.b, c.point, arb.normal, c.depth))  # Contact(...) without its __new__
                         for arb in arbiters.values() for c in arb.points]

    def speculative_search(self, dt):
        """self.manifolds(speculative=dt); the float search called directly when manifolds() would call it."""
        if (type(self).manifolds is World.manifolds and collision.FAST_PATHS and not collision.READABLE
                and "sleep" not in self.effects):
            return _speculative_manifolds(self, dt)  # the same search, without manifolds()' yield from
        return self.manifolds(speculative=dt)

    def readable_substeps(self, arbiters, h, soft, use_push):
        """step_accumulated's phases 3 to 6, readable: ReferenceArbiter.solve for each contact, each pass."""
        start, motion = self.motion_start()
        for _ in range(self.substeps):
            # 3. velocities, then warm start with the accumulated impulses
            self.integrate_velocities(h)
            for arbiter in arbiters.values():
                arbiter.warm_start()
            # 4. solve: `iterations` passes with the soft push-out
            for _ in range(self.iterations):
                for arbiter in arbiters.values():
                    arbiter.solve(h, soft, use_push, motion)
            # 5. positions, and each body's motion since phase 2 (for the separations)
            self.integrate_positions(h)
            self.body_motion(start, motion)
            # 6. relax: one pass without the push-out, which takes its speed away
            for arbiter in arbiters.values():
                arbiter.solve(h, soft, False, motion)

    def motion_start(self):
        """Where body_motion measures from, {id(body): (x, y, angle)} now, and no motion yet (0, 0, 1, 0) each."""
        start = {id(body): (body.pos.x, body.pos.y, body.angle) for body in self.bodies}
        return start, {key: (0.0, 0.0, 1.0, 0.0) for key in start}

    def float_substeps(self, arbiters, h, soft, use_push):
        """readable_substeps on plain floats: every body's position, angle, velocity and spin as lists for the
        whole step, written back to the bodies at its end; each sub-step's passes run by arbiter.solve_passes.

        Each line computes what the readable phases compute (integrate_velocities, integrate_positions,
        body_motion, the arbiters' warm_start and solve), in the same order: the same floats. With "sleep"
        or "ccd" (whose integration is more than x += v h) float_substeps_on_bodies runs instead.
        """
        if "sleep" in self.effects or "ccd" in self.effects:
            return self.float_substeps_on_bodies(arbiters, h, soft, use_push)
        bodies = self.bodies
        index = {id(body): k for k, body in enumerate(bodies)}
        contacts = [(index[id(arbiter.a)], index[id(arbiter.b)], arbiter) for arbiter in arbiters.values()]
        moving = [k for k, body in enumerate(bodies) if body.inv_mass != 0]
        x0, y0, angle0 = [body.pos.x for body in bodies], [body.pos.y for body in bodies], [b.angle for b in bodies]
        x, y, angle = x0[:], y0[:], angle0[:]
        vx, vy, w = [body.vel.x for body in bodies], [body.vel.y for body in bodies], [b.omega for b in bodies]
        motion = [(0.0, 0.0, 1.0, 0.0)] * len(bodies)
        pull = self.gravity * h if "gravity" in self.effects else None  # v += g h, as integrate_velocities adds it
        rotation = "rotation" in self.effects
        for _ in range(self.substeps):
            # 3. velocities, then warm start with the accumulated impulses; 4. solve: `iterations` passes with
            # the soft push-out (what the passes read is worked out first: the bodies have not moved yet)
            if pull is not None:
                for k in moving:
                    vx[k] += pull.x
                    vy[k] += pull.y
            groups = pass_groups(contacts, motion, h, soft, use_push)
            warm_start_floats(groups, vx, vy, w)
            solve_passes(groups, vx, vy, w, self.iterations)
            # 5. positions (x += v h, angle += ω h), and each body's motion since phase 2 (for the separations)
            for k in moving:
                x[k] += vx[k] * h
                y[k] += vy[k] * h
                if rotation:
                    angle[k] += w[k] * h
                turned = angle[k] - angle0[k]
                motion[k] = (x[k] - x0[k], y[k] - y0[k], math.cos(turned), math.sin(turned))
            # 6. relax: one pass without the push-out, which takes its speed away
            groups = pass_groups(contacts, motion, h, soft, False)
            solve_passes(groups, vx, vy, w, 1)
        for k, body in enumerate(bodies):  # back to the bodies: pos in place, as `body.pos += v` changes it
            body.vel.update(vx[k], vy[k])
            body.omega = w[k]
            if body.inv_mass != 0:
                body.pos.update(x[k], y[k])
                turned = angle[k]
                if type(body) is Body and -math.inf < turned < math.inf:
                    body._angle = turned  # what the angle setter keeps of a finite float (as _move_bodies)
                else:
                    body.angle = turned  # the setter's check, and its one-line error

    def float_substeps_on_bodies(self, arbiters, h, soft, use_push):
        """float_substeps with "sleep" or "ccd": the World's own integration on the bodies each sub-step, the
        passes on their velocities copied into lists and back."""
        start, motion = self.motion_start()
        bodies = self.bodies
        index = {id(body): k for k, body in enumerate(bodies)}
        contacts = [(index[id(arbiter.a)], index[id(arbiter.b)], arbiter) for arbiter in arbiters.values()]
        for _ in range(self.substeps):
            self.integrate_velocities(h)
            moved = [motion[id(body)] for body in bodies]
            groups = pass_groups(contacts, moved, h, soft, use_push)
            self.solve_on_floats(groups, self.iterations, warm_start=True)
            self.integrate_positions(h)
            self.body_motion(start, motion)
            moved = [motion[id(body)] for body in bodies]
            groups = pass_groups(contacts, moved, h, soft, False)
            self.solve_on_floats(groups, 1)

    def solve_on_floats(self, groups, passes, warm_start=False):
        """arbiter.solve_passes (after arbiter.warm_start_floats if warm_start) on every body's velocity and spin,
        copied out of the bodies and back."""
        bodies = self.bodies
        vx = [body.vel.x for body in bodies]
        vy = [body.vel.y for body in bodies]
        w = [body.omega for body in bodies]
        if warm_start:
            warm_start_floats(groups, vx, vy, w)
        solve_passes(groups, vx, vy, w, passes)
        for body, x, y, spin in zip(bodies, vx, vy, w):
            body.vel.update(x, y)
            body.omega = spin

    # ---------------------------------------------------------------- the phases' parts

    def push_out(self, found, touching):
        """separate() on each (a, b, manifold) in `found` whose pair (id(a), id(b)) is in `touching` ("correction" only)."""
        if "correction" not in self.effects:
            return
        if collision.FAST_PATHS and self.separate == self.lesson_separate:
            # the library's separate: response.separate with slop and percent read once, not per pair
            separate, slop, percent = response.separate, self.slop, self.percent
            for a, b, m in found:
                if (id(a), id(b)) in touching:
                    separate(a, b, m.normal, m.depth, slop, percent)
            return
        for a, b, m in found:
            if (id(a), id(b)) in touching:
                self.separate(a, b, m.normal, m.depth)

    def resolve_pass(self, found, index):
        """resolve() at every point of every (a, b, manifold); odd `index` goes backwards (pairs and points).

        resolve() starts from nothing each call and can only push, so whatever it
        meets first is over-pushed and the rest never pull back; alternating the
        order (symmetric Gauss-Seidel) stops one corner of a resting crate, or
        one end of the pile, from always being first.
        """
        resolve = self.resolve
        forwards = index % 2 == 0
        for a, b, m in (found if forwards else found[::-1]):
            normal = m.normal
            for point in (m.points if forwards else m.points[::-1]):
                resolve(a, b, normal, point)

    def resolve_calls(self, calls, index):
        """resolve_pass on _resolve_calls(found): resolve(a, b, normal, point) for each, backwards for odd `index`.

        The same calls in the same order (the flat list reversed is the pairs and
        their points reversed), without the nested loops' per-call overhead.
        """
        _deque(_starmap(self.resolve, calls if index % 2 == 0 else reversed(calls)), 0)

    def integrate_velocities(self, dt):
        """Gravity for every dynamic body: v += g dt (only if the scene declares "gravity")."""
        if "gravity" not in self.effects:
            return
        bodies = [body for body in self.bodies if self.moves(body)] if "sleep" in self.effects else self.bodies
        if collision.FAST_PATHS:
            kick = self.gravity * dt  # the same Vector2 the reference computes for each body
            for body in bodies:
                if body.inv_mass != 0:
                    body.vel += kick
            return
        for body in bodies:
            if body.inv_mass != 0:
                body.vel += self.gravity * dt

    def body_motion(self, start, motion):
        """Update motion[id(body)] = (dx px, dy px, cos Δθ, sin Δθ) since `start` = {id: (x, y, angle)}.

        One cos and one sin per moving body per sub-step; static bodies keep (0, 0, 1, 0).
        """
        for body in self.bodies:
            if body.inv_mass != 0:
                x, y, angle = start[id(body)]
                turned = body.angle - angle
                motion[id(body)] = (body.pos.x - x, body.pos.y - y, math.cos(turned), math.sin(turned))

    def integrate_positions(self, dt):
        """Move every dynamic body: x += v dt, angle += ω dt (semi-implicit Euler, after the velocities)."""
        rotation = "rotation" in self.effects
        ccd = "ccd" in self.effects
        bodies = [body for body in self.bodies if self.moves(body)] if "sleep" in self.effects else self.bodies
        if collision.FAST_PATHS and not ccd:
            _move_bodies(bodies, dt, rotation)
            return
        for body in bodies:
            if body.inv_mass == 0:
                continue
            if ccd and body.bullet and body.shape.kind == "circle":
                self.swept_move(body, dt)
            else:
                body.pos += body.vel * dt
            if rotation:
                body.angle += body.omega * dt

    def swept_move(self, bullet, dt):
        """Continuous collision detection for a circle bullet: move it to its first contact.

        Finds the earliest time of impact t in [0, dt] against every other body
        (held still during the sweep, so the contact point lies where both
        bodies are; circles by circle_toi, polygons by circle_polygon_toi),
        moves there, resolves the hit, and spends the rest of dt moving with the
        new velocity. A body that itself moves fast towards the bullet can
        still be missed: only the bullet is swept.
        """
        first = None
        for other in self.bodies:
            if other is bullet:
                continue
            self.counters["swept_tests"] += 1
            if other.shape.kind == "circle":
                t = collision.circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(),
                                         other.radius, dt)
                hit = None if t is None else (t, (other.pos - bullet.pos - bullet.vel * t).normalize())
            else:
                hit = collision.circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius,
                                                   other.world_points(), dt)
            if hit is not None and (first is None or hit[0] < first[0]):
                first = (hit[0], hit[1], other)
        if first is None:
            bullet.pos += bullet.vel * dt
            return
        t, normal, other = first
        bullet.pos += bullet.vel * t
        self.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        bullet.pos += bullet.vel * (dt - t)

    def reach(self, body, dt):
        """How far (px) any point of the body can move in dt s: (|v| + |g| dt + |ω| r) dt; 0 for static bodies."""
        if body.inv_mass == 0:
            return 0.0
        return (body.vel.length() + self.gravity.length() * dt + abs(body.omega) * body.radius) * dt

    def manifolds(self, speculative=None):
        """Every touching pair now: yields (a, b, Manifold) (collision.collide with this world's rule and sat).

        Broad phase first (broadphase.py, `broad_phase`): only pairs in which a
        body moves and whose bounding boxes overlap go to the narrow phase, in
        the order (i, j) of the bodies' indices. A body moves if it is dynamic,
        or with "sleep" if moves(body) is True (not static, not asleep); a pair
        in which neither moves is never visited. With "sleep", each touching
        pair may wake bodies (wake(a, b)); the pairs after it are then searched
        with the woken bodies moving. speculative=dt (s) also yields pairs that
        could touch within dt: closer than SPECULATIVE_MARGIN plus both bodies'
        reach, with negative depths (each box grown by its body's share).
        World points and boxes are computed once per body per search: up front
        for the bodies that move (and every body without "sleep"), on first use
        for the others, so a sleeping pile next to one moving crate costs only
        the crates near it (its sweep uses pos ± the bounding radius).
        """
        if collision.FAST_PATHS and not speculative and "sleep" not in self.effects:
            yield from _plain_manifolds(self)  # the same search on plain lists (the lab's case)
            return
        if collision.FAST_PATHS and not collision.READABLE and speculative and "sleep" not in self.effects:
            yield from _speculative_manifolds(self, speculative)  # the reference solver's search on floats
            return
        bodies = self.bodies
        sleep = "sleep" in self.effects
        moving = [self.moves(body) for body in bodies] if sleep else [body.inv_mass != 0 for body in bodies]
        if not any(moving):
            return
        geometry = _Geometry(bodies)
        bounds = [geometry[k] if moving[k] or not sleep else _circle_box(body) for k, body in enumerate(bodies)]
        reach = [self.reach(body, speculative) for body in bodies] if speculative else None
        base = SPECULATIVE_MARGIN if speculative else 0.0
        search = broadphase.all_pairs if self.broad_phase == "all-pairs" else broadphase.sweep_and_prune
        pairs, tested = search(geometry, moving, reach, base, bounds)
        self.counters["pair_tests"] += tested
        narrow = contacts = 0
        try:
            index = 0
            while index < len(pairs):
                i, j = pairs[index]
                index += 1
                a, b = bodies[i], bodies[j]
                narrow += 1
                manifold = collision.collide(a, b, geometry.points(i), geometry.points(j), self.contact_rule,
                                             self.sat, broadphase.pair_margin(i, j, reach, base),
                                             self.circle_polygon, self.circle_point, self.circle_circle)
                if manifold is None:
                    continue
                contacts += len(manifold.points)
                if sleep:
                    woken = False
                    for body in self.wake_pair(a, b) or ():
                        self.wake(body)
                        woken = True
                    if woken:
                        now = [self.moves(other) for other in bodies]
                        if now != moving:
                            # woken bodies move from here on: search again, keep the pairs after (i, j)
                            moving = now
                            more, tested = search(geometry, moving, reach, base, bounds)
                            self.counters["pair_tests"] += tested
                            pairs, index = [pair for pair in more if pair > (i, j)], 0
                    self.touched.add((id(a), id(b)))
                yield a, b, manifold
        finally:
            self.counters["narrow_tests"] += narrow
            self.counters["contacts"] += contacts


def _sum_is_finite(bodies):
    """end_step's finite check in one sum (fast path): True only if every Body's state is finite.

    A NaN or ±inf in any pos, vel, angle or omega makes the sum NaN or inf,
    so True means Body.is_finite holds for all (a subclass is asked its own
    is_finite); False (also an overflow of finite values, or a value that does
    not add to a float) sends end_step to the readable loop, which decides.
    """
    total = 0.0
    try:
        for body in bodies:
            if type(body) is not Body:
                if not body.is_finite():
                    return False
                continue
            pos, vel = body._pos, body.vel  # _pos, _angle: what Body's pos and angle properties return
            total += pos.x + pos.y + vel.x + vel.y + body._angle + body.omega
    except (TypeError, OverflowError, AttributeError):
        return False
    return total - total == 0.0  # x - x is 0 for finite x, NaN for inf or NaN


def _resolve_calls(found):
    """resolve()'s arguments (a, b, normal, point) for every point of every (a, b, manifold), in the pass's order."""
    return [(a, b, m.normal, point) for a, b, m in found for point in m.points]


def _move_bodies(bodies, dt, rotation):
    """integrate_positions without "ccd" (fast path): x += v dt, angle += ω dt, the same floats.

    For a Body (not a subclass) the setters' checks are skipped where they
    would keep the value as it is: pos += v dt changes the body's own Vector2
    in place (the pos setter keeps that same vector), and a finite float angle
    is what the angle setter keeps. Anything else goes through the setters.
    """
    for body in bodies:
        if body.inv_mass == 0:
            continue
        if type(body) is not Body:
            body.pos += body.vel * dt
            if rotation:
                body.angle += body.omega * dt
            continue
        pos = body._pos
        pos += body.vel * dt  # in place: body._pos is this vector
        if rotation:
            angle = body._angle + body.omega * dt
            if type(angle) is float and -math.inf < angle < math.inf:
                body._angle = angle
            else:
                body.angle = angle  # the setter's check, and its one-line error


def _circle_box(body):
    """A box (left, top, right, bottom) px sure to hold the body: pos ± its bounding radius."""
    r = body.shape.radius
    return (body.pos.x - r, body.pos.y - r, body.pos.x + r, body.pos.y + r)


class _Geometry:
    """World points and bounding boxes of a world's bodies, each computed at most once (one contact search).

    geometry[k] is body k's box (left, top, right, bottom) px, geometry.points(k)
    its world points; both are computed on first use.
    """

    def __init__(self, bodies):
        self.bodies = bodies
        self.shapes = {}
        self.boxes = {}

    def points(self, k):
        """Body k's world points (px), computed once."""
        if k not in self.shapes:
            self.shapes[k] = self.bodies[k].world_points()
        return self.shapes[k]

    def __getitem__(self, k):
        if k not in self.boxes:
            self.boxes[k] = self.bodies[k].aabb(self.points(k))
        return self.boxes[k]


def _plain_manifolds(world):
    """World.manifolds() without "sleep" or speculative contacts, on plain lists: the same pairs, calls and floats.

    Every body's world points and box are computed up front (as _Geometry does
    without "sleep"; boxes of polygons by _polygon_box), and a pair of polygons
    under the corners rule calls the World's sat and collision.contact_points
    directly (collide's own path for it, less its dispatch); other pairs go
    through collision.collide. The reference is the rest of manifolds(), which
    collision.FAST_PATHS = False runs.
    """
    bodies = world.bodies
    moving = [body.inv_mass != 0 for body in bodies]
    if True not in moving:
        return
    corners_rule = world.contact_rule == "corners"
    points, boxes, lesson_pair = [], [], []  # lesson_pair[k]: body k is a polygon under the corners rule
    for body in bodies:
        shape = body.shape
        lesson_pair.append(corners_rule and shape.kind == "polygon")
        if shape.kind == "polygon" and type(body).world_points is _body_world_points:
            corners = _rotated_corners(body)
            boxes.append(_polygon_box(corners))
        else:
            corners = body.world_points()
            boxes.append(body.aabb(corners))
        points.append(corners)
    if world.broad_phase == "all-pairs":
        pairs, tested = broadphase.all_pairs(boxes, moving, None, 0.0, boxes)
    else:
        pairs, tested = broadphase.sweep_boxes(boxes, moving)  # sweep_and_prune without margins, written out
    world.counters["pair_tests"] += tested
    sat, rule = world.sat, world.contact_rule
    circle_polygon, circle_point, circle_circle = world.circle_polygon, world.circle_point, world.circle_circle
    contact_points, collide, manifold_of = collision.contact_points, collision.collide, collision.Manifold
    narrow = contacts = 0
    try:
        for i, j in pairs:
            a, b = bodies[i], bodies[j]
            narrow += 1
            if lesson_pair[i] and lesson_pair[j]:
                hit = sat(points[i], points[j])
                if hit is None:
                    continue
                normal, depth = hit
                found = contact_points(points[i], points[j], normal)
                manifold = manifold_of(normal, depth, found, [depth] * len(found))
            else:
                manifold = collide(a, b, points[i], points[j], rule, sat, 0.0, circle_polygon, circle_point,
                                   circle_circle)
                if manifold is None:
                    continue
            contacts += len(manifold.points)
            yield a, b, manifold
    finally:
        world.counters["narrow_tests"] += narrow
        world.counters["contacts"] += contacts


def _speculative_manifolds(world, dt):
    """World.manifolds(speculative=dt) without "sleep", polygons on plain floats: the same pairs and manifolds.

    Each polygon's corners become (x, y) pairs once per search, with their edge
    normals, shadows and outward faces (collision.flat_outline), worked out on
    first use; a polygon pair goes to collision.sat_xy and corner_manifold_xy
    (or clip_manifold), the float forms of sat and corner_manifold that collide()
    calls with a margin. Other pairs go through collision.collide. The reference is
    the rest of manifolds(), which readable_versions() runs. A list of (a, b, Manifold), not a generator:
    step_accumulated takes them all, and a list is quicker to go through.
    """
    bodies = world.bodies
    moving = [body.inv_mass != 0 for body in bodies]
    if True not in moving:
        return []
    points, xy, boxes = [], [], []  # each body's world points; a polygon's also as (x, y) pairs
    for body in bodies:
        if body.shape.kind == "polygon":
            corners = _world_corners(body)
            pairs = [(p.x, p.y) for p in corners]
            boxes.append(_polygon_box(pairs if len(pairs) == 4 else corners))  # the same floats either way
        else:
            corners, pairs = body.world_points(), None
            boxes.append(body.aabb(corners))
        points.append(corners)
        xy.append(pairs)
    flat = [None] * len(bodies)  # polygon k: its collision.FlatOutline, on first use
    reach = _reaches(world, dt)
    base = SPECULATIVE_MARGIN
    search = broadphase.all_pairs if world.broad_phase == "all-pairs" else broadphase.sweep_and_prune
    pairs, tested = search(boxes, moving, reach, base, boxes)
    world.counters["pair_tests"] += tested
    rule = world.contact_rule
    found, narrow, contacts = [], 0, 0
    try:
        for i, j in pairs:
            a, b = bodies[i], bodies[j]
            narrow += 1
            margin = base + reach[i] + reach[j]  # broadphase.pair_margin
            if a.shape.kind == "polygon" and b.shape.kind == "polygon":
                manifold = _polygon_manifold(points, xy, flat, i, j, rule, margin)
            else:
                manifold = collision.collide(a, b, points[i], points[j], rule, world.sat, margin,
                                             world.circle_polygon, world.circle_point, world.circle_circle)
            if manifold is None:
                continue
            contacts += len(manifold.points)
            found.append((a, b, manifold))
    finally:  # counted also when a pair's test raises, as manifolds() counts
        world.counters["narrow_tests"] += narrow
        world.counters["contacts"] += contacts
    return found


def _world_corners(body):
    """body.world_points() of a polygon, with pos and angle read once (not once per corner) for a body that does
    not override world_points: the same floats."""
    if type(body).world_points is not _body_world_points:
        return body.world_points()
    return _rotated_corners(body)


def _rotated_corners(body):
    """Body.world_points() of a polygon body that does not override it, pos and angle read once: the same floats."""
    pos, angle = body.pos, body.angle
    return WorldPoints([pos + p.rotate_rad(angle) for p in body.shape.points])


def _reaches(world, dt):
    """[world.reach(body, dt) for body in world.bodies], |g| dt worked out once for World's own reach: the same
    floats."""
    if type(world).reach is not World.reach:
        return [world.reach(body, dt) for body in world.bodies]
    fall = world.gravity.length() * dt
    return [0.0 if body.inv_mass == 0 else (body.vel.length() + fall + abs(body.omega) * body.shape.radius) * dt
            for body in world.bodies]


def _polygon_manifold(points, xy, flat, i, j, rule, margin):
    """collision.collide's polygon pair with a margin, on the floats of _speculative_manifolds: a Manifold or None."""
    pa, pb = points[i], points[j]
    a = flat[i] = flat[i] or collision.flat_outline(pa, xy[i])
    b = flat[j] = flat[j] or collision.flat_outline(pb, xy[j])
    hit = collision.sat_xy(pa, a, pb, b, margin)
    if hit is None:
        return None
    normal, depth = hit
    if rule == "clip":
        pairs = collision.clip_manifold_outlines(pa, a, pb, b, normal, depth, margin)
    else:
        pairs = (collision.corner_manifold_xy(pa, a, pb, b, normal, margin)
                 or [(p, depth) for p in collision.contact_points(pa, pb, normal)])
    points, depths = [], []
    for p, d in pairs:
        points.append(p)
        depths.append(d)
    return _manifold((normal, depth, points, depths))  # Manifold(normal, depth, points, depths), made in C


def _polygon_box(corners):
    """Body.aabb of a polygon from its world corners: (min x, min y, max x, max y) px; unrolled for four corners.

    The same comparisons as min() and max() (the first of equal values kept), so the same floats.
    """
    if len(corners) != 4:
        xs = [p.x for p in corners]
        ys = [p.y for p in corners]
        return (min(xs), min(ys), max(xs), max(ys))
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = corners
    left = right = x0  # each of x1, x2, x3 (then y) compared in turn, as min() and max() do
    if x1 < left:
        left = x1
    if x1 > right:
        right = x1
    if x2 < left:
        left = x2
    if x2 > right:
        right = x2
    if x3 < left:
        left = x3
    if x3 > right:
        right = x3
    top = bottom = y0
    if y1 < top:
        top = y1
    if y1 > bottom:
        bottom = y1
    if y2 < top:
        top = y2
    if y2 > bottom:
        bottom = y2
    if y3 < top:
        top = y3
    if y3 > bottom:
        bottom = y3
    return (left, top, right, bottom)
