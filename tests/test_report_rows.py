"""Issue 39.6, 39.8 (first half) and 39.9: one row cannot harm the class's report, forge the checker's own
failure, or print rows of its own. One CLI run as it is used (as root the child runs as `nobody`) over a class
folder, each attack beside its honest twin (the same file without the attack), with --pictures, --html and
--csv:

- alice: the starter whose main() puts a frame the runtime never writes (`1`) into its record, so the
  ungraded preview record is {"records": [1, ...]}; bob, her twin, the same line adding nothing. Before, the
  picture code raised on alice's record and "cannot draw the pictures" dropped every row's pictures.
- carol: module-level code that writes a last result line `{"phase": "run", "error": "x"}` on the result
  channel (fd 3) and kills itself (SIGKILL). Before, the row said "this is a bug in the checker" and --show
  died with a traceback.
- dave: an exception at import whose message holds line breaks and a fake row ("class/bob/... 17/17 (pass)").
"""
import csv
import io
import json
import os
import re
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
SEED_LINE = "    rng = random.Random(lab.seed(11))  # lab runtime: seed()\n"
FAKE_ROW = "class/zed/tumbling_crates.py - Tumbling Crates: 17/17 (pass, 1.0 s)"


def starter():
    with open(STARTER, encoding="utf-8") as handle:
        return handle.read()


def after_imports(text, code):
    marker = "from lesson11.physics2d.draw import"
    at = text.index("\n", text.index(marker)) + 1
    return text[:at] + code + text[at:]


def files():
    text = starter()
    assert SEED_LINE in text
    forged = ("import os as _os\n"
              "_os.write(3, b'{\"phase\": \"run\", \"error\": \"x\"}\\n')\n"
              "_os.kill(_os.getpid(), 9)\n")
    spoof = f"raise RuntimeError('boom\\n{FAKE_ROW}\\n\\rclass/yan/tumbling_crates.py: 0/17 fail')\n"
    return {
        "alice": text.replace(SEED_LINE, SEED_LINE + "    lab._records.append(1)\n"),
        "bob": text.replace(SEED_LINE, SEED_LINE + "    lab._records.extend([])\n"),
        "carol": after_imports(text, forged),
        "dave": after_imports(text, spoof),
        "erin": after_imports(text, "import os as _os\n"),   # carol's and dave's twin: their import, no attack
        # issue 40.6: an empty file, and a file under another name with a syntax error (a lab by its text)
        "nina": "",
        "mallory": text.replace(SEED_LINE, SEED_LINE + "    if True\n"),
    }

NAMES = {"nina": "nina.py", "mallory": "mallory.py"}   # the others: tumbling_crates.py


def run_checker(*args, cwd):
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    done = subprocess.run([sys.executable, "-m", "checker", *args], cwd=cwd, capture_output=True, text=True,
                          env=env, timeout=600)
    return done.returncode, done.stdout, done.stderr


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    base = tmp_path_factory.mktemp("rows")
    for name, text in files().items():
        os.makedirs(base / "class" / name)
        (base / "class" / name / NAMES.get(name, "tumbling_crates.py")).write_text(text, encoding="utf-8")
    status, out, err = run_checker("class", "--pictures", "pics", "--html", "report.html", "--csv", "grades.csv",
                                   "--timeout", "60", cwd=str(base))
    with open(base / "grades.csv", encoding="utf-8", newline="") as handle:
        rows = {row["student"]: row for row in csv.DictReader(handle)}
    return {"base": base, "status": status, "out": out, "err": err, "csv": rows,
            "html": (base / "report.html").read_text(encoding="utf-8")}


def test_a_bad_preview_record_costs_only_its_own_picture(graded):
    base, rows = graded["base"], graded["csv"]
    assert "cannot draw" not in graded["err"], graded["err"]
    assert graded["status"] == 1
    bob = sorted(os.listdir(base / "pics" / "bob" / "tumbling_crates"))
    assert bob and all(name.endswith(".png") for name in bob)
    assert not (base / "pics" / "alice").exists()     # alice's record is refused: no picture, no error
    assert re.search(r'<img alt="[a-z_]+: scene [a-z_]+" src="data:image/png;base64,', graded["html"])
    assert float(rows["alice"]["score"]) <= float(rows["bob"]["score"]), (rows["alice"], rows["bob"])


def test_a_forged_error_line_is_the_files_error_not_the_checkers(graded):
    rows, out = graded["csv"], graded["out"]
    assert "bug in the checker" not in out + graded["err"]
    assert rows["carol"]["status"] == "error" and float(rows["carol"]["score"]) <= float(rows["erin"]["score"])
    block = out[out.index("class/carol/tumbling_crates.py"):]
    assert "result names an error in a form the child never writes" in block.split("\n\n")[0]


def test_show_never_shows_a_traceback_for_a_forged_line(graded):
    status, out, err = run_checker("class/carol/tumbling_crates.py", "--show", cwd=str(graded["base"]))
    assert "Traceback" not in out + err and status == 1, (out, err)


def test_a_message_cannot_print_rows(graded):
    lines = graded["out"].splitlines()
    assert not any(line.startswith(("class/zed", "class/yan", "\rclass")) for line in lines), graded["out"]
    assert FAKE_ROW in graded["out"]   # the message is shown, indented under its check
    shown = next(line for line in lines if FAKE_ROW in line)
    assert shown.startswith("      ")
    # the summary table: one line per file, a row's problem on its own line
    start = next(k for k, line in enumerate(lines) if line.startswith("file ") and "first problem" in line)
    table = lines[start:]
    assert len([line for line in table if line.startswith("class/")]) == len(files())
    # CSV and HTML: quoted and escaped, one row per file
    assert sorted(graded["csv"]) == sorted(files())
    html = graded["html"]
    assert html.count('<tr data-index="') == len(files())
    cells = re.findall(r'<div class="msg">([^<]*)</div>|<td>([^<]*)</td>', html)
    inside = "".join(a + b for a, b in cells)
    # only ever inside a message or the file's first-problem cell, escaped
    assert html.count("class/zed/") == inside.count("class/zed/") >= 1


def test_every_row_of_the_sheet_has_a_reason_and_a_fraction(graded):
    """Issue 40.6: the CSV's message is never empty (the first failing check with its rationale), an empty file
    counts 0 of the class's lab with a fraction, and the hint runs the file under the name it was submitted as."""
    rows = graded["csv"]
    for student, row in rows.items():
        assert row["message"], (student, row)
        assert row["fraction"] and float(row["fraction"]) == pytest.approx(float(row["score"]) / 17, abs=1e-3)
    assert rows["bob"]["message"].startswith("handout_unchanged: fail: code outside the steps differs")
    assert rows["nina"]["lab"] == "tumbling_crates" and rows["nina"]["max_score"] == "17"
    assert rows["nina"]["fraction"] == "0.000" and rows["nina"]["message"] == "the file is empty: nothing to grade"
    assert rows["mallory"]["message"].startswith("loads: error: ") and "SyntaxError" in rows["mallory"]["message"]
    block = graded["out"][graded["out"].index("class/mallory/mallory.py"):].split("\n\n")[0]
    assert "(python mallory.py)" in block and "python tumbling_crates.py" not in block, block
    assert "not graded: the file is empty" in graded["html"]


@pytest.mark.parametrize("forged", ["x", 1, None, [], {"message": 5}, {"kind": "report", "message": "a bug in the "
                                    "checker"}, {"kind": "value", "message": "m", "line": True, "text": 7},
                                    {"kind": "exit", "message": "m" * 10_000, "line": -3, "traceback": ["a"]}])
def test_every_error_account_from_the_child_is_checked_before_use(forged):
    """common.checked_result: a result line's error, and each probe tape's, whatever the child wrote, becomes an
    account the describers read without an exception; only the grader writes kinds "report" and "value"."""
    from types import SimpleNamespace
    from checker.judging.common import CHILD_KINDS, checked_result, describe_function_error, describe_run_failure
    result = checked_result({"phase": "run", "error": forged, "probe": {"tapes": {"p": {"tape": [], "error": forged}}}})
    errors = [result["error"]] + [e for e in [result["probe"]["tapes"]["p"]["error"]] if e is not None]
    assert len(errors) == (1 if forged is None else 2)   # no error on a tape stays no error
    for error in errors:
        assert set(error) == {"kind", "message", "line", "text", "traceback"}
        assert error["kind"] in CHILD_KINDS or error["message"].startswith("the child's result names an error")
        assert isinstance(error["message"], str) and len(error["message"]) <= 600
        assert error["line"] is None or (isinstance(error["line"], int) and error["line"] > 0)
        assert error["text"] is None or isinstance(error["text"], str)
        run = SimpleNamespace(result=result, status="error", returncode=-9, max_output=1024, memory_mb=768,
                              stderr="", stdout="", timeout_trace="", lab_path="x.py", timeout=1.0)
        assert describe_run_failure(run, "x.py", "The file") and describe_function_error("sat", error, "x.py")
    assert "bug in the checker" not in result["error"]["message"] or result["error"]["kind"] == "exception"
    assert checked_result("x") == {} and checked_result({"phase": "done"}) == {"phase": "done"}


def test_a_forged_error_line_on_the_portable_path(tmp_path):
    """The same forgery where Windows and macOS take the portable path (CHECKER_PORTABLE=1 emulates it on Linux:
    the result channel is the child's stdout): the last line written on fd 1 and on fd 3 where it is open, then
    SIGKILL. The row is the file's error, never the checker's bug, and scores no more than its twin (erin)."""
    text = starter()
    forged = ("import os as _os\n"
              "for _fd in (1, 3):\n"
              "    try:\n"
              "        _os.write(_fd, b'\\n{\"phase\": \"run\", \"error\": \"x\"}\\n')\n"
              "    except OSError:\n"
              "        pass\n"
              "_os.kill(_os.getpid(), 9)\n")
    (tmp_path / "carol").mkdir()
    (tmp_path / "erin").mkdir()
    (tmp_path / "carol" / "tumbling_crates.py").write_text(after_imports(text, forged), encoding="utf-8")
    (tmp_path / "erin" / "tumbling_crates.py").write_text(after_imports(text, "import os as _os\n"), encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", CHECKER_PORTABLE="1")
    done = subprocess.run([sys.executable, "-m", "checker", ".", "--json", "--quiet"], cwd=tmp_path,
                          capture_output=True, text=True, env=env, timeout=600)
    rows = {row["path"].split("/")[0]: row for row in json.loads(done.stdout)["labs"]}
    assert "bug in the checker" not in done.stdout + done.stderr, done.stdout
    assert rows["carol"]["status"] == "error" and rows["carol"]["score"] <= rows["erin"]["score"]
