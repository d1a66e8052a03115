"""What accuracy costs in time: six studies measured side by side in one run.

    python -m lesson11.bench.accuracy_cost            # full run, a few minutes; writes the table and plot
    python -m lesson11.bench.accuracy_cost --quick    # smoke run: tiny sizes, seconds; prints only
    python -m lesson11.bench.accuracy_cost --frontier # the frontier study (lesson11/bench/frontier.py)
                                                      # (--out-dir writes bench_accuracy_cost_quick.md/.png)

1. tunnelling     a 3 px bullet against a 4 px wall: discrete steps, sub-steps ×2..×16, CCD
2. iterations     a 10-crate pyramid with 1..20 solver passes, in the lesson solver and the accumulated one
3. contact rule   "corners" (the lesson's) against "clip" (edge clipping) on the same piles
4. effects        the same scene with only the effects it needs, with everything, with "ccd" but no bullet
5. pymunk         the same piles in pymunk (skipped with a message if pymunk is missing)
6. solvers        solver_probe's scenes (flat box and disc restitution, ramp rest, a 10-box stack, 100:1)
                  in the lesson solver solve-first (World's default) and move-first, the reference
                  solver with each contact rule, and pymunk

Each study has a baseline, and its times are reported as ratios to that
baseline, measured in the same run. Every case is repeated (--repeats, 3 by
default) in round-robin order, so a slow moment on a shared machine hits every
case alike, and the median is kept. Only the calls that step the simulation
are timed (time.perf_counter); measuring accuracy between steps is not.
Accuracy figures are deterministic: the repeats must agree, and the run says
so if they do not.

--quick is a smoke run, to see that everything runs: one repeat of tiny
cases, so its spread is unknown and its ratios are noise. It says so at the
top of its report, and it never writes the full study's files: with
--out-dir it writes bench_accuracy_cost_quick.md and _quick.png (QUICK_NOTE).
"""
import math
import statistics
import sys
import time
from dataclasses import dataclass, field

from lesson11.physics2d import LESSON_EFFECTS
from lesson11.physics2d.world import SOLVERS

from . import scenes
from . import solver_probe
from .harness import bench_parser, lockstep, machine_note, output_folder, pymunk_version, write_results

FRAME = 1 / 120  # s: the course's fixed step; sub-stepping splits it into n steps


@dataclass(frozen=True)
class Settings:
    """Sizes of one run. FULL is the published run; QUICK is for the smoke test."""
    shots: int                    # tunnelling shots per speed, start offsets spread over one step's travel
    speeds: tuple                 # px/s
    substeps: tuple               # n for the sub-stepping cases (step = FRAME / n)
    iterations: tuple             # solver passes per step
    pile_seconds: float           # simulated s per pile run
    rule_scenes: tuple            # piles for the contact-rule study
    compare_scenes: tuple         # piles for the pymunk study
    effects_seconds: float        # simulated s per effects run
    repeats: int                  # timing repeats (median kept)
    stack_seconds: float          # solvers study: simulated s of the 10-box stack
    heavy_seconds: float          # solvers study: simulated s of the 100:1 pair
    ramp_seconds: float           # solvers study: simulated s of the crate on the ramp
    disc_seconds: float           # solvers study: simulated s of each disc drop (the first rebound is at 0.64 s)


FULL = Settings(shots=60, speeds=(500, 1000, 2000, 3000, 4000, 6000, 8000, 12000), substeps=(2, 4, 8, 16),
                iterations=(1, 2, 4, 6, 10, 20), pile_seconds=4.0, rule_scenes=("pyramid4", "stack4"),
                compare_scenes=("pyramid4", "stack8"), effects_seconds=3.0, repeats=3,
                stack_seconds=3.0, heavy_seconds=5.0, ramp_seconds=3.0, disc_seconds=6.0)
QUICK = Settings(shots=6, speeds=(500, 2000, 6000, 12000), substeps=(2, 4, 16),
                 iterations=(1, 6, 20), pile_seconds=0.5, rule_scenes=("pyramid4",),
                 compare_scenes=("pyramid4",), effects_seconds=0.5, repeats=1,
                 stack_seconds=0.1, heavy_seconds=0.1, ramp_seconds=0.1, disc_seconds=1.5)

QUICK_NOTE = ("**Smoke run (`--quick`): tiny cases, {repeats} repeat(s). It shows that every study runs; its times, "
              "ratios and spreads are not measurements and may contradict the published figures, which come from "
              "the full run (`python -m lesson11.bench.accuracy_cost`).**")

NEEDED_EFFECTS = frozenset({"gravity", "restitution", "correction"})  # all the settling-balls scene uses


@dataclass
class Measurement:
    """One run of one case: accuracy figures, the time spent stepping (s), and what it stepped."""
    accuracy: dict
    seconds: float
    units: float                  # steps, or simulated seconds (see Row.unit)
    counters: dict = field(default_factory=dict)
    final_state: list = None


@dataclass
class Row:
    """One line of the table: a case of a study with its median time and accuracy."""
    study: str
    scene: str
    variant: str
    accuracy: dict
    times: list                   # s per unit, one per repeat
    unit: str                     # "ms/step" or "ms per simulated s"
    counters: dict = field(default_factory=dict)
    baseline: bool = False
    ratio: float = math.nan
    consistent: bool = True
    final_state: list = None      # the effects study compares final states between rows
    parts: list = None            # the solvers study: this solver's row per scene (its own time and ratio)

    @property
    def ms(self):
        """Median time per unit, in ms."""
        return 1000 * statistics.median(self.times)

    @property
    def spread(self):
        """(slowest - fastest repeat) / median: how noisy this row's timing was (0 with one repeat)."""
        return (max(self.times) - min(self.times)) / statistics.median(self.times)


@dataclass
class Case:
    """A case to measure: run() makes a generator that yields after each piece of work
    and finally returns a Measurement."""
    study: str
    scene: str
    variant: str
    unit: str
    run: object
    baseline: bool = False


# ---------------------------------------------------------------- running

def measure(cases, repeats, progress=None):
    """Run every case `repeats` times; return one Row per case with the median time.

    Within a repeat the cases advance in lockstep, one small piece of work
    (a step, or a shot) each in turn, so a slow moment on a shared machine
    slows every case of the study alike and the ratios stay fair.
    """
    results = [[] for _ in cases]
    for repeat in range(repeats):
        if progress:
            progress(f"  {cases[0].study}: repeat {repeat + 1}/{repeats}, {len(cases)} cases in lockstep")
        for runs, measurement in zip(results, lockstep([case.run() for case in cases])):
            runs.append(measurement)
    rows = []
    for case, runs in zip(cases, results):
        first = runs[0]
        rows.append(Row(case.study, case.scene, case.variant, first.accuracy,
                        [m.seconds / m.units for m in runs], case.unit, first.counters, case.baseline,
                        consistent=all(m.accuracy == first.accuracy and m.final_state == first.final_state
                                       for m in runs),
                        final_state=first.final_state))
    for row in rows:  # ratios against the baseline of the same study and scene
        base = [r for r in rows if r.baseline and r.study == row.study and r.scene == row.scene]
        if base:
            row.ratio = row.ms / base[0].ms
    return rows


def step_timed(step, count):
    """Call step() `count` times; return the seconds spent inside the calls."""
    spent = 0.0
    for _ in range(count):
        start = time.perf_counter()
        step()
        spent += time.perf_counter() - start
    return spent


# ---------------------------------------------------------------- 1. tunnelling

def shot_frames(speed):
    """Frames (of 1/120 s) a shot runs: enough for a caught bullet to hit and a tunnelled one to be past."""
    travel = speed * FRAME
    distance = 2 * travel + 1 + scenes.WALL_WIDTH + 2 * scenes.BULLET_RADIUS + 1
    return math.ceil(distance / travel) + 1


def tunnelling_run(settings, substeps, ccd):
    """All shots at all speeds with one method: {speed: share of shots that tunnel}, and the stepping time.

    A generator (see measure): it yields after each shot.
    """
    accuracy, spent, simulated = {}, 0.0, 0.0
    for speed in settings.speeds:
        travel = speed * FRAME
        tunnels = 0
        frames = shot_frames(speed)
        for k in range(settings.shots):
            phase = (k + 0.5) / settings.shots  # spread the start over one frame's travel
            start_x = scenes.WALL_X - scenes.WALL_WIDTH / 2 - scenes.BULLET_RADIUS - 1 - travel * (1 + phase)
            world, bullet = scenes.bullet_world(start_x, speed, ccd, FRAME / substeps)
            spent += step_timed(world.step, frames * substeps)
            simulated += frames * FRAME
            tunnels += scenes.tunnelled(bullet)
            yield
        accuracy[speed] = tunnels / settings.shots
    return Measurement(accuracy, spent, simulated)


def tunnelling_cases(settings):
    """Discrete ×1 (the baseline), sub-stepping ×n, and CCD."""
    cases = [Case("1 tunnelling", "3 px bullet, 4 px wall", "discrete, 1/120 s", "ms per simulated s",
                  lambda: tunnelling_run(settings, 1, False), baseline=True)]
    for n in settings.substeps:
        cases.append(Case("1 tunnelling", "3 px bullet, 4 px wall", f"sub-steps ×{n} (1/{120 * n} s)",
                          "ms per simulated s", lambda n=n: tunnelling_run(settings, n, False)))
    cases.append(Case("1 tunnelling", "3 px bullet, 4 px wall", "CCD (swept test), 1/120 s", "ms per simulated s",
                      lambda: tunnelling_run(settings, 1, True)))
    return cases


# ---------------------------------------------------------------- 2, 3, 5. piles

class Physics2dPile:
    """A pile scene in a physics2d World, seen through the same four calls as pymunk_pile.PymunkPile."""

    def __init__(self, name, **settings):
        self.world = scenes.pile_world(name, **settings)
        self.crates = self.world.bodies[1:]
        self.step = self.world.step

    def crate_corners(self):
        return [crate.world_points() for crate in self.crates]

    def top_position(self):
        return self.crates[-1].pos

    def kinetic_energy(self):
        return sum(crate.kinetic_energy() for crate in self.crates)


def pile_run(make_pile, seconds):
    """Step a pile for `seconds`: floor penetration (worst, px), top-crate drift (px) and kinetic energy at the end.

    A generator (see measure): it yields after each step.
    """
    pile = make_pile()
    start = tuple(pile.top_position())
    steps = round(seconds / FRAME)
    spent, penetration = 0.0, 0.0
    for _ in range(steps):
        spent += step_timed(pile.step, 1)
        penetration = max(penetration, scenes.floor_penetration(pile.crate_corners()))
        yield
    top = pile.top_position()
    drift = math.hypot(top[0] - start[0], top[1] - start[1])
    accuracy = {"penetration": round(penetration, 6), "drift": round(drift, 6),
                "energy": round(pile.kinetic_energy(), 6)}
    counters = dict(pile.world.counters) if hasattr(pile, "world") else {}
    return Measurement(accuracy, spent, steps, counters)


def iteration_cases(settings):
    """The pyramid with each iteration count, in each solver; the lesson's 6 is the baseline."""
    cases = []
    for solver in SOLVERS:
        extra = {} if solver == "lesson" else {"solver": solver}
        for n in settings.iterations:
            cases.append(Case("2 iterations", "pyramid4", f"{solver} solver, {n} iteration{'s' if n > 1 else ''}", "ms/step",
                              lambda n=n, extra=extra: pile_run(
                                  lambda: Physics2dPile("pyramid4", iterations=n, **extra), settings.pile_seconds),
                              baseline=(solver == "lesson" and n == 6)))
    return cases


def rule_cases(settings):
    """Each rule-study pile with the corners rule (baseline) and with clipping, 6 iterations."""
    cases = []
    for name in settings.rule_scenes:
        for rule in ("corners", "clip"):
            cases.append(Case("3 contact rule", name, f'"{rule}"', "ms/step",
                              lambda name=name, rule=rule: pile_run(
                                  lambda: Physics2dPile(name, contact_rule=rule), settings.pile_seconds),
                              baseline=(rule == "corners")))
    return cases


def pymunk_cases(settings):
    """Each comparison pile in physics2d (lesson solver: the baseline; the accumulated solver) and in pymunk."""
    try:
        from .pymunk_pile import PymunkPile
    except ImportError:
        return []
    cases = []
    for name in settings.compare_scenes:
        cases.append(Case("5 vs pymunk", name, "physics2d, lesson solver, 6 iterations", "ms/step",
                          lambda name=name: pile_run(lambda: Physics2dPile(name), settings.pile_seconds),
                          baseline=True))
        cases.append(Case("5 vs pymunk", name, "physics2d, accumulated solver, 6 iterations", "ms/step",
                          lambda name=name: pile_run(lambda: Physics2dPile(name, solver="accumulated"),
                                                     settings.pile_seconds)))
        cases.append(Case("5 vs pymunk", name, f"pymunk {pymunk_version()}, 6 iterations", "ms/step",
                          lambda name=name: pile_run(lambda: PymunkPile(name, iterations=6), settings.pile_seconds)))
    return cases


# ---------------------------------------------------------------- 4. effects

def world_run(make_world, seconds):
    """Step a world for `seconds`; keep its counters per step and its final state. Yields after each step."""
    world = make_world()
    steps = round(seconds / FRAME)
    spent = 0.0
    for _ in range(steps):
        spent += step_timed(world.step, 1)
        yield
    counters = {key: value / steps for key, value in world.counters.items() if key != "steps"}
    return Measurement({}, spent, steps, counters, scenes.state_of(world))


def effects_cases(settings):
    """Frictionless balls with all the lesson's effects (baseline), with only the three they need,
    with "ccd" declared but no bullet, and with "ccd" and every ball a bullet."""
    seconds = settings.effects_seconds
    balls = "24 frictionless balls in a box"

    def case(variant, effects, bullets=False, baseline=False):
        return Case("4 effects", balls, variant, "ms/step",
                    lambda: world_run(lambda: scenes.settling_balls_world(effects, bullets), seconds), baseline)

    return [case("LESSON_EFFECTS (all five)", LESSON_EFFECTS, baseline=True),
            case("only gravity, restitution, correction", NEEDED_EFFECTS),
            case('LESSON_EFFECTS + "ccd", no bullet', LESSON_EFFECTS | {"ccd"}),
            case('LESSON_EFFECTS + "ccd", every ball a bullet', LESSON_EFFECTS | {"ccd"}, bullets=True)]


def finish_effects(rows):
    """Accuracy of the effects study: how far each run's final state is from its baseline's (same scene)."""
    for row in rows:
        base = next(r for r in rows if r.baseline and r.scene == row.scene)
        row.accuracy = {"difference": scenes.largest_difference(row.final_state, base.final_state)}


# ---------------------------------------------------------------- 6. solvers

SOLVERS_STUDY = "6 solvers"
BASELINE_ENGINE = "lesson solve-first"   # World's default for the lesson solver
ENGINE_NAMES = {"lesson solve-first": "lesson, solve-first (default)", "lesson move-first": "lesson, move-first",
                "reference corners": 'reference, "corners"', "reference clip": 'reference, "clip"'}


def solver_engines():
    """solver_probe's engines, the lesson's default first; pymunk last when installed."""
    engines = [BASELINE_ENGINE] + [e for e in solver_probe.ENGINES if e != BASELINE_ENGINE]
    return engines + (["pymunk"] if solver_probe.pymunk else [])


def engine_name(engine):
    """How a solver_probe engine is named in the table."""
    return ENGINE_NAMES.get(engine, f"pymunk {pymunk_version()}" if engine == "pymunk" else engine)


def first(values):
    """The first of a list of figures, or None if the run produced none (too short)."""
    return values[0] if values else None


def worst_apex(apexes):
    """The apex energy ratio furthest from 1 among the first five, or None if there was no apex."""
    return max(apexes[:5], key=lambda ratio: abs(ratio - 1)) if apexes else None


def figure(value, spec, unit=""):
    """A figure for the table, or "none (run too short)" when the run produced none (None or nan)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "none (run too short)"
    return f"{value:{spec}}{unit}"


def solver_scenes(settings):
    """The solvers study's scenes: (key, title, measurement generator for an engine, figures -> accuracy dict).

    The measurements are solver_probe's; only the durations come from `settings`.
    """
    p = solver_probe
    return [
        ("flat 0.5", "flat box e = 0.5", lambda engine: p.flat_bounce_run(engine, 0.5),
         lambda f: {"rebound": f[0], "spin": f[1]}),
        ("flat 0.9", "flat box e = 0.9", lambda engine: p.flat_bounce_run(engine, 0.9),
         lambda f: {"rebound": f[0], "spin": f[1]}),
        ("disc 0.5", "disc e = 0.5", lambda engine: p.disc_bounce_run(engine, 0.5, seconds=settings.disc_seconds),
         lambda f: {"rebound": first(f[1])}),
        ("disc 1", "disc e = 1", lambda engine: p.disc_bounce_run(engine, 1.0, seconds=settings.disc_seconds),
         lambda f: {"apex energy": worst_apex(f[0]), "apexes": len(f[0][:5])}),
        ("ramp", "crate on a 22° ramp", lambda engine: p.ramp_rest_run(engine, settings.ramp_seconds),
         lambda f: {"moved": f}),
        ("stack", "10-box stack", lambda engine: p.stack_run(engine, settings.stack_seconds),
         lambda f: {"drift": f}),
        ("100:1", "100:1 heavy on light", lambda engine: p.heavy_on_light_run(engine, settings.heavy_seconds),
         lambda f: {"overlap": f[0], "on top": f[1]}),
    ]


def probe_run(measurement, summarise):
    """Run a solver_probe measurement generator, yielding after each step; its figures and in-step time.

    The probe's scenes time their own step() calls (scene.seconds), so measuring between steps is not timed.
    """
    run, scene = measurement(), None
    while True:
        try:
            scene = next(run)
        except StopIteration as done:
            figures = done.value
            break
        yield
    accuracy = {key: round(value, 6) if isinstance(value, float) else value
                for key, value in summarise(figures).items()}
    return Measurement(accuracy, scene.seconds, scene.steps, {"steps": scene.steps})


def solver_cases(settings):
    """Every scene of the solvers study in every engine; the lesson solver's default order is each scene's baseline."""
    cases = []
    for key, _, measurement, summarise in solver_scenes(settings):
        for engine in solver_engines():
            cases.append(Case(SOLVERS_STUDY, key, engine, "ms/step",
                              lambda measurement=measurement, summarise=summarise, engine=engine:
                              probe_run(lambda: measurement(engine), summarise),
                              baseline=(engine == BASELINE_ENGINE)))
    return cases


def solver_summary(scene_rows):
    """One Row per engine from its per-scene rows: accuracy by scene, and the time per step over all
    the scenes' steps (in each repeat: seconds in step, summed over scenes / steps, summed)."""
    summary = []
    for engine in dict.fromkeys(row.variant for row in scene_rows):
        parts = [row for row in scene_rows if row.variant == engine]
        steps = [row.counters["steps"] for row in parts]
        times = [sum(row.times[i] * n for row, n in zip(parts, steps)) / sum(steps)
                 for i in range(len(parts[0].times))]
        summary.append(Row(SOLVERS_STUDY, "all seven scenes", engine,
                           {row.scene: row.accuracy for row in parts}, times, "ms/step",
                           {"steps": sum(steps)}, baseline=(engine == BASELINE_ENGINE),
                           consistent=all(row.consistent for row in parts), parts=parts))
    base = next(row for row in summary if row.baseline)
    for row in summary:
        row.ratio = row.ms / base.ms
    return summary


def solver_cells(row):
    """The accuracy figures of a solvers-study row, one cell per measurement (see SOLVER_COLUMNS)."""
    a = row.accuracy
    flat = lambda key: f"{figure(a[key]['rebound'], '.3f')} (spin {figure(a[key]['spin'], '.2f')})"
    heavy = a["100:1"]
    return [flat("flat 0.5"), flat("flat 0.9"), figure(a["disc 0.5"]["rebound"], ".3f"),
            f"{figure(a['disc 1']['apex energy'], '.4f')} ({a['disc 1']['apexes']} apexes)",
            figure(a["ramp"]["moved"], ".2f", " px"), figure(a["stack"]["drift"], ".2f", " px"),
            f"{figure(heavy['overlap'], '.2f', ' px')} ({'yes' if heavy['on top'] else 'no'})"]


SOLVER_COLUMNS = ["flat box e = 0.5: rebound / impact (spin, rad/s)", "flat box e = 0.9: rebound / impact (spin)",
                  "disc e = 0.5: rebound / impact", "disc e = 1: apex energy / start (worst of the first 5)",
                  "ramp: moved", "10-box stack: largest drift", "100:1: deepest overlap (heavy on top)"]


def solvers_table(rows):
    """Study 6 as one row per solver: each measurement, then time per step relative to the lesson default."""
    lines = ["| solver | " + " | ".join(SOLVER_COLUMNS) + " | time per step × lesson default (per scene) |",
             "|---|" + "---|" * (len(SOLVER_COLUMNS) + 1)]
    for row in rows:
        if row.baseline:
            ratio = f"1 (baseline: {row.ms:.3g} ms/step)"
        else:
            ratios = [part.ratio for part in row.parts]
            ratio = f"{row.ratio:.2g} ({min(ratios):.2g}–{max(ratios):.2g})"
        lines.append(f"| {engine_name(row.variant)} | " + " | ".join(solver_cells(row)) + f" | {ratio} |"
                     + ("" if row.consistent else " (repeats disagreed!)"))
    return "\n".join(lines)


def solver_times_table(rows):
    """Study 6's time per step by scene: ms (× the lesson default on the same scene)."""
    scenes_ = [part.scene for part in rows[0].parts]
    lines = ["| solver | " + " | ".join(scenes_) + " |", "|---|" + "---|" * len(scenes_)]
    for row in rows:
        cells = [f"{part.ms:.3g} ms" + ("" if part.baseline else f" (×{part.ratio:.2g})") for part in row.parts]
        lines.append(f"| {engine_name(row.variant)} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


# ---------------------------------------------------------------- the table

def accuracy_text(row):
    """The accuracy cell of a row, in words and units."""
    a = row.accuracy
    if row.study.startswith("1"):
        clean = [speed for speed, share in a.items() if share == 0]
        safe = max((s for s in a if all(a[t] == 0 for t in a if t <= s)), default=None)
        share = 100 * sum(a.values()) / len(a)
        if len(clean) == len(a):
            text = f"no shot tunnels at any speed ({min(a)}–{max(a)} px/s)"
        elif safe is None:
            text = f"shots tunnel already at {min(a)} px/s; {share:.0f} % of all shots"
        else:
            text = f"no tunnelling up to {safe} px/s; {share:.0f} % of all shots tunnel"
    elif row.study == SOLVERS_STUDY:
        cells = dict(zip(["flat e=0.5", "flat e=0.9", "disc e=0.5", "disc e=1 apex energy", "ramp", "stack",
                          "100:1"], solver_cells(row)))
        text = " · ".join(f"{name} {cell}" for name, cell in cells.items())
    elif row.study.startswith("4"):
        c = row.counters
        text = (f"positions at the end differ from the baseline's by {a['difference']:.2g} px; per step: "
                f"{c['pair_tests']:.0f} pair tests, {c['contacts']:.1f} contacts, {c['swept_tests']:.0f} swept tests")
    else:
        text = (f"floor penetration {a['penetration']:.2f} px · top drift {a['drift']:.2f} px · "
                f"kinetic energy {a['energy']:.3g}")
    return text + ("" if row.consistent else " (repeats disagreed!)")


def table(rows):
    """The Markdown table: one row set per study."""
    lines = ["| study | scene | variant | accuracy | time (median) | spread | × baseline |",
             "|---|---|---|---|---|---|---|"]
    for row in rows:
        ratio = "1 (baseline)" if row.baseline else f"{row.ratio:.3g}"
        spread = f"{100 * row.spread:.0f} %" if len(row.times) > 1 else "n/a (1 repeat)"
        variant = engine_name(row.variant) if row.study == SOLVERS_STUDY else row.variant
        lines.append(f"| {row.study} | {row.scene} | {variant} | {accuracy_text(row)} | "
                     f"{row.ms:.3g} {row.unit} | {spread} | {ratio} |")
    return "\n".join(lines)


def tunnelling_table(rows):
    """Share of shots that tunnel, per method and speed (%)."""
    speeds = list(rows[0].accuracy)
    lines = ["| method | " + " | ".join(f"{s} px/s" for s in speeds) + " | time × discrete |",
             "|---|" + "---|" * (len(speeds) + 1)]
    for row in rows:
        cells = " | ".join(f"{100 * row.accuracy[s]:.0f} %" for s in speeds)
        lines.append(f"| {row.variant} | {cells} | {row.ratio:.2f} |")
    return "\n".join(lines)


METHOD_NOTES = [
    "Sub-stepping ×n runs n steps of 1/(120 n) s per frame; CCD declares \"ccd\" and marks the circle "
    "`bullet=True`, so World.swept_move finds its time of impact against the wall (held still) with "
    "circle_polygon_toi. A shot tunnels when the bullet's centre ends past the middle of the wall. "
    "The tunnelling worlds pin `substeps=1`: World's default (the lesson solver, solve-first) already splits "
    "each 1/120 s step into 4, so a default World catches bullets like the ×4 row.",
    "Pile scenes start with every crate exactly touching its neighbours and at rest; an ideal engine "
    "would show 0 drift and 0 kinetic energy. The lesson's solver in World's default solve-first order "
    "finds contacts once per sub-step (4 sub-steps a step, plus once at the end of the step) and runs the "
    "passes on them, so its time grows "
    "with the passes but less than in proportion; the accumulated solver detects once per step.",
    "The effects study compares final positions with the baseline run of the same scene: 0 px means "
    "bit-for-bit the same simulation, and a round-off difference (below 10⁻⁶ px) the same motion, so any "
    "time saved is pure overhead.",
    "pymunk runs the same scenes with y down and gravity (0, 980): pymunk has no preferred up, so this "
    "behaves as y up with (0, -980). pymunk combines friction and restitution as products, physics2d as "
    "√(μA μB) and min(eA, eB); each pymunk shape gets √0.6 and √0.2 so every pair gets 0.6 and 0.2 in "
    "both. pymunk keeps impulses across passes and steps (warm starting) and removes overlap with a "
    "velocity bias (collision_slop 0.1 px, collision_bias 0.9^60 per s), where the lesson's World pushes "
    "positions by 40 % of (depth - 0.5 px) per pass; so the same iteration count does not mean the same "
    "work. pymunk is C (Chipmunk2D) and physics2d is plain Python: compare the accuracy columns, and read "
    "the time column as the price of readable Python.",
    "Study 6 runs lesson11/bench/solver_probe.py's scenes and measurements (y down, 1/120 s steps, "
    "40 px boxes) in each solver as that probe sets it up: the lesson solver 6 iterations in either order "
    "(solve-first: 4 sub-steps of 1 + 6 resolve passes and a push-out; move-first: the lesson text's "
    "order), the reference solver (`solver=\"accumulated\"`) 3 sub-steps of 1 pass with either contact "
    "rule, pymunk 6 iterations. A rebound is the upward speed after the bouncing step / the downward speed "
    "before it; a flat box should leave with e and no spin. Its time is the seconds inside step() over all "
    "seven scenes' steps, relative to the lesson solver's default; the range is over the scenes, each "
    "against the default on the same scene.",
]


# ---------------------------------------------------------------- main

def run(settings, progress=None):
    """Every study, in one run. Returns (rows by study name, notes)."""
    notes = []
    groups = {"tunnelling": tunnelling_cases(settings), "iterations": iteration_cases(settings),
              "rule": rule_cases(settings), "effects": effects_cases(settings),
              "pymunk": pymunk_cases(settings), "solvers": solver_cases(settings)}
    if not groups["pymunk"]:
        notes.append("Study 5 skipped: pymunk is not installed (pip install -e \".[compare]\").")
    rows = {}
    for name, cases in groups.items():
        if cases:
            rows[name] = measure(cases, settings.repeats, progress)
    finish_effects(rows["effects"])
    rows["solvers"] = solver_summary(rows["solvers"])
    if not solver_probe.pymunk:
        notes.append("Study 6 has no pymunk row: pymunk is not installed.")
    return rows, notes


def report(rows, notes, settings, elapsed, mode):
    """The whole Markdown report: machine note, the table, the tunnelling detail, the notes."""
    all_rows = [row for group in rows.values() for row in group]
    parts = [
        "# What accuracy costs: measured side by side",
        "",
    ] + ([QUICK_NOTE.format(repeats=settings.repeats), ""] if mode == "quick" else []) + [
        f"Run: `python -m lesson11.bench.accuracy_cost{' --quick' if mode == 'quick' else ''}` · {mode} run, "
        f"{settings.repeats} repeat(s) per case, median kept · whole run {elapsed:.0f} s · "
        f"{time.strftime('%Y-%m-%d')}",
        "",
        f"Machine: {machine_note()}",
        "",
        "Times are medians of the time spent inside `step()` only; *spread* is (slowest - fastest repeat) / "
        "median, a measure of how noisy the machine was. *× baseline* divides by the baseline row "
        "of the same study and scene, measured in the same run. Pile figures: *floor penetration* is the "
        "deepest any crate corner went below the floor's top face during the run; *top drift* is how far the "
        "top crate ended from where it started; *kinetic energy* (mass·px²/s²) is what is left at the end "
        f"(0 = at rest). Piles run {settings.pile_seconds:g} simulated s at 1/120 s per step; the effects "
        f"study runs {settings.effects_seconds:g} s.",
        "",
        table(all_rows),
        "",
        "## Tunnelling by speed",
        "",
        f"Share of {settings.shots} shots per speed whose bullet (radius {scenes.BULLET_RADIUS:g} px) ended on the "
        f"far side of the {scenes.WALL_WIDTH:g} px wall; the shots start at offsets spread evenly over one "
        "step's travel.",
        "",
        tunnelling_table(rows["tunnelling"]),
        "",
        "## Solvers: accuracy and time",
        "",
        f"solver_probe's scenes, each solver as the probe sets it up. Durations: the flat boxes run to their "
        f"first rebound, each disc {settings.disc_seconds:g} s, the ramp {settings.ramp_seconds:g} s, the "
        f"10-box stack {settings.stack_seconds:g} s (solver_probe's own table runs 20 s) and 100:1 "
        f"{settings.heavy_seconds:g} s, to keep the whole run to a few minutes. Ideal: a flat box leaves with "
        f"rebound e and spin 0, the disc e = 1 keeps its energy (1), nothing moves on the ramp or in the "
        f"stack, overlap 0 with the heavy box on top.",
        "",
        solvers_table(rows["solvers"]),
        "",
        "Time per step by scene, ms (× the lesson default on the same scene):",
        "",
        solver_times_table(rows["solvers"]),
    ]
    parts += ["", "## How to read it", ""] + [f"- {line}" for line in METHOD_NOTES + notes]
    return "\n".join(parts) + "\n"


def main(argv=None):
    parser = bench_parser("accuracy_cost", "What accuracy costs in time: tunnelling, iterations, contact rule, "
                                           "declared effects, pymunk, solvers, measured side by side.",
                          "bench_accuracy_cost", "tiny sizes", "case")
    parser.add_argument("--frontier", action="store_true",
                        help="run the frontier study instead (lesson11/bench/frontier.py): every solver setting, "
                             "CPU time per step against error, the Pareto front; writes bench_frontier.md/.png")
    args = parser.parse_args(argv)
    if args.frontier:
        from . import frontier
        return frontier.main([a for a in (sys.argv[1:] if argv is None else argv) if a != "--frontier"])
    settings = QUICK if args.quick else FULL
    if args.repeats:
        settings = Settings(**{**settings.__dict__, "repeats": args.repeats})
    mode = "quick" if args.quick else "full"
    out_dir, problem = output_folder(args)
    if problem:
        print(problem, file=sys.stderr)
        return 2

    print(f"Machine: {machine_note()}")
    started = time.perf_counter()
    rows, notes = run(settings, progress=lambda text: print(text, file=sys.stderr, flush=True))
    elapsed = time.perf_counter() - started
    text = report(rows, notes, settings, elapsed, mode)
    print(text)
    if args.quick:
        print("Smoke run: these figures only show that the studies run; see the full run for measurements.")

    def draw(path, subtitle):
        from .plot import plot
        return plot(rows, path, subtitle, engine_name)

    return write_results(args, out_dir, "bench_accuracy_cost", text, draw, "times and ratios are not measurements")


if __name__ == "__main__":
    sys.exit(main())
