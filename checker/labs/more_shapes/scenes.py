"""The More Shapes scenes: which shapes the checker sets where, and what it measures.

Scene geometry is Tumbling Crates' (lesson11/records.py): the floor's
top face at y = 560 px, the 420 × 24 px ramp centred at (230, 380) turned 22°,
the wall just off the right edge; y grows downward, a positive angle turns
clockwise on screen. Scenario items are the lab's own shape descriptions
({"kind", "pos", "size" or "w"/"h", "angle", "vel"}): the runtime hands each
to the lab's build(), so the bodies are made by the student's functions.

Two scenes keep grading cheap (each is one child process):
  solo  (3 s): an equilateral triangle dropped on a corner, a hexagon pushed along the
        floor, a pentagon and a hexagon set at rest on the ramp. They never meet.
  pile  (1.5 s): seven shapes of every kind stacked loosely over the floor's right half.
The measurements reuse lesson11/records.py's metrics (summary, measure_ramp,
measure_pile, free_fall, dynamic_arrays, resting_side_error).
"""
import math

from pygame import Vector2

from lesson11 import records as metrics

FPS = metrics.FPS
SEED = metrics.SEED
FLOOR_TOP = metrics.FLOOR_TOP
SOLO_FRAMES = 180     # 3 s: the ramp criterion is "at most 1 px in 3 s", as in Tumbling Crates
PILE_FRAMES = 90      # 1.5 s: the pile is still 0.5 s after its top row lands (frame 30)
PILE_TAIL = 0.5       # s: the pile's last half second is where sinking and jitter are measured

TRIANGLE = 0          # indices of the solo scene's shapes among its dynamic bodies
PUSHED = 1
ON_RAMP = (2, 3)
TRIANGLE_RADIUS = 34  # px, circumradius
PUSHED_RADIUS = 28    # px
PUSH_SPEED = 420.0    # px/s along the floor (to the right)


def resting_on_side(sides, radius, surface_point, down_angle, gap=0.25):
    """(pos, angle) of a regular polygon (lab convention: corner k at angle + 2πk/sides) lying on a side.

    `surface_point` is a point of the supporting surface (px), `down_angle` the direction (rad)
    pointing into the surface. The side from corner 0 to corner 1 faces down_angle, so the
    body angle is down_angle - π/sides, and the centre sits one apothem r cos(π/n) + gap above.
    """
    apothem = radius * math.cos(math.pi / sides)
    down = Vector2(math.cos(down_angle), math.sin(down_angle))
    pos = Vector2(surface_point) - down * (apothem + gap)
    return [pos.x, pos.y], down_angle - math.pi / sides


def _on_ramp(kind, sides, radius, along):
    slope = Vector2(math.cos(metrics.RAMP_ANGLE), math.sin(metrics.RAMP_ANGLE))
    up = Vector2(math.sin(metrics.RAMP_ANGLE), -math.cos(metrics.RAMP_ANGLE))
    surface = metrics.RAMP_CENTRE + slope * along + up * (metrics.RAMP_THICKNESS / 2)
    pos, angle = resting_on_side(sides, radius, surface, math.pi / 2 + metrics.RAMP_ANGLE)
    return {"kind": kind, "size": radius, "pos": pos, "angle": angle}


def solo_scenario():
    """A triangle dropped on a corner, a hexagon pushed along the floor, a pentagon and a hexagon on the ramp (3 s)."""
    # corner 0 of the triangle points straight down at angle π/2; 0.12 rad more and it tips to one side
    triangle = {"kind": "triangle", "size": TRIANGLE_RADIUS, "pos": [120, FLOOR_TOP - TRIANGLE_RADIUS - 60],
                "angle": math.pi / 2 + 0.12}
    pos, angle = resting_on_side(6, PUSHED_RADIUS, (470, FLOOR_TOP), math.pi / 2)
    pushed = {"kind": "hexagon", "size": PUSHED_RADIUS, "pos": pos, "angle": angle, "vel": [PUSH_SPEED, 0]}
    return {"frames": SOLO_FRAMES, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": [
        triangle, pushed, _on_ramp("pentagon", 5, 30, -90), _on_ramp("hexagon", 6, 28, 60)]}


PILE_KINDS = ("box", "hexagon", "triangle", "pentagon", "house", "hexagon", "triangle")


def pile_scenario():
    """Seven shapes of every kind in two loose rows (four, then three in the gaps) over the floor (1.5 s)."""
    shapes = []
    for index, kind in enumerate(PILE_KINDS):
        row, column = divmod(index, 4)
        pos = [560 + 66 * column + 33 * row, FLOOR_TOP - 34 - 66 * row]
        angle = 0.3 * index
        if kind in ("box", "house"):
            shapes.append({"kind": kind, "w": 56, "h": 44, "pos": pos, "angle": angle if kind == "box" else 0.0})
        else:
            shapes.append({"kind": kind, "size": 30, "pos": pos, "angle": angle})
    return {"frames": PILE_FRAMES, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": shapes}


SCENARIOS = {"solo": solo_scenario, "pile": pile_scenario}


# ---------------------------------------------------------------- measurements

def measure_tipping(record, index, tail_seconds=0.5):
    """One solo-scene shape: turned (rad), side_error (rad), travelled (px), rest speed (px/s) and spin (rad/s)."""
    arrays = metrics.dynamic_arrays(record)
    tail = int(tail_seconds * FPS)
    last = metrics.dynamic(record["records"][-1])[index]
    return {
        "turned": float(abs(arrays["angle"][-1, index] - arrays["angle"][0, index])),
        "side_error": metrics.resting_side_error(last),
        "travelled": float(arrays["pos"][-1, index, 0] - arrays["pos"][0, index, 0]),
        "floor_gap": -metrics.floor_penetration(last),
        "rest_speed": float(arrays["speed"][-tail:, index].max()),
        "rest_omega": float(abs(arrays["omega"][-tail:, index]).max()),
    }
