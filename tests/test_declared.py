"""A declared function step (checker/declared.py) probes, compares, names a mistake and words the message.

A toy step, double(x) = 2 x, with three known wrong forms, graded as a lab's checks grade theirs:
  - a wrong form is named only when it alone gives the student's answer in every case (the one-formula rule);
    two forms that agree everywhere are not told apart, so neither is named;
  - a case's own diagnosis comes before the forms; a malformed answer is worded by the step;
  - the message is two lines (what is wrong, then one case's evidence) and carries the step's hint;
  - in the child (a tape.Recorder) the probe records the student's answers only: the lesson's answer and the
    wrong forms run when the grader replays the tape, never where the student's code runs.
The labs' own declared steps are held to their corpora (tests/test_corpus_<lab>.py).
"""
import types

import pytest

from checker.judging import declared, tape
from checker.judging.checks import Fail, Hint, Passed, Registry

HINTS = {"double": Hint(2, "doubling", "Return 2 x."), "crash": Hint(1, "run the file", "Run it."),
         "halves": Hint(2, "not halves", "Multiply, do not divide.")}
LESSON_CALLS = []


def lesson(case):
    LESSON_CALLS.append(case["x"])
    return 2 * case["x"]


def step(wrong, cases=(1, 2, 3), diagnose=None):
    return declared.Step(
        "doubles", "Step 2: double(x) is 2 x.", 2, "double", cases=lambda module: [{"x": x} for x in cases],
        call=lambda double, c: double(c["x"]), answer=lambda got: got if isinstance(got, int) else repr(got),
        lesson=lesson, wrong=wrong, same=lambda got, want: got == want, bad=lambda got: isinstance(got, str),
        malformed=lambda c: f"double() must return a number.\ndouble({c['x']}) returned {c['got']}.",
        diagnose=diagnose, evidence=lambda c: f"double({c['x']}) returned {c['got']}; expected {c['want']}.",
        unnamed="double() is not 2 x", hint="double", passed="2 x in all {n} cases")


FORMS = (declared.Form("double_adds", "double() adds 2 instead of doubling", lambda c: c["x"] + 2),
         declared.Form("double_squares", "double() squares x", lambda c: c["x"] * c["x"]),
         declared.Form("double_halves", "double() halves x", lambda c: c["x"] // 2, hint="halves"))


def graded(declared_step, double):
    """The step's check on a module whose double() is `double`, probed and judged in this process."""
    module = types.SimpleNamespace(double=double)
    return declared_step.judge(declared_step.probe(module, "lab.py"), HINTS)


def failure(declared_step, double):
    with pytest.raises(Fail) as caught:
        graded(declared_step, double)
    return caught.value


def test_the_lesson_passes_and_hands_on_its_cases():
    passed = graded(step(FORMS), lambda x: 2 * x)
    assert isinstance(passed, Passed) and passed.message == "2 x in all 3 cases" and len(passed.value) == 3


def test_the_one_form_that_fits_every_case_is_named_in_two_lines():
    fail = failure(step(FORMS), lambda x: x + 2)
    assert fail.mistake.id == "double_adds"
    assert fail.rationale == "double() adds 2 instead of doubling.\ndouble(1) returned 3; expected 2."
    assert fail.hint == HINTS["double"]
    assert failure(step(FORMS), lambda x: x // 2).hint == HINTS["halves"]   # a form's own hint


def test_a_form_that_fits_only_some_cases_is_not_named():
    fail = failure(step(FORMS), lambda x: x + 2 if x < 3 else 0)
    assert fail.mistake is None and fail.rationale.startswith("double() is not 2 x.\n")


def test_two_forms_the_cases_do_not_tell_apart_are_both_left_unnamed():
    twins = FORMS + (declared.Form("double_plus_two", "double() adds two", lambda c: c["x"] + 2),)
    fail = failure(step(twins), lambda x: x + 2)
    assert fail.mistake is None and "adds" not in fail.rationale


def test_a_form_that_agrees_with_the_lesson_in_the_failing_case_is_not_a_candidate():
    # at x = 2 squaring gives the lesson's 4, so a file wrong only at x = 2 is never "squares"
    fail = failure(step(FORMS, cases=(2,)), lambda x: 5)
    assert fail.mistake is None


def test_a_diagnosis_of_the_case_comes_before_the_forms_and_a_malformed_answer_is_worded():
    def negative(cases, case):
        return declared.Form("double_negative", "the sign is lost", line="double() returns -2 x") \
            if case["got"] == -case["want"] else None
    fail = failure(step(FORMS, diagnose=negative), lambda x: -2 * x)
    assert fail.mistake.id == "double_negative" and fail.mistake.text == "the sign is lost"
    assert fail.rationale.startswith("double() returns -2 x.\n")
    fail = failure(step(FORMS), lambda x: "two")
    assert fail.rationale == "double() must return a number.\ndouble(1) returned 'two'." and fail.mistake is None


def test_the_check_registers_with_its_id_and_description():
    registry = Registry()
    registry.check()(lambda sub: None)   # stands for the lab's `loads`, which a step's check depends on
    registry.checks[0].id = "loads"
    step(FORMS).register(registry, HINTS)
    check = registry.checks[1]
    assert check.id == "doubles" and check.description == "Step 2: double(x) is 2 x."


def test_in_the_child_the_probe_records_answers_only_and_the_grader_adds_the_lesson():
    student = types.ModuleType("lab")
    exec("def double(x):\n    return x + 2\n", student.__dict__)
    declared_step = step(FORMS)
    recorder = tape.Recorder(student, ("double",))
    LESSON_CALLS.clear()
    in_child = recorder.run(declared_step.probe, "lab.py")
    assert not LESSON_CALLS and all(set(case) == {"x", "got"} for case in in_child)
    handout = types.ModuleType("lab_handout")
    exec("def double(x):\n    return 0\n", handout.__dict__)   # the grader replays the tape: no student code
    replay = tape.Replayer(handout.__dict__, ("double",), recorder.take(), 0)
    judged = declared_step.probe(replay, "lab.py")
    assert LESSON_CALLS == [1, 2, 3] and [case["got"] for case in judged] == [3, 4, 5]
    assert judged[0]["forms"] == {"double_adds": 3, "double_squares": 1, "double_halves": 0}
    with pytest.raises(tape.ReferenceInChild):   # the framework's lesson_answers is a reference: never in the child
        recorder.run(lambda module, path: declared.lesson_answers(declared_step, {"x": 1}), "lab.py")


def test_the_framework_words_what_a_lab_leaves_out():
    """A step that gives only its label, how to show an answer and its kind: the evidence, the malformed answer,
    the unnamed mistake and the passing message are the framework's."""
    plain = declared.Step(
        "doubles", "Step 2: double(x) is 2 x.", 2, "double", lambda module: [{"x": x} for x in (1, 2, 3)],
        lambda double, c: double(c["x"]), lesson, hint="double", bad=lambda got: isinstance(got, str),
        label=lambda c: f"double({c['x']})", show=lambda value: f"{value} units", kind="a number", wrong=FORMS)
    assert graded(plain, lambda x: 2 * x).message == "all 3 cases match the lesson"
    assert failure(plain, lambda x: x + 2).rationale == ("double() adds 2 instead of doubling.\n"
                                                         "double(1) returned 3 units; expected 2 units.")
    assert failure(plain, lambda x: 0).rationale == ("double() does not give the lesson's answer.\n"
                                                     "double(1) returned 0 units; expected 2 units.")
    assert failure(plain, lambda x: "two").rationale == ("double() must return a number.\n"
                                                         "double(1) returned two; expected 2 units.")
    with pytest.raises(AssertionError):   # the hint is the one thing a step must always name
        declared.Step("doubles", "Step 2: double(x) is 2 x.", 2, "double", lambda module: [], None, lesson)


def test_numbers_lays_vectors_flat_and_words_what_is_not_numbers():
    from pygame import Vector2
    assert declared.numbers((Vector2(0.6, 0.8), 5), 3) == [0.6, 0.8, 5.0]
    assert declared.numbers((Vector2(1, 2), Vector2(3, 4)), 4) == [1.0, 2.0, 3.0, 4.0]
    assert declared.numbers(None, 3) is None
    assert all(isinstance(declared.numbers(raw, 3), str) for raw in ((Vector2(1, 0),), ("1", 2, 3), 7, [True, 1, 2]))
    same = declared.close(1e-9)
    assert same([1.0, 2.0], [1.0 + 1e-12, 2.0]) and same(None, None)
    assert not same([1.0, 2.0], [1.0, 2.001]) and not same(None, [1.0]) and not same("(1, 2)", [1.0, 2.0])
    assert declared.listed([1, -0.001, 8]) == "(1.00, 0.00, 8.00)" and declared.listed(None) == "None"


def test_stand_ins_are_in_place_while_the_step_is_probed_and_a_missing_name_is_put_in():
    """The lesson's functions stand in for the student's other steps during the probe and are taken out after it; a
    name the file lacks (a deleted import) gets its stand-in all the same, and is not put back."""
    student = types.SimpleNamespace(helper=lambda x: 0)
    seen = []

    def double(x):
        seen.append((student.helper(x), student.counted(x)))
        return 2 * x
    student.double = double
    declared_step = step(FORMS)
    declared_step.stand_ins = lambda module: {"helper": lambda x: x, "counted": lambda x: -x}
    passed = declared_step.judge(declared_step.probe(student, "lab.py"), HINTS)
    assert passed.message == "2 x in all 3 cases" and seen == [(1, -1), (2, -2), (3, -3)]
    assert student.helper(5) == 0 and student.counted(5) == -5


def test_answer_number_keeps_none_and_refuses_what_is_not_finite_when_asked():
    import math

    from checker.judging.common import answer_number
    assert answer_number(2) == 2.0 and answer_number(None) == {"bad": "None"}   # as before: None is no number
    assert answer_number(None, none=True) is None and answer_number(True, none=True) == {"bad": "True"}
    assert math.isnan(answer_number(float("nan")))   # NaN passes as a number unless refused
    assert answer_number(float("inf"), finite=True) == {"bad": "a number that is not finite: inf"}
    assert answer_number("1.5", none=True, finite=True) == {"bad": "'1.5'"}
