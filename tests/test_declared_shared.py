"""Declared steps graded on an existing probe's records (checker/judging/declared_shared.py).

A toy probe records one call of push(x) per case: the impulse it applied (j) and, from the grader, the lesson's
numbers (k). Two SharedSteps read it, as two steps of one function do in a lab:
  - the step reads the student's answer from the record, computes the lesson's and the wrong forms' answers
    there, and Step.judge names a form by the one-formula rule and words the two lines;
  - a screen fails before the cases (an argument changed in place: causes.SHARED's argument_changed) or keeps
    the records to grade, and receives what the checks it depends on returned;
  - a probe that holds no data (None) hands over to the step's fallback probes;
  - `accepts` decides a pass from more of the case than its two answers; a fallback Form after the forms.
"""
import types

import pytest

from checker.judging import declared
from checker.judging.checks import Fail, Hint, Passed, Registry
from checker.judging.declared_shared import SharedStep, unchanged_arguments

HINTS = {"push": Hint(4, "the push", "j = 2 k."), "crash": Hint(1, "run the file", "Run it."),
         "args": Hint(4, "the arguments", "Leave them alone.")}
SUB = types.SimpleNamespace(flags=(), function_steps={}, name="lab.py", source="")
FORMS = (declared.Form("push_half", "push() halves k instead of doubling it", lambda c: c["k"] / 2),
         declared.Form("push_plus", "push() adds 2 to k", lambda c: c["k"] + 2))


def records(*pairs, **more):
    return [dict({"case": f"case {n}", "k": k, "j": j}, **more) for n, (k, j) in enumerate(pairs)]


def step(**more):
    settings = dict(probe_name="push", read=lambda c: c["j"], lesson=lambda c: 2 * c["k"], wrong=FORMS,
                    evidence=lambda c: f"in '{c['case']}', j = {c['got']}; expected {c['want']}.", hint="push",
                    passed="j = 2 k in all {n} cases")
    settings.update(more)
    return SharedStep("pushes", "Step 4: push() applies j = 2 k.", 4, "push", **settings)


def run(shared, data, *given, probe="push", depends=("loads",)):
    """The step's registered check on probe data `data`, bypassing the probe run."""
    registry = Registry()
    registry.check()(lambda sub: None)   # stands for the lab's `loads`
    registry.checks[0].id = "loads"
    if len(depends) > 1:
        registry.check()(lambda sub: None)
        registry.checks[1].id = depends[1]
    check = shared.register(registry, HINTS, depends=depends)
    return check(SUB, {probe: {"ok": True, "data": data}}, *given)


def test_a_shared_step_reads_the_records_and_the_framework_judges_them():
    passed = run(step(), records((1.0, 2.0), (3.0, 6.0)))
    assert isinstance(passed, Passed) and passed.message == "j = 2 k in all 2 cases"
    assert passed.value[1]["got"] == 6.0 and passed.value[1]["forms"] == {"push_half": 1.5, "push_plus": 5.0}
    with pytest.raises(Fail) as caught:
        run(step(), records((1.0, 0.5), (4.0, 2.0)))
    assert caught.value.mistake.id == "push_half"
    assert caught.value.rationale == "push() halves k instead of doubling it.\nin 'case 0', j = 0.5; expected 2.0."
    with pytest.raises(Fail) as caught:   # one case fits a form, the other does not: nothing is named
        run(step(), records((1.0, 0.5), (4.0, 9.0)))
    assert caught.value.mistake is None and caught.value.rationale.startswith("push() does not give")
    assert step().probes() == {}   # the probe is the lab's own


def test_a_screen_fails_first_and_keeps_the_records_to_grade():
    changed = records((1.0, 2.0), changed={"normal": [0.0, -2.0]})
    with pytest.raises(Fail) as caught:
        run(step(screen=unchanged_arguments("push", "the caller goes on using its {name}", HINTS["args"])), changed)
    assert caught.value.mistake.id == "argument_changed" and caught.value.hint is HINTS["args"]
    assert caught.value.rationale.startswith("push() changed its argument normal in place")
    assert "\nin 'case 0', normal became (0.00, -2.00); the caller goes on using its normal." in caught.value.rationale
    graded = step(screen=lambda cases, sub: [case for case in cases if case["j"] is not None])
    assert run(graded, records((1.0, 2.0), (5.0, None))).message == "j = 2 k in all 1 cases"


def test_the_screen_gets_what_the_checks_it_depends_on_returned():
    seen = []
    screened = step(screen=lambda cases, sub, before: seen.append(before) or cases)
    run(screened, records((1.0, 2.0)), "from step 3", depends=("loads", "step3"))
    assert seen == ["from step 3"]


def test_a_probe_without_data_hands_over_to_the_fallback_probe():
    shared = step(probe_name="spliced", fallbacks=("push",))
    registry = Registry()
    registry.check()(lambda sub: None)
    registry.checks[0].id = "loads"
    check = shared.register(registry, HINTS)
    functions = {"spliced": {"ok": True, "data": None}, "push": {"ok": True, "data": records((2.0, 4.0))}}
    assert check(SUB, functions).message == "j = 2 k in all 1 cases"


def test_accepts_reads_the_whole_case_and_a_fallback_form_follows_the_forms():
    strict = step(accepts=lambda c: c["got"] == c["want"] and c["k"] > 0,
                  fallback=lambda cases, c: declared.Form(None, "k must be positive", hint="args") if c["k"] <= 0
                  else None)
    with pytest.raises(Fail) as caught:
        run(strict, records((-1.0, -2.0)))
    assert caught.value.rationale.startswith("k must be positive.\n") and caught.value.hint is HINTS["args"]
    with pytest.raises(Fail) as caught:   # a form that fits every case is named before the fallback
        run(strict, records((1.0, 0.5), (4.0, 2.0)))
    assert caught.value.mistake.id == "push_half"


def test_a_step_without_accepts_compares_its_two_answers():
    plain = declared.Step("doubles", "Step 2: double(x) is 2 x.", 2, "double", lambda module: [{"x": 1}],
                          lambda double, c: double(c["x"]), lambda c: 2 * c["x"], hint="double")
    assert plain.accepts is None
    assert plain.judge([{"x": 1, "got": 2, "want": 2, "forms": {}}], {"double": None}).message == \
        "all 1 cases match the lesson"
