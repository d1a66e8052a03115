"""Which sub-steps × iterations can be the lab's default: the checker's scenes and bounds at each setting.

    python -m lesson11.bench.default_probe [4x6 2x6 ...]     # default: SETTINGS, 9 of them

For each setting, World's default sub-steps and iterations are swapped for the
run (solve-first, the lab's order) and the Tumbling Crates solution runs in
this process under the lab runtime, as the checker runs it, in:
  corner, ramp, bricks, own    the checker's four scenes (lesson11/crate_scenes.py)
  pile 12                      the lab's 12-crate clicked pile (lesson11/crate_scenes.pile_settings)
  pile 14                      the same with 14 clicks: a denser pile
Each figure is shown against its checker bound as value (bound/value, the
margin); a setting "holds with margin" when every margin is at least MARGIN.
CPU s is the time spent in World.step over the four checker scenes; ms/frame is
the physics CPU time per 60 fps frame (two 1/120 s steps) over the last 2 s of
each clicked pile, once it is all on the floor.
"""
import contextlib
import io
import os
import runpy
import sys
import tempfile
import time

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from lesson11 import crate_scenes as scenes  # noqa: E402  (the checker's scenes and bounds)
from lesson11 import records as metrics  # noqa: E402
from lesson11 import runtime  # noqa: E402
from lesson11.physics2d import World  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")

MARGIN = 1.5
DENSE_DROPS = scenes.pile_drops(14)
SETTINGS = ((1, 6), (2, 4), (1, 10), (1, 20), (2, 6), (2, 10), (3, 6), (4, 4), (4, 6))


class StepClock:
    """Wraps World.step to add up its CPU time (s) and count the calls, for the run in progress."""

    def __init__(self):
        self.seconds, self.steps, self.marks = 0.0, 0, []
        self.original = World.step

    def __enter__(self):
        clock = self

        def step(world, dt=None):
            start = time.process_time()
            try:
                return clock.original(world, dt)
            finally:
                clock.seconds += time.process_time() - start
                clock.steps += 1
                clock.marks.append(clock.seconds)
        World.step = step
        return self

    def __exit__(self, *exc):
        World.step = self.original


def run_lab(settings):
    """Run the solution under the lab runtime with `settings`; (its record, the StepClock of the run)."""
    with tempfile.TemporaryDirectory() as work, StepClock() as clock:
        runtime.configure(dict(settings, record=os.path.join(work, "record.json")))
        try:
            with contextlib.redirect_stdout(io.StringIO()):  # the lab's own "Simulated ... s" line
                runpy.run_path(SOLUTION, run_name="__main__")
        except SystemExit:
            pass
        record = {"records": list(runtime._records)}
        runtime.reset()
    return record, clock


def with_defaults(substeps, iterations):
    """Make (substeps, iterations) World's defaults; returns the old pair."""
    defaults = World.__init__.__kwdefaults__
    old = defaults["substeps"], defaults["iterations"]
    defaults["substeps"], defaults["iterations"] = substeps, iterations
    return old


def fmt(value, bound):
    """value (margin bound/value)."""
    margin = bound / value if value > 0 else float("inf")
    return f"{value:.2f} ({margin:.1f}×)", margin


def clicked_pile(drops):
    """(top speed in the last 1 s (px/s), physics ms per 60 fps frame over the last 2 s) of a clicked pile."""
    settings = scenes.pile_settings(settle_frames=240)
    settings["script"] = scenes.clicks(drops, 10, 20)
    settings["frames"] = settings["script"][-1]["frame"] + 240
    record, clock = run_lab(settings)
    tail = record["records"][-metrics.FPS:]
    top = max(metrics.speed(b) for f in tail for b in metrics.dynamic(f))
    last = 4 * metrics.FPS  # steps in the last 2 s
    per_frame = 2000 * (clock.marks[-1] - clock.marks[-last - 1]) / last
    return top, per_frame


def row(substeps, iterations):
    """One setting's figures: a dict of text cells and the smallest margin."""
    old = with_defaults(substeps, iterations)
    try:
        cpu, margins, cells = 0.0, [], {}
        corner, clock = run_lab(scenes.corner_scenario())
        cpu += clock.seconds
        crates = scenes.measure_corner(corner)
        cells["corner rest"], m = fmt(max(c["rest_speed"] for c in crates), scenes.REST_SPEED)
        margins.append(m)
        ramp, clock = run_lab(scenes.ramp_scenario())
        cpu += clock.seconds
        cells["ramp slide 3 s"], m = fmt(max(abs(c["slid"]) for c in metrics.measure_ramp(ramp)), scenes.RAMP_SLIDE)
        margins.append(m)
        cells["ramp speed"], m = fmt(metrics.summary(ramp)["tail_speed"], scenes.RAMP_SPEED)
        margins.append(m)
        bricks, clock = run_lab(scenes.pile_scenario())
        cpu += clock.seconds
        pile = metrics.measure_pile(bricks)
        for name, key, bound in (("bricks speed", "tail_speed", scenes.PILE_SPEED),
                                 ("bricks drift", "drift", scenes.PILE_DRIFT),
                                 ("bricks floor", "floor_penetration", scenes.PENETRATION),
                                 ("bricks overlap", "pair_overlap", scenes.PAIR_OVERLAP)):
            cells[name], m = fmt(pile[key], bound)
            margins.append(m)
        own, clock = run_lab(scenes.own_scene_scenario())
        cpu += clock.seconds
        cells["own scene speed"], m = fmt(metrics.summary(own)["tail_speed"], metrics.FAST_MOVER)
        margins.append(m)
        cells["CPU s (4 scenes)"] = f"{cpu:.1f}"
        for count, drops in ((12, DENSE_DROPS[:12]), (14, DENSE_DROPS)):
            top, per_frame = clicked_pile(drops)
            cells[f"pile {count}: top speed"] = f"{top:.1f} px/s"
            cells[f"pile {count}: ms/frame"] = f"{per_frame:.1f}"
        return cells, min(margins)
    finally:
        with_defaults(*old)


def main(argv=None):
    cells = []
    for text in (sys.argv[1:] if argv is None else argv):
        try:
            substeps, iterations = (int(v) for v in text.split("x"))
            if substeps < 1 or iterations < 1:
                raise ValueError
        except ValueError:
            print(f"default_probe: {text!r} is not a setting: give SUBSTEPSxITERATIONS, e.g. 4x6", file=sys.stderr)
            return 2
        cells.append((substeps, iterations))
    cells = cells or SETTINGS
    rows = []
    for substeps, iterations in cells:
        figures, margin = row(substeps, iterations)
        verdict = "holds with margin" if margin >= MARGIN else f"smallest margin {margin:.1f}×"
        rows.append((f"{substeps} × {iterations}", figures, verdict))
        print(f"{substeps} × {iterations}: {figures} {verdict}", file=sys.stderr, flush=True)
    heads = list(rows[0][1])
    print("| setting | " + " | ".join(heads) + " | checker bounds |")
    print("|---|" + "---:|" * len(heads) + "---|")
    for name, figures, verdict in rows:
        print(f"| {name} | " + " | ".join(figures[h] for h in heads) + f" | {verdict} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
