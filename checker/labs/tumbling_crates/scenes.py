"""The Tumbling Crates scenarios the checker runs, by name: the scenes themselves are lesson11/crate_scenes.py.

The scenes, measure_corner and the bounds measured on them live in lesson11 (the bench measures the
same scenes and must not import the checker); this module names the runs and orders them.
"""
from lesson11.crate_scenes import DROPS, SETTLE_FRAMES, measure_corner  # noqa: F401 (checks.py reads them here)
from lesson11.crate_scenes import corner_scenario, own_scene_scenario, pile_scenario, ramp_scenario

# Longest first; the grader orders runs by tumbling_crates.SCENE_SECONDS (CPU s of each scene).
SCENARIOS = {
    "pile": pile_scenario,
    "own_scene": own_scene_scenario,
    "ramp": ramp_scenario,
    "corner": corner_scenario,
}
