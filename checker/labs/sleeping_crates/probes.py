"""Probes of a Sleeping Crates file's own functions, run inside the checker's child process.

Each probe calls one of the student's functions on cases chosen to show the
usual mistakes and returns plain data: what the student's function gave and
what the lesson's rule gives (added in the grader only: `judging`, checker/judging/probe_kit.py).
The checks in checker/labs/sleeping_crates/checks.py compare them in the grading process.

    sleep_timer      (step 2) calm and not calm crates: fast, spinning either way, both
    moves            (step 3) static, awake, sleeping bodies (and a static body flagged asleep)
    wake_on_contact  (step 4) every kind of pair, in both orders
    narrow_work      (the cost criterion) one step of a touching 40-crate grid built by the
                     lab's build(), awake and then asleep, in a World running the lab's
                     three functions; World.counters gives the pair and narrow-phase tests

Units: px, s, rad.
"""

from lesson11.physics2d import LESSON_EFFECTS, Body, World, box_points

from checker.judging.common import real, value_text
from checker.judging.probe_kit import judging, reference
from checker.judging.tape import clock, run_rng

REQUIRED = ("sleep_timer", "moves", "wake_on_contact", "build", "main")
SLEEP_SPEED = 5.0   # px/s, the handout's thresholds
SLEEP_SPIN = 0.1    # rad/s
DT = 1 / 120        # s, the course's step
GRID_CRATES = 40
GRID_COLUMNS = 10
W, H = 50, 36       # px
FLOOR_TOP = 560.0   # px


_text = value_text   # repr cut to 60 characters; safe for a 5000-digit int


def _number(value):
    try:
        return real(value)
    except (TypeError, ValueError):
        return _text(value)


# ---------------------------------------------------------------- step 2: sleep_timer

TIMER_CASES = (
    # (what, timer s, speed px/s, spin rad/s)
    ("a crate at rest", 0.0, 0.0, 0.0),
    ("a calm crate, 0.25 s into its timer", 0.25, 2.0, 0.02),
    ("a calm crate spinning slowly backwards", 0.3, 1.0, -0.05),
    ("a crate just under the speed threshold", 0.45, 4.9, 0.0),
    ("a crate moving at 6 px/s", 0.4, 6.0, 0.0),
    ("a crate falling at 300 px/s", 0.2, 300.0, 0.0),
    ("a crate spinning at 0.2 rad/s", 0.4, 1.0, 0.2),
    ("a crate spinning backwards at 0.3 rad/s", 0.4, 1.0, -0.3),
    ("a crate fast and spinning", 0.1, 40.0, 2.0),
    # told-apart cases (issue 33): speed · dt (px per step) is under 5 only below 600 px/s, and a spin of
    # 8 rad/s is under SLEEP_SPEED (5) but not under SLEEP_SPIN, so comparing the wrong quantity shows as itself
    ("a crate falling fast at 900 px/s", 0.2, 900.0, 0.0),
    ("a slow crate spinning fast", 0.3, 1.0, 8.0),
)


@reference
def reference_timer(timer, speed, spin, dt):
    """The lesson's rule: timer + dt (s) while speed < SLEEP_SPEED (px/s) and |spin| < SLEEP_SPIN (rad/s), else 0."""
    return timer + dt if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN else 0.0


@reference
def timer_mistakes(timer, speed, spin, dt):
    """{name: what a known wrong sleep_timer returns} for one case (names: checks.TIMER_MISTAKES)."""
    calm = speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN

    def rule(still):
        return timer + dt if still else 0.0
    return {"or": rule(speed < SLEEP_SPEED or abs(spin) < SLEEP_SPIN),
            "ignores_spin": rule(speed < SLEEP_SPEED), "ignores_speed": rule(abs(spin) < SLEEP_SPIN),
            "signed_spin": rule(speed < SLEEP_SPEED and spin < SLEEP_SPIN),
            "speed_dt": rule(speed * dt < SLEEP_SPEED and abs(spin) < SLEEP_SPIN),
            "spin_vs_speed": rule(speed < SLEEP_SPEED and abs(spin) < SLEEP_SPEED),
            "never_resets": timer + dt if calm else timer, "counts_frames": timer + 1 if calm else 0.0,
            "returns_dt": dt if calm else 0.0, "no_growth": timer if calm else 0.0,
            # issue 40: per-step thresholds, a step fixed at 1/120 s, squared speeds
            "thresholds_dt": rule(speed < SLEEP_SPEED * dt and abs(spin) < SLEEP_SPIN * dt),
            "both_dt": rule(speed * dt < SLEEP_SPEED and abs(spin) * dt < SLEEP_SPIN),
            "fixed_step": timer + 1 / 120 if calm else 0.0,
            "squared": rule(speed * speed < SLEEP_SPEED and spin * spin < SLEEP_SPIN),
            "speed_squared": rule(speed * speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN)}


def probe_sleep_timer(module, lab_path):
    """The student's sleep_timer on each case (dt = 1/120 s) beside the rule, and with dt = 1/60 s once."""
    cases = []
    rng = run_rng(module, "sleep_timer")   # two crates drawn for this run: one calm, one not
    drawn = (("a calm crate drawn for this run", round(rng.uniform(0.05, 0.45), 3), rng.uniform(0, 0.8 * SLEEP_SPEED),
              rng.uniform(-0.8, 0.8) * SLEEP_SPIN),
             ("a moving crate drawn for this run", round(rng.uniform(0.05, 0.45), 3),
              rng.uniform(1.3 * SLEEP_SPEED, 200), rng.uniform(-0.8, 0.8) * SLEEP_SPIN))
    for what, timer, speed, spin in TIMER_CASES + drawn:
        for dt in (DT,) if what != "a calm crate, 0.25 s into its timer" else (DT, 1 / 60):
            cases.append({"case": what, "timer": timer, "speed": speed, "spin": spin, "dt": dt,
                          "got": _number(module.sleep_timer(timer, speed, spin, dt))})
            if judging(module):
                cases[-1]["want"] = reference_timer(timer, speed, spin, dt)
                cases[-1]["mistakes"] = timer_mistakes(timer, speed, spin, dt)
    return cases


# ---------------------------------------------------------------- step 3: moves

def _crate(mass=1.8, asleep=False, pos=(100, 100)):
    body = Body(box_points(W, H), pos, mass)
    body.asleep = asleep
    return body


MOVES_CASES = (("the floor (static)", 0.0, False), ("an awake crate", 1.8, False),
               ("a sleeping crate", 1.8, True), ("a static body flagged asleep", 0.0, True))


def probe_moves(module, lab_path):
    """The student's moves(body) for static, awake and sleeping bodies."""
    cases = []
    rng = run_rng(module, "moves")   # and the four kinds again, in an order and with masses drawn for this run
    drawn = [(f"{what}, drawn for this run", 0.0 if mass == 0 else round(rng.uniform(0.3, 9.0), 3), asleep)
             for what, mass, asleep in rng.sample(MOVES_CASES, len(MOVES_CASES))]
    for what, mass, asleep in MOVES_CASES + tuple(drawn):
        got = module.moves(_crate(mass, asleep))
        cases.append({"case": what, "got": bool(got) if isinstance(got, (bool, int)) else _text(got)})
        if judging(module):
            cases[-1]["want"] = reference_moves(mass, asleep)
    return cases


@reference
def reference_moves(mass, asleep):
    """The lesson's moves(): a body moves when it is dynamic (mass > 0) and awake."""
    return mass != 0 and not asleep


# ---------------------------------------------------------------- step 4: wake_on_contact

KINDS = {"static": (0.0, False), "awake": (1.8, False), "asleep": (1.8, True)}
PAIRS = (("awake", "asleep"), ("asleep", "awake"), ("static", "asleep"), ("asleep", "static"),
         ("asleep", "asleep"), ("awake", "awake"), ("awake", "static"))


def probe_wake_on_contact(module, lab_path):
    """The student's wake_on_contact(a, b) for every kind of pair: which of "a" and "b" it returns."""
    cases = []
    for kind_a, kind_b in PAIRS:
        a, b = _crate(*KINDS[kind_a]), _crate(*KINDS[kind_b])
        got = module.wake_on_contact(a, b)
        try:
            woken = sorted({"a" if body is a else "b" if body is b else "another body" for body in (got or ())})
        except TypeError:
            woken = _text(got)
        cases.append({"a": kind_a, "b": kind_b, "got": woken})
        if judging(module):
            cases[-1]["want"] = reference_woken(kind_a, kind_b)
    return cases


@reference
def reference_woken(kind_a, kind_b):
    """The lesson's wake_on_contact: the sleeping body ("a" or "b") of a pair whose other body is awake."""
    return sorted(name for name, me, other in (("a", kind_a, kind_b), ("b", kind_b, kind_a))
                  if me == "asleep" and other == "awake")


# ---------------------------------------------------------------- the cost criterion

def grid_items(asleep):
    """40 crates in 4 rows of 10, each row resting on the one below (0.2 px of overlap, so they touch)."""
    items = []
    for k in range(GRID_CRATES):
        row, column = divmod(k, GRID_COLUMNS)
        items.append({"w": W, "h": H, "pos": [160 + column * W + (row % 2) * 10,
                                             FLOOR_TOP - H / 2 + 0.2 - row * (H - 0.2)], "asleep": asleep})
    return items


def grid_world(module, asleep):
    floor = Body(box_points(900, 40), (450, 580), 0)
    world = World([floor] + [module.build(item) for item in grid_items(asleep)],
                  effects=LESSON_EFFECTS | {"sleep"}, sleep_timer=module.sleep_timer, moves=module.moves,
                  wake=module.wake_on_contact)
    if asleep:
        world.fall_asleep(world.bodies[1:])
    return world


def probe_narrow_work(module, lab_path):
    """One step of the 40-crate grid awake, then asleep: pair and narrow tests (World.counters) and CPU ms."""
    out = {}
    for name, asleep in (("awake", False), ("asleep", True)):
        world = grid_world(module, asleep)
        start = clock(module)
        world.step()
        out[name] = dict(world.counters, ms=(clock(module) - start) * 1000,
                         still_asleep=sum(1 for body in world.bodies if body.asleep))
    return out


# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("sleep_timer", "moves", "wake_on_contact")

# probe name -> (the lab function it needs, the probe)
PROBES = {"sleep_timer": ("sleep_timer", probe_sleep_timer),
          "moves": ("moves", probe_moves),
          "wake_on_contact": ("wake_on_contact", probe_wake_on_contact),
          "narrow_work": ("build", probe_narrow_work)}
