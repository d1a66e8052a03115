"""Declared steps that share one hand-written probe: several steps graded on the records of one call.

A SharedStep is a declared.Step whose cases are the records of a probe that already exists (probe_name), e.g.
one call of a function whose two steps each leave their mark in it. In the grading parent it reads each record:
read(record) the student's answer, lesson(record) the lesson's, each Form's answer(record) the wrong form's (the
record's reference numbers were computed in the grader already); screen(records, sub, *given) fails first
(nothing to grade, an argument changed in place) or keeps the records to grade. Then Step.judge compares,
names (a case's own diagnosis, the one-formula rule, then the case's fallback diagnosis) and words.
"""
import inspect
from dataclasses import dataclass

from . import lab_checks
from .declared import Step


@dataclass
class SharedStep(Step):
    """A declared.Step graded on the records of the existing probe `probe_name` (see the module docstring);
    cases and call are not used. read(record): the student's answer (it replaces the record's own "got");
    screen(records, sub, *given): the records to grade (given: what the checks this one depends on returned);
    fallbacks: probes read, in order, when probe_name holds no data (None); fallback(cases, case): a Form read
    from the case when no wrong form is named (its id None: words and a hint only)."""
    cases: object = None
    call: object = None
    lesson: object = None
    read: object = None
    screen: object = None
    fallbacks: tuple = ()
    fallback: object = None

    def __post_init__(self):
        assert self.probe_name and self.read and self.lesson, f"{self.check}: a SharedStep reads an existing probe"
        super().__post_init__()

    def probes(self):
        return {}   # the probe is the lab's own, in its PROBES already

    def register(self, registry, hints, depends=("loads",), after=(), max_score=1.0):
        """Register this step's check in `registry`; it receives what the checks in `depends` after "loads" return."""
        def check(sub, functions, *given):
            records = None
            for probe in (self.probe_name,) + tuple(self.fallbacks):
                records = lab_checks.function_data(sub, functions, probe, self.function, self.step, hints["crash"])
                if records is not None:
                    break
            return self.judge(self.screen(records, sub, *given) if self.screen else records, hints)
        check.__name__ = check.__qualname__ = self.check
        check.__doc__ = self.doc
        check.__signature__ = inspect.Signature([inspect.Parameter(name, inspect.Parameter.POSITIONAL_OR_KEYWORD)
                                                 for name in ["sub", *depends]])   # a value per check depended on
        registry.check(depends=list(depends), after=list(after), max_score=max_score)(check)
        return check

    def judge(self, cases, hints):
        return super().judge([dict(case, got=self.read(case), want=self.lesson(case),
                                   forms={form.id: form.answer(case) for form in self.wrong}) for case in cases],
                             hints)

    def named(self, cases, case):
        return super().named(cases, case) or (self.fallback(cases, case) if self.fallback else None)


def unchanged_arguments(function, why, hint):
    """A screen that fails when `function` changed a vector argument in place in some record (the probe's
    `changed`: {name: its value after the call}, probe_kit.changed_vectors); `why` says who goes on using
    {name}. The mistake: causes.SHARED's argument_changed."""
    def screen(cases, sub=None, *given):
        for case in cases:
            for name, now in sorted((case.get("changed") or {}).items()):
                raise lab_checks.argument_changed(
                    function, name, "make new vectors (v * s, v.rotate(90)), not v *= s or v.rotate_ip(90)",
                    f"in '{case['case']}'", now, why.format(name=name), hint)
        return cases
    return screen
