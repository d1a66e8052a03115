"""What sleeping saves: one 40-crate pile stepped awake and asleep (Sleeping Crates' benchmark note).

    python -m lesson11.bench.sleeping_pile [--steps N]

The pile is checker/labs/sleeping_crates/probes.py's grid: 4 rows of 10 crates (50 × 36 px),
each row resting on the one below with 0.2 px of overlap, on the floor, with the
"sleep" effect and the library's sleep rules (the same as the lab's solution).
It prints, per step, CPU ms (time.process_time, mean of N steps, after one
warm-up step) and World.counters' pair and narrow-phase tests, awake and asleep.
"""
import argparse
import time

from lesson11.physics2d import LESSON_EFFECTS, Body, World, box_points

W, H, FLOOR_TOP = 50, 36, 560.0


def pile_world(asleep):
    crates = []
    for k in range(40):
        row, column = divmod(k, 10)
        crates.append(Body(box_points(W, H), (160 + column * W + (row % 2) * 10,
                                              FLOOR_TOP - H / 2 + 0.2 - row * (H - 0.2)), W * H / 1000))
    world = World([Body(box_points(900, 40), (450, FLOOR_TOP + 20), 0)] + crates, effects=LESSON_EFFECTS | {"sleep"})
    if asleep:
        world.fall_asleep(crates)
    return world


def measure(asleep, steps):
    world = pile_world(asleep)
    world.step()
    before = dict(world.counters)
    start = time.process_time()
    for _ in range(steps):
        world.step()
    ms = (time.process_time() - start) * 1000 / steps
    tests = {key: (world.counters[key] - before[key]) / steps for key in ("pair_tests", "narrow_tests")}
    return ms, tests


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=20)
    args = parser.parse_args(argv)
    awake, awake_tests = measure(False, args.steps)
    asleep, asleep_tests = measure(True, args.steps)
    print(f"40 crates awake:  {awake:8.2f} ms/step  pairs {awake_tests['pair_tests']:.0f}  "
          f"narrow {awake_tests['narrow_tests']:.0f}")
    print(f"40 crates asleep: {asleep:8.2f} ms/step  pairs {asleep_tests['pair_tests']:.0f}  "
          f"narrow {asleep_tests['narrow_tests']:.0f}")
    print(f"time ratio awake / asleep: {awake / max(asleep, 1e-9):.0f}x")


if __name__ == "__main__":
    main()
