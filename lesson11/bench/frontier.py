"""The frontier: CPU time per step against error, one point per solver setting.

    python -m lesson11.bench.accuracy_cost --frontier     # the full sweep, a few minutes
    python -m lesson11.bench.frontier [--quick] [--out-dir DIR] [--no-plot]

Each setting (solver, order, sub-steps, iterations; pymunk: iterations) runs
four of solver_probe's scenes at 1/120 s steps and is measured on four errors:
  pile     the 12-crate brick pile (60 × 40 px, rows of 4, 3, 3, 2) for 2.5 s:
           its fastest crate during the last 1 s (px/s; at rest it is 0)
  ramp     a 40 px crate at rest on a 22° slope (μ 0.6) for 3 s: how far it crept (px)
  stack    10 boxes of 40 px for 4 s: the largest drift of any box (px)
  bounce   a 40 px box dropped flat from 100 px, e = 0.5: |rebound/impact - 0.5|
Its cost is the CPU time of one step of the pile (ms; time.process_time around
world.step only), the median of --repeats runs (3; --quick 1). A setting is on the front of an error if no other setting is
both cheaper and more accurate on it; the plot draws one panel per error with
the front as a line, and frontier.json (beside this file) keeps the pile's
figures for the lab panel.
"""
import json
import math
import sys
import textwrap
import time
from pathlib import Path

from . import solver_probe
from .harness import bench_parser, default_out_dir, machine_note, output_folder, write_results

STUDY_JSON = Path(__file__).with_name("frontier.json")
SUBSTEPS = (1, 2, 4, 8)
ITERATIONS = (1, 2, 4, 6, 10, 20)
PYMUNK_ITERATIONS = (1, 2, 4, 6, 10, 20, 50)
QUICK_SUBSTEPS, QUICK_ITERATIONS = (1, 4), (2, 6)
ERRORS = {  # key: (column title, unit, what it is)
    "pile": ("pile speed", "px/s", "12-crate brick pile, fastest crate in the last 1 s of 2.5 s"),
    "ramp": ("ramp creep", "px", "40 px crate at rest on the 22° ramp, distance moved in 3 s"),
    "stack": ("stack drift", "px", "10-box stack, largest drift in 4 s"),
    "bounce": ("bounce error", "", "flat box, e = 0.5: |rebound ratio - 0.5|"),
}
SOLVERS = ("lesson solve-first", "lesson move-first", "reference", "pymunk")
POINT_KEYS = ("solver", "substeps", "iterations", "ms_per_step") + tuple(ERRORS)


def settings_of(solver, substeps, iterations):
    """World settings (a dict for solver_probe.make) for one point of the sweep."""
    if solver == "pymunk":
        return {"pymunk": iterations}
    if solver == "reference":
        return {"solver": "accumulated", "substeps": substeps, "iterations": iterations}
    return {"solver": "lesson", "order": solver.split()[1], "substeps": substeps, "iterations": iterations}


def timed(scene):
    """Wrap scene.step so that it also counts CPU time (process time, s) in scene.cpu."""
    scene.cpu = 0.0
    step = scene.step

    def counted():
        start = time.process_time()
        step()
        scene.cpu += time.process_time() - start
    scene.step = counted
    return scene


def pile(engine, seconds=2.5, repeats=1):
    """(fastest crate in the last 1 s (px/s), CPU ms per step) of solver_probe's brick pile after `seconds`;
    run `repeats` times, the median time kept (the speed is the same every time: the runs are deterministic)."""
    runs = [pile_once(engine, seconds) for _ in range(repeats)]
    return runs[0][0], sorted(ms for _, ms in runs)[len(runs) // 2]


def pile_once(engine, seconds):
    """One run of pile()."""
    scene = timed(solver_probe.make(engine))
    states = solver_probe.brick_pile(scene)
    steps = round(seconds * 120)
    top = 0.0
    for k in range(steps):
        scene.step()
        if k >= steps - 120:
            top = max([top] + [state()[1].length() for state in states])
    return top, 1000 * scene.cpu / steps


def measure(solver, substeps, iterations, repeats=1):
    """One point: {"solver", "substeps", "iterations", "ms_per_step", and one figure per ERRORS key}."""
    engine = settings_of(solver, substeps, iterations)
    speed, ms = pile(engine, repeats=repeats)
    rebound, _ = solver_probe.flat_bounce(engine, 0.5)
    return {"solver": solver, "substeps": substeps, "iterations": iterations, "ms_per_step": ms,
            "pile": speed, "ramp": solver_probe.ramp_rest(engine, 3), "stack": solver_probe.stack(engine, 4),
            "bounce": abs(rebound - 0.5) if math.isfinite(rebound) else float("inf")}


def grid(quick, with_pymunk):
    """The (solver, substeps, iterations) points of the sweep."""
    substeps, iterations = (QUICK_SUBSTEPS, QUICK_ITERATIONS) if quick else (SUBSTEPS, ITERATIONS)
    points = [(solver, s, i) for solver in SOLVERS[:3] for s in substeps for i in iterations]
    if with_pymunk:
        points += [("pymunk", 1, i) for i in (QUICK_ITERATIONS if quick else PYMUNK_ITERATIONS)]
    return points


def front(rows, key):
    """The rows on the Pareto front of (ms_per_step, key), cheapest first: nothing cheaper errs less."""
    best, kept = float("inf"), []
    for row in sorted(rows, key=lambda r: (r["ms_per_step"], r[key])):
        if row[key] < best:
            kept.append(row)
            best = row[key]
    return kept


def name(row):
    """A setting as text: "lesson solve-first 4×6", "pymunk 10 it."."""
    if row["solver"] == "pymunk":
        return f"pymunk {row['iterations']} it."
    return f"{row['solver']} {row['substeps']}×{row['iterations']}"


def mark_fronts(rows):
    """Set row["fronts"] (the ERRORS keys whose front, over every solver, it is on), row["own_front"] (on
    the pile front of its own solver) and row["better"] (the most accurate setting of the same solver that
    costs less and errs less on the pile, or None)."""
    fronts = {key: {id(row) for row in front(rows, key)} for key in ERRORS}
    for row in rows:
        mine = [other for other in rows if other["solver"] == row["solver"]]
        row["fronts"] = [key for key in ERRORS if id(row) in fronts[key]]
        row["own_front"] = any(row is kept for kept in front(mine, "pile"))
        dominating = [other for other in mine
                      if other["ms_per_step"] < row["ms_per_step"] and other["pile"] < row["pile"]]
        best = min(dominating, key=lambda r: r["pile"]) if dominating else None
        row["better"] = name(best) if best else None
        row["better_setting"] = f"{best['substeps']}×{best['iterations']}" if best else None


def table(rows):
    """The Markdown table: one row per setting, the errors, the fronts it is on."""
    head = "| setting | ms/step (pile) | " + " | ".join(
        f"{title} ({unit})" if unit else title for title, unit, _ in ERRORS.values()) + \
        " | overall front of | its solver's pile front |"
    lines = [head, "|---|---:|" + "---:|" * len(ERRORS) + "---|---|"]
    for row in rows:
        cells = " | ".join(f"{row[key]:.3g}" for key in ERRORS)
        own = "yes" if row["own_front"] else f"no: {row['better']} is cheaper and settles better"
        lines.append(f"| {name(row)} | {row['ms_per_step']:.3f} | {cells} | {', '.join(row['fronts']) or '-'} "
                     f"| {own} |")
    return "\n".join(lines)


def write_json(rows, path, machine=""):
    """frontier.json: "settings" for the lab panel (the pile's cost and error per World setting, and whether it is
    on its solver's front), and "points", every row as measured (pymunk too), from which --replot redraws."""
    settings = []
    for row in rows:
        if row["solver"] == "pymunk":
            continue
        solver = "lesson" if row["solver"].startswith("lesson") else "accumulated"
        settings.append({"solver": solver, "order": row["solver"].split()[1] if solver == "lesson" else "-",
                         "substeps": row["substeps"], "iterations": row["iterations"],
                         "ms_per_step": round(row["ms_per_step"], 4), "pile_speed": round(row["pile"], 3),
                         "ramp": round(row["ramp"], 3), "stack": round(row["stack"], 3),
                         "bounce": round(row["bounce"], 4), "on_front": row["own_front"],
                         "better": row["better_setting"]})
    path.write_text(json.dumps({"about": "lesson11/bench/frontier.py; ms_per_step is CPU ms per step of the "
                                         "12-crate pile, pile_speed px/s, ramp and stack px",
                                "machine": machine, "settings": settings,
                                "points": [{key: row[key] for key in POINT_KEYS} for row in rows]},
                               indent=1) + "\n", encoding="utf-8")


def read_points(path):
    """The measured rows kept in frontier.json ("points"), fronts marked again; raises ValueError (one line naming
    the file) if the file has none, e.g. one written before the points were kept."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
        rows = [{key: point[key] for key in POINT_KEYS} for point in data["points"]]
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise ValueError(f"{path}: no measured points to redraw ({error.__class__.__name__}: {error}); "
                         f"run the sweep again") from None
    if not rows:
        raise ValueError(f"{path}: no measured points to redraw; run the sweep again")
    mark_fronts(rows)
    return rows, data.get("machine", "")


def plot(rows, path, subtitle):
    """Four panels (one per error): every setting as a point, cost (x) against error (y), the front as a line."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    colours = dict(zip(SOLVERS, ("tab:blue", "tab:orange", "tab:green", "tab:purple")))
    fig, axes = plt.subplots(2, 2, figsize=(13, 9.5))
    for ax, (key, (title, unit, about)) in zip(axes.flat, ERRORS.items()):
        floor = min([row[key] for row in rows if row[key] > 0] or [1e-3]) / 3
        for solver in SOLVERS:
            mine = [row for row in rows if row["solver"] == solver]
            if mine:
                ax.scatter([r["ms_per_step"] for r in mine], [max(r[key], floor) for r in mine], s=22,
                           color=colours[solver], label=solver, alpha=0.8)
                own = front(mine, key)
                ax.step([r["ms_per_step"] for r in own], [max(r[key], floor) for r in own], where="post",
                        color=colours[solver], lw=0.9, alpha=0.6)
        line = front(rows, key)
        ax.step([r["ms_per_step"] for r in line], [max(r[key], floor) for r in line], where="post",
                color="black", lw=1.4, label="front over every solver (thin: each solver's own)")
        labelled = []   # (log x, log y) of the labels drawn so far: one label per crowded spot
        for row in line:
            x, y = row["ms_per_step"], max(row[key], floor)
            here = (math.log10(x), math.log10(y))
            if all(abs(here[0] - a) > 0.35 or abs(here[1] - b) > 0.6 for a, b in labelled):
                labelled.append(here)
                ax.annotate(name(row).replace("lesson ", ""), (x, y), fontsize=7, xytext=(4, 3),
                            textcoords="offset points")
        for row in rows:
            if row["solver"] == "lesson solve-first" and (row["substeps"], row["iterations"]) == (4, 6):
                ax.scatter([row["ms_per_step"]], [max(row[key], floor)], s=160, facecolors="none",
                           edgecolors="red", lw=1.8, label="lab default (solve-first 4×6)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("CPU ms per 1/120 s step of the 12-crate pile (log)")
        ax.set_ylabel(f"{title} ({unit}, log)" if unit else f"{title} (log)")
        ax.set_title(about, fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=9, frameon=False)
    fig.suptitle("What accuracy costs: every solver setting, time per step against error (lower left is better)\n"
                 + textwrap.fill(subtitle, 150), fontsize=11)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def replot(out_dir):
    """Redraw bench_frontier.png in out_dir from frontier.json's points (no sweep); returns the exit status."""
    try:
        rows, machine = read_points(STUDY_JSON)
    except ValueError as error:
        print(error, file=sys.stderr)
        return 2
    out_dir.mkdir(parents=True, exist_ok=True)
    print(f"wrote {plot(rows, out_dir / 'bench_frontier.png', machine + ' · redrawn by --replot')}")
    return 0


def main(argv=None):
    parser = bench_parser("frontier", "The frontier: CPU time per step against error for every solver setting.",
                          "bench_frontier", "2 × 2 settings per solver", "setting")
    parser.add_argument("--replot", action="store_true",
                        help="no sweep: redraw bench_frontier.png from the points kept in frontier.json")
    args = parser.parse_args(argv)
    out_dir, problem = output_folder(args)
    if problem:
        print(problem, file=sys.stderr)
        return 2
    if args.replot:
        return replot(args.out_dir if args.out_dir is not None else default_out_dir())
    with_pymunk = solver_probe.pymunk is not None
    if not with_pymunk:
        print("pymunk is not installed: its points are skipped (pip install -e \".[compare]\")", file=sys.stderr)
    print(f"Machine: {machine_note()}")
    started = time.perf_counter()
    rows = []
    for solver, substeps, iterations in grid(args.quick, with_pymunk):
        rows.append(measure(solver, substeps, iterations, args.repeats or (1 if args.quick else 3)))
        print(f"  {name(rows[-1])}: {rows[-1]['ms_per_step']:.3f} ms/step, pile {rows[-1]['pile']:.3g} px/s",
              file=sys.stderr, flush=True)
    mark_fronts(rows)
    minutes = (time.perf_counter() - started) / 60
    text = (f"# The frontier: what each solver setting costs and how far it errs\n\n"
            f"`python -m lesson11.bench.frontier{' --quick' if args.quick else ''}` · {machine_note()} · "
            f"{minutes:.1f} min.\n\n" + "\n".join(f"- **{title}**: {about}." for title, _, about in ERRORS.values())
            + f"\n- **ms/step**: CPU time of one 1/120 s step of the pile, the median of "
            f"{args.repeats or (1 if args.quick else 3)} runs back to back (a shared 2-core machine).\n\n"
            + table(rows) + "\n")
    print(text)
    if out_dir is not None and not args.quick and args.out_dir is None:
        write_json(rows, STUDY_JSON, f"full run · {machine_note()} · {minutes:.1f} min")
        print(f"wrote {STUDY_JSON}")
    return write_results(args, out_dir, "bench_frontier", text, lambda path, subtitle: plot(rows, path, subtitle),
                         "one run of a few settings")


if __name__ == "__main__":
    sys.exit(main())
