"""The class report in the browser (issue 14 §3): `python -m checker FOLDER --html report.html`.

One module-scoped run grades a small class of Ball on the Ramp files: the
solution, the solution with SLOP = 6 (fails one scene, so it gets a picture;
graded with --allow-edits) and the starter (fails at step 2 after one probe),
about 7 CPU s. The sorting JS runs in a real headless Chromium when
/usr/bin/chromium (or chromium on PATH) is there; otherwise that test skips.
"""
import html
import json
import os
import re
import shutil
import subprocess

import pytest

from test_checker_pictures import ROOT, SOLUTION, run_checker, slop_file

STARTER = os.path.join(ROOT, "starters", "ball_on_ramp_starter.py")
NAMES = ("alice", "bob", "carol")


@pytest.fixture(scope="module")
def produced(tmp_path_factory):
    base = tmp_path_factory.mktemp("class")
    folder = base / "submissions"
    for name in NAMES:
        (folder / name).mkdir(parents=True)
    shutil.copy(SOLUTION, folder / "alice" / "ball_on_ramp.py")
    slop_file(str(folder / "bob"))
    shutil.copy(STARTER, folder / "carol" / "ball_on_ramp.py")
    report = base / "report.html"
    status, out, err = run_checker(str(folder), "--allow-edits", "--html", str(report), "--json")
    assert status == 1, err
    return report, json.loads(out), base


def test_one_self_contained_file(produced):
    report, _, base = produced
    text = report.read_text(encoding="utf-8")
    assert sorted(os.listdir(base)) == ["report.html", "submissions"]   # nothing else written
    assert text.startswith("<!DOCTYPE html>") and text.rstrip().endswith("</html>")
    assert not re.search(r"https?://", text), "the report must not reach the network"
    assert not re.search(r'<(link|script)[^>]*(href|src)=', text), "no external style sheet or script"
    assert "<style>" in text and "<script>" in text
    assert len(text) < 2_000_000


def test_every_submission_and_check_is_there(produced):
    report, data, _ = produced
    text = report.read_text(encoding="utf-8")
    for name in NAMES:
        assert f"{name}/ball_on_ramp" in text
    for lab in data["labs"]:
        for criterion in lab["criteria"]:
            assert f'data-check="{criterion["id"]}"' in text
            if criterion["hint"]:
                assert html.escape(criterion["hint"], quote=True) in text
    # the histogram: one bar row per check, the failing scene shows one fail of three
    assert text.count('<tr data-check="') == len(data["labs"][0]["criteria"])
    row = re.search(r'<tr data-check="pushed_out_of_crate">.*?</tr>', text).group(0)
    assert 'title="1 fail"' in row and "1/3" in row
    # bob's failed scene is pictured inline, once; carol's starter, which fails step 2 so its scenes never ran,
    # gets the lab's first scene run ungraded for its first failed check; alice's passing file has none
    assert text.count('src="data:image/png;base64,') == 2
    assert re.search(r'alt="pushed_out_of_crate: scene inside" src="data:image/png;base64,', text)
    assert re.search(r'alt="closest_point: scene ramp" src="data:image/png;base64,', text)


def test_summary_rows_carry_sort_keys(produced):
    text = produced[0].read_text(encoding="utf-8")
    table = re.search(r'<table id="summary">.*?</table>', text, re.S).group(0)
    assert re.findall(r'data-sort="([0-9.]+)"', table) == ["18", "16", "3"]
    assert table.count('data-type="number"') == 2   # score, and the number of flagged constructs


def chromium():
    for candidate in ("/usr/bin/chromium", shutil.which("chromium"), shutil.which("chromium-browser"),
                      shutil.which("google-chrome")):
        if candidate and os.path.exists(candidate):
            return candidate
    return None


def dump_dom(browser, page, profile):
    """The page's DOM after its scripts ran, from headless Chromium."""
    proc = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                           "--no-first-run", "--disable-background-networking", "--disable-component-update",
                           "--disable-sync", f"--user-data-dir={profile}", "--dump-dom", page.as_uri()],
                          capture_output=True, text=True, timeout=90)
    assert proc.returncode == 0, proc.stderr[-2000:]
    return proc.stdout


def test_table_sorts_in_a_real_browser(produced, tmp_path):
    browser = chromium()
    if browser is None:
        pytest.skip("no Chromium here (apt-get install -y chromium); CI installs only pip packages, "
                    "so the sorting JS is tested only where a browser is installed")
    text = produced[0].read_text(encoding="utf-8")
    # click the headings the way a user does, then write the order of the rows into the page for --dump-dom
    probe = """<script>
    function order() { return Array.prototype.map.call(document.querySelectorAll('#summary tbody tr'),
        function (r) { return r.cells[0].textContent; }).join(','); }
    var heads = document.querySelectorAll('#summary th'), seen = [];
    heads[2].click(); seen.push(order());
    heads[2].click(); seen.push(order());
    heads[4].click(); seen.push(order());
    heads[0].click(); heads[0].click(); seen.push(order());
    var out = document.createElement('pre'); out.id = 'sorted'; out.textContent = seen.join('|');
    document.body.appendChild(out);
    </script></body>"""
    page = tmp_path / "probe.html"
    page.write_text(text.replace("</body>", probe), encoding="utf-8")
    dom = dump_dom(browser, page, tmp_path / "profile")
    found = re.search(r'<pre id="sorted">(.*?)</pre>', dom)
    assert found, dom[-2000:]
    by_score_up, by_score_down, by_problem, by_name_down = found.group(1).split("|")
    a, b, c = (f"{n}/ball_on_ramp" for n in NAMES)
    assert by_score_up == f"{c},{b},{a}"
    assert by_score_down == f"{a},{b},{c}"
    assert by_problem == f"{a},{b},{c}"      # "" < "pushed_out_of_crate: fail" < "step 2 (closest_point): fail"
    assert by_name_down == f"{c},{b},{a}"


def test_html_refuses_bad_paths(tmp_path):
    graded = tmp_path / "class"
    graded.mkdir()
    (graded / "ball_on_ramp.py").write_text("# not a lab\n")
    for target, words in ((graded / "report.html", "a folder being graded"), (tmp_path, "is a folder"),
                          (graded / "ball_on_ramp.py", "refusing to write to a .py file")):
        status, out, err = run_checker(str(graded), "--html", str(target))
        assert status == 2 and words in err, (target, err)
    assert sorted(os.listdir(graded)) == ["ball_on_ramp.py"]


def test_a_file_not_graded_is_a_row_too():
    from checker.reporting import html_report
    from checker.reporting.report import NotGraded
    text = html_report.html_text([NotGraded("/x/notes/readme.py", None, "not a lab file <b>")])
    assert "readme" in text and "not a lab file &lt;b&gt;" in text and 'class="error"' in text


def test_the_class_figures_are_per_lab_and_name_the_steps(produced):
    """The mean is each lab's own share of its points; the first problem names the lesson step beside the id."""
    report, data, _ = produced
    text = report.read_text(encoding="utf-8")
    scores = [lab["score"] / lab["max_score"] for lab in data["labs"]]
    mean = 100 * sum(scores) / len(scores)
    assert f"Ball on the Ramp: 3 file(s), mean {mean:.0f} % of its points" in text
    assert "mean score" not in text
    assert "Step 2 (closest_point): fail" in text        # carol's starter fails step 2 first


def test_the_csv_has_a_student_column_and_fractions(tmp_path):
    """One row per file with the student's folder, the lab, and the score as a share of that lab's points; a
    check column per lab when several labs are graded, and a file that is not a lab counted apart."""
    import csv
    from checker import labs
    from checker.reporting import report
    from checker.judging.checks import Result
    from checker.grade import LabReport
    by_id = {lab.id: lab for lab in labs.LABS}
    crates, bullets = by_id["tumbling_crates"], by_id["bullets"]

    def graded(path, lab, score):
        results = [Result(c.id, c.description, "pass" if k < score else "fail", score=c.max_score if k < score else 0.0,
                          max_score=c.max_score) for k, c in enumerate(lab.checks.checks)]
        return LabReport(path, lab, results, 0.1)
    rows = [graded("/class/alice/tumbling_crates.py", crates, 3), graded("/class/bob/bullets.py", bullets, 15),
            report.NotGraded("/class/carol/notes.py", None, "not a lab file")]
    table = list(csv.DictReader(report.csv_text(rows).splitlines()))
    assert [r["student"] for r in table] == ["alice", "bob", "carol"]
    assert [r["lab"] for r in table] == ["tumbling_crates", "bullets", ""]
    assert table[1]["fraction"] == "1.000" and table[0]["tumbling_crates:loads"] == "pass"
    assert table[0]["bullets:loads"] == "" and table[1]["bullets:loads"] == "pass"
    assert report._summary_line(rows) == ("1 of 2 lab file(s) pass every check. 1 other file(s) could not be "
                                          "graded as a lab (not counted; see their rows).")


def test_a_csv_cell_that_starts_like_a_formula_is_text(tmp_path):
    """A student's folder named like a spreadsheet formula (`=HYPERLINK(...)`) or a message starting with one
    becomes a cell that starts with an apostrophe: opening the grades in a spreadsheet runs nothing. A plain
    name and the numbers are unchanged."""
    import csv
    from checker.reporting import report
    evil = '=HYPERLINK("x"&A1,"open")'
    rows = [report.NotGraded(f"/class/{evil}/notes.py", None, "@SUM(1+1) is not a lab file"),
            report.NotGraded("/class/dave/notes.py", None, "not a lab file")]
    table = list(csv.DictReader(report.csv_text(rows).splitlines()))
    assert table[0]["student"] == "'" + evil and table[0]["message"].startswith("'@SUM")
    assert table[0]["path"].startswith("'=") or not table[0]["path"].startswith(report.FORMULA_STARTS)
    assert table[1]["student"] == "dave" and table[1]["message"] == "not a lab file" and table[1]["score"] == "0"
    assert all(not cell.startswith(report.FORMULA_STARTS) for row in table for cell in row.values())
    assert report.inert("-3") == "'-3" and report.inert("alice") == "alice"
