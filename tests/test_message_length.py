"""A checker message is two short lines and a hint is short, in every lab (issue 40, item 1).

The labs are found by listing checker/labs/ (not a hand list), so a new lab is held to the same limits:
  - every hint a lab can give, as the student reads it ("[step N: title] text"), is at most 250 characters;
  - every lab has a mistake corpus (tests/corpus_<lab>.py) with wrong entries, and its verdict test holds each
    wrong file's first message to the limits (tests/corpus_verdicts.message_problem: at most two lines, the first
    <= 160 characters, the second <= 200; graded there, in the corpus's one checker run, not again here);
  - the rule itself fails a message over the limits (a test that cannot fail is no test).
"""
import importlib
import os

import pytest

import corpus_verdicts as verdicts
from checker.judging.causes import SHARED
from checker.judging.lab_checks import RUNTIME_HINT

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LABS = sorted(name for name in os.listdir(os.path.join(ROOT, "checker", "labs"))
              if os.path.isfile(os.path.join(ROOT, "checker", "labs", name, "checks.py")))


def test_the_labs_are_found_by_listing_their_folder():
    assert {"tumbling_crates", "more_shapes", "ball_on_ramp", "sleeping_crates", "bullets"} <= set(LABS)


@pytest.mark.parametrize("lab", LABS)
def test_every_hint_of_the_lab_is_short(lab):
    module = importlib.import_module(f"checker.labs.{lab}.checks")
    long = {key: len(hint.render()) for key, hint in module.HINTS.items() if len(hint.render()) > verdicts.HINT}
    assert not long, f"{lab}: hints over {verdicts.HINT} characters as shown: {long}"


def test_the_shared_hint_and_sentences_are_short():
    assert len(RUNTIME_HINT.render()) <= verdicts.HINT
    assert all(len(text) <= verdicts.FIRST_LINE for text in SHARED.values())


@pytest.mark.parametrize("lab", LABS)
def test_every_lab_has_a_corpus_whose_verdicts_hold_the_limits(lab):
    corpus = importlib.import_module(f"corpus_{lab}")
    assert corpus.WRONG, f"tests/corpus_{lab}.py holds no wrong file"
    with open(os.path.join(ROOT, "tests", f"test_corpus_{lab}.py"), encoding="utf-8") as handle:
        text = handle.read()
    assert "verdicts.assert_verdict(" in text or "verdicts.assert_first_message(" in text, \
        f"tests/test_corpus_{lab}.py does not hold its wrong files' first messages to the limits"


def check(message, hint=""):
    return {"id": "x", "message": message, "hint": hint}


def test_the_rule_fails_a_message_over_the_limits():
    assert verdicts.message_problem(check("a" * 160 + "\n" + "b" * 200, "c" * 250)) == ""
    assert "first line" in verdicts.message_problem(check("a" * 161))
    assert "second line" in verdicts.message_problem(check("a\n" + "b" * 201))
    assert "3 lines" in verdicts.message_problem(check("a\nb\nc"))
    assert "hint" in verdicts.message_problem(check("a", "c" * 251))
