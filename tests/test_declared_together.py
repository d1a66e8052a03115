"""Three additions to declared steps (checker/judging/declared.py), on toy steps graded as a lab's are:
  - Step.accepts: a comparison that needs the case's own inputs (here a tolerance from the case's size) decides
    whether an answer is the lesson's, while the wrong forms still match by Step.same;
  - declared.register_together: one check judging two Steps (two probes of one lesson step) in order,
    the first failing Step's message its message, the pass worded from both Steps' judged cases;
  - common.as_number/as_point/as_points: a returned number, point or list of points as plain data, else the text of what it is.
"""
import types

import pytest
from pygame import Vector2

from checker.judging import common as answer_kinds, declared
from checker.judging.checks import Fail, Hint, Passed, Registry
from checker.judging.declared import register_together

HINTS = {"scale": Hint(2, "scaling", "Return x times the size."), "crash": Hint(1, "run the file", "Run it.")}


def scaled(**more):
    """scale(x, size) = x · size, judged to 1e-3 of the case's size (accepts) or exactly (same, for the forms)."""
    fields = dict(cases=lambda module: [{"x": x, "size": size} for x, size in ((1, 1.0), (2, 1000.0))],
                  call=lambda scale, c: scale(c["x"], c["size"]), lesson=lambda c: c["x"] * c["size"],
                  hint="scale", same=lambda got, want: got == want,
                  wrong=(declared.Form("scale_plus", "scale() adds the size", lambda c: c["x"] + c["size"]),))
    fields.update(more)
    return declared.Step("scales", "Step 2: scale(x, size) is x times the size.", 2, "scale", **fields)


def judged(step, function):
    return step.judge(step.probe(types.SimpleNamespace(**{step.function: function}), "lab.py"), HINTS)


def test_accepts_reads_the_case_and_the_forms_still_match_by_same():
    tolerant = scaled(accepts=lambda c: abs(c["got"] - c["want"]) <= 1e-3 * c["size"])
    assert isinstance(judged(tolerant, lambda x, size: x * size + 1e-4 * size), Passed)   # within 1e-3 of the size
    with pytest.raises(Fail):
        judged(scaled(), lambda x, size: x * size + 1e-4 * size)   # without accepts, same() decides: exactly
    with pytest.raises(Fail) as caught:
        judged(tolerant, lambda x, size: x + size)
    assert caught.value.mistake.id == "scale_plus"


def test_two_steps_in_one_check_are_judged_in_order():
    first = scaled()
    second = declared.Step("scales", "", 2, "halve", lambda module: [{"x": 4}], lambda halve, c: halve(c["x"]),
                           lambda c: c["x"] / 2, hint="scale", unnamed="halve() does not halve")
    registry = Registry()
    registry.check()(lambda sub: None)   # stands for the lab's `loads`
    registry.checks[0].id = "loads"
    register_together((first, second), registry, HINTS, "scales", "Step 2: scale() and halve().",
                      lambda a, b: Passed(f"{len(a.value)} and {len(b.value)} cases", value=a.value))
    check = registry.checks[1]
    assert check.id == "scales" and check.description == "Step 2: scale() and halve()."

    def functions(scale, halve):
        return {name: {"ok": True, "data": step.probe(types.SimpleNamespace(**{name: function}), "lab.py")}
                for name, step, function in (("scale", first, scale), ("halve", second, halve))}
    sub = types.SimpleNamespace(name="lab.py", flags=())
    assert check.func(sub, functions(lambda x, s: x * s, lambda x: x / 2)).message == "2 and 1 cases"
    with pytest.raises(Fail) as caught:   # the first Step fails first, though the second fails too
        check.func(sub, functions(lambda x, s: x + s, lambda x: 0))
    assert caught.value.mistake.id == "scale_plus"
    with pytest.raises(Fail) as caught:
        check.func(sub, functions(lambda x, s: x * s, lambda x: 0))
    assert caught.value.rationale.startswith("halve() does not halve.\n")


def test_answer_kinds_give_plain_data_or_the_text_of_what_came_back():
    assert answer_kinds.as_number(3) == 3.0 and answer_kinds.as_number("3") == "'3'"
    assert answer_kinds.is_text(answer_kinds.as_number(True)) and answer_kinds.is_text(answer_kinds.as_number(None))
    assert answer_kinds.as_point(Vector2(1, 2)) == [1.0, 2.0] and answer_kinds.as_point((3, 4)) == [3.0, 4.0]
    assert answer_kinds.is_text(answer_kinds.as_point([Vector2(1, 2)]))   # a point in a list is not a point
    # a bare number is no point (Vector2(20.0) would read it as (20, 20): More Shapes' centroid once called a
    # returned 20.0 a wrong centroid at (20, 20)); nor is a point that is not finite
    assert answer_kinds.as_point(20.0) == "the number 20.0, not a point"
    assert answer_kinds.as_point((float("nan"), 1)) == "a point that is not finite: (nan, 1)"
    assert answer_kinds.as_points([Vector2(1, 2), (3, 4)]) == [[1.0, 2.0], [3.0, 4.0]]
    assert answer_kinds.is_text(answer_kinds.as_points(Vector2(1, 2).x))
    assert answer_kinds.is_text(answer_kinds.as_points(["a"]))
