"""Issue 10 §1 rows for the lesson solver, move-first against solve-first (a probe, not a test).

    python -m lesson11.bench.section1_probe [move-first|solve-first ...]

Rows (units px, s; targets from issue 10 §1):
  ramp     the checker's ramp scene (lesson11/crate_scenes.ramp_scenario, 3 crates, 3 s, run
           through solutions/tumbling_crates.py as the checker runs it): largest slide (px), target <= 1
  pile     the lab's 12-crate pile (crate_scenes.pile_settings: a dozen clicks, 4 s of settling):
           top speed over the last second (px/s), target < 5; deepest corner below the floor over
           the last 2 s and over the whole run (px), targets <= 1 and < 2 (test_lab_criteria)
  bricks   the checker's brick pile (pile_scenario, 2.5 s): top speed, drift over the last second, deepest corner
  own      the lab's own scene with the checker's four clicks: top speed over the last second
  e=1      a disc (r 10 px) dropped from 200 px on the floor, e = 1 (solver_probe.disc_bounce, as
           tests/test_stability_dynamics.py's bounce_figures): energy at each apex / at the start, worst of the first five (target within 1 %)
  e=0.5    the same disc with e = 0.5: first rebound speed / impact speed (target 0.5 ± 0.02)
  flat     solver_probe.flat_bounce: a 40 px box dropped flat, e = 0.5, rebound / impact (no target:
           the lesson solver's two corners share the bounce one after the other)
  stack    solver_probe.stack: 10 boxes, largest drift in 20 s (px), "no worse than today"
Prints one line per order. The lab runs in this process: lesson11.runtime in checker mode, the solution run as __main__,
World's default order swapped for the run.
"""
import math
import os
import runpy
import sys
import tempfile

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from lesson11 import crate_scenes as scenes  # noqa: E402  (the checker's scenes)
from lesson11 import records as metrics  # noqa: E402
from lesson11 import runtime  # noqa: E402
from lesson11.bench import solver_probe as probe  # noqa: E402
from lesson11.physics2d import World  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")


def with_order(order):
    """Make `order` World's default (returns the old one)."""
    old = World.__init__.__kwdefaults__["order"]
    World.__init__.__kwdefaults__["order"] = order
    return old


def run_lab(settings):
    """Run the solution in checker mode with `settings`; its record (dict with "records")."""
    with tempfile.TemporaryDirectory() as work:
        runtime.configure(dict(settings, record=os.path.join(work, "record.json")))
        try:
            runpy.run_path(SOLUTION, run_name="__main__")
        except SystemExit:
            pass
        record = {"records": list(runtime._records)}
        runtime.reset()
    return record


def lab_rows():
    ramp = run_lab(scenes.ramp_scenario())
    slid = max(abs(c["slid"]) for c in metrics.measure_ramp(ramp))
    ramp_tail = metrics.summary(ramp)["tail_speed"]
    pile = run_lab(scenes.pile_settings(settle_frames=240))
    frames = pile["records"]
    tail = frames[-metrics.FPS:]
    top = max(metrics.speed(b) for f in tail for b in metrics.dynamic(f))
    deep_end = max(metrics.floor_penetration(b) for f in frames[-2 * metrics.FPS:] for b in metrics.dynamic(f))
    deep_all = max(metrics.floor_penetration(b) for f in frames for b in metrics.dynamic(f))
    moves = [math.dist(a["pos"], b["pos"]) for a, b in zip(metrics.dynamic(tail[0]), metrics.dynamic(tail[-1]))]
    overlap = max(metrics.max_pair_overlap(metrics.dynamic(f)) for f in tail[::10] + [tail[-1]])
    bricks = metrics.measure_pile(run_lab(scenes.pile_scenario()))
    own = metrics.summary(run_lab(scenes.own_scene_scenario()))
    return (f"ramp slide {slid:.2f} px (tail {ramp_tail:.2f} px/s) | pile top {top:.2f} px/s, corner last 2 s "
            f"{deep_end:.2f} px, all {deep_all:.2f} px, move max {max(moves):.2f} px, overlap {overlap:.2f} px | "
            f"bricks {bricks['tail_speed']:.2f} px/s drift {bricks['drift']:.2f} px corner "
            f"{bricks['floor_penetration']:.2f} px overlap {bricks['pair_overlap']:.2f} | own tail {own['tail_speed']:.2f} px/s")


def bounce_figures(restitution, order, height=200.0):
    """A 10 px disc dropped `height` px on the floor for 6 s, World in `order`: (apex energies / start, rebound ratios).

    solver_probe.disc_bounce measures it (the same scene for every engine).
    """
    return probe.disc_bounce("lesson " + order, restitution, height)


def main():
    orders = sys.argv[1:] or ["move-first", "solve-first"]
    for order in orders:
        old = with_order(order)
        try:
            engine = "lesson " + order
            apexes = bounce_figures(1.0, order)[0][:5]
            worst = max(apexes, key=lambda ratio: abs(ratio - 1))
            print(f"{order}: {lab_rows()} | e=1 apex energy worst {worst:.4f} ({len(apexes)} apexes) | "
                  f"e=0.5 rebound {bounce_figures(0.5, order)[1][0]:.3f} | "
                  f"flat e=0.5 {probe.flat_bounce(engine, 0.5)[0]:.3f} | stack {probe.stack(engine):.2f} px", flush=True)
        finally:
            with_order(old)


if __name__ == "__main__":
    main()
