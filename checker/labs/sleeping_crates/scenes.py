"""The Sleeping Crates scene: which crates the checker sets where, and what it measures.

One scene keeps grading cheap (one child process, 1.5 s at 60 fps, 2 physics
steps a frame). The lab's floor's top face is at y = 560 px, its walls cover
x < 30 and x > 870; y grows downward. Three groups never meet:
  loose pile   (x 60-270)  four crates dropped a little apart, awake: they land, settle
               and must fall asleep;
  asleep pile  (x 375-530) five crates set exactly resting and asleep (the lab's make_world
               puts them to sleep as one island), with a crate dropped onto them from
               60 px above that lands at about 0.35 s: it must wake what it touches, and the
               pile must settle again without sinking or jumping;
  throw        (x 760)     one crate thrown straight up at 400 px/s: at the top of its
               flight (0.41 s, 82 px up) it is slow for an instant only, so it must not sleep in
               the air.
Scenario items are the lab's own crate descriptions ({"w", "h", "pos", "angle",
"vel", "asleep"}), made by the lab's build().
"""
import math

from lesson11 import records as metrics

FPS = metrics.FPS
SEED = metrics.SEED
FLOOR_TOP = metrics.FLOOR_TOP
FRAMES = 90                 # 1.5 s: everything in the scene is asleep by 1.02 s in the solution
SLEEP_SPEED = 5.0           # px/s, the handout's thresholds (a crate under both is "calm")
SLEEP_SPIN = 0.1            # rad/s
W, H = 50, 36               # px, every scene crate
LOOSE = range(0, 4)         # indices among the scene's dynamic bodies
PILE = range(4, 9)
DROPPED = 9
THROWN = 10
THROW_SPEED = 400.0         # px/s upward
AIRBORNE = 2.0              # px: a crate whose lowest corner is this far above the floor is in the air


def scenario():
    """The scene's settings for lesson11.runtime (1.5 s)."""
    crates = []
    for k in LOOSE:  # three crates turned a little 15 px above the floor, one more above them
        row, column = divmod(k, 3)
        crates.append({"w": W, "h": H, "pos": [90 + 60 * column + 28 * row, FLOOR_TOP - H / 2 - 15 - 50 * row],
                       "angle": 0.15 * (k - 1.5)})
    # the sleeping pile: three on the floor, two on top, each resting exactly on what is below it
    for k, (x, row) in enumerate(((400, 0), (452, 0), (504, 0), (426, 1), (478, 1))):
        crates.append({"w": W, "h": H, "pos": [x, FLOOR_TOP - H / 2 - row * H], "asleep": True})
    crates.append({"w": W, "h": H, "pos": [440, FLOOR_TOP - 2 * H - H / 2 - 60], "angle": 0.1})
    crates.append({"w": W, "h": H, "pos": [760, FLOOR_TOP - H / 2 - 1], "vel": [0, -THROW_SPEED]})
    return {"frames": FRAMES, "fps": FPS, "seed": SEED, "record_every": 1, "scenario": crates}


SCENARIOS = {"sleep": scenario}


# ---------------------------------------------------------------- measurements

def _calm(body):
    return metrics.speed(body) < SLEEP_SPEED and abs(body["omega"]) < SLEEP_SPIN


def measure_loose(record):
    """The loose pile: when it settled (s; the first frame from which every crate stays calm), when
    every crate was asleep for good (s, None if never) and its deepest floor / pair overlap (px) at the end."""
    frames = record["records"]
    settled = asleep = None
    for frame in frames:
        bodies = [metrics.dynamic(frame)[i] for i in LOOSE]
        t = frame["frame"] / FPS
        if all(_calm(b) for b in bodies):
            settled = t if settled is None else settled
        else:
            settled = None
        if all(b.get("asleep") for b in bodies):
            asleep = t if asleep is None else asleep
        else:
            asleep = None
    last = [metrics.dynamic(frames[-1])[i] for i in LOOSE]
    return {"settled": settled, "asleep": asleep,
            "penetration": max(metrics.floor_penetration(b) for b in last),
            "overlap": metrics.max_pair_overlap(last)}


def measure_throw(record):
    """The thrown crate: the highest it rose (px above the floor) and the frames it slept in the air."""
    airborne_asleep, height = [], 0.0
    for frame in record["records"]:
        body = metrics.dynamic(frame)[THROWN]
        gap = -metrics.floor_penetration(body)
        height = max(height, gap)
        if body.get("asleep") and gap > AIRBORNE:
            airborne_asleep.append((frame["frame"] / FPS, gap))
    return {"height": height, "asleep_in_air": airborne_asleep}


def measure_drop(record):
    """The sleeping pile and the crate dropped on it.

    woke: pile crates that were awake in some frame; landed: the first time (s) the dropped crate
    touched the pile; asleep_again: the time (s) from which pile and dropped crate all stay asleep
    (None if never); sink / jump: the most a pile crate's centre ends below / went above where it
    started (px); penetration, overlap: at the end (px).
    """
    frames = record["records"]
    start = [metrics.dynamic(frames[0])[i]["pos"] for i in PILE]
    pile_index = set(PILE)
    woke, landed, asleep_again, jump = set(), None, None, 0.0
    for frame in frames:
        bodies = metrics.dynamic(frame)
        statics = len(frame["bodies"]) - len(bodies)
        t = frame["frame"] / FPS
        for n, i in enumerate(PILE):
            if not bodies[i].get("asleep"):
                woke.add(i)
            jump = max(jump, start[n][1] - bodies[i]["pos"][1])
        if landed is None and any({c["a"] - statics, c["b"] - statics} & pile_index and
                                  DROPPED in (c["a"] - statics, c["b"] - statics) for c in frame["touching"]):
            landed = t
        group = [bodies[i] for i in list(PILE) + [DROPPED]]
        if all(b.get("asleep") for b in group):
            asleep_again = t if asleep_again is None else asleep_again
        else:
            asleep_again = None
    last = metrics.dynamic(frames[-1])
    group = [last[i] for i in list(PILE) + [DROPPED]]
    sink = max(last[i]["pos"][1] - start[n][1] for n, i in enumerate(PILE))
    return {"woke": sorted(woke), "landed": landed, "asleep_again": asleep_again, "sink": sink, "jump": jump,
            "penetration": max(metrics.floor_penetration(b) for b in group),
            "overlap": metrics.max_pair_overlap(group), "angle": math.degrees(max(
                abs(last[i]["angle"]) for i in PILE))}
