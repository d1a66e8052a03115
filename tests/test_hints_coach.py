"""Hints coach; they do not hand out the code. A hint says what is wrong and which terms, signs and bounds the
lesson uses, in words and symbols, as the lesson's Hint section does, never a line of the solution's steps.

For every lab, no hint (its text or title) contains a line of code from the solution's step regions, nor any
run of 22 characters of one (spaces ignored): `ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia` inside
a sentence counts as handing out the line it comes from.
"""
import re

import pytest

from checker import labs

WINDOW = 22   # characters (spaces removed) of a solution line that a hint may not repeat


def squeeze(text):
    return re.sub(r"\s+", "", text)


def step_code(path):
    """The code lines (comments and blank lines left out) between each step's markers, spaces removed."""
    lines, inside = [], False
    with open(path, encoding="utf-8") as handle:
        for line in handle:
            if re.match(r"\s*# --- step \d+", line):
                inside = True
            elif re.match(r"\s*# --- end of step", line):
                inside = False
            elif inside and line.strip() and not line.strip().startswith("#"):
                lines.append(squeeze(line.split("  #")[0]))
    return lines


def handed_out(code, hint):
    """The part of a solution line found in the hint, or None."""
    text = squeeze(hint)
    for line in code:
        if len(line) < WINDOW:
            if len(line) >= 14 and line in text:   # a whole short line; not "return None"
                return line
            continue
        for start in range(len(line) - WINDOW + 1):
            if line[start:start + WINDOW] in text:
                return line[start:start + WINDOW]
    return None


@pytest.mark.parametrize("lab", labs.LABS, ids=lambda lab: lab.id)
def test_no_hint_repeats_the_solutions_code(lab):
    code = step_code(lab.solution)
    assert code, f"{lab.id}: no step code found in {lab.solution}"
    leaks = {key: handed_out(code, f"{hint.title} {hint.text}") for key, hint in lab.module.HINTS.items()}
    assert {key: part for key, part in leaks.items() if part} == {}


def test_the_rule_catches_a_hint_that_hands_out_a_line():
    code = step_code(labs.LABS[0].solution)
    assert handed_out(code, "add the spin terms: ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia, or else")
    assert handed_out(code, "keep jt within [-μ j, μ j]") is None
