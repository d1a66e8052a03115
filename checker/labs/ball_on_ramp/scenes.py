"""The Ball on the Ramp scenarios: where the checker puts balls and crates, and what it measures.

The scene's geometry is Tumbling Crates' (lesson11/records.py): the
floor's top face at y = 560 px, the 420 × 24 px ramp centred at (230, 380)
turned 22° (its right end lower), the wall just off the right edge. The lab's
build(item) makes a ball from an item with "r" (px) and a crate from one with
"w" and "h". The measurements reuse lesson11/records.py's record metrics
(body_track, fitted_acceleration, deepest_circle_overlap, circle_depth, ...).

Kept short on purpose: the three scenes together simulate 4.5 s, so grading a
correct file costs a few CPU seconds.
"""
import math

from pygame import Vector2

from lesson11.records import (FLOOR_TOP, FPS, RAMP_ANGLE, RAMP_CENTRE, RAMP_THICKNESS, SEED, body_track,
                              circle_depth, deepest_circle_overlap, dynamic, fitted_acceleration)

GRAVITY = 980.0                   # px/s²
RADIUS = 20.0                     # px, every ball of the scenes
SLOPE = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))     # unit vector down the ramp
RAMP_UP = Vector2(math.sin(RAMP_ANGLE), -math.cos(RAMP_ANGLE))  # the ramp's top face normal
ROLLING = 2 / 3 * GRAVITY * math.sin(RAMP_ANGLE)    # px/s², a solid disc rolling without slipping: 244.74
SLIDING = GRAVITY * math.sin(RAMP_ANGLE)            # px/s², sliding without friction: 367.11
WINDOW = (0.1, 1.1)               # s: the ramp scene's measured stretch (both balls land by 0.05 s)
MIN_SPEED = 20.0                  # px/s: slower frames are left out of the relative slip


def ball_on_ramp(along, friction=0.6, r=RADIUS):
    """A ball of radius r at rest 0.25 px above the ramp's top face, `along` px down the slope from its centre."""
    pos = RAMP_CENTRE + SLOPE * along + RAMP_UP * (RAMP_THICKNESS / 2 + r + 0.25)
    return {"r": r, "pos": [pos.x, pos.y], "friction": friction}


def ramp_scenario():
    """Two balls let go on the ramp: a grippy one (mu 0.6) high up, a frictionless one further down (70 frames).

    The frictionless ball slides faster, so it stays ahead: they never meet.
    """
    return {"frames": 70, "fps": FPS, "seed": SEED, "record_every": 1,
            "scenario": [ball_on_ramp(-185, 0.6), ball_on_ramp(-60, 0.0)]}


KNOCK_CRATE = {"w": 24, "h": 90, "pos": [600, FLOOR_TOP - 45]}


def knock_scenario():
    """A ball rolls from the middle of the ramp, drops onto the floor and hits a tall crate (2.8 s)."""
    return {"frames": 170, "fps": FPS, "seed": SEED, "record_every": 1,
            "scenario": [ball_on_ramp(0, 0.6), dict(KNOCK_CRATE)]}


INSIDE_CRATE = {"w": 80, "h": 60, "pos": [600, FLOOR_TOP - 30]}
INSIDE_BALL = {"r": RADIUS, "pos": [575, 538]}   # centre 15 px inside the crate's left side, 22 px above its bottom


def inside_scenario():
    """A ball started with its centre inside a crate on the floor, near the crate's left side (0.5 s)."""
    return {"frames": 30, "fps": FPS, "seed": SEED, "record_every": 1,
            "scenario": [dict(INSIDE_CRATE), dict(INSIDE_BALL)]}


SCENARIOS = {
    "ramp": ramp_scenario,
    "knock": knock_scenario,
    "inside": inside_scenario,
}


# ---------------------------------------------------------------- measurements

def measure_roll(record, index, radius=RADIUS):
    """One ball on the ramp over WINDOW: acceleration along the slope, slip, spin.

    accel (px/s²): least-squares slope of v = vel·SLOPE against time;
    slip: the largest |ω r - v| / v over frames with v > MIN_SPEED (0 = rolling without slipping);
    omega: the largest |ω| (rad/s); depth (px): its deepest overlap with any polygon in the whole run.
    """
    import numpy as np
    track = body_track(record, index)
    t = track["t"]
    chosen = (t >= WINDOW[0]) & (t <= WINDOW[1])
    v = track["vel"] @ np.array([SLOPE.x, SLOPE.y])
    rim = track["omega"] * radius
    moving = chosen & (np.abs(v) > MIN_SPEED)
    slip = float(np.max(np.abs(rim[moving] - v[moving]) / np.abs(v[moving]))) if moving.any() else math.inf
    depth, frame, _ = deepest_circle_overlap(record, index, radius)
    return {"accel": fitted_acceleration(t[chosen], v[chosen]) if chosen.sum() >= 2 else math.nan,
            "slip": slip, "omega": float(np.max(np.abs(track["omega"][chosen]))) if chosen.any() else 0.0,
            "speed_end": float(v[-1]), "depth": depth, "depth_frame": frame, "frames": int(chosen.sum()),
            "left_ramp": bool(np.any(track["pos"][chosen] @ np.array([RAMP_UP.x, RAMP_UP.y])
                                     - (RAMP_CENTRE.dot(RAMP_UP) + RAMP_THICKNESS / 2) > radius + 5))}


def measure_knock(record, radius=RADIUS):
    """The knock scene: how far the crate turned (rad) and moved (px), and the ball's deepest overlap (px)."""
    frames = record["records"]
    first, last = dynamic(frames[0]), dynamic(frames[-1])
    crate_start, crate_end = first[1], last[1]
    depth, frame, other = deepest_circle_overlap(record, 0, radius)
    return {"turned": abs(crate_end["angle"] - crate_start["angle"]),
            "moved": math.dist(crate_start["pos"], crate_end["pos"]),
            "ball_x": last[0]["pos"][0], "depth": depth, "depth_frame": frame,
            "depth_into": "a crate" if other is not None and not frames[0]["bodies"][other]["static"] else
            ("the floor" if other == 0 else "the ramp" if other == 1 else "the wall")}


def measure_inside(record, radius=RADIUS):
    """The inside scene at its end: the ball's overlap with the crate (px) and which side of it the ball is on.

    side: "near" (the crate's left, where the ball's centre started, 15 px from that side),
    "far" (pushed through to the right), or "middle" (still over the crate's centre line).
    """
    frames = record["records"]
    crate, ball = dynamic(frames[-1])
    start_crate = dynamic(frames[0])[0]
    left = min(p[0] for p in crate["points"])
    right = max(p[0] for p in crate["points"])
    if ball["pos"][0] + radius <= left + 2:
        side = "near"
    elif ball["pos"][0] - radius >= right - 2:
        side = "far"
    else:
        side = "middle"
    return {"depth": circle_depth(ball["pos"], radius, crate["points"]), "side": side,
            "ball": ball["pos"], "crate_moved": math.dist(start_crate["pos"], crate["pos"]),
            "ball_speed": math.hypot(*ball["vel"])}
