"""The Tumbling Crates scenes: what the checker drops where, what it measures there, and its bounds.

The checker grades a Tumbling Crates lab in these scenes (checker/labs/tumbling_crates/), and the
bench measures other solver settings in the same ones against the same bounds
(lesson11/bench/default_probe.py, section1_probe.py): both import them from here, so the bench
never imports the checker. The bounds were measured on these scenes, bit for bit: change a scene
and measure the bounds again.

Scene geometry (from the lab, shared by every lab: lesson11/records.py): the
floor's top face is at y = 560 px, the ramp is a 420 × 24 px static box
centred at (230, 380) turned 22° (its right end lower), the wall sits just
off the right edge. y grows downward; a positive angle turns clockwise on screen.

Each scenario is a settings dict for lesson11.runtime.configure(); the
runtime replaces the lab's crates with the scenario's and records every
body's state each frame. lesson11/records.py's metrics (measure_ramp,
measure_pile, summary, ...) and measure_corner here turn a record into numbers
(px, px/s, rad); checker/labs/tumbling_crates/checks.py compares them with the bounds.
"""
import math

from pygame import Vector2

from lesson11.records import (FLOOR_TOP, FPS, RAMP_ANGLE, RAMP_CENTRE, RAMP_THICKNESS, SEED, dynamic, flat_error,
                              floor_penetration, speed)

# ---------------------------------------------------------------- bounds (measured on the solution)
TIPPED_FLAT = math.radians(6)   # rad from flat at the end; solution: 0.02°-0.11°
MIN_TURN = 0.3                  # rad turned while tipping; solution: 0.50-0.55 (the drop angles are 0.5, 0.55)
REST_SPEED = 5.0                # px/s over the last 0.5 s; solution: 0.002
REST_OMEGA = 0.2                # rad/s over the last 0.5 s; solution: 0.0000
PENETRATION = 1.0               # px below the floor's top face; solution: corner 0.33, pile 0.57 (no push-out: 1.5)
PAIR_OVERLAP = 2.0              # px between two crates in the pile; solution: 0.62 (no push-out: 2.8)
# The ramp: physics2d's World solves the contacts before it moves the bodies (order="solve-first"),
# so friction cancels each step's pull down the slope before the move and a crate at rest stays
# put (the lesson text's order, move-first, let it creep g·sin(22°)·dt = 3.06 px/s: 9.2-10.3 px).
RAMP_SLIDE = 1.0                # px along the slope in 3 s; solution: 0.29
RAMP_SPEED = 2.0                # px/s in the last second; solution: 0.65
PILE_SPEED = 10.0               # px/s in the last second; solution: 4.65 (a pile is chaotic: margin 2x)
PILE_DRIFT = 3.0                # px a crate's centre may move during the last second; solution: 0.27
EXPLODED = 1500.0               # px/s: faster than any fall in these scenes (free fall from the top: ~1100)
GRAVITY = 980.0                 # px/s², the course's gravity
GRAVITY_TOLERANCE = 0.01        # relative; the solution measures the free fall within 1e-9


def ramp_crate(along, w, h, gap=0.25):
    """Scenario entry: a w × h crate at rest `gap` px above the ramp's top face, `along` px from the ramp's
    centre along its slope (px; positive: down the slope)."""
    slope = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))
    up = Vector2(math.sin(RAMP_ANGLE), -math.cos(RAMP_ANGLE))  # the ramp's top face normal
    pos = RAMP_CENTRE + slope * along + up * (RAMP_THICKNESS / 2 + h / 2 + gap)
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
        ramp_crate(-120, 60, 40), ramp_crate(-10, 50, 50), ramp_crate(100, 70, 36)]}


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


# ---------------------------------------------------------------- the clicked pile (the tests' and the bench's)

def pile_drops(count, columns=4):
    """Where `count` clicked crates are dropped (px): `columns` columns 70 px apart from x = 590, right of the
    ramp, rows 50 px apart from y = 150, so they pile up on the floor."""
    return [(590 + 70 * (k % columns), 150 + 50 * (k // columns)) for k in range(count)]


PILE_DROPS = pile_drops(12)   # the lab's pile: a dozen drops


def clicks(positions, first_frame, every):
    """Script entries: a left click at each position, `every` frames apart from `first_frame`."""
    return [{"frame": first_frame + k * every, "type": "click", "pos": list(pos)}
            for k, pos in enumerate(positions)]


def pile_settings(settle_frames=240, every=20):
    """A dozen crates clicked in over the floor (no starting crates), then `settle_frames` frames of settling."""
    script = clicks(PILE_DROPS, 10, every)
    last_drop = script[-1]["frame"]
    return {"frames": last_drop + settle_frames, "fps": FPS, "seed": SEED, "scenario": [], "script": script}


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
