"""The checker's command line: nothing overwritten or lost (issue 9 §3), one bad entry never stops a batch (§4).

Most tests here are usage errors or bad entries, which are refused or reported
before any lab runs, so they take well under a second each. The class folder
(one module-scoped run with --json, --csv and --gradescope-dir) grades one
copy of the solution and two quick-failing labs among a dozen bad entries.
"""
import contextlib
import csv
import hashlib
import io
import json
import os
import stat
import subprocess
import sys

import pytest

from checker import cli, entries
from checker.reporting import outputs, report
from checker.reporting.report import NotGraded
from checker.labs.tumbling_crates.checks import CHECKS

MAX = CHECKS.max_score  # Tumbling Crates' points

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")
MISSING_MAIN = os.path.join(ROOT, "tests", "fixtures", "checker", "hostile_missing_main.py")
CAN_CHMOD_000 = os.geteuid() != 0 if hasattr(os, "geteuid") else False


def run_checker(*args, cwd=ROOT):
    """Run `python -m checker ARGS` from cwd; returns (exit status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               PYTHONDONTWRITEBYTECODE="1")
    command = [sys.executable, "-m", "checker", *args]
    proc = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)
    return proc.returncode, proc.stdout, proc.stderr


def snapshot(folder):
    """Every path under folder (links not followed): kind, mode, mtime_ns, and a digest or link target."""
    state = {}
    for here, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.join(here, name)
            info = os.lstat(path)
            if stat.S_ISLNK(info.st_mode):
                what = "link -> " + os.readlink(path)
            elif stat.S_ISREG(info.st_mode) and info.st_mode & 0o444 and os.access(path, os.R_OK):
                with open(path, "rb") as handle:
                    what = hashlib.sha256(handle.read()).hexdigest()
            else:
                what = stat.filemode(info.st_mode)
            state[os.path.relpath(path, folder)] = (what, info.st_mode, info.st_mtime_ns)
    info = os.stat(folder)
    state["."] = ("folder", info.st_mode, info.st_mtime_ns)
    return state


def one_line_error(err):
    lines = err.strip().splitlines()
    return len(lines) == 1 and lines[0].startswith("checker: error: ") and "Traceback" not in err


def write(path, text, mode="w"):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, mode) as handle:
        handle.write(text)
    return path


# ---------------------------------------------------------------- a class folder with every kind of bad entry

BAD = {  # entry (relative path) -> words its message must contain
    "dangling/tumbling_crates.py": "dangling symbolic link",
    "loop/tumbling_crates.py": "symbolic link loop",
    "latin1/tumbling_crates.py": "not UTF-8",
    "renamed/crates.py": "not a lab",
    "alice/helper.py": "not a lab",
    "fifo/tumbling_crates.py": "not a regular file",
    "linked_folder": "symbolic link to a folder",
}


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    """A class folder with good, failing and bad entries, graded once with every output; also its snapshots."""
    base = tmp_path_factory.mktemp("class")
    folder = str(base / "submissions")
    solution = open(SOLUTION, encoding="utf-8").read()
    missing_main = open(MISSING_MAIN, encoding="utf-8").read()
    write(os.path.join(folder, "alice", "tumbling_crates.py"), solution)
    write(os.path.join(folder, "alice", "helper.py"), "def helper():\n    return 1\n")
    write(os.path.join(folder, "bob", "tumbling_crates.py"), missing_main)
    # a lab file of another name: recognised by the title in its text, and graded
    write(os.path.join(folder, "carol", "my crates (1).py"), missing_main)
    # a lab renamed and stripped of its title: not recognisable, so a row saying so
    write(os.path.join(folder, "renamed", "crates.py"), solution.replace("Tumbling Crates", "Crates"))
    os.makedirs(os.path.join(folder, "dangling"))
    os.symlink("submitted_elsewhere.py", os.path.join(folder, "dangling", "tumbling_crates.py"))
    os.makedirs(os.path.join(folder, "loop"))
    os.symlink("tumbling_crates.py", os.path.join(folder, "loop", "tumbling_crates.py"))
    write(os.path.join(folder, "latin1", "tumbling_crates.py"),
          '"""Tumbling Crates, angle in \xb0."""\n'.encode("latin-1"), mode="wb")
    os.makedirs(os.path.join(folder, "fifo"))
    os.mkfifo(os.path.join(folder, "fifo", "tumbling_crates.py"))
    os.symlink("alice", os.path.join(folder, "linked_folder"))
    write(os.path.join(folder, ".hidden", "tumbling_crates.py"), solution)  # skipped: hidden folder
    before = snapshot(folder)
    csv_path = str(base / "grades.csv")
    gradescope_dir = str(base / "gradescope")
    status, out, err = run_checker(folder, "--json", "--csv", csv_path, "--gradescope-dir", gradescope_dir,
                                   "--timeout", "60", cwd=str(base))  # generous: the machine may be busy
    return {"folder": folder, "base": str(base), "status": status, "doc": json.loads(out), "stderr": err,
            "before": before, "after": snapshot(folder), "csv": csv_path, "gradescope": gradescope_dir}


def rows_by_path(doc):
    return {os.path.relpath(lab["path"], "submissions"): lab for lab in doc["labs"]}


def test_every_bad_entry_is_its_own_row_with_its_reason(klass):
    rows = rows_by_path(klass["doc"])
    for path, words in BAD.items():
        assert rows[path]["status"] == "error", rows[path]
        assert words in rows[path]["message"], rows[path]
        assert rows[path]["score"] == 0 and rows[path]["criteria"] == []
        assert f"{path}: not graded: " in klass["stderr"]
    # rows whose lab is known by the file name count 0 of the lab's points, not 0 of 0
    assert rows["dangling/tumbling_crates.py"]["lab"] == "tumbling_crates"
    assert rows["dangling/tumbling_crates.py"]["max_score"] == MAX
    assert rows["alice/helper.py"]["lab"] is None and rows["alice/helper.py"]["max_score"] == 0
    assert {e["path"] for e in klass["doc"]["errors"]} == {os.path.join("submissions", p) for p in BAD}


def test_every_other_file_is_still_graded(klass):
    rows = rows_by_path(klass["doc"])
    assert rows["alice/tumbling_crates.py"]["status"] == "pass", rows["alice/tumbling_crates.py"]
    assert rows["alice/tumbling_crates.py"]["score"] == MAX
    for path in ("bob/tumbling_crates.py", "carol/my crates (1).py"):
        assert rows[path]["lab"] == "tumbling_crates" and rows[path]["criteria"], rows[path]
        assert rows[path]["criteria"][0]["status"] == "error"  # hostile_missing_main: no main()
    assert len(rows) == 3 + len(BAD)  # the hidden folder is skipped
    assert klass["status"] == 1 and klass["doc"]["passed"] is False


def test_csv_has_a_row_per_entry_with_the_reason(klass):
    with open(klass["csv"], newline="", encoding="utf-8") as handle:
        rows = {os.path.relpath(r["path"], "submissions"): r for r in csv.DictReader(handle)}
    assert set(rows) == set(rows_by_path(klass["doc"]))
    for path, words in BAD.items():
        assert rows[path]["status"] == "error" and words in rows[path]["message"], rows[path]
    assert rows["alice/tumbling_crates.py"]["status"] == "pass" and \
        rows["alice/tumbling_crates.py"]["message"] == "all checks pass"   # a reason in every row (issue 40.6)
    assert rows["alice/tumbling_crates.py"]["corner_tips"] == "pass"


def test_gradescope_dir_has_one_results_json_per_submission(klass):
    found = {}
    for here, _, files in os.walk(klass["gradescope"]):
        if "results.json" in files:
            with open(os.path.join(here, "results.json"), encoding="utf-8") as handle:
                found[os.path.relpath(here, klass["gradescope"])] = json.load(handle)
    assert len(found) == len(klass["doc"]["labs"])
    assert found["alice/tumbling_crates"]["score"] == MAX and len(found["alice/tumbling_crates"]["tests"]) == len(CHECKS.checks)
    dangling = found["dangling/tumbling_crates"]
    assert dangling["score"] == 0 and dangling["tests"][0]["status"] == "failed"
    assert "dangling symbolic link" in dangling["tests"][0]["output"] and dangling["tests"][0]["max_score"] == MAX
    assert "carol/my crates (1)" in found


def test_submissions_are_left_exactly_as_they_were(klass):
    assert klass["after"] == klass["before"]  # same files, digests, modes and mtimes; no __pycache__ added
    assert not any("__pycache__" in path for path in klass["after"])
    # and nothing was written beside the class folder except the outputs asked for
    assert sorted(os.listdir(klass["base"])) == sorted(["gradescope", "grades.csv", "submissions"])


def test_text_report_and_summary_show_the_bad_rows(tmp_path):
    write(str(tmp_path / "subs" / "a" / "tumbling_crates.py"), open(MISSING_MAIN).read())
    os.symlink("gone.py", str(tmp_path / "subs" / "b.py"))
    write(str(tmp_path / "subs" / "notes.py"), "x = 1\n")
    status, out, err = run_checker(str(tmp_path / "subs"), "--quiet", cwd=str(tmp_path))
    assert status == 1
    assert "subs/b.py: 0/0 (error, not graded)" in out and "could not be graded: a dangling symbolic link" in out
    assert "subs/notes.py" in out.split("first problem")[1]
    # the dangling link and the non-lab file are not lab files: counted apart, not as lab files that failed
    assert "0 of 1 lab file(s) pass every check. 2 other file(s) could not be graded as a lab" in out
    assert os.listdir(str(tmp_path)) == ["subs"]  # no grades.csv unless asked


# ---------------------------------------------------------------- unreadable files

def test_unreadable_file_is_a_row_in_process(tmp_path, monkeypatch):
    """A file open() refuses (simulated: root can read a chmod 000 file) becomes an entry with the reason."""
    path = write(str(tmp_path / "tumbling_crates.py"), open(MISSING_MAIN).read())
    real_open = open

    def refusing_open(name, *args, **kwargs):
        if os.fspath(name) == path:
            raise PermissionError(13, "Permission denied", name)
        return real_open(name, *args, **kwargs)

    monkeypatch.setattr("builtins.open", refusing_open)
    entry = entries.examine(path)
    assert entry.problem == "cannot read: Permission denied" and entry.lab is not None and not entry.gradable


@pytest.mark.skipif(not CAN_CHMOD_000, reason="running as root: a chmod 000 file is still readable, so this "
                    "case is simulated in test_unreadable_file_is_a_row_in_process and _in_a_batch instead")
def test_chmod_000_file_is_a_row_and_the_rest_is_graded(tmp_path):
    """Really unreadable (needs a user other than root)."""
    locked = write(str(tmp_path / "locked" / "tumbling_crates.py"), open(MISSING_MAIN).read())
    write(str(tmp_path / "open" / "tumbling_crates.py"), open(MISSING_MAIN).read())
    os.chmod(locked, 0)
    try:
        status, out, err = run_checker(str(tmp_path), "--json", "--quiet", cwd=str(tmp_path))
    finally:
        os.chmod(locked, 0o644)
    rows = {os.path.relpath(lab["path"], str(tmp_path)): lab for lab in json.loads(out)["labs"]}
    assert rows["locked/tumbling_crates.py"]["message"] == "cannot read: Permission denied", rows
    assert rows["open/tumbling_crates.py"]["criteria"], rows  # still graded
    assert status == 1


def test_unreadable_file_is_a_row_in_a_batch(tmp_path, monkeypatch):
    """The whole command line, in process, with open() refusing one file (as chmod 000 does for non-root)."""
    monkeypatch.setattr(cli, "Grader", FakeGrader)
    locked = write(str(tmp_path / "locked" / "tumbling_crates.py"), "x = 1\n")
    write(str(tmp_path / "open" / "tumbling_crates.py"), "x = 1\n")
    real_open = open

    def refusing_open(name, *args, **kwargs):
        if os.fspath(name) == locked:
            raise PermissionError(13, "Permission denied", name)
        return real_open(name, *args, **kwargs)

    monkeypatch.setattr("builtins.open", refusing_open)
    status, out, err = run_main(str(tmp_path), "--json", "--quiet")
    rows = {os.path.relpath(lab["path"], str(tmp_path)): lab for lab in json.loads(out)["labs"]}
    assert rows["locked/tumbling_crates.py"]["status"] == "error"
    assert rows["locked/tumbling_crates.py"]["message"] == "cannot read: Permission denied"
    assert rows["open/tumbling_crates.py"]["status"] == "pass" and status == 1


def test_unreadable_subfolder_is_a_row(tmp_path, monkeypatch):
    folder = str(tmp_path / "subs")
    write(os.path.join(folder, "a", "tumbling_crates.py"), open(MISSING_MAIN).read())
    os.makedirs(os.path.join(folder, "b"))
    real_scandir = os.scandir

    def refusing_scandir(path="."):
        if os.fspath(path).endswith(os.sep + "b"):
            raise PermissionError(13, "Permission denied", os.fspath(path))
        return real_scandir(path)

    monkeypatch.setattr(os, "scandir", refusing_scandir)
    found, problems = entries.discover([folder])
    assert problems == []
    by_name = {os.path.relpath(e.path, folder): e for e in found}
    assert by_name["b"].problem == "cannot read this folder: Permission denied"
    assert by_name[os.path.join("a", "tumbling_crates.py")].gradable


# ---------------------------------------------------------------- the grader failing on one file

class FakeGrader:
    """Stands in for grade.Grader: raises on files named boom*.py, passes everything else."""

    def __init__(self, *args, **kwargs):
        pass

    def grade(self, path, lab):
        if os.path.basename(path).startswith("boom"):
            raise KeyError("a bug of ours")
        from checker.judging.checks import Result
        from checker.grade import LabReport
        return LabReport(path, lab, [Result(c.id, c.description, "pass", score=c.max_score, max_score=c.max_score)
                                     for c in lab.checks.checks], 0.1)


def run_main(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = cli.main(list(argv))
    return status, out.getvalue(), err.getvalue()


def test_a_grader_crash_on_one_file_is_an_error_row_and_the_batch_goes_on(tmp_path, monkeypatch):
    monkeypatch.setattr(cli, "Grader", FakeGrader)
    for name in ("a_tumbling_crates.py", "boom_tumbling_crates.py", "c_tumbling_crates.py"):
        write(str(tmp_path / name), "# Tumbling Crates\n")
    status, out, err = run_main(str(tmp_path), "--json", "--quiet")
    labs = {os.path.basename(lab["path"]): lab for lab in json.loads(out)["labs"]}
    assert labs["a_tumbling_crates.py"]["status"] == labs["c_tumbling_crates.py"]["status"] == "pass"
    boom = labs["boom_tumbling_crates.py"]
    assert boom["status"] == "error" and "KeyError" in boom["message"] and "bug in the checker" in boom["message"]
    assert boom["max_score"] == MAX
    assert status == 1 and "internal error KeyError" in err


def test_all_pass_exits_zero(tmp_path, monkeypatch):
    monkeypatch.setattr(cli, "Grader", FakeGrader)
    write(str(tmp_path / "tumbling_crates.py"), "x = 1\n")
    assert run_main(str(tmp_path / "tumbling_crates.py"), "--quiet")[0] == 0


# ---------------------------------------------------------------- outputs: never over an input, never unasked

@pytest.fixture
def two_labs(tmp_path):
    a = write(str(tmp_path / "a" / "tumbling_crates.py"), open(MISSING_MAIN).read())
    b = write(str(tmp_path / "b" / "tumbling_crates.py"), open(MISSING_MAIN).read())
    return tmp_path, a, b


def test_gradescope_cannot_swallow_a_submission(two_labs):
    tmp, a, b = two_labs
    before = snapshot(str(tmp))
    status, out, err = run_checker("--gradescope", a, b, cwd=str(tmp))
    assert status == 2 and one_line_error(err) and ".py file" in err and a in err
    assert out == "" and snapshot(str(tmp)) == before


@pytest.mark.parametrize("option", ["--csv", "--gradescope"])
def test_output_over_an_input_is_refused(two_labs, option):
    tmp, a, b = two_labs
    notes = write(str(tmp / "notes.txt"), "my notes\n")  # a non-.py input named explicitly
    before = snapshot(str(tmp))
    status, out, err = run_checker(notes, option, notes, cwd=str(tmp))
    assert status == 2 and one_line_error(err) and "one of the paths being graded" in err
    assert snapshot(str(tmp)) == before


@pytest.mark.parametrize("option", ["--csv", "--gradescope", "--gradescope-dir"])
def test_output_inside_a_graded_folder_is_refused(two_labs, option):
    tmp, a, b = two_labs
    before = snapshot(str(tmp))
    status, out, err = run_checker(str(tmp / "a"), option, str(tmp / "a" / "out"), cwd=str(tmp))
    assert status == 2 and one_line_error(err) and "a folder being graded" in err
    assert snapshot(str(tmp)) == before


def test_gradescope_file_for_several_submissions_is_refused(two_labs):
    tmp, a, b = two_labs
    status, out, err = run_checker(a, b, "--gradescope", str(tmp / "results.json"), cwd=str(tmp))
    assert status == 2 and one_line_error(err) and "--gradescope-dir" in err and "2 files" in err
    assert not os.path.exists(str(tmp / "results.json"))


@pytest.mark.parametrize("args, words", [
    (["--csv", "{tmp}"], "is a folder"),
    (["--csv", "{tmp}/no/such/folder/g.csv"], "does not exist"),
    (["--csv", "{tmp}/g.csv", "--gradescope", "{tmp}/g.csv"], "the same path as --csv"),
    (["--gradescope-dir", "{tmp}"], "holds files being graded"),
    (["--gradescope-dir", "{tmp}/a/tumbling_crates.py"], ".py file"),
    (["--csv"], "expected one argument"),
    (["--jobs", "0"], "--jobs must be >= 1"),
    (["--timeout", "nan"], "--timeout must be > 0"),
    (["--gradescop", "x.json"], "unrecognized arguments"),
])
def test_bad_output_or_option_is_one_line_and_nothing_runs(two_labs, args, words):
    tmp, a, b = two_labs
    before = snapshot(str(tmp))
    status, out, err = run_checker(a, *[arg.format(tmp=tmp) for arg in args], cwd=str(tmp))
    assert status == 2 and one_line_error(err) and words in err, err
    assert out == "" and snapshot(str(tmp)) == before


@pytest.mark.parametrize("paths, words", [(["no/such.py"], "no/such.py: no such file or folder"),
                                          (["empty"], "empty: no .py file in this folder")])
def test_bad_top_level_path_is_a_usage_error(tmp_path, paths, words):
    os.makedirs(str(tmp_path / "empty"))
    write(str(tmp_path / "empty" / "readme.txt"), "hi\n")
    status, out, err = run_checker(*paths, cwd=str(tmp_path))
    assert status == 2 and one_line_error(err) and words in err


def test_no_file_is_written_unasked_and_csv_none_writes_nothing(two_labs):
    tmp, a, b = two_labs
    before = sorted(os.listdir(str(tmp)))
    status, out, err = run_checker(a, b, "--quiet", "--csv", "none", cwd=str(tmp))
    assert status == 1 and "CSV written" not in out
    assert sorted(os.listdir(str(tmp))) == before  # no grades.csv, no file named none


def test_existing_output_named_by_the_user_is_replaced_whole(two_labs):
    tmp, a, b = two_labs
    target = write(str(tmp / "out" / "grades.csv"), "an older grades.csv\n")
    os.chmod(target, 0o640)
    status, out, err = run_checker(a, b, "--quiet", "--csv", target, cwd=str(tmp))
    text = open(target, encoding="utf-8").read()
    assert status == 1 and text.startswith("student,path,lab,status,score,max_score,fraction,")
    assert len(text.splitlines()) == 3
    assert stat.S_IMODE(os.stat(target).st_mode) == 0o640  # kept the instructor's permissions
    assert os.listdir(str(tmp / "out")) == ["grades.csv"]  # no temporary file left behind
    assert f"CSV written to {target}" in out


def test_single_gradescope_file_for_an_entry_that_cannot_be_graded(tmp_path):
    os.symlink("gone.py", str(tmp_path / "tumbling_crates.py"))
    status, out, err = run_checker("tumbling_crates.py", "--gradescope", "results.json", cwd=str(tmp_path))
    data = json.load(open(str(tmp_path / "results.json")))
    assert status == 1 and data["score"] == 0 and len(data["tests"]) == 1
    assert data["tests"][0]["max_score"] == MAX and "dangling" in data["tests"][0]["output"]


def test_write_atomic_leaves_the_old_file_when_it_fails(tmp_path, monkeypatch):
    target = write(str(tmp_path / "grades.csv"), "old\n")

    def crash(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", crash)
    with pytest.raises(OSError):
        report.write_atomic(target, "new\n" * 1000)
    assert open(target).read() == "old\n" and os.listdir(str(tmp_path)) == ["grades.csv"]


def test_submission_names_are_relative_to_the_common_folder_and_unique():
    names = outputs.submission_names(["c/alice/tumbling_crates.py", "c/bob/tumbling_crates.py", "c/x.py", "c/x"])
    assert names == {"c/alice/tumbling_crates.py": "alice/tumbling_crates", "c/bob/tumbling_crates.py":
                     "bob/tumbling_crates", "c/x.py": "x.py", "c/x": "x"}
    assert outputs.submission_names(["lab/tumbling_crates.py"]) == {"lab/tumbling_crates.py": "tumbling_crates"}


def test_not_graded_row_reads_like_a_lab_report():
    from checker.labs import LABS
    row = NotGraded("x/tumbling_crates.py", LABS[0], "cannot read: Permission denied")
    assert (row.score, row.max_score, row.passed, row.status, list(row.results)) == (0, MAX, False, "error", [])
    assert NotGraded("notes.py", None, "not a lab").max_score == 0
    stream = io.StringIO()
    report.summary_table([row], stream)
    assert "not graded: cannot read: Permission denied" in stream.getvalue()


def test_help_names_the_output_options_and_exit_statuses():
    status, out, err = run_checker("--help")
    out = " ".join(out.split())  # argparse wraps the text to the terminal's width
    assert status == 0 and "--gradescope-dir DIR" in out and "Exit status: 0" in out and "No file is written" in out


def test_an_existing_output_folder_needs_only_its_own_permission(tmp_path):
    """A grader running as root hands the student user a writable pictures folder inside a folder only root may
    write in (Gradescope, PrairieLearn): the folder's own permission decides, not its parent's."""
    parent = tmp_path / "root-owned"
    pictures = parent / "pictures"
    pictures.mkdir(parents=True)
    parent.chmod(0o555)
    try:
        assert outputs.check([("--pictures", str(pictures), "folder")], [], [], []) == []
        if os.geteuid() != 0:   # root may write anywhere: only an unprivileged user can see the refusal
            pictures.chmod(0o555)
            assert outputs.check([("--pictures", str(pictures), "folder")], [], [], []) == \
                [f"--pictures {pictures}: cannot write in this folder"]
        missing = parent / "new"
        problems = outputs.check([("--pictures", str(missing), "folder")], [], [], [])
        assert problems == ([] if os.geteuid() == 0 else [f"--pictures {missing}: cannot write in the folder {parent}"])
    finally:
        pictures.chmod(0o755)
        parent.chmod(0o755)
