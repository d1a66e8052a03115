"""What Tumbling Crates' mistake corpus keeps beyond every lab's (tests/test_corpus_labs.py grades it).

tests/test_corpus_labs.py grades this corpus as every lab's, in one checker run, by tests/corpus_verdicts.py's
rules (with this corpus's DEPENDS and SAME_FUNCTION: sat_normal may be skipped when sat_axes fails, a crash may
take the other check of the same function with it). Here, without grading, what this larger corpus keeps
besides: at least 25 wrong and 5 correct entries, three in every step and one outside the steps; each entry
changes only the steps it names (the others are the solution's, byte for byte); an edit that no longer fits
fails naming its entry.
"""
import pytest

import corpus_tumbling_crates as corpus
import corpus_verdicts as verdicts


# ---------------------------------------------------------------- the corpus itself

def test_the_corpus_is_big_enough_and_covers_every_step():
    assert len(corpus.WRONG) >= 25
    assert len(corpus.ENTRIES) - len(corpus.WRONG) >= 5
    for step in corpus.STEPS:
        inside = [e.name for e in corpus.WRONG if e.step == step]
        assert len(inside) >= 3, (step, inside)
    assert [e.name for e in corpus.WRONG if e.check == "handout_unchanged"], "no mistake outside the steps"


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_is_well_formed(entry):
    assert entry.what and "\n" not in entry.what
    verdicts.assert_says_words(entry)   # a wrong entry lists the words its first message must contain
    assert entry.check == "pass" or entry.check in corpus.CHECK_STEP, entry.check
    if entry.check == "pass":
        assert entry.step is None and entry.status == ("pass",) and not entry.also
        return
    assert entry.step == corpus.CHECK_STEP[entry.check]
    assert entry.status and set(entry.status) <= {"fail", "error"}
    assert set(entry.also) <= set(corpus.CHECK_STEP) - {entry.check}
    assert entry.why, f"{entry.name}: say which input shows the mistake"
    # a mistake in a step changes only that step; a mistake outside the steps changes no step
    if entry.check == "handout_unchanged":
        assert entry.edits and not entry.steps
    else:
        assert list(entry.steps) == [entry.step] and not entry.edits


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_builds_from_the_starter_and_wrong_ones_differ_from_the_correct_build(entry):
    source = corpus.build(entry.name)  # raises AssertionError naming the entry when an edit no longer fits
    compile(source, entry.name + ".py", "exec")
    assert "Tumbling Crates" in source.split('"""')[1], "the checker recognises the lab by its docstring's title"
    placeholders = [line for line in source.splitlines() if line.strip().startswith("return None  # until you write")]
    assert not placeholders or entry.name == "sat_placeholder_left"   # (the solution's prompt quotes it as a comment)
    reference = corpus.build("correct_solution_steps")
    if entry.check != "pass":
        assert source != reference
    # the steps the entry does not give are the solution's
    given = corpus.step_code(source, entry.name)
    solution = corpus.step_code(open(corpus.SOLUTION, encoding="utf-8").read())
    for step in corpus.STEPS:
        assert given[step] == (entry.steps[step] if step in entry.steps else solution[step]), (entry.name, step)


def test_an_edit_that_no_longer_fits_fails_loudly_naming_the_entry():
    with pytest.raises(AssertionError, match="entry_x: the text to replace occurs 0 times"):
        corpus.apply_edits("a = 1\n", [("b = 2", "b = 3")], "entry_x")
    with pytest.raises(AssertionError, match="entry_x: the text to replace occurs 2 times"):
        corpus.apply_edits("a = 1\na = 1\n", [("a = 1", "a = 2")], "entry_x")
    with pytest.raises(AssertionError, match="starter: step 3 has no"):
        corpus.regions("# --- step 2: x ---\n# --- end of step 2 ---\n", "starter")


# ---------------------------------------------------------------- a report that does not depend on the run's seed

def _raises_on(pairs):
    """The pairs on which step 2's `continue` loop keeps no axis, so its sat() raises in step 3's test."""
    from checker.labs.tumbling_crates.probes import _sat_mistakes_reference
    return [name for name, pa, pb in pairs if _sat_mistakes_reference(pa, pb)["gap_continue"] == "raises"]


def test_no_drawn_pair_makes_the_continue_loop_raise_whatever_the_seed():
    """Before, 9 of 2,000 seeds drew a pair apart on every axis: sat_gap_continue then got a crash report (at
    --seed 4) instead of its name, and its corpus verdict failed in about one run in 200."""
    import random
    from checker.judging.probe_kit import box, drawn_sat_pairs
    assert _raises_on([("apart on every axis", box(40, 40, (0, 0)), box(40, 40, (100, 100)))])   # the check can fail
    for seed in range(2000):   # as the grader draws them: tape.run_rng(module, "sat") with the run's seed
        assert not _raises_on(drawn_sat_pairs(random.Random(f"{seed}:sat"))), seed


def test_the_continue_loop_is_named_at_the_seed_that_once_drew_a_crash(tmp_path):
    import json
    import subprocess
    import sys
    path = tmp_path / "sat_gap_continue.py"
    path.write_text(corpus.build("sat_gap_continue"), encoding="utf-8")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--seed", "4", str(path)],
                          cwd=corpus.ROOT, capture_output=True, text=True, timeout=300,
                          env=dict(__import__("os").environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy"))
    checks = {c["id"]: c for c in json.loads(proc.stdout)["labs"][0]["criteria"]}
    assert checks["sat_axes"]["status"] == "fail", checks["sat_axes"]
    assert checks["sat_axes"]["mistake"]["id"] == "sat_gap_continue", checks["sat_axes"]["message"]
