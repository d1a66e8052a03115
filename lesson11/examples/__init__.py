"""The lesson's programs, each a small script on lesson11.physics2d.

Run one with `python -m lesson11.examples.<name>`, or all of them with
`python -m lesson11.examples`. The README in this folder says what each shows.
"""
from lesson11.console import safe_output

safe_output()  # every way in (one example or all) prints θ, ×, ²: a console that is not UTF-8 gets stand-ins

# name, what it shows; the runner (__main__.py) and the tests use this list.
EXAMPLES = [
    ("sat_three_pairs",
     "SAT on three box pairs: an overlap, a near miss that bounding boxes get wrong, a diagonal hit"),
    ("box_inertia", "moment of inertia of a 30 × 20 box of mass 2: box formula and polygon_inertia agree"),
    ("ball_on_ramp", "a ball sunk into a triangle ramp: circle_polygon's normal and depth, then the push-out"),
    ("bullet_swept", "a 3000 px/s bullet: the discrete test misses the target, the swept test finds the hit"),
]
