"""Speed, measured side by side: the lesson's listing, the lab's World, the reference solver and pymunk.

    python -m lesson11.bench.speed            # full run, a few minutes; writes assets/bench_speed.md/.png
    python -m lesson11.bench.speed --quick    # smoke run, seconds; prints only
                                              # (--out-dir writes bench_speed_quick.md/.png)

Engines, every one started from the same snapshot (positions, velocities,
angles, spins, masses, materials of every body) and stepped the same number
of 1/120 s steps with 6 solver iterations:

    listing    listing.py: the lesson's example solver (move first, all pairs, pure Python)
    lab        physics2d World as the lab runs it: World(bodies, sat=..., resolve=...) with
               solutions/tumbling_crates.py's sat and resolve (World's default lesson solver,
               solve-first, 4 sub-steps)
    reference  physics2d World(bodies, solver="accumulated")
    pymunk     pymunk (Chipmunk2D, C), when installed; materials matched as in pymunk_pile.py

Table 1 is the lab's pile: the Tumbling Crates scene (floor, 22° ramp, wall)
with 14 crates of 40 px, piled 5-4-3-2 on the floor and settled by the lab's
World for SETTLE_SECONDS before the snapshot is taken. Table 2 is the scaling
study: N crates in two layers (columns of two) in a wide box whose floor grows
with N, so the pile's depth stays the same and the cost per body-step should
stay flat.

Timing follows accuracy_cost.py: only the step() calls are timed; within a repeat the engines advance one step each in
turn (round-robin, harness.lockstep), so a slow moment on the shared
machine hits every engine alike; each repeat starts from a fresh copy of the
snapshot; the median over repeats is kept and every ratio divides two
medians of the same run. Unlike accuracy_cost.py, the clock is the process's
CPU time (time.process_time, ns resolution here): every engine is
single-threaded, and on a shared 2-core machine the wall clock also counts
the time the process waited for a core, which hits whichever step is running.

--quick is a smoke run (1 repeat, few steps, N up to 100): its figures only
show that everything runs. It never writes the full run's files: with
--out-dir it writes bench_speed_quick.md and bench_speed_quick.png.
"""
import importlib.util
import math
import statistics
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from lesson11.physics2d import Body, World, box_points

from . import listing
from .harness import bench_parser, lockstep, machine_note, output_folder, write_results

ROOT = Path(__file__).resolve().parents[2]
SOLUTION = ROOT / "solutions" / "tumbling_crates.py"

STEP = 1 / 120          # s
ITERATIONS = 6
FRAME = 1 / 60          # s: a 60 fps frame runs two physics steps
STEPS_PER_FRAME = 2
BOX = 40.0              # px, side of a crate
CRATE_MASS = BOX * BOX / 1000  # the lab's rule: mass = area / 1000
LAB_FLOOR_TOP = 560.0   # px, the lab's floor (a 900 × 40 box centred at (450, 580))
SETTLE_SECONDS = 2.0    # s the lab's World settles the 14-crate pile before the snapshot
PILE_ROWS = (5, 4, 3, 2)  # crates per row, bottom first: 14
PILE_X = 640.0          # px, centre of the pile on the lab's floor (right of the ramp)
OVERLAP = 0.2           # px each scaling crate starts sunk into what it rests on, so contacts exist at once
COLUMN_GAP = 2.0        # px between the scaling study's columns

TARGETS = {"lab_vs_listing": 2.0, "frame_share": 1 / 3, "reference_vs_listing": 10.0, "reference_vs_pymunk": 50.0,
           "growth": 1.3}


@dataclass(frozen=True)
class Settings:
    """Sizes of one run. FULL is the published run; QUICK is for the smoke test."""
    repeats: int            # timing repeats of table 1 (median kept)
    pile_steps: int         # steps per repeat in table 1
    sizes: tuple            # crate counts of table 2
    scale_steps: dict       # N -> steps per repeat in table 2
    listing_max: int        # the listing runs table 2 up to this N (it tests all pairs: 1000 would take minutes)
    scale_repeats: int      # timing repeats of table 2
    settle_seconds: float = SETTLE_SECONDS


FULL = Settings(repeats=5, pile_steps=60, sizes=(14, 50, 100, 300, 1000),
                scale_steps={14: 40, 50: 20, 100: 12, 300: 8, 1000: 4}, listing_max=1000, scale_repeats=3)
QUICK = Settings(repeats=1, pile_steps=8, sizes=(14, 50, 100), scale_steps={14: 4, 50: 3, 100: 2}, listing_max=100,
                 scale_repeats=1, settle_seconds=0.25)

QUICK_NOTE = ("**Smoke run (`--quick`): {repeats} repeat(s) of a few steps. It shows that every engine runs; its "
              "times and ratios are not measurements and may contradict the published figures, which come from "
              "the full run (`python -m lesson11.bench.speed`).**")

ENGINE_NAMES = {"listing": "the lesson's example solver (listing.py, pure Python)",
                "lab": "physics2d as the lab runs it (solution's sat/resolve)",
                "reference": 'physics2d `solver="accumulated"`',
                "pymunk": "pymunk (C)"}


# ---------------------------------------------------------------- the solution's functions

def solution_functions():
    """(sat, resolve) of solutions/tumbling_crates.py, loaded as a module (its main() does not run)."""
    spec = importlib.util.spec_from_file_location("tumbling_crates_solution", SOLUTION)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.sat, module.resolve


# ---------------------------------------------------------------- snapshots

def record(body):
    """One physics2d Body as a snapshot entry: a plain dict every engine can be built from."""
    return {"points": [(p.x, p.y) for p in body.shape.points], "pos": (body.pos.x, body.pos.y),
            "vel": (body.vel.x, body.vel.y), "angle": body.angle, "omega": body.omega, "mass": body.mass,
            "restitution": body.restitution, "friction": body.friction}


def physics2d_bodies(snapshot):
    """Fresh physics2d Bodies from a snapshot."""
    return [Body(b["points"], b["pos"], b["mass"], angle=b["angle"], vel=b["vel"], omega=b["omega"],
                 restitution=b["restitution"], friction=b["friction"]) for b in snapshot]


def lab_statics():
    """The Tumbling Crates scene's static bodies: the floor, the 22° ramp, the wall off the right edge."""
    return [Body(box_points(900, 40), (450, LAB_FLOOR_TOP + 20), 0),
            Body(box_points(420, 24), (230, 380), 0, angle=math.radians(22)),
            Body(box_points(30, 600), (910, 300), 0)]


def lab_pile_snapshot(settle_seconds=SETTLE_SECONDS):
    """The 14-crate lab pile, settled by the lab's World for settle_seconds: (snapshot, floor top y)."""
    crates = []
    for row, count in enumerate(PILE_ROWS):
        left = PILE_X - (count - 1) * BOX / 2
        y = LAB_FLOOR_TOP - BOX / 2 - row * BOX
        crates += [Body(box_points(BOX, BOX), (left + k * BOX, y), CRATE_MASS) for k in range(count)]
    sat, resolve = solution_functions()
    world = World(lab_statics() + crates, sat=sat, resolve=resolve)
    for _ in range(round(settle_seconds / STEP)):
        world.step()
    return [record(body) for body in world.bodies], LAB_FLOOR_TOP


def wide_box_snapshot(count):
    """`count` crates (even) in columns of two in a box just wide enough: (snapshot, floor top y).

    Each crate starts OVERLAP px into what it rests on, columns COLUMN_GAP px apart,
    walls 10 px from the outer columns. The floor is one static box as long as the pile.
    """
    columns = math.ceil(count / 2)
    pitch = BOX + COLUMN_GAP
    width = columns * pitch + 20
    floor_top = LAB_FLOOR_TOP
    statics = [Body(box_points(width + 60, 40), (width / 2, floor_top + 20), 0),
               Body(box_points(30, 200), (-15, floor_top - 100), 0),
               Body(box_points(30, 200), (width + 15, floor_top - 100), 0)]
    crates = []
    for k in range(count):
        column, level = divmod(k, 2)
        x = 10 + pitch * column + pitch / 2
        y = floor_top - BOX / 2 + OVERLAP - level * (BOX - OVERLAP)
        crates.append(Body(box_points(BOX, BOX), (x, y), CRATE_MASS))
    return [record(body) for body in statics + crates], floor_top


# ---------------------------------------------------------------- engines

class ListingEngine:
    """listing.step_world on Crates built from the snapshot."""

    def __init__(self, snapshot):
        self.bodies = listing.from_snapshot(snapshot)
        self.found = []

    def step(self):
        listing.step_world(self.bodies, STEP, self.found)

    def contacts(self):
        return len(self.found)

    def crates(self):
        """(position, corners) of every dynamic body, in px."""
        return [(b.pos, b.world_points()) for b in self.bodies if b.inv_mass > 0]


class WorldEngine:
    """A physics2d World built from the snapshot with the given settings."""

    def __init__(self, snapshot, **settings):
        self.world = World(physics2d_bodies(snapshot), iterations=ITERATIONS, step_seconds=STEP, **settings)
        self.step = self.world.step

    def contacts(self):
        return len(self.world.contacts)

    def crates(self):
        return [(b.pos, b.world_points()) for b in self.world.bodies if b.inv_mass > 0]


class PymunkEngine:
    """A pymunk Space built from the snapshot. Per shape friction √μ and elasticity √e, so that each pair
    gets μ and e as in physics2d (pymunk multiplies, physics2d takes √(μA μB) and min(eA, eB))."""

    def __init__(self, snapshot):
        import pymunk
        self.space = pymunk.Space()
        self.space.gravity = (0, 980)
        self.space.iterations = ITERATIONS
        self.bodies = []
        for b in snapshot:
            if b["mass"] == 0:
                body = pymunk.Body(body_type=pymunk.Body.STATIC)
            else:
                body = pymunk.Body(b["mass"], pymunk.moment_for_poly(b["mass"], b["points"]))
                body.velocity, body.angular_velocity = b["vel"], b["omega"]
            body.position, body.angle = b["pos"], b["angle"]
            shape = pymunk.Poly(body, b["points"])
            shape.friction, shape.elasticity = math.sqrt(b["friction"]), math.sqrt(b["restitution"])
            self.space.add(body, shape)
            self.bodies.append((body, shape))

    def step(self):
        self.space.step(STEP)

    def contacts(self):
        seen = {}

        def count(arbiter):
            a, b = arbiter.shapes
            seen[frozenset((id(a), id(b)))] = len(arbiter.contact_point_set.points)
        for body, _ in self.bodies:
            if body.body_type == body.DYNAMIC:
                body.each_arbiter(count)
        return sum(seen.values())

    def crates(self):
        from pygame import Vector2
        return [(Vector2(tuple(body.position)), [Vector2(tuple(body.local_to_world(v))) for v in shape.get_vertices()])
                for body, shape in self.bodies if body.body_type == body.DYNAMIC]


def pymunk_available():
    try:
        import pymunk  # noqa: F401
    except ImportError:
        return False
    return True


def engine_makers(sat_resolve=None):
    """{name: function(snapshot) -> engine}, pymunk only when importable."""
    sat, resolve = sat_resolve or solution_functions()
    makers = {"listing": ListingEngine,
              "lab": lambda snap: WorldEngine(snap, sat=sat, resolve=resolve),
              "reference": lambda snap: WorldEngine(snap, solver="accumulated")}
    if pymunk_available():
        makers["pymunk"] = PymunkEngine
    return makers


# ---------------------------------------------------------------- measuring

@dataclass
class Result:
    """One engine on one scene: seconds per step of each repeat, and what the pile looked like at the end."""
    engine: str
    times: list
    steps: int
    contacts: int          # contact points after the last step (first repeat)
    sunk: float            # px: deepest crate corner below the floor's top face at the end (first repeat)
    moved: float           # px: largest distance any crate's centre moved from the snapshot (first repeat)
    finite: bool

    @property
    def ms(self):
        """Median ms per step."""
        return 1000 * statistics.median(self.times)


def engine_run(make, snapshot, steps, floor_top, chunk=1):
    """Build an engine from the snapshot (untimed), step it `steps` times, yielding after every `chunk` steps;
    returns (seconds per step, contacts, sunk px, moved px, all finite)."""
    engine = make(snapshot)
    start = [(b["pos"][0], b["pos"][1]) for b in snapshot if b["mass"] > 0]
    spent = 0.0
    for done in range(1, steps + 1):
        started = time.process_time()
        engine.step()
        spent += time.process_time() - started
        if done % chunk == 0:
            yield
    crates = engine.crates()
    values = [v for pos, corners in crates for p in [pos] + corners for v in (p.x, p.y)]
    finite = all(math.isfinite(v) for v in values)
    sunk = max(max(p.y for _, corners in crates for p in corners) - floor_top, 0.0) if finite else math.inf
    moved = max(math.hypot(pos.x - x, pos.y - y) for (pos, _), (x, y) in zip(crates, start)) if finite else math.inf
    return spent / steps, engine.contacts(), sunk, moved, finite


@dataclass
class Case:
    """One engine on one scene: how to build it, from what, for how many steps, yielding every `chunk` steps."""
    make: object
    snapshot: list
    steps: int
    floor_top: float
    chunk: int = 1


def measure(cases, repeats, progress=None, label=""):
    """Every case `repeats` times from fresh copies of its snapshot, round-robin: {key: Result}.

    Within a repeat the cases advance in turn, one chunk of steps each
    (harness.lockstep), and the order rotates between repeats, so the
    machine's slow moments hit every case alike.
    """
    keys = list(cases)
    runs = {key: [] for key in keys}
    for repeat in range(repeats):
        if progress:
            progress(f"{label}: repeat {repeat + 1}/{repeats}, {len(keys)} cases round-robin")
        order = keys[repeat % len(keys):] + keys[:repeat % len(keys)]  # rotate who goes first
        outcomes = lockstep([engine_run(cases[k].make, cases[k].snapshot, cases[k].steps, cases[k].floor_top,
                                        cases[k].chunk) for k in order])
        for key, outcome in zip(order, outcomes):
            runs[key].append(outcome)
    results = {}
    for key in keys:
        first = runs[key][0]
        name = key[-1] if isinstance(key, tuple) else key
        results[key] = Result(name, [r[0] for r in runs[key]], cases[key].steps, first[1], first[2], first[3],
                              all(r[4] for r in runs[key]))
    return results


def run(settings, progress=None):
    """Both tables in one run: (pile results {engine: Result}, scaling results {N: {engine: Result}}).

    Table 2 runs every N and engine in the same round-robin, in ROUNDS chunks of
    steps each (N = 14 steps ten at a time while N = 1000 steps one), so that the
    growth ratio cost(N)/cost(14) also divides two figures measured side by side.
    """
    makers = engine_makers()
    say = progress or (lambda text: None)
    say(f"settling the 14-crate lab pile for {settings.settle_seconds:g} s")
    snapshot, floor_top = lab_pile_snapshot(settings.settle_seconds)
    pile = measure({name: Case(make, snapshot, settings.pile_steps, floor_top) for name, make in makers.items()},
                   settings.repeats, say, f"table 1, {settings.pile_steps} steps")
    rounds = min(settings.scale_steps.values())
    cases = {}
    for n in settings.sizes:
        snap, top = wide_box_snapshot(n)
        steps = settings.scale_steps[n]
        for name, make in makers.items():
            if name != "listing" or n <= settings.listing_max:
                cases[(n, name)] = Case(make, snap, steps, top, chunk=max(1, steps // rounds))
    results = measure(cases, settings.scale_repeats, say, f"table 2, N = {', '.join(map(str, settings.sizes))}")
    scaling = {n: {name: result for (size, name), result in results.items() if size == n} for n in settings.sizes}
    return pile, scaling


# ---------------------------------------------------------------- the report

def spread(result):
    """(slowest - fastest repeat) / median, in %, or n/a with one repeat."""
    if len(result.times) < 2:
        return "n/a (1 repeat)"
    return f"{100 * (max(result.times) - min(result.times)) / statistics.median(result.times):.0f} %"


def ratios(pile):
    """The figures the targets are about, from table 1's medians."""
    figures = {"lab_vs_listing": pile["listing"].ms / pile["lab"].ms,
               "frame_share": STEPS_PER_FRAME * pile["lab"].ms / (1000 * FRAME),
               "reference_vs_listing": pile["listing"].ms / pile["reference"].ms}
    if "pymunk" in pile:
        figures["reference_vs_pymunk"] = pile["reference"].ms / pile["pymunk"].ms
    return figures


def pile_table(pile):
    """Table 1: ms/step, listing ÷ this, this ÷ pymunk, spread, contacts and how the pile ended."""
    lines = ["| engine, 14-crate lab pile, 6 iterations, 1/120 s | ms/step (median) | spread | "
             "listing ÷ this | this ÷ pymunk | contact points at the end | deepest corner below floor | "
             "largest crate move |",
             "|---|---|---|---|---|---|---|---|"]
    for name, result in pile.items():
        faster = "1 (baseline)" if name == "listing" else f"{pile['listing'].ms / result.ms:.3g}"
        if "pymunk" in pile:
            slower = "1" if name == "pymunk" else f"{result.ms / pile['pymunk'].ms:.3g}"
        else:
            slower = "n/a (no pymunk)"
        lines.append(f"| {ENGINE_NAMES[name]} | {result.ms:.3g} | {spread(result)} | {faster} | {slower} | "
                     f"{result.contacts} | {result.sunk:.2f} px | {result.moved:.2f} px |"
                     + ("" if result.finite else " NOT FINITE |"))
    return "\n".join(lines)


def growth(scaling, name):
    """cost per body-step at the largest N this engine ran ÷ at the smallest: (ratio, largest N)."""
    sizes = [n for n in scaling if name in scaling[n]]
    first, last = sizes[0], sizes[-1]
    per_body = {n: scaling[n][name].ms / n for n in sizes}
    return per_body[last] / per_body[first], last


def scaling_table(scaling, settings):
    """Table 2: µs per body-step for each N and engine, and the growth ratio to the smallest N."""
    sizes = list(scaling)
    names = [name for name in ENGINE_NAMES if any(name in scaling[n] for n in sizes)]
    lines = ["| engine | " + " | ".join(f"N = {n}" for n in sizes) + f" | growth, cost(N)/cost({sizes[0]}) |",
             "|---|" + "---|" * (len(sizes) + 1)]
    for name in names:
        cells = []
        for n in sizes:
            if name in scaling[n]:
                cells.append(f"{1000 * scaling[n][name].ms / n:.3g}")
            else:
                cells.append(f"not run (all pairs; > {settings.listing_max} crates would take minutes)")
        ratio, last = growth(scaling, name)
        lines.append(f"| {ENGINE_NAMES[name]} | " + " | ".join(cells) + f" | {ratio:.2f}× (at N = {last}) |")
    return "\n".join(lines)


def targets(pile, scaling):
    """[(target, measured, met)] for the issue's targets this run can judge."""
    figures = ratios(pile)
    rows = [("lab ≥ 2× faster than the listing (14 crates)", f"{figures['lab_vs_listing']:.2f}×",
             figures["lab_vs_listing"] >= TARGETS["lab_vs_listing"]),
            ("lab physics ≤ ⅓ of a 60 fps frame (2 steps)", f"{100 * figures['frame_share']:.0f} % of a frame",
             figures["frame_share"] <= TARGETS["frame_share"]),
            ("reference ≥ 10× faster than the listing", f"{figures['reference_vs_listing']:.2f}×",
             figures["reference_vs_listing"] >= TARGETS["reference_vs_listing"])]
    if "reference_vs_pymunk" in figures:
        rows.append(("reference ≤ 50× pymunk", f"{figures['reference_vs_pymunk']:.0f}×",
                     figures["reference_vs_pymunk"] <= TARGETS["reference_vs_pymunk"]))
    else:
        rows.append(("reference ≤ 50× pymunk", "not measured: pymunk is not installed", None))
    sizes = list(scaling)
    for name in ("lab", "reference"):
        ratio, last = growth(scaling, name)
        rows.append((f"{name}: cost per body-step grows ≤ 1.3× from {sizes[0]} to 1000 crates",
                     f"{ratio:.2f}× ({sizes[0]} → {last})", ratio <= TARGETS["growth"] if last >= 1000 else None))
    return rows


def targets_table(rows):
    lines = ["| target | measured | met? |", "|---|---|---|"]
    for target, measured, met in rows:
        verdict = "not judged (this run stops below 1000 crates)" if met is None and "1000" in target else (
            "not judged" if met is None else ("met" if met else "not met"))
        lines.append(f"| {target} | {measured} | {verdict} |")
    return "\n".join(lines)


def report(pile, scaling, settings, elapsed, mode):
    """The whole Markdown report."""
    figures = ratios(pile)
    command = "python -m lesson11.bench.speed" + (" --quick" if mode == "quick" else "")
    lab = pile["lab"]
    parts = ["# Speed, measured side by side", ""]
    if mode == "quick":
        parts += [QUICK_NOTE.format(repeats=settings.repeats), ""]
    parts += [
        f"Run: `{command}` · {mode} run, {settings.repeats} repeat(s) per engine in table 1 and "
        f"{settings.scale_repeats} in table 2, round-robin, median kept, CPU time inside step() · "
        f"whole run {elapsed:.0f} s · {time.strftime('%Y-%m-%d')}",
        "",
        f"Machine: {machine_note()}",
        "",
        "## 1. The lab's pile",
        "",
        f"The Tumbling Crates scene (floor, 22° ramp, wall) with 14 crates of {BOX:g} px piled "
        f"{'-'.join(map(str, PILE_ROWS))} on the floor, settled by the lab's World for {settings.settle_seconds:g} s; "
        f"every engine starts from that snapshot and runs {settings.pile_steps} steps of 1/120 s per repeat. "
        "Times are the median over repeats of the CPU time inside step(); *spread* is (slowest - fastest repeat) / "
        "median. The last three columns are how each engine left the pile (first repeat): contact points "
        "(per point, as each engine counts them), the deepest crate corner below the floor's top face, and the "
        "largest distance any crate's centre moved from the snapshot.",
        "",
        pile_table(pile),
        "",
        f"The lab's physics: 2 steps × {lab.ms:.3g} ms = {STEPS_PER_FRAME * lab.ms:.3g} ms, "
        f"{100 * figures['frame_share']:.0f} % of a 60 fps frame (16.7 ms).",
        "",
        "## 2. Scaling: cost per body-step in a wide box",
        "",
        f"N crates of {BOX:g} px in columns of two (so the pile is two crates deep at every N) on a floor as long "
        f"as the pile, walls at both ends; each crate starts {OVERLAP:g} px sunk into what it rests on. "
        "Cost per body-step = median ms/step ÷ N crates, in µs. Every N and engine runs in the same "
        f"round-robin, in {min(settings.scale_steps.values())} rounds a repeat, so the growth ratio compares "
        "figures measured side by side. Steps per repeat: "
        + ", ".join(f"N = {n}: {settings.scale_steps[n]}" for n in settings.sizes) + ".",
        "",
        scaling_table(scaling, settings),
        "",
        "## Targets (issue 13)",
        "",
        targets_table(targets(pile, scaling)),
        "",
    ]
    if "pymunk" not in pile:
        parts += ["pymunk is not installed (pip install -e \".[compare]\"): no pymunk rows or ratios.", ""]
    return "\n".join(parts)


def plot(scaling, path, subtitle):
    """Log-log figure: cost per body-step (µs) against N, one line per engine. Needs matplotlib."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 6))
    markers = {"listing": "s", "lab": "o", "reference": "D", "pymunk": "^"}
    for name in ENGINE_NAMES:
        sizes = [n for n in scaling if name in scaling[n]]
        if not sizes:
            continue
        costs = [1000 * scaling[n][name].ms / n for n in sizes]
        ratio, last = growth(scaling, name)
        label = ENGINE_NAMES[name].replace("`", "")
        ax.plot(sizes, costs, marker=markers[name], label=f"{label}: ×{ratio:.2f} from "
                                                          f"{sizes[0]} to {last}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks(list(scaling))
    ax.set_xticklabels([str(n) for n in scaling])
    ax.minorticks_off()
    ax.set_xlabel("crates in the wide box (log scale)")
    ax.set_ylabel("cost per body-step (µs, log scale)")
    ax.set_title("Cost per body-step against the number of bodies (flat = scales linearly)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.text(0.5, 0.005, subtitle, ha="center", fontsize=6.5, color="dimgray", wrap=True)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main(argv=None):
    parser = bench_parser("speed", "Speed side by side: the lesson's listing, the lab's World, the reference solver "
                                   "and pymunk, on the lab's pile and at scale.", "bench_speed", "few steps", "engine")
    args = parser.parse_args(argv)
    settings = QUICK if args.quick else FULL
    if args.repeats:
        settings = Settings(**{**settings.__dict__, "repeats": args.repeats, "scale_repeats": args.repeats})
    mode = "quick" if args.quick else "full"
    out_dir, problem = output_folder(args)
    if problem:
        print(problem, file=sys.stderr)
        return 2
    if not pymunk_available():
        print("pymunk is not installed: no pymunk rows (pip install -e \".[compare]\")", file=sys.stderr)

    started = time.perf_counter()
    pile, scaling = run(settings, progress=lambda text: print(text, file=sys.stderr, flush=True))
    elapsed = time.perf_counter() - started
    text = report(pile, scaling, settings, elapsed, mode)
    print(text)
    if args.quick:
        print("Smoke run: these figures only show that every engine runs; see the full run for measurements.")
    return write_results(args, out_dir, "bench_speed", text, lambda path, subtitle: plot(scaling, path, subtitle),
                         "not measurements")


if __name__ == "__main__":
    sys.exit(main())
