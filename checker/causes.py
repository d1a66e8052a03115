"""Naming a mistake only when the probe told it apart (issue 33): the labs' checks share this rule.

A function check compares the student's answers with the lesson's on every probe case. When one
differs, a message may say *why* only if a known wrong formula (computed in the grader, beside the
lesson's answer) gives the student's answer in every case, and no other known formula does: two
formulas that agree on every case were not told apart, so neither is named.
"""


def consistent_mistake(cases, matches, candidates):
    """The one name among `candidates` whose answers match the student's in every case, else None.

    `matches(case, name)`: the student's answer in `case` is that of mistake `name`. Callers pass
    as candidates only the mistakes whose answer differs from the lesson's in the failing case.
    """
    fitting = [name for name in candidates if all(matches(case, name) for case in cases)]
    return fitting[0] if len(fitting) == 1 else None
