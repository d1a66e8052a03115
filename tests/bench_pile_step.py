"""Benchmark: CPU time of one World.step on the 12-crate pile, this tree against another (e.g. before a change).

    python tests/bench_pile_step.py --base DIR [--repeats 5] [--steps 300]
    python tests/bench_pile_step.py --plain [--repeats 5] [--steps 300]

DIR is another checkout of the repository (e.g. `git worktree add /tmp/base main`, or
`git archive COMMIT lesson11 solutions checker | tar -x -C DIR`). Each run is a child
process that imports lesson11 and solutions/ from its tree, builds the Tumbling Crates
checker's pile scenario (checker/labs/tumbling_crates/scenes.pile_scenario: 12 crates of
60 × 40 px laid like bricks) with the lab solution's sat() and resolve(), and times
`steps` calls of world.step() (time.process_time) in two settings: the lab's default
(the lesson solver, solve-first, 4 sub-steps) and solver="accumulated". Runs of the two
trees alternate (base, this, base, this, ...), so a busy moment on a shared machine hits
both; the medians and their ratio (this / base) are printed, with the load average.
--plain compares this tree with itself, its bodies switched to a copy of the Body class
without its checked settings (physics2d.settings.Setting): plain attributes, the cost of
the checks alone.
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


def plain_class():
    """A copy of this tree's Body without its Settings: every field a plain attribute."""
    from lesson11.physics2d import Body
    from lesson11.physics2d.settings import Setting
    return type("Body", (), {name: value for name, value in vars(Body).items()
                             if not isinstance(value, Setting) and name not in ("__dict__", "__weakref__")})


def child(root, steps, plain=False):
    """In a child process: {setting: CPU s of `steps` steps} for the tree at `root` (plain: bodies unchecked)."""
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
        if plain:
            cls = plain_class()
            for body in world.bodies:
                body.__class__ = cls
        start = time.process_time()
        for _ in range(steps):
            world.step()
        times[name] = time.process_time() - start
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--base", help="the other tree (a checkout of the repository)")
    parser.add_argument("--plain", action="store_true", help="compare with this tree's bodies unchecked")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--steps", type=int, default=300, help="1/120 s steps per run (300: 2.5 s)")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(child(args.child, args.steps, args.plain)))
        return
    if (args.base is None) == (not args.plain):
        parser.error("give --base DIR or --plain")
    other = "base" if args.base else "plain"
    trees = {other: (os.path.abspath(args.base), []) if args.base else (ROOT, ["--plain"]), "this": (ROOT, [])}
    runs = {tree: [] for tree in trees}
    print(f"load average at start: {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg") else "load: n/a")
    for _ in range(args.repeats):
        for tree, (root, extra) in trees.items():
            out = subprocess.run([sys.executable, __file__, "--child", root, "--steps", str(args.steps)] + extra,
                                 capture_output=True, text=True, check=True).stdout
            runs[tree].append(json.loads(out.strip().splitlines()[-1]))
    for setting in SETTINGS:
        base = statistics.median(run[setting] for run in runs[other]) / args.steps * 1000
        this = statistics.median(run[setting] for run in runs["this"]) / args.steps * 1000
        print(f"{setting:12s} {other} {base:7.3f} ms/step  this {this:7.3f} ms/step  ratio {this / base:.3f}")
    print(f"load average at end: {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg") else "")


if __name__ == "__main__":
    main()
