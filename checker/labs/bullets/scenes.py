"""The Bullets scene: the lab's own scene as the checker runs it, to show that the file runs.

The criteria come from the probe (the lab's own BulletWorld, wall and modes, stepped in the child
process, checker/labs/bullets/probes.py); this one scene (main() with scripted keys and clicks) is
what the `runs` check reads and --pictures draws.
"""
from lesson11.records import FPS, SEED


def scene_scenario():
    """The lab's own scene in CCD mode (key 5), 6 bullets fired at the wall and the crates, 0.5 s."""
    clicks = [(300, 250), (600, 100), (260, 545), (600, 400), (390, 480), (600, 250)]
    script = [{"frame": 1, "type": "key", "key": "5"}]
    script += [{"frame": 2 + 3 * i, "type": "click", "pos": list(pos)} for i, pos in enumerate(clicks)]
    return {"frames": 30, "fps": FPS, "seed": SEED, "record_every": 1, "script": script}


SCENARIOS = {"scene": scene_scenario}
