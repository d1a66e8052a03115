"""Benchmark: CPU time of one World.step on the 12-crate pile, this tree against another (e.g. before a change).

    python tests/bench_pile_step.py --base DIR [--repeats 5] [--steps 300]

DIR is another checkout of the repository (e.g. `git worktree add /tmp/base main`, or
`git archive COMMIT lesson11 solutions checker | tar -x -C DIR`). Each run is a child
process that imports lesson11 and solutions/ from its tree, builds the Tumbling Crates
checker's pile scenario (checker/labs/tumbling_crates/scenes.pile_scenario: 12 crates of
60 × 40 px laid like bricks) with the lab solution's sat() and resolve(), and times
`steps` calls of world.step() (time.process_time) in two settings: the lab's default
(the lesson solver, solve-first, 4 sub-steps) and solver="accumulated". Runs of the two
trees alternate (base, this, base, this, ...), so a busy moment on a shared machine hits
both; the medians and their ratio (this / base) are printed, with the load average.
Not a test (its name does not start with test_): the figures depend on the machine.
Property access on Body (pos, vel, omega, inv_mass read thousands of times a step) is
what this watches.
"""
import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SETTINGS = {"lab default": {}, "accumulated": {"solver": "accumulated"}}


def child(root, steps):
    """In a child process: {setting: CPU s of `steps` steps} for the tree at `root`."""
    sys.path.insert(0, root)
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    import importlib.util

    from checker.labs.tumbling_crates.scenes import pile_scenario
    from lesson11 import runtime
    spec = importlib.util.spec_from_file_location("lab", os.path.join(root, "solutions", "tumbling_crates.py"))
    lab = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(lab)
    times = {}
    for name, settings in SETTINGS.items():
        runtime.configure({"scenario": pile_scenario()["scenario"]})
        world = lab.make_world(random.Random(11))
        runtime.reset()
        for key, value in settings.items():
            setattr(world, key, value)
        start = time.process_time()
        for _ in range(steps):
            world.step()
        times[name] = time.process_time() - start
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--base", required=True, help="the other tree (a checkout of the repository)")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--steps", type=int, default=300, help="1/120 s steps per run (300: 2.5 s)")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(child(args.child, args.steps)))
        return
    trees = {"base": os.path.abspath(args.base), "this": ROOT}
    runs = {tree: [] for tree in trees}
    print(f"load average at start: {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg") else "load: n/a")
    for _ in range(args.repeats):
        for tree, root in trees.items():
            out = subprocess.run([sys.executable, __file__, "--base", root, "--child", root, "--steps",
                                  str(args.steps)], capture_output=True, text=True, check=True).stdout
            runs[tree].append(json.loads(out.strip().splitlines()[-1]))
    for setting in SETTINGS:
        base = statistics.median(run[setting] for run in runs["base"]) / args.steps * 1000
        this = statistics.median(run[setting] for run in runs["this"]) / args.steps * 1000
        print(f"{setting:12s} base {base:7.3f} ms/step  this {this:7.3f} ms/step  ratio {this / base:.3f}")
    print(f"load average at end: {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg") else "")


if __name__ == "__main__":
    main()
