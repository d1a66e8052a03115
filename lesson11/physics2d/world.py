"""The World: bodies advanced with a fixed step, gravity, and an iterative contact solver.

A scene declares the effects it needs in `effects`; the world runs those and
nothing else (no friction pass for a frictionless scene, no swept tests unless
"ccd" is asked for). Every setting is an attribute, checked whenever it is set
(in World(...) or later), with a one-line ValueError naming it and the value.
A lab can hand in its own `sat`, `resolve` and `separate` (and, for balls,
`circle_polygon` and `circle_point`), and the world calls them inside its
loop, so a student's functions run the whole simulation.

World.step reads top to bottom, one comment per phase, for both solvers.
With the "sleep" effect, step() ends with update_sleep (sleep timers, then
calm islands fall asleep), and manifolds() visits only pairs in which a body
moves and wakes what an awake body touches (the hooks sleep_timer, moves, wake).
"""
import math
from collections import namedtuple

from . import broadphase, collision, response
from .arbiter import (CONTACT_HERTZ, DAMPING_RATIO, RESTITUTION_PASSES, SPECULATIVE_MARGIN, Arbiter,
                      soft_constants)
from .vectors import Vector2, finite_number, finite_vector

GRAVITY = Vector2(0, 980)  # px/s², the course's gravity (y down)
STEP = 1 / 120             # s, the course's fixed physics step
EFFECTS = ("gravity", "rotation", "friction", "restitution", "correction", "ccd", "sleep")
SOLVERS = ("lesson", "accumulated")
ORDERS = ("move-first", "solve-first")
BROAD_PHASES = ("sweep-and-prune", "all-pairs")
LESSON_SUBSTEPS = 4        # the lesson solver's sub-steps in the solve-first order (see World.lesson_solve_first)
CONTACT_RULES = ("corners", "clip")
LESSON_EFFECTS = frozenset({"gravity", "rotation", "friction", "restitution", "correction"})
SLEEP_SPEED = 5.0          # px/s: "sleep" effect, a body slower than this (and spinning slower than SLEEP_SPIN) ...
SLEEP_SPIN = 0.1           # rad/s
SLEEP_AFTER = 0.5          # s ... for this long, with every body it touches, falls asleep
MAX_STEPS = 4              # fixed steps per advance() at most: two 60 fps frames' worth of 1/120 s steps

Contact = namedtuple("Contact", "a b point normal depth")
Contact.__doc__ = "One contact: bodies a and b, the world point (px), the unit normal A→B, the depth (px)."


# ---------------------------------------------------------------- one validator per setting

def _positive_seconds(name):
    def check(value):
        value = finite_number(value, f"world {name}")
        if value <= 0:
            raise ValueError(f"world {name} must be > 0 s, got {value}")
        return value
    return check


def _whole_number(name):
    def check(value):
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise ValueError(f"world {name} must be a whole number >= 1, got {value!r}")
        return value
    return check


def _whole_number_or_none(name):
    def check(value):
        return None if value is None else _whole_number(name)(value)
    return check


def _at_least_zero(name, unit):
    def check(value):
        value = finite_number(value, f"world {name}")
        if value < 0:
            raise ValueError(f"world {name} must be >= 0 {unit}, got {value}")
        return value
    return check


def _check_percent(value):
    value = finite_number(value, "world percent")
    if not 0 <= value <= 1:
        raise ValueError(f"world percent must be between 0 and 1, got {value}")
    return value


def _one_of(choices, sentence):
    """A validator accepting only the values in `choices`; `sentence` words the error."""
    def check(value):
        if value not in choices:
            raise ValueError(sentence.format(value=value))
        return value
    return check


_check_contact_rule = _one_of(CONTACT_RULES, "contact_rule must be 'corners' or 'clip', got {value!r}")
_check_solver = _one_of(SOLVERS, f"solver must be one of {list(SOLVERS)}, got {{value!r}}")
_check_broad_phase = _one_of(BROAD_PHASES, f"broad_phase must be one of {list(BROAD_PHASES)}, got {{value!r}}")
_check_order = _one_of(ORDERS, f"order must be one of {list(ORDERS)}, got {{value!r}}")


def _check_effects(value):
    if isinstance(value, str):
        raise ValueError(f"effects must be a set of names such as {{{value!r}}}, not the string {value!r}")
    unknown = set(value) - set(EFFECTS)
    if unknown:
        raise ValueError(f"unknown effects {sorted(unknown)}; choose from {list(EFFECTS)}")
    return frozenset(value)


def _check_hook(name):
    def check(value):
        if not callable(value):
            raise ValueError(f"world {name} must be a function (or None for the library's), got {value!r}")
        return value
    return check


def _check_bool(name):
    def check(value):
        if not isinstance(value, bool):
            raise ValueError(f"world {name} must be True or False, got {value!r}")
        return value
    return check


def _setting(name, check, forget_arbiters=False):
    """A World attribute validated on every set; forget_arbiters drops the cached contacts when it changes."""
    def get(world):
        return getattr(world, "_" + name)

    def set_(world, value):
        value = check(value)
        if forget_arbiters and getattr(world, "_" + name, value) != value:
            world.arbiters = {}
        setattr(world, "_" + name, value)
    return property(get, set_, doc=f"World setting {name!r}, checked when set.")


class World:
    """A collection of bodies stepped with a fixed time step.

    Settings (keywords of World(...) and attributes; defaults are the lesson's):
      gravity        GRAVITY = (0, 980) px/s²
      step_seconds   STEP = 1/120 s, the fixed physics step (step() is the action that runs one)
      iterations     6 solver passes over the contacts per (sub-)step, int >= 1
      substeps       each fixed step is split into this many equal sub-steps, int >= 1;
                     None (default): LESSON_SUBSTEPS = 4 for the lesson solver's solve-first order, else 1
      slop           0.5 px of overlap tolerated by the push-out
      percent        0.4, share of the remaining overlap pushed out per push-out pass
      resting_speed  30 px/s; slower impacts do not bounce
      max_frame      0.25 s; longer frames are clamped (window drags, breakpoints)
      max_steps      MAX_STEPS = 4 fixed steps at most per advance(), int >= 1, or None (no cap);
                     the frame time that does not fit is dropped, so a frame whose physics runs
                     long makes the simulation run slower than the clock, instead of making the
                     next frame longer still (the "spiral": 30 catch-up steps a frame, 3 fps)
      contact_rule   "corners" (the lesson's corners-inside rule) or "clip" (edge clipping)
      effects        which effects run, a subset of EFFECTS; LESSON_EFFECTS by default
                     (the push-out is the "correction" effect)
      order          the lesson solver's order: "solve-first" (default; Box2D-Lite's: contacts
                     once per sub-step, resolve passes, move, one push-out pass) or "move-first"
                     (the lesson text's step_world: gravity, move, then `iterations` passes of
                     contacts, resolve and push-out; a crate on the 22° ramp creeps ~3 px/s)
      solver         "lesson" (fresh impulses every pass by resolve, push-out by separate) or
                     "accumulated" (arbiter.py: impulses kept across passes and steps,
                     soft contacts, sub-steps; for tall stacks and large mass ratios)
      warm_starting  True: the accumulated solver starts from last step's impulses
                     (the lesson solver ignores it)
      sleep_speed    SLEEP_SPEED = 5 px/s, sleep_spin SLEEP_SPIN = 0.1 rad/s, sleep_after SLEEP_AFTER = 0.5 s:
                     the "sleep" effect (not in LESSON_EFFECTS; a scene that does not declare it
                     pays nothing). After each step every awake dynamic body's `sleep_time` is
                     sleep_timer(sleep_time, speed, spin, dt); an island of touching dynamic bodies
                     whose sleep_time are all >= sleep_after falls asleep together (`asleep`,
                     velocity and spin zeroed). Bodies for which moves(body) is False are not
                     integrated, and a pair in which neither moves is never visited by the broad
                     phase. For every touching pair found, wake(a, b) returns the bodies to wake;
                     World.wake(body) wakes the body and the island it fell asleep with.
    Hooks: sat(pa, pb), resolve(a, b, normal, point), separate(a, b, normal, depth);
      for sleep: sleep_timer(timer, speed, spin, dt) -> the new timer (s), moves(body) -> bool,
      wake(a, b) -> the bodies to wake (library: sleep_timer_of_world, moves_of_world, wake_of_world);
      for circles: circle_polygon(center, radius, points) -> None or (normal out of the
      circle into the polygon, depth px), the test for every circle–polygon pair, and
      circle_point(center, radius, normal, depth) -> the contact point (world px) of every
      circle pair, normal pointing out of that circle (default collision.circle_contact_point,
      halfway into the overlap). Each hook must be a function (or None: the library's);
      anything else is a one-line ValueError. Like sat, the two circle hooks serve the
      lesson solver; the accumulated solver's speculative contacts use the library's.
      broad_phase    "sweep-and-prune" (default; broadphase.py: boxes sorted along x and swept)
                     or "all-pairs" (the reference: every pair box against box); the same pairs
                     in the same order, so the same results to the last bit
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
    Changing solver or contact_rule between steps is safe: the accumulated
    solver's kept contacts (`arbiters`) are dropped.
    """

    gravity = property(lambda w: w._gravity,
                       lambda w, v: setattr(w, "_gravity", finite_vector(v, "world gravity")),
                       doc="Gravity (px/s²), checked when set.")
    step_seconds = _setting("step_seconds", _positive_seconds("step_seconds"))
    iterations = _setting("iterations", _whole_number("iterations"))
    substeps = property(lambda w: w._substeps or (LESSON_SUBSTEPS if w.solver == "lesson" and w.order == "solve-first"
                                                  else 1),
                        lambda w, v: setattr(w, "_substeps", None if v is None else _whole_number("substeps")(v)),
                        doc="Sub-steps per fixed step, checked when set; None: 4 for the lesson solver's "
                            "solve-first order, else 1.")
    slop = _setting("slop", _at_least_zero("slop", "px"))
    percent = _setting("percent", _check_percent)
    resting_speed = _setting("resting_speed", _at_least_zero("resting_speed", "px/s"))
    max_frame = _setting("max_frame", _positive_seconds("max_frame"))
    max_steps = _setting("max_steps", _whole_number_or_none("max_steps"))
    contact_rule = _setting("contact_rule", _check_contact_rule, forget_arbiters=True)
    solver = _setting("solver", _check_solver, forget_arbiters=True)
    effects = _setting("effects", _check_effects)
    order = _setting("order", _check_order)
    broad_phase = _setting("broad_phase", _check_broad_phase)
    warm_starting = _setting("warm_starting", _check_bool("warm_starting"))
    circle_polygon = _setting("circle_polygon", _check_hook("circle_polygon"))
    circle_point = _setting("circle_point", _check_hook("circle_point"))
    sleep_speed = _setting("sleep_speed", _at_least_zero("sleep_speed", "px/s"))
    sleep_spin = _setting("sleep_spin", _at_least_zero("sleep_spin", "rad/s"))
    sleep_after = _setting("sleep_after", _positive_seconds("sleep_after"))
    sleep_timer = _setting("sleep_timer", _check_hook("sleep_timer"))
    moves = _setting("moves", _check_hook("moves"))
    wake_pair = _setting("wake_pair", _check_hook("wake"))

    def __init__(self, bodies=(), *, gravity=GRAVITY, step_seconds=STEP, iterations=6, substeps=None,
                 slop=response.SLOP, percent=response.PERCENT, resting_speed=response.RESTING_SPEED,
                 max_frame=0.25, max_steps=MAX_STEPS, contact_rule="corners", effects=LESSON_EFFECTS, solver="lesson",
                 warm_starting=True, order="solve-first", sat=None, resolve=None, separate=None,
                 circle_polygon=None, circle_point=None, sleep_speed=SLEEP_SPEED, sleep_spin=SLEEP_SPIN,
                 sleep_after=SLEEP_AFTER, sleep_timer=None, moves=None, wake=None,
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

    # ---------------------------------------------------------------- the "sleep" effect

    def sleep_timer_of_world(self, timer, speed, spin, dt):
        """The library's sleep timer: timer + dt (s) while speed < sleep_speed and |spin| < sleep_spin, else 0."""
        return timer + dt if speed < self.sleep_speed and abs(spin) < self.sleep_spin else 0.0

    @staticmethod
    def moves_of_world(body):
        """The library's rule: a body is integrated (and its pairs tested) if it is dynamic and awake."""
        return body.inv_mass != 0 and not body.asleep

    @staticmethod
    def wake_of_world(a, b):
        """The library's rule: of a touching pair, the sleeping body is woken if the other is dynamic and awake."""
        return [sleeper for sleeper, other in ((a, b), (b, a))
                if sleeper.asleep and other.inv_mass != 0 and not other.asleep]

    def wake(self, body):
        """Wake `body` and every body that fell asleep in the same island (timers back to 0)."""
        for other in getattr(body, "island", None) or [body]:
            if other.asleep:
                other.asleep = False
                other.sleep_time = 0.0
                other.island = None
        body.asleep = False
        body.sleep_time = 0.0

    def fall_asleep(self, bodies):
        """Put these dynamic bodies to sleep together, as one island: no velocity, no spin."""
        island = list(bodies)
        for body in island:
            body.asleep = True
            body.vel = Vector2()
            body.omega = 0.0
            body.island = island

    def update_sleep(self, dt):
        """After a step: each awake dynamic body's sleep_time = sleep_timer(...); calm islands fall asleep.

        An island is a group of awake dynamic bodies joined by the pairs that touched
        in any contact search of this step
        (static bodies do not join islands); it sleeps when every member's
        sleep_time >= sleep_after, so a pile sleeps as one (and World.wake wakes it
        as one).
        """
        awake = [body for body in self.bodies if body.inv_mass != 0 and not body.asleep]
        for body in awake:
            timer = finite_number(self.sleep_timer(body.sleep_time, body.vel.length(), body.omega, dt),
                                  "sleep_timer's result")
            body.sleep_time = timer
        parent = {id(body): id(body) for body in awake}

        def root(key):
            while parent[key] != key:
                parent[key] = parent[parent[key]]
                key = parent[key]
            return key
        for ka, kb in self.touched:
            if ka in parent and kb in parent:
                parent[root(ka)] = root(kb)
        self.touched = set()
        islands = {}
        for body in awake:
            islands.setdefault(root(id(body)), []).append(body)
        for members in islands.values():
            if all(body.sleep_time >= self.sleep_after for body in members):
                self.fall_asleep(members)

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
        """Advance every body by one step of dt seconds (default: step_seconds), in `substeps` sub-steps h = dt/substeps.

        The lesson solver, order="solve-first" (the default, Box2D-Lite's order),
        each sub-step: contacts once, the push-out of the last move, resolve()
        passes, then move; the step ends with one more contact search and the
        last move's push-out (lesson_solve_first has the phases). order="move-first" (the
        lesson text's order), each sub-step:
          1. v += g h
          2. x += v h, angle += ω h (a swept move for "ccd" bullets)
          3. `iterations` passes of: contacts (broad phase, sat, contact points),
             resolve() at each point, separate() on each pair
        Moving before solving lets a crate resting on a slope creep down by
        g sin θ h² per step (3.1 px/s on the 22° ramp): the impulses cancel the
        velocity, but not the move already made (see lesson11/README.md).
        The accumulated solver: arbiter.py's phases (its module docstring).
        Raises ValueError if any body ends the step with a non-finite state.
        """
        dt = self.step_seconds if dt is None else _positive_seconds("step dt")(dt)
        h = dt / self.substeps
        if self.solver == "lesson" and self.order == "solve-first":
            touching = set()  # pairs that touched before the last move (none yet: the last step pushed them out)
            for _ in range(self.substeps):
                touching = self.lesson_solve_first(h, touching)
            # where the bodies touch after the last move (what the lab draws), then its push-out
            found = list(self.manifolds())
            self.push_out(found, touching)
            self.contacts = [Contact(a, b, point, m.normal, m.depth) for a, b, m in found for point in m.points]
        elif self.solver == "lesson":
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
        else:
            # 1. collide once per step: speculative manifolds, matched with last step's arbiters
            arbiters = {}
            for a, b, manifold in self.manifolds(speculative=dt):
                arbiter = self.arbiters.get((id(a), id(b))) or Arbiter(a, b)
                arbiter.update(manifold)
                arbiters[(id(a), id(b))] = arbiter
            self.arbiters = arbiters
            # 2. prepare: anchors, effective masses, approach speeds (before any impulse)
            for arbiter in arbiters.values():
                arbiter.prepare(self, self.warm_starting)
            soft = soft_constants(min(CONTACT_HERTZ, 0.25 / h), DAMPING_RATIO, h)
            use_push = "correction" in self.effects
            start = {id(body): (body.pos.x, body.pos.y, body.angle) for body in self.bodies}
            motion = {key: (0.0, 0.0, 1.0, 0.0) for key in start}
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
            # 7. restitution, from the approach speeds found in phase 2
            for _ in range(RESTITUTION_PASSES):
                for arbiter in arbiters.values():
                    arbiter.bounce(self.resting_speed)
            self.contacts = [Contact(arb.a, arb.b, c.point, arb.normal, c.depth)
                             for arb in arbiters.values() for c in arb.points]
        if "sleep" in self.effects:
            self.update_sleep(dt)
        self.time += dt
        self.counters["steps"] += 1
        for index, body in enumerate(self.bodies):
            if not body.is_finite():
                raise ValueError(f"body {index} {body!r} became non-finite at t = {self.time:.4f} s; "
                                 "check its mass, the step and the hooks")

    def lesson_solve_first(self, h, touching):
        """One sub-step h (s) of the lesson solver in Box2D-Lite's order, with the lab's resolve and separate.

        `touching` holds the pairs (id(a), id(b)) that touched before the last
        move; returns the pairs touching now, for the next sub-step.
          1. contacts, found once (broad phase, the lab's sat, contact points)
          2. the push-out of the last move: separate() on the pairs found in
             step 1 that were in `touching` too. A pair that met during the
             last move waits for this sub-step's impulses (pushing it out first
             would lift a falling body before it bounces: energy from nowhere)
          3. v += g h/2, then the impact pass: resolve() once at every point,
             then v += g h/2. The bounce sits in the middle of the step's
             gravity kick: an e = 1 disc that arrives at vn leaves at exactly
             -vn, and ½ v² + g·height + ½ g h v_down, the energy this integrator
             keeps in free flight, is unchanged by the bounce. (Bouncing after
             the whole kick reflects vn + g h: +g h v per bounce; before it,
             -g h v, 2.6 % per bounce from 200 px.)
          4. `iterations` passes of resolve() over every point (resolve_pass:
             forwards, backwards, ...); the speeds left are below resting_speed,
             so e = 0 here and resting crates do not bounce
          5. x += v h, angle += ω h: friction has already stopped the slide, so a
             crate on the 22° ramp no longer creeps g sin θ h² per step
        step() ends with one more contact search (what the lab draws) and the
        last move's push-out.
        The contacts of step 1 serve the push-out and the impulses: the push-out
        moves a body by at most percent × (depth - slop) along the normal, so the
        points the impulses use are off by that much (a fraction of a px).
        Why 4 sub-steps (measured in the lab's 12-crate pile,
        lesson11/bench/section1_probe.py): every push-out moves crates along
        their SAT normals and shakes a leaning pile (2 sub-steps with 3 push-out
        passes each: top speed 5.41 px/s); 4 shorter sub-steps let a landing
        crate in at most v h/4 per move and still push it out 4 times a step.
        Per fixed step with LESSON_SUBSTEPS = 4: 4 + 1 contact searches
        (move-first: 6) and 4 × (1 + iterations) = 28 resolve passes
        (move-first: 6).
        """
        found = list(self.manifolds())
        self.push_out(found, touching)
        self.integrate_velocities(h / 2)
        self.resolve_pass(found, 0)
        self.integrate_velocities(h / 2)
        for index in range(self.iterations):
            self.resolve_pass(found, index)
        self.integrate_positions(h)
        return {(id(a), id(b)) for a, b, _ in found}

    def push_out(self, found, touching):
        """separate() on each (a, b, manifold) in `found` whose pair (id(a), id(b)) is in `touching` ("correction" only)."""
        if "correction" not in self.effects:
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

    def integrate_velocities(self, dt):
        """Gravity for every dynamic body: v += g dt (only if the scene declares "gravity")."""
        if "gravity" not in self.effects:
            return
        bodies = [body for body in self.bodies if self.moves(body)] if "sleep" in self.effects else self.bodies
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
                                             self.circle_polygon, self.circle_point)
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
    points = [body.world_points() for body in bodies]
    boxes = []
    for body, corners in zip(bodies, points):
        if body.shape.kind == "polygon":
            boxes.append(_polygon_box(corners))
        else:
            boxes.append(body.aabb(corners))
    search = broadphase.all_pairs if world.broad_phase == "all-pairs" else broadphase.sweep_and_prune
    pairs, tested = search(boxes, moving, None, 0.0, boxes)
    world.counters["pair_tests"] += tested
    sat, rule = world.sat, world.contact_rule
    circle_polygon, circle_point = world.circle_polygon, world.circle_point
    contact_points, collide, manifold_of = collision.contact_points, collision.collide, collision.Manifold
    narrow = contacts = 0
    try:
        for i, j in pairs:
            a, b = bodies[i], bodies[j]
            narrow += 1
            if rule == "corners" and a.shape.kind == "polygon" and b.shape.kind == "polygon":
                hit = sat(points[i], points[j])
                if hit is None:
                    continue
                normal, depth = hit
                found = contact_points(points[i], points[j], normal)
                manifold = manifold_of(normal, depth, found, [depth] * len(found))
            else:
                manifold = collide(a, b, points[i], points[j], rule, sat, 0.0, circle_polygon, circle_point)
                if manifold is None:
                    continue
            contacts += len(manifold.points)
            yield a, b, manifold
    finally:
        world.counters["narrow_tests"] += narrow
        world.counters["contacts"] += contacts


def _polygon_box(corners):
    """Body.aabb of a polygon from its world corners: (min x, min y, max x, max y) px; unrolled for four corners.

    The same comparisons as min() and max() (the first of equal values kept), so the same floats.
    """
    if len(corners) != 4:
        xs = [p.x for p in corners]
        ys = [p.y for p in corners]
        return (min(xs), min(ys), max(xs), max(ys))
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = corners
    left = right = x0
    top = bottom = y0
    for x, y in ((x1, y1), (x2, y2), (x3, y3)):
        if x < left:
            left = x
        if x > right:
            right = x
        if y < top:
            top = y
        if y > bottom:
            bottom = y
    return (left, top, right, bottom)
