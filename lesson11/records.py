"""What a recorded run measures, for every lab's checker and the bench: the shared scene geometry and the metrics.

A record is what lesson11.runtime writes: {"records": [frame, ...]}, each frame
{"frame", "contacts", "touching", "bodies": [{"static", "pos", "vel", "angle",
"omega", "points"}, ...]}. The functions here turn records into numbers (px,
px/s, rad); each lab's checks compare them with that lab's bounds.

The three labs share one scene (lesson11's Tumbling Crates scene): the
floor's top face at y = 560 px, a 420 × 24 px static ramp centred at
(230, 380) turned 22° (its right end lower), a wall just off the right edge;
y grows downward, a positive angle turns clockwise on screen. Where arrays of
frames × bodies make a metric simpler (a body's track, a fitted acceleration)
the metric uses numpy.
"""
import math

import numpy as np
from pygame import Vector2

from lesson11.physics2d import circle_polygon
from lesson11.physics2d import sat as reference_sat

FPS = 60
SEED = 11
FLOOR_TOP = 560.0                 # px
RAMP_CENTRE = Vector2(230, 380)   # px
RAMP_ANGLE = math.radians(22)     # rad
RAMP_THICKNESS = 24.0             # px
FAST_MOVER = 30.0                 # px/s, the lab's threshold for a fast mover


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
    """True when every recorded number is finite: positions, velocities, angles, spins and corners.

    The metrics compare numbers: a NaN compares False with every bound, so a record holding one
    must fail here rather than slip through a criterion.
    """
    for frame in frames:
        for body in frame["bodies"]:
            values = body["pos"] + body["vel"] + [body["angle"], body["omega"]] + \
                [c for point in body.get("points", ()) for c in point]
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


def dynamic_arrays(record):
    """The dynamic bodies' states over a record as numpy arrays (frames × bodies).

    Keys: "pos" and "vel" (frames × bodies × 2, px and px/s), "angle" (rad), "omega" (rad/s),
    "speed" (px/s). Every frame must hold the same dynamic bodies (true for a scene without clicks).
    """
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


def body_track(record, index):
    """One dynamic body (index among the dynamic bodies) through a record, as numpy arrays.

    {"t": frame / FPS (s), "pos": n × 2 (px), "vel": n × 2 (px/s), "angle": (rad), "omega": (rad/s)}.
    """
    frames = record["records"]
    bodies = [dynamic(frame)[index] for frame in frames]
    return {"t": np.array([frame["frame"] / FPS for frame in frames]),
            "pos": np.array([body["pos"] for body in bodies], dtype=float),
            "vel": np.array([body["vel"] for body in bodies], dtype=float),
            "angle": np.array([body["angle"] for body in bodies], dtype=float),
            "omega": np.array([body["omega"] for body in bodies], dtype=float)}


def fitted_acceleration(times, speeds):
    """The least-squares slope (px/s²) of speed (px/s) against time (s): the mean acceleration."""
    return float(np.polyfit(np.asarray(times, dtype=float), np.asarray(speeds, dtype=float), 1)[0])


def circle_depth(center, radius, points):
    """How far (px) a circle (center, radius px) overlaps a convex polygon (world points); 0 when apart.

    physics2d's circle_polygon: radius - distance to the outline, or radius + distance when
    the center is inside.
    """
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
