"""Naming a mistake only when the probe told it apart (issue 33): the labs' checks share this rule.

A function check compares the student's answers with the lesson's on every probe case. When one
differs, a message may say *why* only if a known wrong formula (computed in the grader, beside the
lesson's answer) gives the student's answer in every case, and no other known formula does: two
formulas that agree on every case were not told apart, so neither is named.
"""
from .checks import Hint


def consistent_mistake(cases, matches, candidates):
    """The one name among `candidates` whose answers match the student's in every case, else None.

    `matches(case, name)`: the student's answer in `case` is that of mistake `name`. Callers pass
    as candidates only the mistakes whose answer differs from the lesson's in the failing case.
    """
    fitting = [name for name in candidates if all(matches(case, name) for case in cases)]
    return fitting[0] if len(fitting) == 1 else None


def arguments_hint(step, function):
    """The hint for a step function that changed a vector it was given in place (a contact's normal, a lever arm)."""
    return Hint(step, f"the arguments of {function}()", "Change the bodies' motion, never the vectors you are given: "
                "the caller goes on using them. v * s and v.rotate(90) make new vectors; v *= s and "
                "v.rotate_ip(90) change the caller's.")
