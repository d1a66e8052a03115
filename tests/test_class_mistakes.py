"""A failing check carries its named mistake, and the class report counts them (issue 40, items 3 and 4).

Item 3: `mistake` ({"id", "text"}) on a failing check's result in --json, the CSV's `mistakes` column,
Gradescope's results.json (a test's extra_data, from `--gradescope` and from the packaged grader) and
PrairieLearn's tests. Item 4: per check some file failed, how many files fail it of how many it graded, each
named mistake with its count and files, then the files not named: in --mistakes-csv and the HTML report.

The unit tests build rows by hand; one test grades a small class folder for real (three Ball on the Ramp
files from the corpus: two with the same step-7 mistake, one with another, and a correct one), as an
instructor runs it: `python -m checker class/ --json --csv --mistakes-csv --html`.
"""
import csv
import importlib.util
import io
import json
import os
import subprocess
import sys

from checker.reporting import report
from checker.judging.checks import FAIL, PASS, Mistake, Result
from checker.grade import LabReport
from checker.reporting.html_report import html_text

import corpus_ball_on_ramp

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Lab:
    id, title = "tumbling_crates", "Tumbling Crates"


FLIP = Mistake("normal_not_flipped", "the axis is never turned round")
LARGEST = Mistake("sat_largest", "that is the LARGEST overlap")


def row(name, step2=None, step3=None):
    """A graded row: sat_axes (Step 2) and sat_normal (Step 3), each failing with its mistake or passing."""
    def result(check_id, step, mistake):
        failing = mistake is not None
        named = mistake if isinstance(mistake, Mistake) else None
        return Result(check_id, f"Step {step}: the check", FAIL if failing else PASS,
                      message="what.\nevidence." if failing else "", score=0.0 if failing else 1.0, mistake=named)
    return LabReport(f"class/{name}.py", Lab(), [result("sat_axes", 2, step2), result("sat_normal", 3, step3)], 0.1)


CLASS = [row("ann", step3=FLIP), row("bob", step3=FLIP), row("cat", step3="unnamed"), row("dan", step2=LARGEST),
         row("eve")]


def test_a_failing_check_carries_its_mistake_in_the_json():
    criteria = report.to_json([CLASS[0]])["labs"][0]["criteria"]
    assert criteria[1]["mistake"] == {"id": "normal_not_flipped", "text": "the axis is never turned round"}
    assert criteria[0]["mistake"] is None


def test_the_csv_lists_each_rows_mistakes():
    rows = list(csv.DictReader(io.StringIO(report.csv_text(CLASS))))
    assert [r["mistakes"] for r in rows] == ["sat_normal=normal_not_flipped", "sat_normal=normal_not_flipped", "",
                                            "sat_axes=sat_largest", ""]


def test_gradescope_keeps_the_mistake_in_extra_data():
    tests = report.gradescope([CLASS[0]])["tests"]
    assert tests[1]["extra_data"] == {"mistake": FLIP.to_json()} and "extra_data" not in tests[0]


def test_the_class_mistakes_count_per_check_with_the_files():
    found = report.class_mistakes(CLASS)
    assert [(label, failing, graded) for _, label, failing, graded, _, _ in found] == [
        ("Step 2 (sat_axes)", 1, 5), ("Step 3 (sat_normal)", 3, 5)]
    _, _, _, _, named, unnamed = found[1]
    assert [(mid, paths) for mid, _, paths in named] == [("normal_not_flipped", ["class/ann.py", "class/bob.py"])]
    assert unnamed == ["class/cat.py"]
    table = list(csv.reader(io.StringIO(report.mistakes_csv_text(CLASS))))
    assert table[0] == ["lab", "check", "step", "failing", "graded", "mistake", "sentence", "files", "paths"]
    assert table[2][:8] == ["Tumbling Crates", "Step 3 (sat_normal)", "3", "3", "5", "normal_not_flipped",
                            FLIP.text, "2"]
    assert table[3][5:8] == ["(not named)", "", "1"]


def test_the_html_report_shows_the_mistakes_per_check():
    page = html_text(CLASS)
    section = page[page.index('<table id="mistakes">'):page.index("</table>", page.index('<table id="mistakes">'))]
    assert "Step 3 (sat_normal)" in section and "3 of 5" in section
    assert f'data-mistake="normal_not_flipped"><td>{FLIP.text} <code>normal_not_flipped</code></td>' \
           f'<td class="num">2</td>' in section
    assert "not named" in section and ">cat<" in section


def grading_script():
    spec = importlib.util.spec_from_file_location("grade_submission",
                                                  os.path.join(ROOT, "checker", "platforms", "templates", "grade_submission.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_packaged_grader_passes_the_mistake_to_gradescope_and_prairielearn():
    script = grading_script()
    document = report.to_json([CLASS[0]])["labs"][0]
    gradescope = script.gradescope_results(document, "Graded ann.py.", 2.0, {"hide": []})
    assert gradescope["tests"][1]["extra_data"] == {"mistake": FLIP.to_json()}
    prairielearn = script.prairielearn_results(document, "Graded ann.py.", 2.0, {"hide": []})
    assert prairielearn["tests"][1]["mistake"] == FLIP.to_json() and "mistake" not in prairielearn["tests"][0]


def test_a_class_folder_graded_for_real_shows_its_mistakes(tmp_path):
    folder, out = tmp_path / "class", tmp_path / "out"
    folder.mkdir()
    out.mkdir()
    names = ("friction_clamped_to_mu", "friction_applied_twice", "correct_solution_steps")
    corpus_ball_on_ramp.write_corpus(str(folder), names)
    os.rename(folder / "friction_clamped_to_mu.py", folder / "ann.py")
    corpus_ball_on_ramp.write_corpus(str(folder), ["friction_clamped_to_mu"])   # a second file, same mistake
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", str(folder), "--json", "--quiet", "--csv",
                           str(out / "grades.csv"), "--mistakes-csv", str(out / "mistakes.csv"), "--html",
                           str(out / "class.html")], cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
    assert proc.returncode == 1, proc.stderr[-2000:]
    document = json.loads(proc.stdout)
    carried = {os.path.basename(lab["path"]): [c["mistake"]["id"] for c in lab["criteria"] if c["mistake"]]
               for lab in document["labs"]}
    assert carried == {"ann.py": ["friction_bound_mu"], "friction_clamped_to_mu.py": ["friction_bound_mu"],
                       "friction_applied_twice.py": ["friction_twice"], "correct_solution_steps.py": []}
    with open(out / "mistakes.csv", encoding="utf-8") as handle:
        table = list(csv.DictReader(handle))
    step7 = {r["mistake"]: r for r in table if r["check"] == "Step 7 (friction_rolls)"}
    assert set(step7) == {"friction_bound_mu", "friction_twice"}
    assert step7["friction_bound_mu"]["failing"] == "3" and step7["friction_bound_mu"]["graded"] == "4"
    assert step7["friction_bound_mu"]["files"] == "2" and "ann.py" in step7["friction_bound_mu"]["paths"]
    with open(out / "grades.csv", encoding="utf-8") as handle:
        mistakes = {os.path.basename(r["path"]): r["mistakes"] for r in csv.DictReader(handle)}
    assert mistakes["ann.py"] == "friction_rolls=friction_bound_mu" and mistakes["correct_solution_steps.py"] == ""
    with open(out / "class.html", encoding="utf-8") as handle:
        page = handle.read()
    assert 'data-mistake="friction_bound_mu"' in page and "3 of 4" in page
