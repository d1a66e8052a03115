"""A step function that returns, or leaves in its arguments, a value of the wrong kind is the file's failure.

For each lab and each step function the checker probes, this module writes student files whose step region
returns a wrong-kind value (a tuple where a Vector2 belongs, a Vector2 where a number belongs, a string, a
3-tuple, NaN, a bool, an int too big for a float, a dict, ...) or, for a function that changes its arguments,
leaves a body's field of the wrong kind. The other steps hold the solution's code. Each lab's files are graded in
ONE run of `python -m checker --json`, as a teacher runs it, and every file must get: a graded row (no "not
graded" / internal error), the function's check failing or erroring, and that check's message two short lines
(issue 40: tests/corpus_verdicts.message_problem) that do not blame the checker. Before these tests such values raised inside the checks' own arithmetic (TypeError,
OverflowError) and the file got "this is a bug in the checker".

The plausible mistakes among these are in the lab corpora too (tests/corpus_<lab>.py, with their SAYS words).
"""
import importlib
import os
from types import SimpleNamespace

import pytest

import corpus_verdicts as verdicts
from corpus_files import CorpusFiles

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
V = "pygame.Vector2"   # the one module attribute a step may use (checker/reading/step_rules.py)

# wrong kinds by the kind the function returns
NUMBER = [f"{V}(1, 0)", "'1.5'", "[1.5]", "float('nan')", "True", "10 ** 400", "{'x': 1.0}", "10 ** 5000", "-float('inf')"]
VECTOR = ["(1.0, 2.0)", "[1.0, 2.0]", "3.0", f"{V}(float('nan'), 0)", "'v'", "{'x': 1.0}"]
POINTS = ["[(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)]", f"{V}(1, 0)", "[1.0, 2.0, 3.0]", "'abc'",
          f"[{V}(float('nan'), 0)] * 3", "5", "[{V}(1, 0), 'x', None]".replace("{V}", V)]
HIT = [f"({V}(1, 0), (1.0, 2.0))", "((1.0, 0.0), 2.0)", f"({V}(1, 0), 2.0, 3.0)", "2.0",
       f"({V}(1, 0), {V}(1, 0))", f"({V}(1, 0), float('nan'))", f"({V}(1, 0), '3')", f"({V}(1, 0), 10 ** 400)",
       "{'normal': 1}", f"({V}(1, 0), True)", f"({V}(0, float('inf')), 2.0)", "[[1.0, 0.0], 2.0]"]
TOI = ["(0.5, (1.0, 0.0))", f"({V}(1, 0), 0.5)", f"(0.5, {V}(1, 0), 1)", "0.5", f"('0.5', {V}(1, 0))",
       f"(float('nan'), {V}(1, 0))", f"(10 ** 400, {V}(1, 0))", f"(True, {V}(1, 0))"]
AS_TEXT = ["str(answer)"]
FLAGS = ["'yes'", f"{V}(1, 0)", "[True]", "float('nan')"]


def returns(values):
    """Each value as a step region's whole code: `return value`."""
    return [f"return {value}" for value in values]


def after_solution(statements):
    """Each statement run after the solution's own code of the step (a body left of the wrong kind)."""
    return [("+", statement) for statement in statements]


def wrapped(wraps):
    """Each wrap of the solution's own answer (`answer`), for a step region that holds its function's return: the
    right value in the wrong kind (a string, a one-item list) must fail as surely as a wrong value."""
    return [("wrap", wrap) for wrap in wraps]


def substituted(old, news):
    """The solution's code with `old` replaced by each of `news` (a hook called with a wrong-kind argument)."""
    return [("sub", old, new) for new in news]


def before_solution(statements):
    """Each statement run before the solution's own code of the step (for a step region that returns)."""
    return [("pre", statement) for statement in statements]


MOTION = ["a.omega = 'spin'", "b.omega = float('nan')", "a.omega = [0.5]", "b.omega = 10 ** 400",
          f"a.vel = {V}(float('nan'), 0)", "b.vel = (0.0, 0.0)"]
PLACES = ["a.pos = (1.0, 2.0)", "b.pos = 'here'", f"b.pos = {V}(float('nan'), 0)", "a.angle = [0.5]",
          f"b.angle = {V}(1, 0)", "b.pos = None"]

# lab -> [(function, step, [step code or ("+", statement)])]
CASES = {
    "tumbling_crates": [("sat", 2, returns(HIT)), ("apply_impulse", 6, after_solution(MOTION)),
                        ("resolve", 4, after_solution(MOTION[:3] + ["a.pos = 'x'", f"k += {V}(1, 0)", "k = float('nan')",
                                                                    "k = '1'"])),
                        ("resolve", 5, after_solution([f"jt = {V}(1, 0)", "jt = (1.0, 0.0)", "jt = float('inf')",
                                                       "jt = 10 ** 400", "jt = None"]))],
    "more_shapes": [("regular_polygon", 2, returns(POINTS) + wrapped(AS_TEXT + ["[str(p) for p in answer]"])),
                    ("polygon_centroid", 3, returns(VECTOR) + wrapped(AS_TEXT + ["[answer]"])),
                    ("polygon_inertia", 4, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]", "(answer,)"])),
                    ("separating_axes", 5, returns(POINTS))],
    "ball_on_ramp": [("closest_on_segment", 2, returns(VECTOR) + wrapped(AS_TEXT + ["[answer]"])), ("circle_polygon", 3, returns(HIT)),
                     ("separate", 4, after_solution(PLACES)), ("disc_inertia", 5, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]"])),
                     ("contact_point", 6, returns(VECTOR) + wrapped(AS_TEXT)), ("resolve", 7, after_solution(MOTION[:4]) + substituted(
                         "apply_impulse(a, b, t * jt, ra, rb)",
                         ["apply_impulse(a, b, (t * jt).x, ra, rb)", "apply_impulse(a, b, tuple(t * jt), ra, rb)",
                          "apply_impulse(a, b, t * jt, tuple(ra), rb)", "apply_impulse(a, b, t * jt, ra, 'rb')"]))],
    "sleeping_crates": [("sleep_timer", 2, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]"])),
                        ("moves", 3, returns(FLAGS) + wrapped(["[answer]"])
                         + before_solution(["body.asleep = 'no'", "body.vel = None", "body.sleep_time = 'x'"])),
                        ("wake_on_contact", 4, returns(["a", "(a, b)", "[a, 'b']", "'ab'", "[a, b, a] * 400",
                                                        "5", "{'a': a}"])
                         + before_solution(["a.asleep = [1]", "b.omega = 'x'"]))],
    "bullets": [("circle_toi", 2, returns(NUMBER) + wrapped(["None if answer is None else str(answer)",
                                                             "None if answer is None else [answer]"])),
                ("bounding_radius", 3, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]"])),
                ("time_of_impact", 4, returns(TOI) + before_solution(["bullet.vel = (1.0, 2.0)", "other.omega = 'x'"])),
                ("swept_move", 5, after_solution(["bullet.pos = (1.0, 2.0)", "bullet.vel = 'fast'",
                                                  f"bullet.pos = {V}(float('nan'), 0)",
                                                  f"bullet.omega = {V}(1, 0)", "bullet.vel = None"])
                 + substituted("normal, bullet.pos + normal * bullet.radius)",
                               ["normal, 'here')",
                                "normal, None)", "tuple(normal), bullet.pos + normal * bullet.radius)"]))],
}


def _entries(lab):
    """{file stem: (function, step, code)} for the lab's cases."""
    out = {}
    for function, step, codes in CASES[lab]:
        for index, code in enumerate(codes):
            out[f"{lab}_{function}_step{step}_{index}"] = (function, step, code)
    return out


def _code(solution, code):
    """A step region's code from a case: its own text, the solution's then a statement ("+"), or the solution's
    inside a local function whose answer is returned wrapped ("wrap")."""
    if not isinstance(code, tuple):
        return code
    kind, text = code[:2]
    if kind == "+":
        return solution + "\n" + text
    if kind == "pre":
        return text + "\n" + solution
    if kind == "sub":   # ("sub", old, new): the solution's code with one call's argument of the wrong kind
        assert solution.count(code[1]) == 1, code
        return solution.replace(code[1], code[2])
    inner = "\n".join("    " + line if line.strip() else "" for line in solution.split("\n"))
    return f"def right():\n{inner}\nanswer = right()\nreturn {text}"


def _build(lab, directory):
    """Write the lab's wrong-kind files; {path: (function, step, code)}."""
    files = CorpusFiles(os.path.join(ROOT, "starters", f"{lab}_starter.py"), os.path.join(ROOT, "solutions", f"{lab}.py"),
                        [step for _, step, _ in CASES[lab]], {}, "test_wrong_kinds")
    solution = open(files.solution, encoding="utf-8").read()
    solved = files.step_code(solution)
    built = {}
    for stem, (function, step, code) in _entries(lab).items():
        text = _code(solved[step], code)
        files.by_name[stem] = SimpleNamespace(steps={step: text}, edits=())
        path = os.path.join(directory, f"{stem}.py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(files.build(stem))
        built[path] = (function, step, text)
    return built


def _step_of(check, lab):
    """The step a check's hint names, read from the lab's corpus module (CHECK_STEP)."""
    return importlib.import_module(f"corpus_{lab}").CHECK_STEP.get(check)


@pytest.fixture(scope="module", params=sorted(CASES))
def graded(request, tmp_path_factory):
    """(lab, {path: (function, step, code)}, {path: {check id: the check's JSON}}) from one checker run over the
    lab's files (corpus_verdicts.grade: every file graded as the lab, no internal error stops the batch)."""
    lab = request.param
    built = _build(lab, tmp_path_factory.mktemp(lab))
    return lab, built, verdicts.grade({path: path for path in built}, lab)


def test_a_wrong_kind_is_the_files_failure_never_the_checkers(graded):
    lab, built, rows = graded
    problems = []
    for path, (function, step, code) in built.items():
        checks = rows[path]
        what = f"{os.path.basename(path)} ({function}, step {step}: {code.splitlines()[-1].strip()})"
        if not checks:   # not graded: the checker failed on the file (its message is on the row)
            problems.append(f"{what}: not graded")
            continue
        mine = [c for cid, c in checks.items() if _step_of(cid, lab) == step]
        if not mine or not any(c["status"] in ("fail", "error") for c in mine):
            problems.append(f"{what}: its step's checks " + "; ".join(f"{c['id']} {c['status']}" for c in mine))
        for check in checks.values():
            message = check.get("message") or ""
            if "bug in the checker" in message or message.strip().count("\n") > 1 or len(message) > 600:
                problems.append(f"{what}: {check['id']}: {message[:300]!r}")
            elif check["status"] in ("fail", "error") and verdicts.message_problem(check):
                problems.append(f"{what}: {check['id']}: {verdicts.message_problem(check)}")
    assert not problems, "\n".join(problems)


# ---------------------------------------------------------------- the helpers, on the values above

def test_real_reads_numbers_only():
    from checker.judging.common import real
    assert real(3) == 3.0 and real(-0.5) == -0.5 and real(float("inf")) == float("inf")
    for value in ("1.5", True, [1.5], None, {"x": 1.0}):
        with pytest.raises(TypeError):
            real(value)
    with pytest.raises(ValueError, match="too large for a float"):   # not OverflowError: the probes catch ValueError
        real(10 ** 400)


def test_a_body_left_with_a_non_finite_or_non_number_motion_is_named():
    from pygame import Vector2
    from checker.judging.tape import motion_problem

    def body(**fields):
        return SimpleNamespace(**{"pos": Vector2(1, 2), "vel": Vector2(), "angle": 0.5, "omega": 0, **fields})
    assert motion_problem([body()]) == ""
    for field, value, says in (("omega", True, "not a number (rad/s)"), ("omega", float("nan"), "not a finite number"),
                               ("omega", 10 ** 400, "too large for a float"), ("angle", [0.5], "not a number (rad)"),
                               ("vel", Vector2(float("inf"), 0), "not finite (px/s)"), ("pos", (1, 2), "not a Vector2")):
        problem = motion_problem([body(), body(**{field: value})])
        assert problem.startswith(f"left a body's {field} as ") and says in problem, problem


def test_an_int_beyond_json_crosses_the_tape_as_a_named_stand_in():
    from checker.judging.common import value_text
    from checker.judging.tape import decode, encode
    assert encode(2 ** 1000, None) == 2 ** 1000
    back = decode(encode(10 ** 5000, None), None)
    assert value_text(back) == "<an int of 16610 bits: too large for a float>"
    assert value_text(10 ** 5000) == "<an int of 16610 bits>" and len(value_text("x" * 500)) == 60   # repr of 10**5000 raises
