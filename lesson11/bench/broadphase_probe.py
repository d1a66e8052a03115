"""How a step's cost grows with the number of crates: sweep-and-prune against the all-pairs reference.

    python -m lesson11.bench.broadphase_probe [--steps N] [--sizes 14,100,300,1000]

A probe, not a test. Each scene is N crates (40 × 30 px, mass 1) in two layers
on a static floor as wide as the row (so the pile's depth stays the same as N
grows), stepped with both solvers (solver="lesson", the lab's default, and
"accumulated") and both broad phases (World.broad_phase "all-pairs", the
reference, and "sweep-and-prune"). Before timing, the scene is stepped 3 times
(the crates settle onto each other). It prints, per row, CPU µs per body-step
(time.process_time over N steps / (steps × N)), its growth against N = 14 with
the same solver and broad phase, and the share of a step spent in the broad phase
(cProfile: the broad-phase function's own time and its callees', over the step's),
World.counters' pair tests per step and narrow-phase tests per body-step (the
contacts a body has: what the narrow phase and the solver pay for).
Timings are noisy on a shared machine: compare ratios from one run.
"""
import argparse
import cProfile
import pstats
import time

from lesson11.physics2d import Body, World, box_points

W, H = 40.0, 30.0        # px, a crate
FLOOR_TOP = 600.0        # px


def wide_pile(count, solver, broad_phase):
    """`count` crates in 2 layers (staggered by half a crate) on a floor as wide as the row."""
    per_row = (count + 1) // 2
    gap = 4.0            # px between crates in a row
    width = per_row * (W + gap) + 2 * W
    crates = []
    for k in range(count):
        layer, column = divmod(k, per_row)
        x = W + column * (W + gap) + layer * (W + gap) / 2
        y = FLOOR_TOP - H / 2 - layer * H + 0.1
        crates.append(Body(box_points(W, H), (x, y), 1.0))
    floor = Body(box_points(width, 40), (width / 2, FLOOR_TOP + 20), 0)
    return World([floor] + crates, solver=solver, broad_phase=broad_phase)


def micros_per_body_step(world, steps):
    """CPU µs per body per step over `steps` steps."""
    start = time.process_time()
    for _ in range(steps):
        world.step()
    return (time.process_time() - start) / steps / len(world.bodies) * 1e6


def broad_share(world, steps):
    """Share (0..1) of the steps' time spent inside the broad-phase function (cumulative, by cProfile)."""
    profile = cProfile.Profile()
    profile.enable()
    for _ in range(steps):
        world.step()
    profile.disable()
    stats = pstats.Stats(profile).stats
    total = sum(tt for (_, _, _), (_, _, tt, _, _) in stats.items())
    broad = sum(ct for (file, _, name), (_, _, _, ct, _) in stats.items()
                if file.endswith("broadphase.py") and name in ("all_pairs", "sweep_and_prune"))
    return broad / total if total else 0.0


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=3, help="timed steps per scene (default 3)")
    parser.add_argument("--sizes", default="14,100,300,1000", help="crate counts, comma-separated")
    args = parser.parse_args(argv)
    sizes = [int(n) for n in args.sizes.split(",")]
    print(f"{'solver':12} {'broad phase':16} {'crates':>6} {'µs/body-step':>13} {'× N=' + str(sizes[0]):>8} "
          f"{'broad share':>11} {'pair tests/step':>15} {'narrow/body':>11}")
    for solver in ("lesson", "accumulated"):
        for broad_phase in ("all-pairs", "sweep-and-prune"):
            first = None
            for count in sizes:
                world = wide_pile(count, solver, broad_phase)
                for _ in range(3):
                    world.step()
                before = dict(world.counters)
                cost = micros_per_body_step(world, args.steps)
                tests = (world.counters["pair_tests"] - before["pair_tests"]) / args.steps
                narrow = (world.counters["narrow_tests"] - before["narrow_tests"]) / args.steps / len(world.bodies)
                share = broad_share(world, 1)
                first = first or cost
                print(f"{solver:12} {broad_phase:16} {count:6d} {cost:13.1f} {cost / first:8.2f} "
                      f"{share:11.1%} {tests:15.0f} {narrow:11.2f}", flush=True)


if __name__ == "__main__":
    main()
