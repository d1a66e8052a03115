"""What lesson11/README.md says the Tumbling Crates window shows after each step is what it shows.

The starter with steps 2..N filled in from the solution (the rest left as handed out) runs the lab's own
scene (seed 11, four crates, no clicks) for 5 s, headless; the figures each step's description names are
read from the runtime's record. Measured (crates 1 and 2, dropped at x = 150 and 330, come down on the
ramp; crates 3 and 4 on the floor):
  steps 1-2   every crate below the window (y > 12000 px), 0 contacts at the end; at step 2 contacts are
              found while the crates sink through the floor, their normals pointing down into it
  step 3      all four in the window, contacts, no crate has turned (spin 0 all along), no fast mover;
              crate 1 goes on from x = 150 to about 215 and crate 2 from x = 330 to 403 after landing on the ramp
  step 4      the same, except that crate 2 stops where it lands (x = 330, moves 0.4 px after 1 s)
  step 5      crate 1 slides about 95 px further down the ramp than at step 4, crate 2 about 27 px, and
              both stop, still unturned
  step 6      every crate turned (spin up to 7.5 rad/s) and flat: crate 1 on the ramp at 22°, crate 2 slid
              off the ramp's low end, the others on the floor at 0°/90°
"""
import math
import os
import tempfile

import pytest

import corpus_tumbling_crates as corpus
from lab_run import run_lab

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SECONDS = 5
_runs = {}


def after_step(n):
    """The record and printed line of the starter with steps 2..n from the solution (cached per n)."""
    if n not in _runs:
        starter = open(os.path.join(ROOT, "starters", "tumbling_crates_starter.py"), encoding="utf-8").read()
        solution = open(os.path.join(ROOT, "solutions", "tumbling_crates.py"), encoding="utf-8").read()
        codes = corpus.step_code(solution)
        source = corpus.fill(starter, {step: code for step, code in codes.items() if step <= n})
        with tempfile.TemporaryDirectory() as work:
            path = os.path.join(work, "tumbling_crates.py")
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(source)
            run = run_lab(path, {"frames": SECONDS * 60, "fps": 60, "seed": 11, "record_every": 5}, work)
        frames = run.record["records"]
        crates = [[b for b in frame["bodies"] if not b["static"]] for frame in frames]
        _runs[n] = {"frames": frames, "crates": crates, "last": crates[-1], "printed": run.stdout.strip()}
    return _runs[n]


def flat(angle, surface=0.0):
    """How far (degrees) a crate's angle is from lying flat on a surface tilted `surface` degrees."""
    off = (math.degrees(angle) - surface) % 90
    return min(off, 90 - off)


def downward_normals(frames):
    """How many recorded contacts have a normal pointing down (y > 0.9), and how many there are."""
    touching = [c for frame in frames for c in frame["touching"]]
    return sum(1 for c in touching if c["normal"][1] > 0.9), len(touching)


@pytest.mark.parametrize("n", [1, 2])
def test_until_the_normal_is_flipped_every_crate_falls_through(n):
    run = after_step(n)
    assert all(crate["pos"][1] > 600 for crate in run["last"]) and run["frames"][-1]["contacts"] == 0
    # step 2's sat() finds the overlaps (contacts while the crates sink through), resolve() does nothing
    assert any(frame["contacts"] for frame in run["frames"]) == (n == 2)


def test_step_2_normals_point_into_the_floor():
    down, total = downward_normals(after_step(2)["frames"])
    assert total > 0 and down == total      # every contact: the floor's edge normal, pointing into the floor


def along_ramp(crate, start_x):
    """How far (px) a crate's end position is along the x axis from where it was dropped."""
    return crate["pos"][0] - start_x


def test_step_3_lands_every_crate_but_none_turns():
    run = after_step(3)
    assert all(crate["pos"][1] < 600 for crate in run["last"]) and run["frames"][-1]["contacts"] > 0
    assert max(abs(crate["omega"]) for frame in run["crates"] for crate in frame) == 0.0
    assert run["printed"].endswith("fast movers now: 0")
    assert 50 < along_ramp(run["last"][1], 330) < 90          # the second ramp crate hops about 70 px
    print(f"step 3: ramp crates go on {along_ramp(run['last'][0], 150):.0f} and {along_ramp(run['last'][1], 330):.0f} px")
    assert 50 < along_ramp(run["last"][0], 150) < 80          # the first about 65 px


def test_step_4_stops_the_second_ramp_crate_where_it_lands():
    three, four = after_step(3), after_step(4)
    assert max(abs(crate["omega"]) for frame in four["crates"] for crate in frame) == 0.0
    assert all(crate["pos"][1] < 600 for crate in four["last"])
    assert abs(along_ramp(four["last"][1], 330)) < 5          # no hop: it stops where it lands
    one_second = next(k for k, frame in enumerate(four["frames"]) if frame["frame"] >= 60)
    assert math.dist(four["crates"][one_second][1]["pos"], four["last"][1]["pos"]) < 2   # and stays there
    # the rest looks as before: the crates on the floor end where they did at step 3
    assert all(math.dist(a["pos"], b["pos"]) < 3 for a, b in zip(three["last"][2:], four["last"][2:]))


def test_step_5_lets_the_ramp_crates_slide_until_they_catch():
    four, five = after_step(4), after_step(5)
    first = math.dist(five["last"][0]["pos"], four["last"][0]["pos"])
    second = math.dist(five["last"][1]["pos"], four["last"][1]["pos"])
    assert 75 < first < 115 and 15 < second < 40            # measured about 97 and 27 px
    assert all(math.hypot(*crate["vel"]) < 2.0 for crate in five["last"][:2])   # and they have stopped
    assert max(abs(crate["omega"]) for frame in five["crates"] for crate in frame) == 0.0


def test_step_6_tips_every_crate_flat():
    run = after_step(6)
    assert max(abs(crate["omega"]) for frame in run["crates"] for crate in frame) > 1.0
    ramp, *floor = run["last"]
    assert flat(ramp["angle"], 22.0) < 2.0                    # flat on the 22° ramp
    assert all(flat(crate["angle"]) < 2.0 for crate in floor)  # flat on the floor
    assert floor[0]["pos"][1] > 520                            # the second ramp crate slid off onto the floor
    assert run["printed"].endswith("fast movers now: 0")


def pile_top_speed(presses):
    """The finished lab's 12-crate clicked pile with the panel's Up/Down pressed `presses` times at frame 12
    (negative: Down): the fastest crate during the last second of 8 s."""
    from lab_run import FPS, SOLUTION, pile_settings
    settings = pile_settings(settle_frames=8 * FPS - 250)
    key = "up" if presses > 0 else "down"
    settings["script"] = settings["script"] + [{"frame": 12, "type": "key", "key": key}] * abs(presses)
    settings["record_every"] = 5
    with tempfile.TemporaryDirectory() as work:
        run = run_lab(SOLUTION, settings, work)
    frames = run.record["records"]
    last = [f for f in frames if f["frame"] >= frames[-1]["frame"] - FPS]
    return max(math.hypot(*b["vel"]) for f in last for b in f["bodies"] if not b["static"])


def test_step_7_fewer_passes_leave_the_pile_restless_more_settle_it():
    """Step 7's panel experiment as a student does it: Down five times (1 iteration), none (6), Up 14 times (20)."""
    one, six, twenty = pile_top_speed(-5), pile_top_speed(0), pile_top_speed(14)
    assert one > six > twenty     # measured in the bench's pile: 8.6, 3.9 and 1.4 px/s
