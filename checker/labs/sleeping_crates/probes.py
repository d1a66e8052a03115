"""Sleeping Crates' steps, declared (checker/judging/declared.py), and the cost criterion's probe.

    sleep_timer      (step 2) calm and not calm crates: fast, spinning either way, both; 15 known wrong rules
    moves            (step 3) static, awake, sleeping bodies (and a static body flagged asleep)
    wake_on_contact  (step 4) every kind of pair, in both orders
    narrow_work      (the cost criterion) one step of a touching 40-crate grid built by the lab's build(), awake
                     and then asleep, in a World running the lab's three functions (World.counters)
The lesson's answers are computed in the grader only (each reference_* is a @reference). Units: px, s, rad.
"""

from lesson11.physics2d import LESSON_EFFECTS, Body, World, box_points

from checker.judging.common import as_number, value_text
from checker.judging.declared import Form, Step
from checker.judging.probe_kit import reference
from checker.judging.tape import clock, run_rng

REQUIRED = ("sleep_timer", "moves", "wake_on_contact", "build", "main")
SLEEP_SPEED = 5.0   # px/s, the handout's thresholds
SLEEP_SPIN = 0.1    # rad/s
DT = 1 / 120        # s, the course's step
GRID_CRATES = 40
GRID_COLUMNS = 10
W, H = 50, 36       # px
FLOOR_TOP = 560.0   # px
ABS = 1e-9          # s: the timer against the rule (same arithmetic, timer + dt)


_text = value_text   # repr cut to 60 characters; safe for a 5000-digit int


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


def _calm(c, speed=lambda c: c["speed"] < SLEEP_SPEED, spin=lambda c: abs(c["spin"]) < SLEEP_SPIN, both=all):
    return both((speed(c), spin(c)))


def _timer_form(name, text, calm=_calm, grows=lambda c: c["timer"] + c["dt"], rest=lambda c: 0.0):
    """A known wrong sleep_timer: it finds a crate calm by its own rule, grows and starts again its own way."""
    return Form(f"timer_{name}", text, lambda c: grows(c) if calm(c) else rest(c))


def timer_cases(module):
    """TIMER_CASES at dt = 1/120 s (one also at 1/60 s) and two crates drawn for this run: one calm, one not."""
    rng = run_rng(module, "sleep_timer")
    drawn = (("a calm crate drawn for this run", round(rng.uniform(0.05, 0.45), 3), rng.uniform(0, 0.8 * SLEEP_SPEED),
              rng.uniform(-0.8, 0.8) * SLEEP_SPIN),
             ("a moving crate drawn for this run", round(rng.uniform(0.05, 0.45), 3),
              rng.uniform(1.3 * SLEEP_SPEED, 200), rng.uniform(-0.8, 0.8) * SLEEP_SPIN))
    return [{"case": what, "timer": timer, "speed": speed, "spin": spin, "dt": dt}
            for what, timer, speed, spin in TIMER_CASES + drawn
            for dt in ((DT,) if what != "a calm crate, 0.25 s into its timer" else (DT, 1 / 60))]


TIMER = Step(
    "timer_rule", "Step 2: sleep_timer() adds dt while speed < SLEEP_SPEED and |spin| < SLEEP_SPIN, else starts "
    "again from 0.", 2, "sleep_timer", timer_cases, lambda timer, c: timer(c["timer"], c["speed"], c["spin"], c["dt"]),
    lambda c: reference_timer(c["timer"], c["speed"], c["spin"], c["dt"]), answer=as_number, hint="timer",
    same=lambda got, want: not isinstance(got, str) and abs(got - want) <= ABS, bad=lambda got: isinstance(got, str),
    label=lambda c: f"sleep_timer({c['timer']:g}, {c['speed']:g}, {c['spin']:g}, {c['dt']:.4g}) ({c['case']})",
    show=lambda seconds: f"{seconds:.6g} s", kind="a number of seconds", unnamed="the timer does not follow the rule",
    wrong=(_timer_form("or", "calm when speed < SLEEP_SPEED `or` |spin| < SLEEP_SPIN; the rule needs both (`and`)",
                       lambda c: _calm(c, both=any)),
           _timer_form("ignores_spin", "the timer looks at the speed only: a spinning crate must start again from 0 "
                       "too", lambda c: _calm(c, spin=lambda c: True)),
           _timer_form("ignores_speed", "the timer looks at the spin only: a moving crate must start again from 0 "
                       "too", lambda c: _calm(c, speed=lambda c: True)),
           _timer_form("signed_spin", "the spin is compared with its sign: a crate spinning backwards counts as calm; "
                       "compare abs(spin)", lambda c: _calm(c, spin=lambda c: c["spin"] < SLEEP_SPIN)),
           _timer_form("speed_dt", "speed * dt (px per step) is compared with SLEEP_SPEED, which is in px/s",
                       lambda c: _calm(c, speed=lambda c: c["speed"] * c["dt"] < SLEEP_SPEED)),
           _timer_form("both_dt", "speed * dt and |spin| * dt (per step) are compared with SLEEP_SPEED and "
                       "SLEEP_SPIN, which are per second",
                       lambda c: c["speed"] * c["dt"] < SLEEP_SPEED and abs(c["spin"]) * c["dt"] < SLEEP_SPIN),
           _timer_form("thresholds_dt", "the thresholds are scaled to one step (SLEEP_SPEED * dt, SLEEP_SPIN * dt); "
                       "they are per second, like speed and spin",
                       lambda c: c["speed"] < SLEEP_SPEED * c["dt"] and abs(c["spin"]) < SLEEP_SPIN * c["dt"]),
           _timer_form("spin_vs_speed", "|spin| is compared with SLEEP_SPEED (5 px/s) where its own threshold is "
                       "SLEEP_SPIN (0.1 rad/s)", lambda c: _calm(c, spin=lambda c: abs(c["spin"]) < SLEEP_SPEED)),
           _timer_form("squared", "speed² and spin² are compared with SLEEP_SPEED and SLEEP_SPIN: compare speed and "
                       "|spin| themselves",
                       lambda c: c["speed"] * c["speed"] < SLEEP_SPEED and c["spin"] * c["spin"] < SLEEP_SPIN),
           _timer_form("speed_squared", "speed² is compared with SLEEP_SPEED: compare the speed itself",
                       lambda c: _calm(c, speed=lambda c: c["speed"] * c["speed"] < SLEEP_SPEED)),
           _timer_form("never_resets", "the timer keeps its value when the crate moves: it must start again from 0",
                       rest=lambda c: c["timer"]),
           _timer_form("counts_frames", "the timer adds 1 (a frame) per step; it counts seconds: add dt",
                       grows=lambda c: c["timer"] + 1),
           _timer_form("fixed_step", "the timer adds 1/120 s per step, not dt: a World stepping at another rate "
                       "counts wrong", grows=lambda c: c["timer"] + 1 / 120),
           _timer_form("returns_dt", "you return dt, not timer + dt: the timer must grow from its value",
                       grows=lambda c: c["dt"]),
           _timer_form("no_growth", "the timer does not grow while the crate is calm: return timer + dt",
                       grows=lambda c: c["timer"])))


# ---------------------------------------------------------------- step 3: moves

def _crate(mass=1.8, asleep=False, pos=(100, 100)):
    body = Body(box_points(W, H), pos, mass)
    body.asleep = asleep
    return body


MOVES_CASES = (("the floor (static)", 0.0, False), ("an awake crate", 1.8, False),
               ("a sleeping crate", 1.8, True), ("a static body flagged asleep", 0.0, True))


def moves_cases(module):
    """The four kinds of body, then again in an order and with masses drawn for this run."""
    rng = run_rng(module, "moves")
    drawn = [(f"{what}, drawn for this run", 0.0 if mass == 0 else round(rng.uniform(0.3, 9.0), 3), asleep)
             for what, mass, asleep in rng.sample(MOVES_CASES, len(MOVES_CASES))]
    return [{"case": what, "mass": mass, "asleep": asleep} for what, mass, asleep in MOVES_CASES + tuple(drawn)]


def _moves_mistake(cases, c):
    """The rule a wrong moves() breaks, read from the kind of body it got wrong."""
    if c["want"]:
        return Form("moves_awake_false", "an awake crate must move, or nothing ever falls")
    if "static" in c["case"]:
        return Form("moves_static_true", "a static body never moves: with moves() True for the floor, every "
                                         "sleeping crate on it is still tested")
    return Form("moves_sleeping_true", "a sleeping crate does not move, so its quiet pairs are not tested")


MOVES = Step(
    "skips_sleepers", "Step 3: moves(body) is True for an awake dynamic body only (False for static and sleeping "
    "bodies).", 3, "moves", moves_cases, lambda moves, c: moves(_crate(c["mass"], c["asleep"])),
    lambda c: reference_moves(c["mass"], c["asleep"]), hint="moves", kind="True or False",
    answer=lambda got: bool(got) if isinstance(got, (bool, int)) else _text(got), bad=lambda got: isinstance(got, str),
    label=lambda c: f"moves() for {c['case']}", diagnose=_moves_mistake)


@reference
def reference_moves(mass, asleep):
    """The lesson's moves(): a body moves when it is dynamic (mass > 0) and awake."""
    return mass != 0 and not asleep


# ---------------------------------------------------------------- step 4: wake_on_contact

KINDS = {"static": (0.0, False), "awake": (1.8, False), "asleep": (1.8, True)}
PAIRS = (("awake", "asleep"), ("asleep", "awake"), ("static", "asleep"), ("asleep", "static"),
         ("asleep", "asleep"), ("awake", "awake"), ("awake", "static"))


def _pairs(rng):
    """The cases: every pair of PAIRS, its dynamic crates' mass drawn for this run (0.3-6; their kind, not their
    mass, decides the answer)."""
    return [{"a": a, "b": b, "mass": rng.uniform(0.3, 6.0)} for a, b in PAIRS]


def _woken(wake_on_contact, c):
    """Which of "a" and "b" the student's wake_on_contact(a, b) returns for a pair of c's kinds."""
    a, b = (_crate(c["mass"] * KINDS[kind][0] / KINDS["awake"][0], KINDS[kind][1]) for kind in (c["a"], c["b"]))
    got = wake_on_contact(a, b)
    try:
        return sorted({"a" if body is a else "b" if body is b else "another body" for body in (got or ())})
    except TypeError:
        return _text(got)


@reference
def reference_woken(kind_a, kind_b):
    """The lesson's wake_on_contact: the sleeping body ("a" or "b") of a pair whose other body is awake."""
    return sorted(name for name, me, other in (("a", kind_a, kind_b), ("b", kind_b, kind_a))
                  if me == "asleep" and other == "awake")


def _wake_mistake(cases, c):
    """The rule a wrong wake_on_contact() breaks, read from the pair it got wrong."""
    got, want = c["got"], c["want"]
    if not want and "static" in (c["a"], c["b"]) and got:
        return Form("wake_by_floor", "the floor never wakes a crate: a crate sleeps on the floor")
    if not want and c["a"] == c["b"] == "asleep":
        return Form("wake_two_sleepers", "two sleeping crates leave each other asleep")
    if not want and c["a"] == c["b"] == "awake":
        return Form("wake_awake", "neither is asleep: there is nothing to wake")
    if want and not got:
        order = "the sleeping body second" if want == ["b"] else "the sleeping body first"
        return Form("wake_one_order", f"an awake crate touching a sleeping one must wake it, with {order} too: "
                                      "check both orders")
    return Form("wake_not_only_sleeper", "only the sleeping body of the pair is woken")


WAKE = Step(
    "wakes_on_contact", "Step 4: wake_on_contact(a, b) returns the sleeping body of a pair whose other body is "
    "dynamic and awake.", 4, "wake_on_contact", lambda module: _pairs(run_rng(module, "wake_on_contact")), _woken,
    lambda c: reference_woken(c["a"], c["b"]), hint="wake", kind="a list of bodies (or [])",
    bad=lambda got: isinstance(got, str), diagnose=_wake_mistake,
    label=lambda c: f"wake_on_contact(a, b) with a {c['a']} and b {c['b']}",
    evidence=lambda c: f"wake_on_contact(a, b) with a {c['a']} and b {c['b']} wakes {' and '.join(c['got']) or 'nothing'}"
                       f"; it should wake {' and '.join(c['want']) or 'nothing'}.")


# ---------------------------------------------------------------- the cost criterion

def grid_items(asleep, shift=0.0):
    """40 crates in 4 rows of 10, each row resting on the one below (0.2 px of overlap, so they touch), the grid
    `shift` px to the right."""
    items = []
    for k in range(GRID_CRATES):
        row, column = divmod(k, GRID_COLUMNS)
        items.append({"w": W, "h": H, "pos": [160 + shift + column * W + (row % 2) * 10,
                                             FLOOR_TOP - H / 2 + 0.2 - row * (H - 0.2)], "asleep": asleep})
    return items


def grid_world(module, asleep, shift=0.0):
    floor = Body(box_points(900, 40), (450, 580), 0)
    world = World([floor] + [module.build(item) for item in grid_items(asleep, shift)],
                  effects=LESSON_EFFECTS | {"sleep"}, sleep_timer=module.sleep_timer, moves=module.moves,
                  wake=module.wake_on_contact)
    if asleep:
        world.fall_asleep(world.bodies[1:])
    return world


def probe_narrow_work(module, lab_path):
    """One step of the 40-crate grid awake, then asleep: pair and narrow tests (World.counters) and CPU ms."""
    out, shift = {}, run_rng(module, "narrow_work").uniform(-40, 40)   # the grid's place on the floor, per run
    for name, asleep in (("awake", False), ("asleep", True)):
        world = grid_world(module, asleep, shift)
        start = clock(module)
        world.step()
        out[name] = dict(world.counters, ms=(clock(module) - start) * 1000,
                         still_asleep=sum(1 for body in world.bodies if body.asleep))
    return out


# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("sleep_timer", "moves", "wake_on_contact")

# probe name -> (the lab function it needs, the probe)
STEPS = (TIMER, MOVES, WAKE)
PROBES = dict(TIMER.probes(), **MOVES.probes(), **WAKE.probes(), narrow_work=("build", probe_narrow_work))
