"""Billiards: the checks and the hints (written by `python -m checker new-lab`; make them yours).

Order of checks: loads, handout_unchanged, runtime_lines, normal_speed_right (step 2), runs (the scene).
normal_speed_right reads checker/labs/billiards/probes.py's cases, names the first that differs, and the
mistake when exactly one known wrong form (NORMAL_MISTAKES) gives the student's answer in every case.
"""
from checker.judging import lab_checks
from checker.judging.causes import consistent_mistake, mistake
from checker.judging.checks import Fail, Hint, Registry
from lesson11 import records as metrics
from . import scenes

TITLE = "Billiards"
# the library functions step 2 asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("relative_velocity",)}
STEP_ADVICE = {2: "subtract the velocities and take the dot product with the normal yourself"}

RELATIVE = 1e-9   # the answer against (vB - vA) · n, relative to its size (other orders of the same sums differ)

HINTS = {
    "normal": Hint(2, "the speed along the normal",
                   "Section 5: the relative velocity is B's minus A's; its part along the unit normal n (from A "
                   "to B) is a dot product, negative while the bodies approach."),
    "handout": lab_checks.handout_hint("the scene, the World, the `# lab runtime` lines, the final print"),
    "runtime": lab_checks.RUNTIME_HINT,
    "crash": Hint(1, "run the file", "Run the file yourself (python billiards.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("drop",)}

# CPU s of the solution's run of each scene (the template's: 0.4 s in a child process; measure yours again when
# the scene changes: the grader starts the longest first).
SCENE_SECONDS = {"drop": 0.4}

CHECKS = Registry()

lab_checks.register_common(CHECKS, HINTS, ("normal_speed", "main"))

# the known wrong forms of step 2, by the name the probe gives their answers (probes.normal_mistakes)
NORMAL_MISTAKES = {
    "sign": "you take A's velocity relative to B's: vB - vA, so that approaching reads negative",
    "only_b": "only B's velocity is projected: subtract A's first",
    "only_a": "only A's velocity is projected: take B's minus A's",
    "length": "the length of vB - vA is not its part along the normal: take the dot product with n",
    "sum": "vB + vA is projected: the relative velocity is vB - vA",
    "cross": "a cross product gives the part across the normal: take the dot product",
    "abs": "the speed lost its sign: approaching must read negative",
    "halved": "the speed is halved: (vB - vA) · n has no factor 1/2",
    "clamped": "a separating pair reads 0: keep the positive speeds too",
    "x_only": "only the x part is taken: the normal is not always along x, take the dot product",
}


def _mistake(cases, case):
    """The Mistake of the one known wrong form that gives the student's answer in every case, or None."""
    def close(got, value):
        return abs(got - value) <= RELATIVE * max(1.0, abs(value))
    named = consistent_mistake(cases, lambda c, name: close(c["got"], c["mistakes"][name]),
                               [name for name, value in case["mistakes"].items() if not close(value, case["want"])])
    return mistake(f"normal_{named}", NORMAL_MISTAKES[named]) if named else None


@CHECKS.check(depends=["loads"])
def normal_speed_right(sub, functions):
    """Step 2: normal_speed(va, vb, normal) is (vB - vA) · n, negative while the bodies approach."""
    cases = lab_checks.function_data(sub, functions, "normal_speed", "normal_speed", 2, HINTS["crash"])
    numbers = all(not isinstance(c["got"], str) for c in cases)
    for case in cases:
        got, want = case["got"], case["want"]
        label = (f"normal_speed({lab_checks.vec_text(case['va'])}, {lab_checks.vec_text(case['vb'])}, "
                 f"{lab_checks.vec_text(case['normal'])}) ({case['case']})")
        if isinstance(got, str):
            raise Fail(f"normal_speed() must return a number (px/s).\n{label} returned {got}.", HINTS["normal"])
        if abs(got - want) <= RELATIVE * max(1.0, abs(want)):
            continue
        found = _mistake(cases, case) if numbers else None
        first = found.text if found else "the speed along the normal is not (vB - vA) · n"
        raise Fail(f"{first}.\n{label} gave {got:.6g} px/s; expected {want:.6g} ({case['how']}).", HINTS["normal"],
                   found)
    return f"all {len(cases)} pairs (approaching, separating, sliding past, at rest) read (vB - vA) · n"


@CHECKS.check(after=["loads", "handout_unchanged", "runtime_lines", "normal_speed_right"], needs_scenarios=True)
def runs(sub):
    """main() runs the checker's scene to the end."""
    records = lab_checks.scene_records(sub, scenes.SCENARIOS, HINTS["crash"], HINTS["runtime"])
    for name, run in records.items():
        if not metrics.finite(run.record["records"]):
            raise Fail(f"a crate's position or speed became infinite or NaN.\nin the '{name}' scene.",
                       HINTS["crash"])
    return f"main() ran {', '.join(records)} to the end"
