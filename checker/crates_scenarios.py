"""The Tumbling Crates scenarios: what the checker drops where, and the measurements it takes.

Scene geometry (from the lab): the floor's top face is at y = 560 px, the
ramp is a 420 × 24 px static box centred at (230, 380) turned 22° (its right
end lower), the wall sits just off the right edge. y grows downward; a
positive angle turns clockwise on screen.

Each scenario is a settings dict for lesson11.runtime.configure(); the
runtime replaces the lab's crates with the scenario's and records every
body's state each frame. The measure_* functions turn a record into numbers
(px, px/s, rad); checker/tumbling_crates.py compares them with the bounds.
"""
import math

from pygame import Vector2

from lesson11.physics2d import sat as reference_sat

FPS = 60
SEED = 11
FLOOR_TOP = 560.0                 # px
RAMP_CENTRE = Vector2(230, 380)   # px
RAMP_ANGLE = math.radians(22)     # rad
RAMP_THICKNESS = 24.0             # px
FAST_MOVER = 30.0                 # px/s, the lab's threshold for a fast mover


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
    """A dozen 60 × 40 crates laid like bricks (rows of 4, 3, 3, 2) with 2 px gaps, on the floor (3.5 s)."""
    crates = []
    rows = ((4, 0.0), (3, 31.0), (3, 31.0), (2, 62.0))  # (crates in the row, shift right in px)
    y = FLOOR_TOP - 20 - 2
    for count, shift in rows:
        for k in range(count):
            crates.append({"w": 60, "h": 40, "pos": [520 + shift + 62 * k, y], "angle": 0.0})
        y -= 42
    return {"frames": 210, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": crates}


DROPS = ((30, (180, 120)), (50, (620, 120)), (70, (720, 60)), (90, (300, 60)))
SETTLE_FRAMES = 240               # 4 s after the last drop
LAST_FRAME = DROPS[-1][0] + SETTLE_FRAMES


def own_scene_scenario():
    """The lab's own scene (seed 11) with four clicked drops, closed 4 s after the last one."""
    script = [{"frame": frame, "type": "click", "pos": list(pos)} for frame, pos in DROPS]
    script.append({"frame": LAST_FRAME, "type": "quit"})
    return {"frames": LAST_FRAME + 5, "fps": FPS, "seed": SEED, "record_every": 1, "script": script}


SCENARIOS = {
    "corner": corner_scenario,
    "ramp": ramp_scenario,
    "pile": pile_scenario,
    "own_scene": own_scene_scenario,
}


# ---------------------------------------------------------------- measurements

def dynamic(frame):
    """The dynamic bodies of one recorded frame."""
    return [body for body in frame["bodies"] if not body["static"]]


def speed(body):
    return math.hypot(*body["vel"])


def flat_error(body):
    """How far (rad) the body is from lying on a flat side: angle distance to the nearest multiple of 90°."""
    quarter = math.pi / 2
    a = body["angle"] % quarter
    return min(a, quarter - a)


def floor_penetration(body):
    """How deep (px) the body's lowest corner is below the floor's top face (negative: above it)."""
    return max(p[1] for p in body["points"]) - FLOOR_TOP


def max_pair_overlap(bodies):
    """Largest SAT depth (px) between any two of the given bodies (0 if none overlap)."""
    shapes = [[Vector2(p) for p in body["points"]] for body in bodies]
    deepest = 0.0
    for i in range(len(shapes)):
        for j in range(i + 1, len(shapes)):
            hit = reference_sat(shapes[i], shapes[j])
            if hit is not None:
                deepest = max(deepest, hit[1])
    return deepest


def finite(frames):
    """True when every recorded number is finite."""
    for frame in frames:
        for body in frame["bodies"]:
            values = body["pos"] + body["vel"] + [body["angle"], body["omega"]]
            if not all(math.isfinite(v) for v in values):
                return False
    return True


def summary(record, settle_seconds=1.0):
    """Common numbers for any scenario record: peak speed, last-second speeds, escapes."""
    frames = record.get("records", [])
    if not frames:
        return {"frames": 0}
    tail = frames[-int(settle_seconds * FPS):]
    out = {
        "frames": len(frames),
        "finite": finite(frames),
        "crates": len(dynamic(frames[-1])),
        "peak_speed": max((speed(b) for f in frames for b in dynamic(f)), default=0.0),
        "tail_speed": max((speed(b) for f in tail for b in dynamic(f)), default=0.0),
        "tail_omega": max((abs(b["omega"]) for f in tail for b in dynamic(f)), default=0.0),
        "lowest_y": max((b["pos"][1] for b in dynamic(frames[-1])), default=0.0),
        "highest_y": min((b["pos"][1] for f in frames for b in dynamic(f)), default=0.0),
        "fell_through": sum(1 for b in dynamic(frames[-1]) if b["pos"][1] > FLOOR_TOP + 20),
        "off_screen": sum(1 for b in dynamic(frames[-1])
                          if not (-100 < b["pos"][0] < 1000 and -400 < b["pos"][1] < 700)),
    }
    return out


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


def measure_ramp(record):
    """Per crate: distance (px) moved along the slope (positive = downhill), and turn (rad)."""
    frames = record["records"]
    slope = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))
    first, last = dynamic(frames[0]), dynamic(frames[-1])
    crates = []
    for a, b in zip(first, last):
        moved = Vector2(b["pos"]) - Vector2(a["pos"])
        crates.append({"slid": moved.dot(slope), "moved": moved.length(), "turned": abs(b["angle"] - a["angle"])})
    return crates


def measure_pile(record, settle_seconds=1.0):
    """Over the last second: deepest floor penetration, deepest crate-crate overlap (px), top speed (px/s), drift (px)."""
    frames = record["records"]
    tail = frames[-int(settle_seconds * FPS):]
    sampled = tail[::10] + [tail[-1]]
    return {
        "floor_penetration": max(floor_penetration(b) for f in tail for b in dynamic(f)),
        "pair_overlap": max(max_pair_overlap(dynamic(f)) for f in sampled),
        "tail_speed": max(speed(b) for f in tail for b in dynamic(f)),
        "drift": max((math.dist(a["pos"], b["pos"]) for a, b in zip(dynamic(tail[0]), dynamic(tail[-1]))),
                     default=0.0),
    }


def fast_movers(frame):
    """How many dynamic bodies of a recorded frame move faster than FAST_MOVER px/s."""
    return sum(1 for body in dynamic(frame) if speed(body) > FAST_MOVER)


def free_fall(record, frames=4):
    """Gravity (px/s²) measured from the first recorded frames, while every crate still falls freely.

    Per frame the vertical speed of each crate grows by g / FPS; returns the mean over the
    first `frames` frame pairs before any contact, or None if contacts start at once.
    """
    recorded = record["records"]
    rates = []
    for before, after in zip(recorded, recorded[1:frames + 1]):
        if after["contacts"] or before["contacts"] or after["frame"] != before["frame"] + 1:
            break
        for a, b in zip(dynamic(before), dynamic(after)):
            rates.append((b["vel"][1] - a["vel"][1]) * FPS)
    return sum(rates) / len(rates) if rates else None


def drops_added(record):
    """How many crates the scripted clicks added: the dynamic bodies at the end minus those at the start."""
    frames = record["records"]
    return len(dynamic(frames[-1])) - len(dynamic(frames[0]))


# --- shared metrics added for More Shapes ---

def dynamic_arrays(record):
    """The dynamic bodies' states over a record as numpy arrays (frames × bodies).

    Keys: "pos" and "vel" (frames × bodies × 2, px and px/s), "angle" (rad), "omega" (rad/s),
    "speed" (px/s). Every frame must hold the same dynamic bodies (true for a scene without clicks).
    """
    import numpy as np
    frames = [dynamic(frame) for frame in record["records"]]
    pos = np.array([[body["pos"] for body in bodies] for bodies in frames], dtype=float)
    vel = np.array([[body["vel"] for body in bodies] for bodies in frames], dtype=float)
    return {"pos": pos, "vel": vel, "speed": np.hypot(vel[..., 0], vel[..., 1]),
            "angle": np.array([[body["angle"] for body in bodies] for bodies in frames], dtype=float),
            "omega": np.array([[body["omega"] for body in bodies] for bodies in frames], dtype=float)}


def resting_side_error(body):
    """How far (rad) a body's lowest edge is from horizontal: 0 when it lies flat on a side on the floor.

    The lowest edge is the one whose midpoint is lowest on screen (largest y); works for any
    convex polygon, whatever its number of sides or the angle convention of its corners.
    """
    points = body["points"]
    edges = [(points[i], points[(i + 1) % len(points)]) for i in range(len(points))]
    a, b = max(edges, key=lambda edge: edge[0][1] + edge[1][1])
    return math.atan2(abs(b[1] - a[1]), abs(b[0] - a[0]))


# --- shared metrics added for Ball on the Ramp ---

def body_track(record, index):
    """One dynamic body (index among the dynamic bodies) through a record, as numpy arrays.

    {"t": frame / FPS (s), "pos": n × 2 (px), "vel": n × 2 (px/s), "angle": (rad), "omega": (rad/s)}.
    """
    import numpy as np
    frames = record["records"]
    bodies = [dynamic(frame)[index] for frame in frames]
    return {"t": np.array([frame["frame"] / FPS for frame in frames]),
            "pos": np.array([body["pos"] for body in bodies], dtype=float),
            "vel": np.array([body["vel"] for body in bodies], dtype=float),
            "angle": np.array([body["angle"] for body in bodies], dtype=float),
            "omega": np.array([body["omega"] for body in bodies], dtype=float)}


def fitted_acceleration(times, speeds):
    """The least-squares slope (px/s²) of speed (px/s) against time (s): the mean acceleration."""
    import numpy as np
    return float(np.polyfit(np.asarray(times, dtype=float), np.asarray(speeds, dtype=float), 1)[0])


def circle_depth(center, radius, points):
    """How far (px) a circle (center, radius px) overlaps a convex polygon (world points); 0 when apart.

    physics2d's circle_polygon: radius - distance to the outline, or radius + distance when
    the center is inside.
    """
    from lesson11.physics2d import circle_polygon
    hit = circle_polygon(Vector2(center), radius, [Vector2(p) for p in points])
    return 0.0 if hit is None else hit[1]


def deepest_circle_overlap(record, index, radius):
    """The deepest overlap (px) of dynamic circle `index` (radius px) with any polygon body, over a record.

    Returns (depth, frame number, index of the polygon in the frame's bodies); depth 0 when never touching.
    """
    deepest = (0.0, None, None)
    for frame in record["records"]:
        circle = dynamic(frame)[index]
        for number, body in enumerate(frame["bodies"]):
            if len(body["points"]) >= 3:
                depth = circle_depth(circle["pos"], radius, body["points"])
                if depth > deepest[0]:
                    deepest = (depth, frame["frame"], number)
    return deepest
