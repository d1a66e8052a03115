"""The figure for accuracy_cost: one panel per study, accuracy against time.

Needs matplotlib (the `compare` extra); it draws off-screen (Agg) and saves a PNG.
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

FLOOR = 1e-3  # px: figures of 0 are drawn here on the log axes


def _tunnelling_by_speed(ax, rows):
    for row in rows:
        speeds = list(row.accuracy)
        shares = [100 * row.accuracy[s] for s in speeds]
        style = dict(lw=3, color="black") if "CCD" in row.variant else dict(lw=1.8)
        cost = 1.0 if row.baseline else row.ratio
        name = "CCD, 1/120 s" if "CCD" in row.variant else row.variant.replace(" (", ", ").rstrip(")")
        ax.plot(speeds, shares, marker="o", ms=4, label=f"{name}   time ×{cost:.1f}", **style)
    ax.set_xscale("log")
    ax.set_xticks(speeds)
    ax.set_xticklabels([f"{s / 1000:g}k" for s in speeds])
    ax.minorticks_off()
    ax.set_xlabel("bullet speed (px/s, log scale)")
    ax.set_ylabel("shots that tunnel through the wall (%)")
    ax.set_ylim(-4, 140)
    ax.set_yticks(range(0, 101, 20))
    ax.set_title("1a  Tunnelling: 3 px bullet, 4 px wall")
    ax.legend(fontsize=8, loc="upper left")


def _safe_speed(row):
    """Highest tested speed below which no shot tunnelled (0 if even the slowest tunnels)."""
    speeds = sorted(row.accuracy)
    safe = 0
    for speed in speeds:
        if row.accuracy[speed] > 0:
            break
        safe = speed
    return safe


def _tunnelling_cost(ax, rows):
    top = max(rows[0].accuracy)
    for row in rows:
        ratio = 1.0 if row.baseline else row.ratio
        safe = _safe_speed(row)
        ccd = "CCD" in row.variant
        ax.scatter([ratio], [safe], s=90 if ccd else 50, color="black" if ccd else "tab:blue", zorder=3)
        name = "CCD" if ccd else ("discrete" if row.baseline else row.variant.split(" (")[0])
        label = f"{name}: none tunnel\nat any tested speed" if ccd and safe == top else name
        ax.annotate(label, (ratio, safe), textcoords="offset points", xytext=(8, -4), fontsize=8)
    ax.set_xscale("log", base=2)
    ax.set_xticks([1, 2, 4, 8, 16])
    ax.set_xticklabels(["×1", "×2", "×4", "×8", "×16"])
    ax.minorticks_off()
    ax.set_xlabel("time per simulated second, relative to discrete (log scale)")
    ax.set_ylabel("highest speed with no tunnelling (px/s)")
    ax.set_ylim(0, top * 1.15)
    ax.set_xlim(0.7, max(r.ratio for r in rows if not r.baseline) * 2.2)
    ax.set_title("1b  What each fix buys, and what it costs")
    ax.grid(alpha=0.3)


def _iterations(ax, rows):
    colors = {"lesson": "tab:red", "accumulated": "tab:green"}
    for solver, color in colors.items():
        chosen = [r for r in rows if r.variant.startswith(solver)]
        if not chosen:
            continue
        times = [r.ms for r in chosen]
        ax.plot(times, [max(r.accuracy["drift"], FLOOR) for r in chosen], "-o", color=color,
                label=f"{solver} solver: top crate drift")
        ax.plot(times, [max(r.accuracy["penetration"], FLOOR) for r in chosen], "--s", color=color, ms=4,
                label=f"{solver} solver: floor penetration")
        for r in chosen:
            n = r.variant.split(", ")[1].split()[0]
            ax.annotate(n, (r.ms, max(r.accuracy["drift"], FLOOR)), textcoords="offset points",
                        xytext=(4, 4), fontsize=8, color=color)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per step (ms, log scale)")
    ax.set_ylabel("error (px, log scale; lower is better)")
    ax.set_title("2  Solver iterations (numbers = passes): 10-crate pyramid")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")


def _contact_rule(ax, rows):
    markers = {'"corners"': "o", '"clip"': "s"}
    colors = {}
    for r in rows:
        color = colors.setdefault(r.scene, f"C{len(colors)}")
        rule = r.variant.strip('"')
        ax.scatter([r.ms], [r.accuracy["drift"]], marker=markers[r.variant], s=70, color=color, zorder=3)
        ax.scatter([r.ms], [r.accuracy["penetration"]], marker=markers[r.variant], s=70, facecolors="none",
                   edgecolors=color, zorder=3)
        ax.annotate(f"{r.scene}, {rule}", (r.ms, r.accuracy["drift"]), textcoords="offset points",
                    xytext=(7, 3), fontsize=8, color=color)
    ax.scatter([], [], marker="o", color="gray", label="filled: top crate drift")
    ax.scatter([], [], marker="o", facecolors="none", edgecolors="gray", label="hollow: floor penetration")
    ax.scatter([], [], marker="o", color="gray", label='circle: "corners" (lesson)')
    ax.scatter([], [], marker="s", color="gray", label='square: "clip" (edge clipping)')
    ax.set_ylim(0, max(max(r.accuracy["drift"], r.accuracy["penetration"]) for r in rows) * 1.25)
    ax.set_xlim(0, max(r.ms for r in rows) * 1.45)
    ax.set_xlabel("time per step (ms)")
    ax.set_ylabel("error (px; lower is better)")
    ax.set_title("3  Contact rule, lesson solver, 6 passes")
    ax.legend(fontsize=8, loc="upper right")
    ax.grid(alpha=0.3)


def _effects(ax, rows):
    labels = [r.variant.replace("LESSON_EFFECTS (all five)", "all five lesson effects")
              .replace("LESSON_EFFECTS", "all five").replace(", ", ",\n", 1) for r in rows]
    y = list(range(len(rows)))[::-1]
    ax.barh(y, [r.ms for r in rows], color=["tab:gray" if r.baseline else "tab:blue" for r in rows])
    for yy, r in zip(y, rows):
        swept = r.counters.get("swept_tests", 0)
        text = (f" ×{1 if r.baseline else r.ratio:.2f};  {swept:.0f} swept tests/step;\n"
                f" end positions differ by {r.accuracy['difference']:.2g} px")
        ax.text(r.ms, yy, text, va="center", fontsize=8)
    ax.set_yticks(y)
    ax.set_yticklabels(labels, fontsize=8)
    ax.set_xlabel("time per step (ms)")
    ax.set_xlim(0, max(r.ms for r in rows) * 2.1)
    ax.set_title(f"4  Declared effects: {rows[0].scene}")


def _pymunk(ax, rows):
    colors = {}
    for r in rows:
        engine = r.variant.split(",")[0] if "pymunk" in r.variant else r.variant.split(", ")[1]
        color = colors.setdefault(engine, f"C{len(colors) + 3}")
        pyramid = r.scene.startswith("pyramid")
        ratio = 1 if r.baseline else r.ratio
        ax.scatter([r.ms], [max(r.accuracy["drift"], FLOOR)], marker="o" if pyramid else "^", s=80, color=color,
                   zorder=3)
        ax.annotate(f"{engine}, {r.scene}\ntime ×{ratio:.3g}", (r.ms, max(r.accuracy["drift"], FLOOR)),
                    textcoords="offset points", xytext=(8, -22) if pyramid else (-20, 9), fontsize=8, color=color)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(min(r.ms for r in rows) / 2, max(r.ms for r in rows) * 40)
    ax.set_xlabel("time per step (ms, log scale)")
    ax.set_ylabel("top crate drift (px, log scale; lower is better)")
    ax.scatter([], [], marker="o", color="gray", label="pyramid4: 10 crates")
    ax.scatter([], [], marker="^", color="gray", label="stack8: 8 crates in a column")
    ax.legend(fontsize=8, loc="upper left")
    drifts = [max(r.accuracy["drift"], FLOOR) for r in rows]
    ax.set_ylim(min(drifts) / 15, max(drifts) * 40)
    ax.set_title("5  physics2d against pymunk, 6 passes")
    ax.grid(alpha=0.3, which="both")


SOLVER_COLORS = ["tab:red", "tab:orange", "tab:green", "tab:olive", "tab:purple"]


def _solver_points(ax, rows, measures, title, ylabel, floor, label):
    """Study 6: one marker per measurement, one colour per solver, at (time × lesson default on that scene, error)."""
    markers = "osD^v<>"
    for color, row in zip(SOLVER_COLORS, rows):
        parts = {part.scene: part for part in row.parts}
        for marker, (name, scene, error) in zip(markers, measures):
            value = error(row.accuracy[scene])
            if value is None or value != value:  # the run was too short to measure it (None or nan)
                continue
            ratio = 1.0 if row.baseline else parts[scene].ratio
            ax.scatter([ratio], [max(value, floor)], marker=marker, s=60, color=color, zorder=3,
                       edgecolors="black", linewidths=0.5)
    for color, row in zip(SOLVER_COLORS, rows):
        ax.scatter([], [], marker="s", s=60, color=color, label=label(row.variant))
    for marker, (name, _, _) in zip(markers, measures):
        ax.scatter([], [], marker=marker, s=60, facecolors="none", edgecolors="black", label=name)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per step on that scene, × lesson solver's default (log scale)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.axvline(1.0, color="gray", lw=0.8, ls=":")
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    ax.grid(alpha=0.3, which="both")


def _solvers_bounce(ax, rows, name):
    measures = [("flat box e=0.5: |rebound/0.5 - 1|", "flat 0.5", lambda a: a["rebound"] and abs(a["rebound"] / 0.5 - 1)),
                ("flat box e=0.9: |rebound/0.9 - 1|", "flat 0.9", lambda a: a["rebound"] and abs(a["rebound"] / 0.9 - 1)),
                ("disc e=0.5: |rebound/0.5 - 1|", "disc 0.5", lambda a: a["rebound"] and abs(a["rebound"] / 0.5 - 1)),
                ("disc e=1: |apex energy - 1|", "disc 1", lambda a: a["apex energy"] and abs(a["apex energy"] - 1))]
    _solver_points(ax, rows, measures, "6a  Solvers: restitution error (0 drawn at 10⁻⁴)",
                   "relative error (log scale; lower is better)", 1e-4, name)


def _solvers_rest(ax, rows, name):
    measures = [("ramp 22°: moved", "ramp", lambda a: a["moved"]),
                ("10-box stack: largest drift", "stack", lambda a: a["drift"]),
                ("100:1: deepest overlap", "100:1", lambda a: a["overlap"])]
    _solver_points(ax, rows, measures, f"6b  Solvers: things at rest (0 drawn at {FLOOR:g} px)",
                   "error (px, log scale; lower is better)", FLOOR, name)


def plot(rows, path, subtitle, name=str):
    """Draw every study present in `rows` (a dict of study name -> list of Row) and save a PNG at `path`;
    name(engine) is a solver's name in study 6's legend (accuracy_cost.engine_name, the table's)."""
    fig = plt.figure(figsize=(18, 15.5))
    grid = fig.add_gridspec(3, 6)
    axes = [[fig.add_subplot(grid[r, 2 * c:2 * c + 2]) for c in range(3)] for r in range(2)]
    if "solvers" in rows:
        _solvers_bounce(fig.add_subplot(grid[2, 0:3]), rows["solvers"], name)
        _solvers_rest(fig.add_subplot(grid[2, 3:6]), rows["solvers"], name)
    _tunnelling_by_speed(axes[0][0], rows["tunnelling"])
    _tunnelling_cost(axes[0][1], rows["tunnelling"])
    _iterations(axes[0][2], rows["iterations"])
    _contact_rule(axes[1][0], rows["rule"])
    _effects(axes[1][1], rows["effects"])
    if "pymunk" in rows:
        _pymunk(axes[1][2], rows["pymunk"])
    else:
        axes[1][2].text(0.5, 0.5, "pymunk not installed:\nstudy 5 skipped", ha="center", va="center")
        axes[1][2].set_axis_off()
    fig.suptitle("What accuracy costs in time (lesson11 physics2d)", fontsize=15)
    fig.text(0.5, 0.957, subtitle, ha="center", fontsize=8, color="dimgray")
    fig.tight_layout(rect=(0, 0, 1, 0.955))
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path
