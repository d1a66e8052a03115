"""The Billiards scenes and what they measure. Cloth x 60-840, y 150-550 px; balls (the lab's items: pos, vel,
color, rolling (0: no cloth)) 14 px, mass 1. frictionless, 0.75 s: a ball at 500 px/s head-on into one at rest,
one at 600 px/s 10 px off centre into another, none reaching a cushion; break, 6 s: the cue ball at 900 px/s."""
import math

from lesson11 import records as metrics

TABLE = (60, 150, 840, 550)   # px: left, top, right, bottom of the cloth
HEAD_ON_SPEED = 500.0         # px/s
RACK = 2 * 14 + 0.5           # px between racked balls' centres


def frictionless():
    balls = [{"pos": [300, 250], "vel": [HEAD_ON_SPEED, 0]}, {"pos": [500, 250]},
             {"pos": [250, 410], "vel": [600, 0]}, {"pos": [450, 400]}]
    return {"frames": 45, "fps": metrics.FPS, "seed": metrics.SEED, "scenario": [dict(b, rolling=0.0) for b in balls]}


def breaking():
    balls = [{"pos": [255, 350], "vel": [900, 0]}] + [
        {"pos": [606 + row * RACK * math.sqrt(3) / 2, 350 + (k - row / 2) * RACK], "color": [210, 50, 40]}
        for row in range(4) for k in range(row + 1)]
    return {"frames": 360, "fps": metrics.FPS, "seed": metrics.SEED, "scenario": balls}


SCENARIOS = {"frictionless": frictionless, "break": breaking}



def momentum(frame):
    """Total momentum of the frame's balls (mass 1 each: px/s)."""
    return [sum(ball["vel"][axis] for ball in metrics.dynamic(frame)) for axis in (0, 1)]


def overlap(frame):
    """(px, what) of the frame's deepest overlap of two balls, or of a ball and a cushion."""
    found, (left, top, right, bottom) = metrics.dynamic(frame), TABLE
    deepest = [(0.0, "nothing")]
    for i, a in enumerate(found):
        x, y = a["pos"]
        deepest.append((a["radius"] - min(x - left, right - x, y - top, bottom - y), f"ball {i} and a cushion"))
        deepest += [(a["radius"] + b["radius"] - math.dist(a["pos"], b["pos"]), f"balls {i} and {k}")
                    for k, b in enumerate(found[i + 1:], i + 1)]
    return max(deepest)

