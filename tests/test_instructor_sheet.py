"""Issue 40.6: an edit outside the steps that changes nothing a check grades costs a warning, not the grade; the
Gradescope package says which file students submit and what it is worth.

A constant changed outside the steps that no check reads (handout.constant_edits; grade.checked_names: no
step region, and none of the lab's checks, probes and scenes names it) is graded with the handout's line put
back, so the edit never runs in a graded run: the file scores exactly what it scores without the edit, and
handout_unchanged passes with a warning. That is the guard against forging: the grade is the unedited
file's. When the scenes run, the file's own runs of them are compared with the graded ones: if the edit
changes what they record or print (MAX_CRATES = 4), it fails handout_unchanged as before. A constant a check
reads (Ball on the Ramp's SLOP), a constant over two lines, or any other edit also fails as before.
"""
import os
import re
import subprocess
import sys
import zipfile

import pytest

from checker.reading import handout, source
from checker import labs
from checker.grade import Grader, checked_names

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LAB = {lab.id: lab for lab in labs.LABS}


def text_of(path):
    return source.read(os.path.join(ROOT, path))


def edited(text, name, value):
    line = re.search(rf"^{name} = [^#\n]*", text, re.M)
    assert line, name
    return text[:line.start()] + f"{name} = {value}" + text[line.end():]


def grade(tmp_path, lab, text, name=None):
    path = tmp_path / (name or f"{lab}.py")
    path.write_text(text, encoding="utf-8")
    row = Grader().grade(str(path), LAB[lab])
    return row, {r.id: r for r in row.results}


def test_a_constant_no_check_reads_costs_a_warning_not_the_grade(tmp_path):
    """Tumbling Crates' correct file with MAX_CRATES = 30 (the issue's example: 7/17 before) scores 17/17."""
    row, by_id = grade(tmp_path, "tumbling_crates", edited(text_of("solutions/tumbling_crates.py"), "MAX_CRATES", 30))
    assert row.score == row.max_score == 17, [(r.id, r.status, r.message) for r in row.results]
    message = by_id["handout_unchanged"].message
    assert message.startswith("warning: line ") and "MAX_CRATES = 30" in message and "put it back" in message


def test_a_free_constant_that_changes_a_scene_still_fails(tmp_path):
    """MAX_CRATES = 4 (tests/corpus_tumbling_crates.py's outside_max_crates: the four clicks drop nothing): no
    check reads the name, but the file's own runs of the scenes differ from the handout's, so it is an edit that
    fails handout_unchanged and the criteria wait for it, as before."""
    row, by_id = grade(tmp_path, "tumbling_crates", edited(text_of("solutions/tumbling_crates.py"), "MAX_CRATES", 4))
    assert by_id["handout_unchanged"].status == "fail" and "MAX_CRATES = 4" in by_id["handout_unchanged"].message
    assert by_id["fast_movers_zero"].status == "skip" and row.score == 7


@pytest.mark.parametrize("name, value", [("BULLET_MASS", 50.0), ("MAX_BULLETS", 0), ("BULLET_COLOR", (1, 2, 3))])
def test_a_free_constant_gains_nothing(tmp_path, name, value):
    """The attack: a constant no check reads, changed where running it could change what a scene measures (a
    bullet 50x heavier, MAX_BULLETS = 0), and a colour that changes nothing measured. Beside its unedited twin
    (the solution, the starter) none scores more: either it scores the same with a warning (its scenes show
    exactly what the handout's line shows, or never run), or it fails handout_unchanged as before."""
    for kind in ("solutions/{}.py", "starters/{}_starter.py"):
        text = text_of(kind.format("bullets"))
        honest, _ = grade(tmp_path, "bullets", text)
        attack, by_id = grade(tmp_path, "bullets", edited(text, name, value))
        shown = (kind, [(r.id, r.status) for r in attack.results])
        assert attack.score <= honest.score, shown
        if by_id["handout_unchanged"].status == "pass":   # the edit changed nothing graded: a warning, same score
            assert attack.score == honest.score and by_id["handout_unchanged"].message.startswith("warning"), shown
        else:   # it changed what a scene shows: an edit that fails, the criteria waiting, as before
            assert by_id["runs"].status == "skip", shown
        if name == "BULLET_COLOR" or kind.startswith("starters"):   # nothing measured / no scene runs
            assert by_id["handout_unchanged"].status == "pass", shown
        if name == "BULLET_MASS" and kind.startswith("solutions"):    # a heavier bullet: the scene differs
            assert by_id["handout_unchanged"].status == "fail", shown


def test_a_constant_a_check_reads_still_fails(tmp_path):
    """Ball on the Ramp's SLOP (the push-out's, read by its probes): SLOP = 6 fails handout_unchanged, and the
    scenes wait for it, as before."""
    assert "SLOP" in checked_names(LAB["ball_on_ramp"], text_of("solutions/ball_on_ramp.py"))
    row, by_id = grade(tmp_path, "ball_on_ramp", edited(text_of("solutions/ball_on_ramp.py"), "SLOP", 6))
    assert by_id["handout_unchanged"].status == "fail" and "SLOP = 6" in by_id["handout_unchanged"].message
    assert by_id["runs"].status == "skip" and row.score < row.max_score - 6


def test_which_edits_are_only_constants():
    starter = text_of("starters/tumbling_crates_starter.py")
    solution = text_of("solutions/tumbling_crates.py")
    assert handout.constant_edits(starter, starter) is None   # no edit at all
    one = handout.constant_edits(edited(solution, "MAX_CRATES", 30), starter)
    assert [e.names for e in one] == [("MAX_CRATES",)]
    assert handout.with_handout_lines(edited(solution, "MAX_CRATES", 30), starter, one) == solution
    # any other edit is no constant edit: a new target, a function outside the steps, a line added
    assert handout.constant_edits(solution.replace("MAX_CRATES = ", "MAX_BOXES = ", 1), starter) is None
    assert handout.constant_edits(solution.replace("def make_world(rng):", "def make_world(rng, x=1):", 1),
                                  starter) is None
    assert handout.constant_edits(solution + "\nEXTRA = 1\n", starter) is None
    # the same constant over two lines is not put back line for line
    assert handout.constant_edits(edited(solution, "MAX_CRATES", "(\n    30)"), starter) is None


def test_the_gradescope_package_says_what_to_submit_and_its_points(tmp_path):
    out = tmp_path / "autograder.zip"
    done = subprocess.run([sys.executable, "-m", "checker", "package", "gradescope", "--out", str(out), "--labs",
                           "tumbling_crates", "--hide", "pile_stable"], cwd=ROOT, capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=ROOT))
    assert done.returncode == 0, done.stderr
    said = "Students submit tumbling_crates.py (Tumbling Crates, 17 points). A submission scores out of 17 points"
    assert said in done.stdout
    with zipfile.ZipFile(out) as archive:
        readme = archive.read("README.txt").decode("utf-8")
    assert said in readme and "pile_stable" in readme and "[hidden]" in readme
    assert all(check.id in readme for check in LAB["tumbling_crates"].checks.checks)
