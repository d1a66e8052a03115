"""The checker owes every entry of the Bullets mistake corpus its verdict: no false pass, no false fail.

tests/corpus_bullets.py builds plausible student files from the current starter;
they are graded in ONE run of `python -m checker --json`, one test per entry,
by the rules in tests/corpus_verdicts.py.
Grading the corpus (24 files) costs about 7 s of CPU (a wrong file stops after the probe).
"""
import pytest

import corpus_bullets as corpus
import corpus_verdicts as verdicts


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """{entry name: {check id: the check's JSON}}, from one checker run over the whole corpus."""
    return verdicts.grade(corpus.write_corpus(tmp_path_factory.mktemp("bullets_corpus")), "bullets")


def test_the_corpus_is_big_enough_and_covers_every_step():
    verdicts.assert_big_enough(corpus, per_step=1)


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_is_well_formed_and_builds(entry):
    verdicts.assert_builds(entry, corpus, "Bullets")


def test_the_reference_build_is_the_solution():
    verdicts.assert_reference_build_is_the_solution(corpus)


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_the_checker_gives_each_entry_its_verdict(entry, graded):
    verdicts.assert_verdict(entry, graded[entry.name], corpus)
