"""Issue 39.5: the root grader writes only what it created, in folders it made, and follows no link.

The attack: the student's code (unprivileged) plants `<pictures folder>/<lab>/<check>.png -> VICTIM`; a
grader that writes its PNG with `open(path, "wb")` writes as root through the link. Here VICTIM is a file
only root may read or write, outside every work folder (in pytest's root-only tmp folder).

- test_gradescope_pictures_folder_is_not_the_students: Gradescope's own procedure (the package unpacked
  into ROOT/source, run_autograder copied to ROOT and run from there, as root), the student's code run
  unprivileged. What differs from Gradescope: the root is a temporary folder named by AUTOGRADER_ROOT, the
  student's user is `nobody` (this machine has no `student`), and TMPDIR is a private world-enterable folder,
  so the payload reaches no other test's folders. The planted links would point at VICTIM; the file must
  score what the same file without the payload scores, and VICTIM must be untouched.
- test_write_pictures_follows_no_link: the writing itself (checker/reporting/outputs.py), with the links already
  planted (a link as the picture, a link as the submission's folder, a folder of another user): none is
  followed, the other rows' pictures are written.
"""
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import zipfile

import pytest

from checker.reporting import outputs, report
from checker.replay import pictures
from checker.reporting.report import NotGraded

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0
SECRET = b"root's own file: nobody else may change it\n"

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_checker_package import gradescope_setup_stand_in, run_package  # noqa: E402


def victim(folder):
    """A root-only file (0600) outside every work folder."""
    path = os.path.join(str(folder), "victim.txt")
    with open(path, "wb") as handle:
        handle.write(SECRET)
    os.chmod(path, 0o600)
    return path


def payload(tmp, target, lab="tumbling_crates"):
    """Module-level code that plants a link to `target` for every check of `lab` in every pictures folder it
    can reach under `tmp` (the folders grade_submission.py makes: tmp/autograde-*/pictures-*)."""
    from checker import labs
    ids = [c.id for c in next(x for x in labs.LABS if x.id == lab).checks.checks]
    return (f"import glob as _glob, os as _os\n"
            f"for _folder in _glob.glob({tmp!r} + '/autograde-*/pictures-*'):\n"
            f"    for _lab in ({lab!r}, 'x'):\n"
            f"        try:\n"
            f"            _os.makedirs(_folder + '/' + _lab, exist_ok=True)\n"
            f"        except OSError:\n"
            f"            pass\n"
            f"        for _check in {ids!r}:\n"
            f"            try:\n"
            f"                _os.symlink({target!r}, _folder + '/' + _lab + '/' + _check + '.png')\n"
            f"            except OSError:\n"
            f"                pass\n")


def with_payload(text, code):
    """text with `code` after its imports."""
    lines = text.split("\n")
    last = max(k for k, line in enumerate(lines[:80]) if line.startswith(("import ", "from ")))
    return "\n".join(lines[:last + 1] + code.rstrip("\n").split("\n") + lines[last + 1:])


@pytest.fixture(scope="module")
def crates_bundle(tmp_path_factory):
    base = tmp_path_factory.mktemp("crates")
    done = run_package("gradescope", "--out", str(base / "autograder.zip"), "--labs", "tumbling_crates")
    assert done.returncode == 0, done.stderr
    source = base / "source"
    with zipfile.ZipFile(base / "autograder.zip") as archive:
        archive.extractall(source)
    os.chmod(source / "run_autograder", 0o755)
    gradescope_setup_stand_in(source)
    return source


def gradescope_as_root(source, folder, text, user, tmpdir):
    """Grade {tumbling_crates.py: text} by Gradescope's procedure in `folder`; its results.json."""
    root = folder / "autograder"
    shutil.copytree(source, root / "source", symlinks=True)
    (root / "submission").mkdir(parents=True)
    (root / "submission" / "tumbling_crates.py").write_text(text, encoding="utf-8")
    script = shutil.copy2(root / "source" / "run_autograder", root / "run_autograder")
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "HOME": str(root), "AUTOGRADER_ROOT": str(root),
           "AUTOGRADER_USER": user, "TMPDIR": tmpdir}
    done = subprocess.run([str(script)], cwd=root, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    with open(root / "results" / "results.json", encoding="utf-8") as handle:
        return json.load(handle)


@pytest.mark.skipif(not AS_ROOT, reason="the attack is on a root grader; run as root")
def test_gradescope_pictures_folder_is_not_the_students(crates_bundle, tmp_path):
    secret = victim(tmp_path)
    tmpdir = tempfile.mkdtemp(prefix="i39-root-writes-", dir="/tmp")   # enterable by the student's user
    try:
        os.chmod(tmpdir, 0o755)
        with open(os.path.join(ROOT, "starters", "tumbling_crates_starter.py"), encoding="utf-8") as handle:
            starter = handle.read()
        attack = with_payload(starter, payload(tmpdir, secret))
        # the honest file: the same code without the planted links (the payload's imports and loop kept, so
        # the handout comparison fails alike)
        honest = with_payload(starter, payload(tmpdir + "/none", secret))
        scores = {}
        for name, text in (("honest", honest), ("attack", attack)):
            doc = gradescope_as_root(crates_bundle, tmp_path / name, text, "nobody", tmpdir)
            scores[name] = doc["score"]
            with open(secret, "rb") as handle:
                assert handle.read() == SECRET, f"{name}: the grader wrote through the student's link"
            assert stat.S_IMODE(os.stat(secret).st_mode) == 0o600
        assert scores["attack"] <= scores["honest"], scores
        failed = [t for t in doc["tests"] if t["status"] == "failed"]
        assert failed, doc
    finally:
        shutil.rmtree(tmpdir, ignore_errors=True)


@pytest.mark.skipif(not AS_ROOT, reason="the attack is on a root grader; run as root")
def test_prairielearn_pictures_folder_is_not_the_students(tmp_path):
    """PrairieLearn's entrypoint uses the same script: the same attack, by its own procedure (GRADE_ROOT in place
    of /grade, the student's code as `nobody`)."""
    out = tmp_path / "pl"
    done = run_package("prairielearn", "--out", str(out), "--labs", "tumbling_crates", "--image", "me/l11")
    assert done.returncode == 0, done.stderr
    secret = victim(tmp_path)
    tmpdir = tempfile.mkdtemp(prefix="i39-root-writes-", dir="/tmp")
    try:
        os.chmod(tmpdir, 0o755)
        with open(os.path.join(ROOT, "starters", "tumbling_crates_starter.py"), encoding="utf-8") as handle:
            attack = with_payload(handle.read(), payload(tmpdir, secret))
        grade = tmp_path / "grade"
        (grade / "student").mkdir(parents=True)
        (grade / "student" / "tumbling_crates.py").write_text(attack, encoding="utf-8")
        env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "GRADE_ROOT": str(grade),
               "GRADER_PYTHON": sys.executable, "AUTOGRADER_USER": "nobody", "TMPDIR": tmpdir}
        done = subprocess.run([str(out / "run_prairielearn")], env=env, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
        doc = json.loads((grade / "results" / "results.json").read_text())
        assert doc["gradable"] is True and doc["score"] < 1
        with open(secret, "rb") as handle:
            assert handle.read() == SECRET, "the grader wrote through the student's link"
    finally:
        shutil.rmtree(tmpdir, ignore_errors=True)


class _Row:
    """The least a row needs for write_pictures: its path."""
    def __init__(self, path):
        self.path = path


def test_write_pictures_follows_no_link(tmp_path):
    secret = victim(tmp_path)
    secret_folder = tmp_path / "secret_folder"
    secret_folder.mkdir()
    out = tmp_path / "pictures"
    out.mkdir()
    png = pictures.Picture("runs", "corner", b"\x89PNG\r\n\x1a\nfake")
    rows = [_Row(f"class/{name}/tumbling_crates.py") for name in ("alice", "bob", "carol", "dave")]
    names = outputs.submission_names([r.path for r in rows])
    assert names[rows[0].path] == os.path.join("alice", "tumbling_crates")
    (out / "alice" / "tumbling_crates").mkdir(parents=True)
    os.symlink(secret, out / "alice" / "tumbling_crates" / "runs.png")      # the picture is a link
    (out / "bob").mkdir()
    os.symlink(secret_folder, out / "bob" / "tumbling_crates")               # the submission's folder is a link
    os.symlink(secret_folder, out / "carol")                                  # a folder above it is a link
    made = {r.path: {"runs": [png]} for r in rows}
    problems = []
    written = pictures.write_pictures(rows, str(out), names, made, problems)
    with open(secret, "rb") as handle:
        assert handle.read() == SECRET
    assert os.listdir(secret_folder) == []
    # alice's planted link was replaced by the grader's own file, not followed
    alice = out / "alice" / "tumbling_crates" / "runs.png"
    assert not alice.is_symlink() and alice.read_bytes() == png.png
    assert written[rows[0].path]["runs"] == [str(alice)]
    # bob's and carol's folders are links: their pictures are not written, each row says why, dave's are
    assert set(written) == {rows[0].path, rows[3].path}
    assert (out / "dave" / "tumbling_crates" / "runs.png").read_bytes() == png.png
    assert len(problems) == 2 and all("not written" in p for p in problems), problems
    assert "bob" in problems[0] and "carol" in problems[1]
    # a second run over the same folder replaces the pictures it wrote
    problems = []
    again = {r.path: made[r.path] for r in (rows[0], rows[3])}
    written = pictures.write_pictures(rows, str(out), names, again, problems)
    assert not problems and alice.read_bytes() == png.png


@pytest.mark.skipif(not AS_ROOT, reason="a folder of another user can only be made as root")
def test_write_pictures_refuses_a_folder_another_user_made(tmp_path):
    import pwd
    out = tmp_path / "pictures"
    (out / "eve").mkdir(parents=True)
    nobody = pwd.getpwnam("nobody")
    os.chown(out / "eve", nobody.pw_uid, nobody.pw_gid)
    png = pictures.Picture("runs", "corner", b"\x89PNG\r\n\x1a\nfake")
    row = _Row("eve.py")
    problems = []
    written = pictures.write_pictures([row], str(out), {"eve.py": "eve"}, {"eve.py": {"runs": [png]}}, problems)
    assert written == {} and len(problems) == 1 and "not the grader's" in problems[0], problems
    assert os.listdir(out / "eve") == []


def test_results_json_is_not_written_through_a_link(tmp_path):
    """grade_submission.write_json (the platform's results.json) and report.write_atomic (--csv, --html,
    --gradescope, --gradescope-dir): a link where the file goes is replaced, never followed."""
    from test_checker_package import grading_script
    script = grading_script()
    secret = victim(tmp_path)
    results = tmp_path / "results"
    results.mkdir()
    os.symlink(secret, results / "results.json")
    os.symlink(secret, results / "results.json.tmp")   # the old fixed temporary name
    script.write_json(str(results / "results.json"), {"score": 0.0})
    assert json.loads((results / "results.json").read_text()) == {"score": 0.0}
    report.write_atomic(str(tmp_path / "grades.csv"), "x\n")
    os.symlink(secret, tmp_path / "report.html")
    report.write_atomic(str(tmp_path / "report.html"), "<html>\n")
    assert not (tmp_path / "report.html").is_symlink()
    with open(secret, "rb") as handle:
        assert handle.read() == SECRET
    assert stat.S_IMODE(os.stat(secret).st_mode) == 0o600
    assert stat.S_IMODE(os.stat(tmp_path / "report.html").st_mode) != 0o777
