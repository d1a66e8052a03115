"""A message names a mistake only when that one known wrong formula fits every probe case (issue 33, item 6).

Each file here makes TWO of a step's known mistakes at once (checker/causes.consistent_mistake): neither
formula alone gives the file's answers, so the first message must give the step and the values but name
neither cause (a cause the file does not have is a false lead). The single mistakes are corpus entries,
whose messages name them. The files are each lab's corpus's COMBINED (tests/corpus_<id>.py, for every lab in
checker/labs/ whose corpus has them: today Tumbling Crates and Bullets); one checker run per lab.
"""
import os
import textwrap

import pytest

import corpus_verdicts as verdicts
import labs_found

# (lab, name, {step: code}, the check that must fail first, the causes' words it must not contain)
COMBINED = [(lab, name, codes, check, causes) for lab in labs_found.with_corpus()
            for name, (check, codes, causes) in getattr(labs_found.corpus(lab), "COMBINED", {}).items()]


def test_some_lab_makes_two_mistakes_at_once():
    """The rule is tested at all: at least one lab's corpus has COMBINED files."""
    assert COMBINED


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """{lab id: {name: {check id: JSON}}}: one checker run per lab over its combined-mistake files."""
    out = {}
    for lab in sorted({lab for lab, *_ in COMBINED}, key=lambda lab: lab.id):
        corpus = labs_found.corpus(lab)
        directory = tmp_path_factory.mktemp(lab.id + "_combined")
        built = {}
        for lab_of, name, codes, _, _ in COMBINED:
            if lab_of is lab:
                source = corpus.fill(corpus.build("correct_solution_steps"),
                                     {step: textwrap.dedent(code).strip("\n") for step, code in codes.items()})
                built[name] = os.path.join(directory, f"{lab.id}_{name}.py")
                with open(built[name], "w", encoding="utf-8") as handle:
                    handle.write(source)
        out[lab.id] = verdicts.grade(built, lab.id)
    return out


@pytest.mark.parametrize("lab, name, codes, check, causes", COMBINED, ids=[c[1] for c in COMBINED])
def test_two_mistakes_at_once_fail_at_their_step_naming_neither(lab, name, codes, check, causes, graded):
    checks = graded[lab.id][name]
    first = next(c for c in checks.values() if c["status"] != "pass")
    assert first["id"] == check and first["status"] == "fail", verdicts.show(checks)
    stated = [words for words in causes if words.lower() in first["message"].lower()]
    assert not stated, f"{name}: the message names {stated}, a cause the file does not have alone: {first['message']}"
