"""A scene criterion declared as a bounds table (checker/judging/criteria.py) measures, compares and words.

A toy criterion over a fake scene record: the check it registers passes when every bound holds and lists the
bounded metrics; it fails at the FIRST broken bound, in its table order, with that bound's sentence and hint and
the evidence "<metric> <value> <unit> (bound <limit>)"; a metric None (never happened) or NaN breaks its bound;
`least` bounds are minimums; a list of measures (one per body) is checked body by body.
The labs' own criteria are held to their corpora's correct entries (tests/test_corpus_labs.py).
"""
import math

import pytest

from checker.judging import criteria
from checker.judging.checks import Fail, Hint, Passed, Registry
from checker.judging.criteria import Bound, Criterion

HINTS = {"sink": Hint(5, "sinking", "Push out."), "rest": Hint(6, "rest", "Let it rest.")}
BOUNDS = (Bound("depth", 1.0, "the crate sank", "sink", "px"),
          Bound("speed", 5.0, "the crate is still moving", "rest", "px/s"),
          Bound("turned", math.pi / 4, "the crate did not tip over", "rest", "°", least=True, scale=180 / math.pi))


def runs():
    """A stand-in for the lab's check that runs the scenes."""


def check(measured, bounds=BOUNDS):
    registry = Registry()
    registry.check()(runs)
    criteria.register(registry, HINTS, (Criterion("tips", "A crate tips over and rests.", lambda records: measured,
                                                  bounds),), depends=("runs",))
    chk = registry.checks[-1]
    assert chk.id == "tips" and chk.depends == ("runs",) and chk.max_score == 2
    return chk.func


def test_every_bound_held_passes_and_lists_the_metrics():
    passed = check({"depth": 0.25, "speed": 1.0, "turned": math.pi / 2})({})
    assert isinstance(passed, Passed) and passed.message == "depth 0.25 px, speed 1 px/s, turned 90 °"


@pytest.mark.parametrize("measured, first, evidence, hint", [
    ({"depth": 1.004, "speed": 9.0, "turned": 0.0}, "the crate sank", "depth 1.004 px (bound 1)", "sink"),
    ({"depth": 0.5, "speed": 9.0, "turned": 0.0}, "the crate is still moving", "speed 9.0 px/s (bound 5)", "rest"),
    ({"depth": 0.5, "speed": 1.0, "turned": 0.5}, "the crate did not tip over", "turned 28.6 ° (bound 45)", "rest"),
    ({"depth": math.nan, "speed": 1.0, "turned": 1.0}, "the crate sank", "depth nan px (bound 1)", "sink"),
    ({"depth": None, "speed": 1.0, "turned": 1.0}, "the crate sank", "depth: never", "sink"),
])
def test_the_first_broken_bound_fails_in_two_lines(measured, first, evidence, hint):
    with pytest.raises(Fail) as failed:
        check(measured)({})
    assert failed.value.rationale == f"{first}.\n{evidence}."
    assert failed.value.hint is HINTS[hint]


def test_a_list_of_bodies_is_checked_body_by_body():
    bodies = [{"depth": 0.1, "speed": 9.0, "turned": 1.0}, {"depth": 3.0, "speed": 1.0, "turned": 1.0}]
    with pytest.raises(Fail) as failed:
        check(bodies)({})
    assert failed.value.rationale.startswith("the crate is still moving.")


def test_a_sentence_may_name_another_metric_of_the_body():
    bounds = (Bound("depth", 1.0, "the {kind} sank", "sink", "px"),)
    with pytest.raises(Fail) as failed:
        check([{"kind": "box", "depth": 0.5}, {"kind": "hexagon", "depth": 2.0}], bounds)({})
    assert failed.value.rationale == "the hexagon sank.\ndepth 2.0 px (bound 1)."


def test_every_lab_s_bounds_are_short_and_name_a_hint_the_lab_has():
    """Every lab's declared criteria (found through the registry): a sentence fits a message's first line (with
    another metric named in it, a long one) and its hint is the lab's."""
    from checker import labs
    from corpus_verdicts import FIRST_LINE
    declared = [(lab, c.func.criterion) for lab in labs.LABS for c in lab.checks.checks if hasattr(c.func, "criterion")]
    assert declared
    for lab, criterion in declared:
        for bound in criterion.bounds:
            assert len(bound.sentence.replace("{kind}", "x" * 12)) + 1 <= FIRST_LINE, (lab.id, bound.sentence)
            assert bound.hint in lab.module.HINTS, (lab.id, criterion.id, bound.hint)


def test_the_evidence_names_the_frame_the_replay_marks():
    from checker.replay import show_series
    bounds = (Bound("depth", 1.0, "the ball sank into the ramp", "sink", "px", frame="depth_frame"),)
    with pytest.raises(Fail) as failed:
        check({"depth": 3.2, "depth_frame": 42}, bounds)({})
    assert failed.value.rationale == "the ball sank into the ramp.\ndepth 3.2 px at frame 42 (bound 1)."
    assert show_series.marked_frame(type("R", (), {"message": failed.value.rationale})) == 42
