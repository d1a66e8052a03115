"""Where a frame of the Tumbling Crates lab goes: the lab's own step functions against everything else.

    python -m lesson11.bench.frame_share           # 12, 40 and 200 crates; 10-20 minutes on 2 cores
                                                   # (clicking and settling the 200-crate pile takes most)
    python -m lesson11.bench.frame_share --quick   # smoke run (12 and 40 crates, a few frames): not a measurement
    python -m lesson11.bench.frame_share --sizes 12 200   # a per-size run: only those piles, the same figures

The pile is the lab's clicked pile: the finished lab (solutions/tumbling_crates.py,
loaded by energy.lab()) with its own scene, make_crate, sat and resolve, seed 11,
its crates clicked in over the floor right of the ramp (energy.PILE_DROPS for 12;
the same grid with more columns, and the floor and wall moved out to hold them, for
40 and 200), a wave of clicks every 20 frames, then SETTLE_FRAMES frames of settling.
That pile is copied (copy.deepcopy) and each copy runs `frames` 60 fps frames of
two 1/120 s steps with World's default setting (4 sub-steps × 6 passes) and with
the lesson listing's 1 × 6 (World(substeps=1, iterations=6), solve-first). Each
is measured twice in the same turns: with physics2d's fast paths (as the lab runs)
and with the readable reference forms they replace (collision.fast_paths(False):
the same numbers, bit for bit, tests/test_fast_paths.py), so the table shows what
the fast paths buy, side by side. (The broad phase is sweep and prune in both: with
the fast paths on, the lesson solver's search runs broadphase.sweep_boxes, the sweep
written out for boxes without margins; the reference forms run broadphase.sweep_and_prune.
tests/test_broadphase.py holds the two, and broad_phase="all-pairs", to the same pairs.)

Definitions (per frame, in ms):
  frame    the CPU time (time.process_time) of the two World.step calls, measured on
           a copy whose hooks are not wrapped: the time the lab really takes
  lab      the time inside the lab's own functions the World calls (its hooks that are
           not the library's, lesson11/hook_clock.lab_hooks: sat and resolve), inclusive: with
           everything they call, i.e. apply_impulse, and the library's project,
           edge_normals, center_of (centre_of), spin_velocity and cross (the issue's grouping:
           the student's code and the helpers it chooses to call)
  engine   the rest of the frame: broad phase, world points, contact points,
           collide and search glue, the resolve-pass loop, the push-out, integration
  share    engine / (lab + engine)
The split is measured on a second copy whose hooks are wrapped in a timer
(CLOCK = time.process_time, CPU time, read before and after each call; on a shared
machine the wall clock also counts the waits for a core). The two copies run the
same steps of the same pile, frame by frame in turn, so the wrappers' own cost per
call is measured in the run itself: (wrapped frame - plain frame) / calls (the
"timer" column, about 2 µs: two reads of the CPU clock, each a system call). The
part of it the wrappers count inside the calls is removed from the lab's time, in
the proportion a calibration loop finds (a wrapped no-op against a
bare one, median of 5, hook_clock.calibrate; printed first), and engine = plain frame - lab.

In the same run, on the same pile: the lesson listing's own solver
(lesson11/bench/listing.py: move first, all pairs, 6 passes, one step per 1/120 s)
and pymunk (if installed), as "× the lab": their CPU ms per frame ÷ the lab's
frame at the default setting.
"""
import argparse
import copy
import math
import sys
import time

from lesson11 import hook_clock
from lesson11.physics2d import Body, box_points, collision

from . import energy, harness, speed

SIZES = (12, 40, 200)
SETTINGS = {"default 4 × 6": {}, "listing's 1 × 6": {"substeps": 1, "iterations": 6}}
SETTLE_FRAMES = 240        # frames of settling after the last click (lesson11/crate_scenes.pile_settings)
FRAMES = {12: 60, 40: 30, 200: 8}   # timed 60 fps frames per setting
QUICK_FRAMES = {12: 3, 40: 2}
WAVES = 12                 # the clicks come in 12 waves, 20 frames apart (12 crates: one click a wave)
STEPS_PER_FRAME = energy.STEPS_PER_FRAME
FORMS = ("fast", "reference")  # collision.fast_paths(True) and (False)
CLOCK = time.process_time  # CPU s: on a shared machine the wall clock also counts waiting for a core


# ---------------------------------------------------------------- the clicked pile

def drops(count):
    """Where the `count` clicks land (px): energy.PILE_DROPS's grid, 70 px columns from x = 590, three rows deep."""
    columns = max(4, math.ceil(count / 3))
    return [(590 + 70 * (k % columns), 150 + 50 * (k // columns)) for k in range(count)]


def clicked_pile(count, settle_frames=SETTLE_FRAMES):
    """The lab's world after `count` clicked crates and `settle_frames` frames of settling (default setting).

    Click k comes at frame 10 + 20 * (k * WAVES // count) (12 crates: one every
    20 frames, as in the lab's pile). Past 4 columns the floor is widened to the
    right (same top face) and the wall moved to its end, so every crate lands on it.
    """
    world, rng = energy.lab_world({}, crates=False)
    points = drops(count)
    right = max(x for x, _ in points) + 90
    if right > energy.WINDOW[2]:
        floor, _, wall = world.bodies
        world.bodies[0] = Body(box_points(right, 40), (right / 2, floor.pos.y), 0, color=floor.color)
        wall.pos.x = right + 10
    clicks = {}
    for k, pos in enumerate(points):
        step = (10 + 20 * (k * WAVES // count)) * STEPS_PER_FRAME
        clicks.setdefault(step, []).append(energy.lab().make_crate(rng, pos))
    last = max(clicks)
    for index in range(last + 1 + settle_frames * STEPS_PER_FRAME):
        for body in clicks.get(index, ()):
            world.add(body)
        world.step()
    return world


# ---------------------------------------------------------------- timing the lab's hooks

def measure(pile, setting, frames, overhead):
    """One setting on copies of the pile, with the fast paths and with the readable reference forms:
    {"fast": figures, "reference": figures}, each {"frame", "lab", "engine"} ms per frame, "timer" µs per call
    and "calls" a frame."""
    copies = {}
    for form in FORMS:
        copies[form] = plain, timed = copy.deepcopy(pile), copy.deepcopy(pile)
        for world in (plain, timed):
            for name, value in setting.items():
                setattr(world, name, value)
    tallies = {form: [0.0, 0] for form in FORMS}
    for form, (_, timed) in copies.items():
        for name, function in hook_clock.lab_hooks(timed).items():
            setattr(timed, name, hook_clock.wrap(function, tallies[form], CLOCK))
    spent = {(form, kind): 0.0 for form in FORMS for kind in (0, 1)}
    for _ in range(frames):  # the copies take turns, frame by frame: the machine's load hits all alike
        for form, worlds in copies.items():
            with collision.fast_paths(form == "fast"):
                for kind, world in enumerate(worlds):
                    start = CLOCK()
                    for _ in range(STEPS_PER_FRAME):
                        world.step()
                    spent[form, kind] += CLOCK() - start
    figures = {}
    for form, (total, calls) in tallies.items():
        cpu, wrapped = spent[form, 0], spent[form, 1]
        added = (wrapped - cpu) / calls if calls else 0.0   # the wrappers' cost per call, in this run
        inside = added * overhead[1] / overhead[0]          # the part of it counted inside the calls
        lab = total - calls * inside
        figures[form] = {"frame": 1000 * cpu / frames, "lab": 1000 * lab / frames,
                         "engine": 1000 * (cpu - lab) / frames, "timer": 1e6 * added, "calls": calls / frames}
    return figures


def other_engine(make, pile, frames):
    """CPU ms per 60 fps frame of another engine (listing or pymunk) built from the pile's snapshot."""
    engine = make([speed.record(body) for body in pile.bodies])
    start = time.process_time()
    for _ in range(frames * STEPS_PER_FRAME):
        engine.step()
    return 1000 * (time.process_time() - start) / frames


# ---------------------------------------------------------------- the run

def run(sizes, frames, settle_frames, say=print):
    """Every size and setting: a list of table rows (dicts)."""
    overhead = hook_clock.calibrate(CLOCK)
    say(f"calibration: a wrapped call costs {1e9 * overhead[0]:.0f} ns, of which {1e9 * overhead[1]:.0f} ns "
        f"({100 * overhead[1] / overhead[0]:.0f} %) is counted inside the call")
    rows = []
    for count in sizes:
        started = time.perf_counter()
        pile = clicked_pile(count, settle_frames)
        say(f"{count} crates clicked and settled in {time.perf_counter() - started:.0f} s; "
            f"timing {frames[count]} frames")
        others = {"listing": other_engine(speed.ListingEngine, pile, frames[count])}
        others["pymunk"] = other_engine(speed.PymunkEngine, pile, frames[count]) if speed.pymunk_available() else None
        for label, setting in SETTINGS.items():
            figures = measure(pile, setting, frames[count], overhead)
            rows.append(dict(figures["fast"], crates=count, setting=label, reference=figures["reference"]))
        default = rows[-len(SETTINGS)]["frame"]
        for name, ms in others.items():
            rows[-len(SETTINGS)][name] = None if ms is None else ms / default
    return rows


def share(figures):
    """The engine's share of the frame, engine / (lab + engine)."""
    return figures["engine"] / (figures["lab"] + figures["engine"])


def table(rows):
    """The rows as a Markdown table."""
    lines = ["| crates | setting | frame ms (CPU) | lab's functions ms | engine ms | engine share | "
             "reference forms: frame ms, engine share | timer µs/call | lab calls/frame | listing × the lab | "
             "pymunk × the lab |", "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for row in rows:
        listing = f"{row['listing']:.2f}" if row.get("listing") is not None else ""
        pymunk = ("not installed" if "pymunk" in row and row["pymunk"] is None
                  else f"{row['pymunk']:.4f}" if row.get("pymunk") is not None else "")
        reference = row["reference"]
        lines.append(f"| {row['crates']} | {row['setting']} | {row['frame']:.2f} | {row['lab']:.2f} | "
                     f"{row['engine']:.2f} | {100 * share(row):.1f} % | {reference['frame']:.2f}, "
                     f"{100 * share(reference):.1f} % | {row['timer']:.2f} | {row['calls']:.0f} | {listing} | "
                     f"{pymunk} |")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="smoke run: 12 and 40 crates, a few frames (not a measurement)")
    parser.add_argument("--sizes", type=int, nargs="+", choices=SIZES, metavar="CRATES",
                        help=f"only these pile sizes (of {', '.join(map(str, SIZES))}; a per-size run)")
    args = parser.parse_args(argv)
    sizes, frames, settle = ((12, 40), QUICK_FRAMES, 20) if args.quick else (SIZES, FRAMES, SETTLE_FRAMES)
    sizes = tuple(args.sizes) if args.sizes else sizes
    command = " ".join(["python -m lesson11.bench.frame_share"] + (argv if argv is not None else sys.argv[1:]))
    print(f"{command} · {harness.machine_note()}")
    print(table(run(sizes, frames, settle)))
    if args.quick:
        print("Smoke run: these figures only show that the benchmark runs; they are not measurements.")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
