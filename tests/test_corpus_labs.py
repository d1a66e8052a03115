"""The checker owes every entry of every lab's mistake corpus its verdict: no false pass, no false fail.

Every lab in checker/labs/ is covered by being there (tests/labs_found.py): its corpus, tests/corpus_<id>.py,
builds plausible student files from the lab's current starter; they are graded in ONE run of
`python -m checker --json` per lab, one test per entry, by the rules in tests/corpus_verdicts.py.
A lab without a corpus file fails test_every_lab_has_a_corpus, naming the file to write.
Grading costs about 7-10 s of CPU for a lab whose wrong files stop after the probe (24-40 files), and
about 12 s a file for Tumbling Crates, whose files all run their four scenes (73 files).
"""
import pytest

import corpus_verdicts as verdicts
import labs_found

WITH_CORPUS = labs_found.with_corpus()


def _entries():
    return [pytest.param(lab, entry, id=f"{lab.id}-{entry.name}")
            for lab in WITH_CORPUS for entry in labs_found.corpus(lab).ENTRIES]


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """grade(lab) -> {entry name: {check id: the check's JSON}}, from one checker run over the lab's corpus (once)."""
    done = {}

    def grade(lab):
        if lab.id not in done:
            corpus = labs_found.corpus(lab)
            done[lab.id] = verdicts.grade(corpus.write_corpus(tmp_path_factory.mktemp(f"{lab.id}_corpus")), lab.id)
        return done[lab.id]
    return grade


@pytest.mark.parametrize("lab", labs_found.params())
def test_every_lab_has_a_corpus(lab):
    labs_found.need_corpus(lab)


@pytest.mark.parametrize("lab", labs_found.params(WITH_CORPUS))
def test_the_corpus_is_big_enough_and_covers_every_step(lab):
    corpus = labs_found.corpus(lab)
    verdicts.assert_big_enough(corpus)
    assert set(corpus.STEPS) == set(labs_found.steps(lab)), "the corpus's STEPS are not the solution's step regions"
    assert corpus.SOLUTION == lab.solution and corpus.STARTER == lab.starter


@pytest.mark.parametrize("lab, entry", _entries())
def test_each_entry_is_well_formed_and_builds(lab, entry):
    verdicts.assert_builds(entry, labs_found.corpus(lab), lab.title)


@pytest.mark.parametrize("lab", labs_found.params(WITH_CORPUS))
def test_the_reference_build_is_the_solution(lab):
    verdicts.assert_reference_build_is_the_solution(labs_found.corpus(lab))


@pytest.mark.parametrize("lab, entry", _entries())
def test_the_checker_gives_each_entry_its_verdict(lab, entry, graded):
    verdicts.assert_verdict(entry, graded(lab)[entry.name], labs_found.corpus(lab))
