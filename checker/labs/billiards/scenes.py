"""The Billiards scenes: which balls the checker sets where, and what it measures.

The table's cloth is x 60-840, y 150-550 px (the lab's TABLE), every ball 14 px in radius, mass 1. Items
are the lab's own ball descriptions ({"pos", "vel", "color", "rolling"}), made by the lab's build();
"rolling": 0 is a frictionless cloth.
  frictionless  0.75 s, no cloth: a head-on pair (y = 250) and a glancing pair (y = 400), each a ball
                at 500-600 px/s into one at rest; no ball reaches a cushion;
  break         6 s, the lab's cloth: the cue ball at 900 px/s into ten racked balls.
"""
import math

from lesson11 import records as metrics

TABLE = (60, 150, 840, 550)   # px: left, top, right, bottom of the cloth
HEAD_ON_SPEED = 500.0        # px/s
RACK = 2 * 14 + 0.5          # px between racked balls' centres


def frictionless():
    """Two pairs on a frictionless cloth: head-on (balls 0, 1) and glancing, 10 px off centre (balls 2, 3)."""
    balls = [{"pos": [300, 250], "vel": [HEAD_ON_SPEED, 0]}, {"pos": [500, 250]},
             {"pos": [250, 410], "vel": [600, 0]}, {"pos": [450, 400]}]
    for ball in balls:
        ball["rolling"] = 0.0
    return {"frames": 45, "fps": metrics.FPS, "seed": metrics.SEED, "record_every": 1, "scenario": balls}


def breaking():
    """The cue ball at 900 px/s into ten balls racked in a triangle, on the lab's cloth (6 s)."""
    balls = [{"pos": [255, 350], "vel": [900, 0]}]
    for row in range(4):
        balls += [{"pos": [606 + row * RACK * math.sqrt(3) / 2, 350 + (k - row / 2) * RACK], "color": [210, 50, 40]}
                  for k in range(row + 1)]
    return {"frames": 360, "fps": metrics.FPS, "seed": metrics.SEED, "record_every": 1, "scenario": balls}


SCENARIOS = {"frictionless": frictionless, "break": breaking}


# ---------------------------------------------------------------- measurements

def balls(frame):
    """The frame's balls (its moving bodies), in the scenario's order."""
    return [body for body in frame["bodies"] if not body["static"]]


def momentum(frame):
    """Total momentum (mass 1 each: px/s) of the frame's balls."""
    return [sum(ball["vel"][0] for ball in balls(frame)), sum(ball["vel"][1] for ball in balls(frame))]


def momentum_drift(record):
    """Largest |P(t) - P(0)| / |P(0)| over the frames, and the frame's time (s)."""
    frames = record["records"]
    start = momentum(frames[0])
    drifts = [(math.dist(momentum(frame), start) / math.hypot(*start), frame["frame"] / metrics.FPS)
              for frame in frames]
    return max(drifts)


def head_on(record):
    """The head-on pair at the end, as shares of the first ball's speed: (first's, second's)."""
    first, second = balls(record["records"][-1])[:2]
    return math.hypot(*first["vel"]) / HEAD_ON_SPEED, math.hypot(*second["vel"]) / HEAD_ON_SPEED


def overlap(frame):
    """The deepest overlap (px) of two balls, or of a ball and a cushion, in a frame, and what overlaps."""
    found = balls(frame)
    deepest = (0.0, "nothing")
    for i, a in enumerate(found):
        for k, b in enumerate(found[i + 1:], i + 1):
            deepest = max(deepest, (a["radius"] + b["radius"] - math.dist(a["pos"], b["pos"]), f"balls {i} and {k}"))
        left, top, right, bottom = TABLE
        x, y = a["pos"]
        wall = a["radius"] - min(x - left, right - x, y - top, bottom - y)
        deepest = max(deepest, (wall, f"ball {i} and a cushion"))
    return deepest


def deepest_overlap(record):
    """(px, what, time s) of the deepest overlap over the run."""
    return max(overlap(frame) + (frame["frame"] / metrics.FPS,) for frame in record["records"])


def at_rest(record):
    """The time (s) from which every ball stays exactly at rest, or None when some ball still rolls at the end."""
    frames = record["records"]
    moving = [k for k, frame in enumerate(frames) if any(ball["vel"] != [0.0, 0.0] for ball in balls(frame))]
    if not moving:
        return 0.0
    return None if moving[-1] == len(frames) - 1 else frames[moving[-1] + 1]["frame"] / metrics.FPS


def still_rolling(record):
    """How many balls still roll in the last frame, and the fastest one's speed (px/s)."""
    speeds = [math.hypot(*ball["vel"]) for ball in balls(record["records"][-1])]
    return sum(1 for s in speeds if s > 0), max(speeds)
