"""Probes of a Billiards file's own functions, run inside the checker's child process (new-lab's template).

    normal_speed  (step 2) pairs approaching, separating, sliding past each other, moving together and at
                  rest, with normals along the axes and slanted, and two pairs drawn for this run; beside
                  the lesson's answer, what each known wrong form gives (checks.NORMAL_MISTAKES)

The lesson's answers are added in the grader only (`judging`, checker/judging/probe_kit.py). Units: px, s.
"""
import math

from pygame import Vector2

from checker.judging.common import real, value_text
from checker.judging.probe_kit import judging, reference
from checker.judging.tape import run_rng

REQUIRED = ("normal_speed", "main")

CASES = (
    # (what, vA px/s, vB px/s, unit normal from A to B)
    ("head-on along x", (240, 0), (-240, 0), (1, 0)),
    ("B falling onto A at rest", (0, 0), (0, 300), (0, -1)),
    ("B catching up with A from behind", (50, 0), (200, 0), (-1, 0)),
    ("a slanted normal", (30, 80), (-60, 10), (0.6, 0.8)),
    ("separating along y", (0, -50), (0, 120), (0, 1)),
    ("sliding past each other", (100, 0), (-100, 0), (0, 1)),
    ("moving together", (75, -20), (75, -20), (0.8, -0.6)),
    ("both at rest", (0, 0), (0, 0), (1, 0)),
)


def _number(value):
    try:
        return real(value)
    except (TypeError, ValueError):
        return value_text(value)


@reference
def reference_normal_speed(va, vb, normal):
    """The lesson's speed along the normal (px/s): (vB - vA) · n."""
    return (Vector2(vb) - Vector2(va)).dot(Vector2(normal))


@reference
def reference_approach(va, vb, normal):
    """How the pair moves along the normal: "approaching", "separating" or "level" (the case's words)."""
    speed = reference_normal_speed(va, vb, normal)
    return "approaching" if speed < 0 else "separating" if speed > 0 else "level"


@reference
def normal_mistakes(va, vb, normal):
    """{name: what a known wrong normal_speed gives} for one case (names: checks.NORMAL_MISTAKES)."""
    va, vb, n = Vector2(va), Vector2(vb), Vector2(normal)
    right = (vb - va).dot(n)
    return {"sign": (va - vb).dot(n), "only_b": vb.dot(n), "only_a": va.dot(n), "length": (vb - va).length(),
            "sum": (vb + va).dot(n), "cross": (vb - va).cross(n), "abs": abs(right), "halved": right / 2,
            "clamped": min(0.0, right), "x_only": (vb - va).x}


def probe_normal_speed(module, lab_path):
    """The student's normal_speed on every case beside the lesson's answer and the known wrong forms."""
    rng = run_rng(module, "normal_speed")   # two pairs drawn for this run, one approaching and one separating
    drawn = []
    for what, sign in (("a pair drawn for this run, approaching", -1), ("a pair drawn for this run, separating", 1)):
        angle = rng.uniform(0, 2 * math.pi)
        normal = (math.cos(angle), math.sin(angle))
        va = (rng.uniform(-200, 200), rng.uniform(-200, 200))
        along = sign * rng.uniform(20, 300)
        drawn.append((what, va, (va[0] + along * normal[0] + rng.uniform(-50, 50) * normal[1],
                                 va[1] + along * normal[1] - rng.uniform(-50, 50) * normal[0]), normal))
    cases = []
    for what, va, vb, normal in CASES + tuple(drawn):
        got = module.normal_speed(Vector2(va), Vector2(vb), Vector2(normal))
        cases.append({"case": what, "va": list(va), "vb": list(vb), "normal": list(normal), "got": _number(got)})
        if judging(module):
            cases[-1]["want"] = reference_normal_speed(va, vb, normal)
            cases[-1]["how"] = reference_approach(va, vb, normal)
            cases[-1]["mistakes"] = normal_mistakes(va, vb, normal)
    return cases


# the step functions that answer a question and must leave their arguments as they got them
PURE = ("normal_speed",)

# probe name -> (the lab function it needs, the probe)
PROBES = {"normal_speed": ("normal_speed", probe_normal_speed)}
