"""Hints coach; they do not hand out the code. A hint says what is wrong and which terms, signs and bounds the
lesson uses, in words and symbols, as the lesson's Hint section does, never a line of the solution's steps.

For every lab, no hint (its text or title) contains a line of code from the solution's step regions, nor any
run of 22 characters of one (spaces ignored): `ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia` inside
a sentence counts as handing out the line it comes from.
"""
import pytest

from checker import labs
from checker.authoring import lab_rules
from checker.authoring.lab_rules import WINDOW, handed_out  # noqa: F401 (the rule lint-lab states: one source)
from checker.reading import source


def step_code(path):
    """The code lines (comments and blank lines left out) between each step's markers, spaces removed."""
    return lab_rules.step_code(source.read(path))


@pytest.mark.parametrize("lab", labs.LABS, ids=lambda lab: lab.id)
def test_no_hint_repeats_the_solutions_code(lab):
    assert step_code(lab.solution), f"{lab.id}: no step code found in {lab.solution}"
    assert lab_rules.hints_hand_out_no_code(lab_rules.Subject(lab)) is None   # the rule lint-lab states


def test_the_rule_catches_a_hint_that_hands_out_a_line():
    code = step_code(labs.LABS[0].solution)
    assert handed_out(code, "add the spin terms: ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia, or else")
    assert handed_out(code, "keep jt within [-μ j, μ j]") is None
