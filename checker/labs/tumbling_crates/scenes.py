"""The Tumbling Crates scenarios: what the checker drops where, and the one crate-only measurement.

Scene geometry (from the lab, shared by every lab: checker/records.py): the
floor's top face is at y = 560 px, the ramp is a 420 × 24 px static box
centred at (230, 380) turned 22° (its right end lower), the wall sits just
off the right edge. y grows downward; a positive angle turns clockwise on screen.

Each scenario is a settings dict for lesson11.runtime.configure(); the
runtime replaces the lab's crates with the scenario's and records every
body's state each frame. checker/records.py's metrics (measure_ramp,
measure_pile, summary, ...) and measure_corner here turn a record into numbers
(px, px/s, rad); checker/labs/tumbling_crates/checks.py compares them with the bounds.
"""
import math

from pygame import Vector2

from ...records import (FLOOR_TOP, FPS, RAMP_ANGLE, RAMP_CENTRE, RAMP_THICKNESS, SEED, dynamic, flat_error,
                      floor_penetration, speed)



def _ramp_crate(along, w, h):
    """A w × h crate resting on the ramp's top face, `along` px from the ramp's centre along its slope."""
    slope = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))
    up = Vector2(math.sin(RAMP_ANGLE), -math.cos(RAMP_ANGLE))  # the ramp's top face normal
    pos = RAMP_CENTRE + slope * along + up * (RAMP_THICKNESS / 2 + h / 2 + 0.25)
    return {"w": w, "h": h, "pos": [pos.x, pos.y], "angle": RAMP_ANGLE}


def corner_scenario():
    """Two crates dropped from 100 px onto the floor, each turned so it lands on one corner (2.5 s)."""
    return {"frames": 150, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": [
        {"w": 70, "h": 40, "pos": [560, 440], "angle": 0.55},
        {"w": 60, "h": 44, "pos": [760, 440], "angle": -0.5},
    ]}


def ramp_scenario():
    """Three crates set at rest on the 22° ramp, lined up with its slope (3 s)."""
    return {"frames": 180, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": [
        _ramp_crate(-120, 60, 40), _ramp_crate(-10, 50, 50), _ramp_crate(100, 70, 36)]}


def pile_scenario():
    """A dozen 60 × 40 crates laid like bricks (rows of 4, 3, 3, 2) with 2 px gaps, on the floor (2.5 s).

    The crates land within 0.1 s; the checks read the last second. The solution
    (and every correct entry of the corpus, bit for bit) measures the same at
    2.5, 3 and 3.5 s: top speed 4.7, 4.0, 4.5 px/s, drift 0.3 px, deepest 0.6 px.
    The pile without its push-out sinks further the longer it runs: at 2.5 s
    1.5 px below the floor (bound 1) and 2.8 px into each other (bound 2); at
    3.5 s, what this scene was, 2.1 and 3.8 px, for 40 % more CPU time.
    """
    crates = []
    rows = ((4, 0.0), (3, 31.0), (3, 31.0), (2, 62.0))  # (crates in the row, shift right in px)
    y = FLOOR_TOP - 20 - 2
    for count, shift in rows:
        for k in range(count):
            crates.append({"w": 60, "h": 40, "pos": [520 + shift + 62 * k, y], "angle": 0.0})
        y -= 42
    return {"frames": 150, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": crates}


DROPS = ((30, (180, 120)), (50, (620, 120)), (70, (720, 60)), (90, (300, 60)))
# 3 s after the last drop ("a few seconds", as the lesson says): the solution and every correct entry of
# the corpus have their last crate faster than 30 px/s 93 frames (1.55 s) after the last drop, and
# 1.3 px/s or less from 2.5 s on (4 s, which this was, measured the same and cost 60 frames more)
SETTLE_FRAMES = 180
LAST_FRAME = DROPS[-1][0] + SETTLE_FRAMES


def own_scene_scenario():
    """The lab's own scene (seed 11) with four clicked drops, closed 3 s after the last one (4.5 s in all)."""
    script = [{"frame": frame, "type": "click", "pos": list(pos)} for frame, pos in DROPS]
    script.append({"frame": LAST_FRAME, "type": "quit"})
    return {"frames": LAST_FRAME + 5, "fps": FPS, "seed": SEED, "record_every": 1, "script": script}


# Longest first; the grader orders runs by tumbling_crates.SCENE_SECONDS (CPU s of each scene).
SCENARIOS = {
    "pile": pile_scenario,
    "own_scene": own_scene_scenario,
    "ramp": ramp_scenario,
    "corner": corner_scenario,
}


# ---------------------------------------------------------------- measurements

def measure_corner(record):
    """Per crate: turn (rad) from start to end, distance from flat at the end, final speed and spin."""
    frames = record["records"]
    first, last = dynamic(frames[0]), dynamic(frames[-1])
    tail = frames[-30:]
    crates = []
    for index, (a, b) in enumerate(zip(first, last)):
        crates.append({
            "turned": abs(b["angle"] - a["angle"]),
            "flat_error": flat_error(b),
            "floor_gap": -floor_penetration(b),
            "rest_speed": max(speed(dynamic(f)[index]) for f in tail),
            "rest_omega": max(abs(dynamic(f)[index]["omega"]) for f in tail),
        })
    return crates
