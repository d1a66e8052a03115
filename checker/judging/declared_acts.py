"""Declared steps whose function acts on what it is given (declared.Step, extended for any lab).

Acting is a declared.Step (the same cases, wrong forms, naming and words) for a function that moves bodies or
must leave its arguments alone: each call gets fresh arguments built from the case's plain inputs (bodies as
cases), its answer may be read from them after the call, a vector it changed in place fails the step (mistake
argument_changed), calls it makes to a hooked function are noted, the probed function may be a spliced one, and
more Steps may be judged under the same check. Helpers: rows() makes cases of a table, body_of() a case's body
from its plain description, motions() reads bodies' motion back, fields() compares dict answers field by field,
roles() tells which given objects a hooked call was passed.
"""
from dataclasses import dataclass, field

from pygame import Vector2

from lesson11.physics2d import Body, Circle, box_points

from . import lab_checks
from .checks import Hint, Passed
from .common import close
from .declared import Step, lesson_answers, register_together, stood_in
from .tape import judging


def fields(same, keys):
    """A Step's `same` for dict answers: every field in `keys` agrees by same(got field, want field)."""
    return lambda got, want: isinstance(got, dict) and all(k in got and same(got[k], want[k]) for k in keys)


def first_differing(got, want, keys, same):
    """The first of `keys` whose field differs by `same` (None when all agree): which body to name."""
    return next((k for k in keys if not (isinstance(got, dict) and k in got and same(got[k], want[k]))), None)


def rows(keys, table):
    """A step's cases as plain dicts from a table of tuples, {key: value} in `keys`' order: Vector2s (also in
    lists) become lists, as the tape and the messages want them."""
    def plain(value):
        return list(value) if isinstance(value, Vector2) else [plain(v) for v in value] if isinstance(value, list) \
            else value
    return [{key: plain(value) for key, value in zip(keys, row)} for row in table]


def described(**spec):
    """A body's plain description for a case (its vectors pos and vel as lists): the keys of body_of()."""
    return {key: list(value) if key in ("pos", "vel") else value for key, value in spec.items()}


def body_of(spec):
    """A fresh Body from a case's plain description: a circle of radius "r", a "w" × "h" box or a polygon's
    "points"; every other key is Body's own (pos, mass, angle, vel, omega, restitution, friction)."""
    shape = Circle(spec["r"]) if "r" in spec else box_points(spec["w"], spec["h"]) if "w" in spec else spec["points"]
    return Body(shape, **{key: value for key, value in spec.items() if key not in ("r", "w", "h", "points")})


def motions(**bodies):
    """Each body's motion as plain data, {name: {"vel": [x, y], "omega": w}} (px/s, rad/s): an answer read from
    the bodies a step changed."""
    return {name: {"vel": [body.vel.x, body.vel.y], "omega": body.omega} for name, body in bodies.items()}


def same_motion(got, want):
    """One body's motion (motions()) agrees: its velocity and spin, each number by common.close."""
    return close(got["omega"], want["omega"]) and all(close(g, w) for g, w in zip(got["vel"], want["vel"]))


def motion_difference(got, want, keys):
    """The first of `keys` whose motion differs (else the last), as "B ends with v (x, y) px/s, ω w rad/s; the
    lesson's (x, y) px/s, w rad/s"."""
    key = first_differing(got, want, keys, same_motion) or keys[-1]
    mine, lesson = got[key], want[key]
    return (f"{key.upper()} ends with v {lab_checks.vec_text(mine['vel'])} px/s, ω {mine['omega']:.3f} rad/s; the "
            f"lesson's {lab_checks.vec_text(lesson['vel'])} px/s, {lesson['omega']:.3f} rad/s")


def roles(given, params, args, named, which=None):
    """Which item of `given` each argument of a hooked call is, for the parameters in `which` (default all):
    "b a rb ra" (an object by identity, a vector within 1e-9 of one; "-" none): a call's order, for a hook's
    describe."""
    bound = dict(zip(params, args), **named)
    return " ".join(next((name for name, value in given.items() if _is(bound.get(param), value)), "-")
                    for param in which or params)


def _is(argument, value):
    """`argument` is `value` itself, or a vector within 1e-9 of the Vector2 `value`."""
    if argument is value:
        return True
    try:
        return isinstance(value, Vector2) and abs(argument[0] - value.x) <= 1e-9 and abs(argument[1] - value.y) <= 1e-9
    except (TypeError, IndexError, ValueError):
        return False


def noting(module, hooks, given, calls):
    """{name: a stand-in for module.<name>} that calls the module's own and appends describe(given, args, named)
    to `calls` first, for each {name: describe} in `hooks` whose function the module has."""
    def wrap(original, describe):
        def noted(*args, **named):
            calls.append(describe(given, args, named))
            return original(*args, **named)
        return noted
    return {name: wrap(getattr(module, name), describe) for name, describe in hooks.items()
            if callable(getattr(module, name, None))}


@dataclass
class Acting(Step):
    """A declared.Step whose `call(function, given)` receives given(case): the call's arguments, fresh objects
    (Vector2s, Bodies) built from the case's plain inputs; `outcome(given, raw)`: the answer, read from the
    arguments after the call (None: `answer(raw)`). kept: the names in `given` (vectors, also in the case as
    lists) the function must leave as it got them, `advice` what to do instead, `user` who goes on using a changed
    argument (for the message), `changed_hint` the hint's key or
    a Hint (None: the step's). hooks: {name of a module function: describe(given, args, named)}: each call of it
    during the call is noted in the record's "calls". function_of(module, lab_path): the function probed (e.g. a
    spliced one; None: the module's). also: more Steps judged in order under this check once its cases pass;
    joint(case lists): the check's passing message then (the first list is its value)."""
    given: object = None
    outcome: object = None
    kept: tuple = ()
    advice: str = "make a new vector"
    user: str = "the caller goes on using it"
    changed_hint: object = None
    hooks: dict = field(default_factory=dict)
    function_of: object = None
    also: tuple = ()
    joint: object = None

    def probe(self, module, lab_path):
        """Every case's record: the student's answer, what changed in place, the noted calls; in the grader also
        the lesson's and the wrong forms' answers (declared.lesson_answers)."""
        with stood_in(module, self.stand_ins(module) if self.stand_ins else {}):
            function = self.function_of(module, lab_path) if self.function_of else getattr(module, self.function)
            return [self.record(module, function, case) for case in self.cases(module)]

    def record(self, module, function, case):
        """One case's record: the case, the student's answer, what changed in place and the noted calls."""
        given = self.given(case)
        before = {name: Vector2(given[name]) for name in self.kept}
        calls = []
        with stood_in(module, noting(module, self.hooks, given, calls)):
            raw = self.call(function, given)
        got = self.outcome(given, raw) if self.outcome else raw if self.answer is None else self.answer(raw)
        record = dict(case, got=got, changed={name: list(given[name]) for name in self.kept
                                              if given[name] != before[name]}, calls=calls)
        if judging(module):
            record.update(lesson_answers(self, case))
        return record

    def judge(self, cases, hints):
        """Fail for the first argument changed in place, else declared.Step.judge."""
        for case in cases:
            for name, now in (case.get("changed") or {}).items():
                hint = self.changed_hint or self.hint
                raise lab_checks.argument_changed(self.function, name, self.advice, self.named_case(case), now,
                                                  self.user, hint if isinstance(hint, Hint) else hints[hint],
                                                  before=case[name])
        return super().judge(cases, hints)

    def register(self, registry, hints, depends=("loads",), after=(), max_score=1.0):
        """declared.Step.register, judging the `also` steps after this one under the same check."""
        joint = (lambda *passed: Passed(self.joint([p.value for p in passed]), value=passed[0].value)) if self.also \
            else (lambda passed: passed)
        return register_together((self,) + tuple(self.also), registry, hints, self.check, self.doc, joint, depends,
                                 after, max_score)
