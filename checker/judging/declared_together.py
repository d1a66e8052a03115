"""One check made of several declared Steps: a lesson step graded through more than one probe.

A lesson step may be seen through two of the student's functions (a helper, and the handout's function that
calls it): each is a declared.Step with its own probe and cases, and one check judges them in order, as the
student reads the step. The first Step that fails fails the check with its own message; when all pass,
passed(*results) words the pass from each Step's Passed (its .value: that Step's judged cases).
"""
from . import lab_checks


def register_together(steps, registry, hints, check, doc, passed, depends=("loads",), after=(), max_score=1.0):
    """Register check `check` (description `doc`) in `registry`: it judges `steps` (declared.Steps of one lesson
    step) in order and returns passed(*their Passed); `hints`: the lab's HINTS (its "crash" hint for a probe that
    raised). Each Step's own register() is not called: its probe still goes in the lab's PROBES (Step.probes())."""
    def judged(sub, functions):
        return passed(*[step.judge(lab_checks.function_data(sub, functions, step.probe_id, step.function, step.step,
                                                            hints["crash"]), hints) for step in steps])
    judged.__name__ = judged.__qualname__ = check
    judged.__doc__ = doc
    registry.check(depends=list(depends), after=list(after), max_score=max_score)(judged)
    return judged
