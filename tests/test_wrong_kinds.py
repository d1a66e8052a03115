"""A step function that returns, or leaves in its arguments, a value of the wrong kind is the file's failure.

For each lab in checker/labs/ with a corpus (tests/labs_found.py) and each step function its corpus's WRONG_KINDS
names (else each step that returns its function's answer: tests/wrong_kinds.py derived_cases), this module writes student files whose step region
returns a wrong-kind value (a tuple where a Vector2 belongs, a Vector2 where a number belongs, a string, a
3-tuple, NaN, a bool, an int too big for a float, a dict, ...) or, for a function that changes its arguments,
leaves a body's field of the wrong kind. The other steps hold the solution's code. Each lab's files are graded in
ONE run of `python -m checker --json`, as a teacher runs it, and every file must get: a graded row (no "not
graded" / internal error), the function's check failing or erroring, and that check's message two short lines
(issue 40: tests/corpus_verdicts.message_problem) that do not blame the checker. Before these tests such values raised inside the checks' own arithmetic (TypeError,
OverflowError) and the file got "this is a bug in the checker".

The plausible mistakes among these are in the lab corpora too (tests/corpus_<lab>.py, with their SAYS words).
"""
import os
from types import SimpleNamespace

import pytest

import corpus_verdicts as verdicts
import labs_found
from corpus_files import CorpusFiles
from wrong_kinds import derived_cases

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# lab -> [(function, step, [step code or ("+", statement), ...])]: each lab's corpus's WRONG_KINDS, else the cases
# derived from the lab itself (tests/wrong_kinds.py)
CASES = {lab.id: getattr(labs_found.corpus(lab), "WRONG_KINDS", None) or derived_cases(lab)
         for lab in labs_found.with_corpus()}


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
    found = labs_found.by_id(lab)
    files = CorpusFiles(found.starter, found.solution, [step for _, step, _ in CASES[lab]], {}, "test_wrong_kinds")
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
    return labs_found.corpus(labs_found.by_id(lab)).CHECK_STEP.get(check)


@pytest.mark.parametrize("lab", labs_found.params(labs_found.with_corpus()))
def test_every_lab_has_wrong_kind_cases(lab):
    """From its corpus or derived from the lab: no lab with a corpus goes without (one without a corpus fails
    tests/test_corpus_labs.py)."""
    assert CASES[lab.id], (f"{lab.id}: no step of its solution returns its function's answer: list its wrong-kind "
                           f"cases as WRONG_KINDS in tests/corpus_{lab.id}.py (tests/wrong_kinds.py)")


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
