"""A declared step whose function acts on what it is given (checker/judging/declared_acts.py).

A toy step, move(a, b, offset): A goes back by offset, B forward, each through the module's kick(body, v) (a hook):
  - each call gets fresh bodies and vectors built from the case's plain inputs (bodies as cases), and its answer
    is read from them after the call, compared field by field;
  - a vector changed in place fails the step with mistake argument_changed, before any answer is compared;
  - the hooked function's calls are noted in the record (roles() names which given object each argument is);
  - a probed function may be another than the module's own (function_of), and `also` steps are judged under the
    same check, which passes with the `joint` message.
Ball on the Ramp's steps 2, 3, 4 and 7 are held to their corpus (tests/corpus_ball_on_ramp.py).
"""
import math
import types

import pytest
from pygame import Vector2

from checker.judging import declared_acts
from checker.judging.checks import Fail, Hint, Passed, Registry
from checker.judging.common import answer_point, same_point
from checker.judging.declared import Form
from checker.judging.declared_acts import (Acting, body_of, described, fields, first_differing, motion_difference,
                                           motions, roles, rows, same_motion)

HINTS = {"move": Hint(4, "moving apart", "A back, B forward."), "crash": Hint(1, "run the file", "Run it."),
         "arguments": Hint(4, "the offset", "Leave it alone.")}


def lesson(case):
    return {"a": list(Vector2(case["a"]["pos"]) - Vector2(case["offset"])),
            "b": list(Vector2(case["b"]["pos"]) + Vector2(case["offset"]))}


def kick_call(given, args, named):
    return roles(given, ("body", "v"), args, named)


def step(**more):
    return Acting(
        "moves_apart", "Step 4: move() moves A back and B forward by offset.", 4, "move",
        lambda module: [{"case": "two balls", "a": described(r=5, pos=Vector2(0, 0), mass=1.0),
                         "b": described(w=4, h=2, pos=(10, 0), mass=2.0, vel=Vector2(1, 0)), "offset": [1.0, 2.0]}],
        lambda move, g: move(g["a"], g["b"], g["offset"]), lesson,
        given=lambda c: {"a": body_of(c["a"]), "b": body_of(c["b"]), "offset": Vector2(c["offset"])},
        outcome=lambda g, raw: {k: answer_point(g[k].pos) for k in "ab"}, kept=("offset",),
        advice="make a new vector", changed_hint=HINTS["arguments"], hooks={"kick": kick_call},
        label=lambda c: f"for {c['case']}", same=fields(same_point, "ab"), hint="move",
        wrong=(Form("move_swapped", "A went forward and B back",
                    lambda c: {"a": list(Vector2(c["a"]["pos"]) + Vector2(c["offset"])),
                               "b": list(Vector2(c["b"]["pos"]) - Vector2(c["offset"]))}),),
        evidence=lambda c: f"A is at {c['got']['a']}; expected {c['want']['a']}.",
        passed="moved apart in all {n} cases", **more)


def module_with(move):
    def kick(body, v):
        body.pos += v
    return types.SimpleNamespace(move=move, kick=kick)


def lesson_move(module):
    def move(a, b, offset):
        module.kick(a, -offset)
        module.kick(b, offset)
    return move


def graded(declared_step, make_move):
    module = module_with(None)
    module.move = make_move(module)
    records = declared_step.probe(module, "lab.py")
    return records, declared_step.judge(records, HINTS)


def test_fresh_bodies_per_call_the_answer_read_after_it_and_the_hooks_calls_noted():
    records, passed = graded(step(), lesson_move)
    assert isinstance(passed, Passed) and passed.message == "moved apart in all 1 cases"
    (record,) = records
    assert record["got"] == {"a": [-1.0, -2.0], "b": [11.0, 2.0]} and record["changed"] == {}
    assert record["calls"] == ["a -", "b offset"]   # -offset is a new vector: no given object
    assert record["a"]["pos"] == [0.0, 0.0]   # the case's description is untouched by the call


def test_a_vector_changed_in_place_fails_first_with_argument_changed():
    def make(module):
        def move(a, b, offset):
            offset *= 2   # Vector2 *= changes the caller's vector
            module.kick(b, offset)
        return move
    with pytest.raises(Fail) as caught:
        graded(step(), make)
    fail = caught.value
    assert fail.mistake.id == "argument_changed" and fail.hint == HINTS["arguments"]
    assert fail.rationale == ("move() changed its argument offset in place: make a new vector.\nfor two balls, "
                              "offset went from (1.00, 2.00) to (2.00, 4.00); the caller goes on using it.")


def test_the_wrong_forms_are_named_from_the_answers_read_after_the_call():
    def make(module):
        def move(a, b, offset):
            module.kick(a, offset)
            module.kick(b, -offset)
        return move
    with pytest.raises(Fail) as caught:
        graded(step(), make)
    assert caught.value.mistake.id == "move_swapped"
    assert caught.value.rationale == "A went forward and B back.\nA is at [1.0, 2.0]; expected [-1.0, -2.0]."


def test_also_steps_are_judged_under_one_check_with_the_joint_message():
    other = step(probe_name="move_spliced", function_of=lambda module, path: lesson_move(module))
    first = step(also=(other,), joint=lambda lists: f"{len(lists[0])} and {len(lists[1])} cases")
    module = module_with(None)
    module.move = lesson_move(module)
    functions = {"move": {"ok": True, "data": first.probe(module, "lab.py")},
                 "move_spliced": {"ok": True, "data": other.probe(module_with(lambda a, b, o: None), "lab.py")}}
    registry = Registry()
    registry.check()(lambda sub: None)
    registry.checks[0].id = "loads"
    check = first.register(registry, HINTS)
    assert registry.checks[1].id == "moves_apart"
    passed = check(types.SimpleNamespace(name="lab.py"), functions)
    assert passed.message == "1 and 1 cases" and passed.value == functions["move"]["data"]
    functions["move_spliced"]["data"] = first.probe(module_with(lambda a, b, o: None), "lab.py")   # moves nothing
    with pytest.raises(Fail):
        check(types.SimpleNamespace(name="lab.py"), functions)


def test_fields_first_differing_and_roles():
    same = fields(lambda g, w: abs(g - w) < 1e-9, "xy")
    assert same({"x": 1, "y": 2}, {"x": 1, "y": 2}) and not same({"x": 1}, {"x": 1, "y": 2}) and not same(3, {})
    assert first_differing({"x": 1, "y": 3}, {"x": 1, "y": 2}, "xy", lambda g, w: g == w) == "y"
    assert first_differing({"x": 1}, {"x": 1}, "x", lambda g, w: g == w) is None
    a, b = object(), object()
    given = {"a": a, "b": b, "ra": Vector2(1, 2), "rb": Vector2(3, 4)}
    assert roles(given, ("a", "b", "p", "ra", "rb"), (b, a, Vector2(9, 9), (3, 4)), {"rb": Vector2(1, 2)},
                 ("a", "b", "ra", "rb")) == "b a rb ra"
    assert roles(given, ("a", "ra"), ("a", object()), {}) == "- -"


def test_body_of_builds_a_circle_a_box_or_a_polygon_from_plain_data():
    ball = body_of(described(r=5, pos=Vector2(1, 2), mass=2.0, vel=(3, 4), friction=0.1))
    assert ball.shape.radius == 5 and ball.pos == Vector2(1, 2) and ball.vel == Vector2(3, 4) and ball.friction == 0.1
    crate = body_of(described(w=4, h=2, pos=(0, 0), mass=0, angle=math.pi / 2))
    assert crate.inv_mass == 0 and len(crate.shape.points) == 4
    assert len(body_of({"points": [(0, 0), (2, 0), (0, 2)], "pos": (0, 0)}).shape.points) == 3
    assert described(pos=Vector2(1, 2), vel=(0, 1), omega=2.0) == {"pos": [1.0, 2.0], "vel": [0, 1], "omega": 2.0}


def test_stood_in_puts_the_modules_own_functions_back():
    module = types.SimpleNamespace(f=len)
    with declared_acts.stood_in(module, {"f": abs}):
        assert module.f is abs
    assert module.f is len


def test_answer_point_words_what_is_not_a_finite_point():
    assert answer_point(Vector2(1, 2)) == [1.0, 2.0] and answer_point((3, 4)) == [3.0, 4.0]
    assert answer_point(0.5) == {"bad": "the number 0.5, not a point", "number": 0.5}
    assert answer_point(Vector2(math.inf, 0))["bad"].startswith("a point that is not finite")
    assert "bad" in answer_point("(1, 2)") and "number" not in answer_point(10 ** 400)


def test_motions_are_compared_body_by_body_and_the_first_difference_worded():
    a, b = body_of(described(r=5, pos=(0, 0), mass=1.0, vel=(1, 2), omega=0.5)), body_of(described(r=5, pos=(9, 0)))
    got = motions(a=a, b=b)
    assert got == {"a": {"vel": [1.0, 2.0], "omega": 0.5}, "b": {"vel": [0.0, 0.0], "omega": 0.0}}
    want = {"a": got["a"], "b": {"vel": [0.0, 1.0], "omega": 0.0}}
    assert same_motion(got["a"], want["a"]) and not fields(same_motion, "ab")(got, want)
    assert motion_difference(got, want, "ab") == ("B ends with v (0.00, 0.00) px/s, ω 0.000 rad/s; the lesson's "
                                                  "(0.00, 1.00) px/s, 0.000 rad/s")


def test_rows_make_plain_cases_of_a_table():
    assert rows(("case", "p", "points", "r"), [("one", Vector2(1, 2), [Vector2(3, 4)], 5)]) == [
        {"case": "one", "p": [1.0, 2.0], "points": [[3.0, 4.0]], "r": 5}]


def test_a_collision_tests_answer_is_compared_and_worded():
    from checker.judging.declared_hits import hit_difference, hit_text, same_hit
    want = {"normal": [0.0, 1.0], "depth": 2.0}
    assert same_hit({"normal": [0.0, 1.0], "depth": 2.0}, want) and not same_hit(None, want)
    assert same_hit(None, None) and same_hit({"normal": [1.0, 0.0], "depth": 1e-7}, None)   # exactly touching
    assert not same_hit({"bad": "(depth, normal)"}, want) and not same_hit({"normal": [1.0, 0.0], "depth": 1.0}, None)
    assert hit_text(None) == "None (apart)" and hit_text(want) == "normal (0.00, 1.00), depth 2.000 px"
    assert hit_difference({"normal": [0.0, -1.0], "depth": 2.0}, want) == "normal (0.00, -1.00); expected (0.00, 1.00)"
    assert hit_difference({"normal": [0.0, 1.0], "depth": 1.0}, want) == "depth 1.000 px; expected 2.000 px"
    assert hit_difference(None, want) == "None (apart); expected normal (0.00, 1.00), depth 2.000 px"
    assert hit_difference({"bad": "(depth, normal)"}, want) == "(depth, normal)"
