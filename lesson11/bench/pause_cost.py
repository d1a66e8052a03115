"""What the pause on a student's error (lesson11/breakdown.py) costs a lab frame while nothing breaks.

    python -m lesson11.bench.pause_cost            # the 12-crate pile, 600 frames each way, 3 rounds
    python -m lesson11.bench.pause_cost --quick    # smoke run (60 frames, 1 round): not a measurement

The one cost is the copy of the World and its bodies the solver panel keeps before each frame
(breakdown.Snapshot), so that after an error it can run that frame again and name the function that
left a bad value; the `try` around world.advance costs nothing in Python 3.11 while nothing is raised,
and the World's step is unchanged. The scene is the Tumbling Crates lab's clicked pile (energy.scene
"pile": the solution's sat and resolve, 12 crates clicked in, seed 11), advanced 60 fps frames of two
1/120 s steps by a LabPanel. Two copies of the same pile run the same frames in turn, one by a panel
that keeps the copy (a student's run, `guard` on) and one by a panel that does not (the checker's run,
`guard` off: the frame as it was before the pause existed), each frame timed with time.process_time.
Printed: the CPU ms per frame of each, their ratio, and the copy's own cost in µs per frame.
"""
import argparse
import copy
import time

from lesson11 import breakdown
from lesson11.bench import energy
from lesson11.panel import LabPanel

FRAME = 1 / 60           # s: the labs' frame
SETTLE_FRAMES = 10 + 20 * len(energy.PILE_DROPS)   # frames until the last crate is clicked in


def pile():
    """The Tumbling Crates pile after its crates are clicked in (energy.scene "pile")."""
    world, clicks = energy.scene("pile", {})
    steps = 0
    for _ in range(SETTLE_FRAMES + 30):
        for _ in range(2):
            for body in clicks.get(steps, []):
                world.add(body)
            world.step()
            steps += 1
    return world


def measure(frames, rounds):
    """{"guarded": ms/frame, "bare": ms/frame, "copy_us": µs per Snapshot} over `rounds` rounds of `frames`."""
    start = pile()
    totals = {"guarded": 0.0, "bare": 0.0}
    for _ in range(rounds):
        worlds = {name: copy.deepcopy(start) for name in totals}
        panels = {name: LabPanel() for name in totals}
        panels["guarded"].guard, panels["bare"].guard = True, False
        for _ in range(frames):
            for name in totals:   # the two in turn, frame by frame: the same load on both
                begin = time.process_time()
                panels[name].advance(worlds[name], FRAME)
                totals[name] += time.process_time() - begin
    count = frames * rounds
    begin = time.process_time()
    for _ in range(count):
        breakdown.Snapshot(start)
    copy_us = (time.process_time() - begin) / count * 1e6
    return {"guarded": 1000 * totals["guarded"] / count, "bare": 1000 * totals["bare"] / count, "copy_us": copy_us,
            "bodies": len(start.bodies)}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a smoke run, not a measurement")
    parser.add_argument("--frames", type=int, default=600)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args(argv)
    frames, rounds = (60, 1) if args.quick else (args.frames, args.rounds)
    m = measure(frames, rounds)
    print(f"Tumbling Crates pile, {m['bodies']} bodies, {frames} frames × {rounds} rounds (CPU time):")
    print(f"  frame with the pause's copy (a student's run)  {m['guarded']:.3f} ms")
    print(f"  frame without it (as before; the checker's)    {m['bare']:.3f} ms")
    print(f"  ratio {m['guarded'] / m['bare']:.3f}; the copy alone {m['copy_us']:.1f} µs per frame")


if __name__ == "__main__":
    main()
