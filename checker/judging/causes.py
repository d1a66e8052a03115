"""Naming a mistake only when the probe told it apart (issue 33): the labs' checks share this rule.

A function check compares the student's answers with the lesson's on every probe case. When one
differs, a message may say *why* only if a known wrong formula (computed in the grader, beside the
lesson's answer) gives the student's answer in every case, and no other known formula does: two
formulas that agree on every case were not told apart, so neither is named.
"""
from checker.judging.checks import Hint, Mistake

# The mistakes more than one lab names, in the same words everywhere (the Coulomb clamp of Tumbling Crates step 5
# is Ball on the Ramp step 7's): id -> the sentence in the student's terms. A lab's own mistakes live in its checks.
SHARED = {
    "argument_changed": "a step function changes an argument it is given in place: make new vectors",
    "friction_missing": "resolve() applies no friction impulse",
    "friction_unclamped": "the friction impulse is never clamped to [-mu·j, mu·j]",
    "friction_sign": "the friction impulse pushes along the slip, not against it",
    "friction_always_full": "friction always takes its full mu·j, even where a smaller impulse stops the slip",
    "friction_bound_mu": "jt is clamped to ±mu, not ±mu·j: the bound is mu times the normal impulse j",
    "friction_clamp_loses_sign": "where |jt| > mu·j your clamp sets jt = +mu·j and loses jt's sign "
                                 "(`if abs(jt) > mu * j: jt = mu * j`): clamp to the sign of jt",
    "friction_twice": "the friction impulse is applied twice",
    "friction_whole_rel": "jt uses the whole relative speed |rel|, not the slip along the tangent, rel·t",
    "kt_no_spin": "kt lacks the spin terms (ra × t)²/I_A + (rb × t)²/I_B",
    "kt_is_k": "kt = k: it uses the normal's (ra × n)², (rb × n)² where kt needs (ra × t)², (rb × t)²",
}


def mistake(name, text=None):
    """The Mistake `name`: its sentence from SHARED unless `text` (a lab's own mistake) is given."""
    return Mistake(name, text if text is not None else SHARED[name])


def fitting_mistakes(cases, matches, candidates):
    """Every name among `candidates` whose answers match the student's in every case, in their order: one is a
    mistake told apart; two or more were not told apart, and a message names them all or none."""
    return [name for name in candidates if all(matches(case, name) for case in cases)]


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
