"""Safe by default (issue 35 item 5): a grader running as root runs the student's code as an unprivileged user.

As root with no option the child runs as users.DEFAULT_CHILD_USER (nobody); `--child-user root` opts out.
The child runs a copy of the lab alone in its work folder with only the project on its path, so a module
beside the submission is not importable; it cannot reach the grader's stdout through /proc. Where the
child's user cannot run Python or read a module, the row carries the checker's one line, never the
student's error. The tests that switch users need root (skipped otherwise); the rest run anywhere.
"""
import json
import os
import subprocess
import sys

import pytest

from checker.isolation import sandbox, users

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
TITLE = '"""Tumbling Crates lab."""\n'   # the checker recognises the lab by the title in its text

as_root = pytest.mark.skipif(not users.is_root(), reason="switching users needs a grader running as root")
needs_nobody = pytest.mark.skipif(not users.is_root() or users.choose(None)[0] != users.DEFAULT_CHILD_USER,
                                  reason=f"needs root and a user {users.DEFAULT_CHILD_USER!r}")


def checker(*argv, zygote=True, cwd=None, jail=True, project=ROOT):
    """(exit status, stdout, stderr) of `python -m checker ARGV` run as this test's user (jail=False: as on a
    system that refuses chroot; project: the copy of the project to run)."""
    cwd = cwd or project
    env = dict(os.environ, PYTHONPATH=project, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               CHECKER_ZYGOTE="1" if zygote else "0", CHECKER_NO_JAIL="0" if jail else "1")
    proc = subprocess.run([sys.executable, "-m", "checker", *argv], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=900)
    return proc.returncode, proc.stdout, proc.stderr


def rows(stdout):
    return {os.path.basename(row["path"]): row for row in json.loads(stdout)["labs"]}


def loads_message(row):
    return next(c["message"] for c in row["criteria"] if c["id"] == "loads")


def lab_raising(folder, name, expression, before=""):
    """A Tumbling Crates file whose import raises RuntimeError(f"seen={expression}"): its loads message shows it."""
    path = os.path.join(folder, name)
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(f"{TITLE}import os\n{before}raise RuntimeError(f\"seen={{{expression}}}\")\n")
    return path


@pytest.fixture(scope="module")
def private_project():
    """A copy of the project in a folder of mode 700 (tests/test_project_folder_mode.py): the child's user cannot
    reach its solutions/, so a grader without the jail (CHECKER_NO_JAIL=1) grades there instead of refusing."""
    from test_project_folder_mode import clone_in_private_folder
    private, project = clone_in_private_folder()
    yield project
    import shutil
    shutil.rmtree(private)


@needs_nobody
def test_without_the_jail_answers_the_child_could_read_are_refused_in_one_line():
    """Issue 39 item 7: no chroot (CHECKER_NO_JAIL=1, as where the system refuses it) and the repository's
    solutions/ readable by the run's user: nothing is graded; one line says so and how to fix it. The line comes
    from a real try by a process of that user, not from the mode bits."""
    where = users.readable_answers(users.DEFAULT_CHILD_USER, ROOT)
    status, out, err = checker(SOLUTION, "--json", "--quiet", jail=False)
    if where is None:
        assert status == 0, err
        return
    assert status == 2 and out == ""
    assert err.strip().splitlines() == [f"checker: error: {users.answers_problem(users.DEFAULT_CHILD_USER, ROOT)}"]
    assert f"chmod -R go-rwx {os.path.join(ROOT, 'solutions')}" in err


# ---------------------------------------------------------------- who runs the child

@needs_nobody
def test_as_root_the_child_runs_as_nobody_without_being_told_and_root_only_when_asked(tmp_path):
    path = lab_raising(str(tmp_path), "uid_lab.py", "(os.getuid(), os.geteuid(), os.getgroups())")
    status, out, err = checker(path, "--json", "--quiet")
    assert status == 1, err
    nogroup = __import__("pwd").getpwnam(users.DEFAULT_CHILD_USER).pw_gid   # nobody's group, a uid of the run's own
    seen = loads_message(rows(out)["uid_lab.py"]).split("seen=(", 1)[1].split(")", 1)[0]
    uid, euid, groups = seen.split(", ", 2)
    assert uid == euid and int(uid) in users.RUN_UIDS and groups == "[]", seen
    gid_path = lab_raising(str(tmp_path), "gid_lab.py", "os.getgid()")
    assert f"seen={nogroup}" in loads_message(rows(checker(gid_path, "--json", "--quiet")[1])["gid_lab.py"])
    status, out, err = checker(path, "--json", "--quiet", "--child-user", "root")   # the opt-out
    assert status == 1, err
    assert "seen=(0, 0," in loads_message(rows(out)["uid_lab.py"])


def test_choosing_the_user():
    if not users.is_root():
        assert users.choose(None) == (None, None)   # not root: no switch, and no option to ask for one
        assert users.choose("nobody")[1].startswith("--child-user nobody: only a grader running as root")
        return
    assert users.choose("root") == (None, None)
    assert users.choose("no-such-user-35")[1] == "--child-user no-such-user-35: no such user on this machine"
    if users.choose(None)[0] is None:   # this machine has no nobody: the default says so and how to go on
        assert "--child-user root" in users.choose(None)[1]
    else:
        assert users.choose(None) == (users.DEFAULT_CHILD_USER, None)


@needs_nobody
def test_solution_full_marks_and_starter_its_usual_verdicts_as_nobody_through_the_zygote():
    status, out, err = checker(SOLUTION, STARTER, "--json", "--quiet")
    assert status == 1, err   # the starter fails
    graded = rows(out)
    solution, starter = graded["tumbling_crates.py"], graded["tumbling_crates_starter.py"]
    assert (solution["status"], solution["score"], solution["max_score"]) == ("pass", 17, 17), solution
    verdicts = {c["id"]: c["status"] for c in starter["criteria"]}
    assert (starter["score"], verdicts["loads"], verdicts["handout_unchanged"], verdicts["runtime_lines"],
            verdicts["sat_axes"]) == (3, "pass", "pass", "pass", "fail"), verdicts


@needs_nobody
def test_without_the_zygote_it_grades_or_says_in_one_line_that_it_cannot():
    """CHECKER_ZYGOTE=0: every child starts Python as nobody. Where nobody can (Python installed where it may
    read), the solution gets full marks; where it cannot (here: a pyenv under /root, mode 700), the checker
    stops before grading with one line naming the folder and the fix (exit 2), and blames no file."""
    problem = users.python_problem(users.DEFAULT_CHILD_USER, ROOT)
    status, out, err = checker(SOLUTION, "--json", "--quiet", zygote=False)
    if problem is None:
        assert status == 0 and rows(out)["tumbling_crates.py"]["score"] == 17, err
        return
    assert status == 2 and out == ""
    assert err.strip().splitlines() == [f"checker: error: {problem}"]
    blocked = users.python_blocked(users.DEFAULT_CHILD_USER)
    assert problem == (f"the checker cannot run Python as user 'nobody': {blocked} is not readable by it; "
                       f"install Python where that user can read it, or choose another --child-user")


@needs_nobody
def test_a_zygote_that_fails_mid_run_gives_the_checkers_line_not_the_students(monkeypatch):
    """The grader falls back to starting the child itself; when nobody cannot run this Python that is a
    users.ChildUserError (the CLI's row for the file: the one line), never a crash blamed on the file."""
    if users.python_problem(users.DEFAULT_CHILD_USER, ROOT) is None:
        pytest.skip("nobody can run this Python here: the fallback simply works")
    monkeypatch.setattr(sandbox, "zygote_enabled", lambda: False)
    with pytest.raises(users.ChildUserError, match=r"^the checker cannot run Python as user 'nobody': "):
        sandbox.run_child(SOLUTION, "probe", {"probes": "checker.labs.tumbling_crates.probes"},
                          sandbox.Limits(timeout=5, user=users.DEFAULT_CHILD_USER))


@needs_nobody
@pytest.mark.parametrize("jail", [True, False], ids=["jail", "no_jail"])
def test_an_import_error_is_the_checkers_only_when_the_users_own_try_confirms_it(tmp_path, jail, private_project):
    """Issue 39 item 8: a step's ModuleNotFoundError is not believed. Jailed (chroot), the child has only what
    the zygote imported, so every import error is the file's own. Without the jail the grader has a process of
    the run's user try the module: a forged "No module named 'pygame'" (a module that user can read) stays the
    file's error; one it really cannot read ('wave' in a Python under /root) is the checker's line, which never
    advises running the student's code as root. (Without the jail the repository's world-readable solutions/ is
    refused, so that run grades a copy of the project in a 700 folder, where the answers are out of reach.)"""
    import importlib.util
    solution = open(SOLUTION, encoding="utf-8").read()
    at = solution.index("import math")
    files = {"reads.py": "import wave\n", "missing.py": "import no_such_module_35\n",
             "forged_wave.py": "raise ModuleNotFoundError(\"No module named 'wave'\")\n",
             "forged_pygame.py": "raise ModuleNotFoundError(\"No module named 'pygame'\")\n"}
    for name, line in files.items():
        with open(tmp_path / name, "w", encoding="utf-8") as handle:
            handle.write(solution[:at] + line + solution[at:])
    status, out, err = checker(*(str(tmp_path / name) for name in files), "--json", "--quiet", jail=jail,
                               project=ROOT if jail else private_project)
    graded = rows(out)
    wave_unreadable = users.blocked(os.path.realpath(importlib.util.find_spec("wave").origin), "nobody")
    for name in files:
        row = graded[name]
        assert "--child-user root" not in row["message"], row["message"]
        ours = not jail and name in ("reads.py", "forged_wave.py") and wave_unreadable
        if ours:
            assert row["message"].startswith("the checker cannot import 'wave' as user 'nobody': ")
            assert row["criteria"] == [] and err.count(row["message"]) == 1
        else:
            assert row["message"] == "" and "ModuleNotFoundError: No module named" in loads_message(row), row
            assert row["score"] == 0


def test_an_import_of_the_answers_kept_from_the_child_stays_the_files_error(tmp_path):
    """Gradescope and PrairieLearn keep solutions/ from the child's user (mode 700): a file importing them
    gets the student's ModuleNotFoundError (and its step flags), not the checker's 'cannot import' line.
    Emulated here: a solutions/ folder the user cannot enter, on the child's path."""
    private = tmp_path / "project"
    (private / "solutions").mkdir(parents=True)
    (private / "solutions" / "tumbling_crates.py").write_text("X = 1\n", encoding="utf-8")
    (private / "solutions").chmod(0o700)
    (private / "shared").mkdir()
    (private / "shared" / "__init__.py").write_text("", encoding="utf-8")
    (private / "shared").chmod(0o700)
    error = {"message": "ModuleNotFoundError: No module named 'solutions.tumbling_crates'"}
    assert users.unreadable_import(error, "nobody", [str(private)]) is None
    other = users.unreadable_import({"message": "ModuleNotFoundError: No module named 'shared'"}, "nobody",
                                    [str(private)])
    if users.blocked(str(private / "shared"), "nobody"):   # the control: any other unreadable module is ours
        assert other.startswith("the checker cannot import 'shared' as user 'nobody': ")


@needs_nobody
def test_an_error_naming_a_module_the_child_had_warm_is_the_files_even_where_its_user_cannot_read_it(tmp_path):
    """Issue 44: in a clone inside a 700 folder the venv's pygame is unreadable by nobody, yet the forked child
    has it imported before it left root. A ModuleNotFoundError naming a warm module cannot come from the folder's
    mode, so it stays the file's (forged); the same name not warm, on the same unreadable path, is the checker's."""
    (tmp_path / "venv" / "warmpkg").mkdir(parents=True)
    (tmp_path / "venv" / "warmpkg" / "__init__.py").write_text("", encoding="utf-8")
    tmp_path.chmod(0o700)
    error = {"message": "ModuleNotFoundError: No module named 'warmpkg'"}
    path = [str(tmp_path / "venv")]
    assert users.unreadable_import(error, "nobody", path, warm=frozenset({"warmpkg"})) is None
    assert users.unreadable_import(error, "nobody", path).startswith("the checker cannot import 'warmpkg' as user")
    from checker.isolation import zygote
    assert {"pygame", "numpy", "lesson11.physics2d", "checker.labs.tumbling_crates.probes"} <= zygote.warm_names()


# ---------------------------------------------------------------- the child's folder and path

@pytest.mark.parametrize("user", ["default", "root"])
def test_a_module_beside_the_lab_is_not_importable_and_the_lab_is_alone_in_its_folder(tmp_path, user):
    if user == "root" and not users.is_root():
        pytest.skip("--child-user root needs a grader running as root")
    (tmp_path / "crate_utils.py").write_text("HELPER = 1\n", encoding="utf-8")
    path = lab_raising(str(tmp_path), "side_lab.py", "(found, sorted(os.listdir(os.path.dirname(__file__))))",
                       before="try:\n    import crate_utils\n    found = 'imported'\nexcept ImportError:\n"
                              "    found = 'not importable'\n")
    argv = [path, "--json", "--quiet"] + (["--child-user", "root"] if user == "root" else [])
    status, out, err = checker(*argv, cwd=str(tmp_path))   # even from the submission's own folder
    message = loads_message(rows(out)["side_lab.py"])
    assert "seen=('not importable', [" in message, message
    listed = message.split("seen=('not importable', [", 1)[1].split("]", 1)[0]
    names = {name.strip(" '") for name in listed.split(",")}
    assert "side_lab.py" in names and "crate_utils.py" not in names
    assert names <= {"side_lab.py", "settings.json", "out"}, names   # out/: the child's own (its cwd)


@needs_nobody
@pytest.mark.parametrize("user", ["default", "root"])
def test_the_lab_cannot_write_to_the_graders_stdout_through_proc(tmp_path, user):
    """The lab walks up two parents (the zygote and the grader; no further, so nothing outside this test is
    written to) and writes a forged --json document to each one's fd 1 through /proc. As nobody every open is refused and the grader's stdout is its own document; as
    root (the opt-out) the forgery does reach it, which is what the default prevents."""
    forged = json.dumps({"schema": "lesson11-checker/1", "passed": True, "forged": "FORGED-35"})
    path = lab_raising(str(tmp_path), "proc_lab.py", "reached", before=f"""reached = []
pid = os.getppid()
for hop in range(2):
    try:
        with open(f"/proc/{{pid}}/fd/1", "w") as handle:
            handle.write({forged!r} + "\\n")
        reached.append(pid)
    except OSError:
        pass
    try:
        with open(f"/proc/{{pid}}/stat") as handle:
            pid = int(handle.read().rsplit(")", 1)[1].split()[1])
    except OSError:
        break
""")
    argv = [path, "--json", "--quiet"] + (["--child-user", "root"] if user == "root" else [])
    status, out, err = checker(*argv)
    if user == "root":
        assert "FORGED-35" in out   # the hole the default closes: root's child reaches the grader's stdout
        return
    assert "FORGED-35" not in out
    assert "seen=[]" in loads_message(rows(out)["proc_lab.py"])   # no open succeeded


@needs_nobody
def test_work_folders_the_child_user_cannot_enter_are_the_checkers_line(tmp_path, monkeypatch):
    """TMPDIR in a folder only root may enter: the child could not even enter its work folder."""
    private = tmp_path / "private"
    private.mkdir(mode=0o700)
    monkeypatch.setenv("TMPDIR", str(private))
    status, out, err = checker(SOLUTION, "--json", "--quiet")
    row = rows(out)["tumbling_crates.py"]
    assert row["criteria"] == [] and row["message"].startswith(
        f"the checker's work folders in {private} are not reachable by user 'nobody': ")
    assert "set TMPDIR to a folder it can enter" in row["message"]


# ---------------------------------------------------------------- what the child leaves in its folder

@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs are POSIX")
def test_a_fifo_in_place_of_the_traceback_file_does_not_hang_the_grader(tmp_path):
    """The child's user owns its work folder: a lab that swaps timeout_traceback.txt for a FIFO made the
    grader's open() wait forever (the whole batch stalled); now only regular files are read."""
    path = tmp_path / "fifo_lab.py"
    path.write_text(f'{TITLE}import os\nos.unlink("timeout_traceback.txt")\nos.mkfifo("timeout_traceback.txt")\n',
                    encoding="utf-8")
    status, out, err = checker(str(path), "--json", "--quiet", "--total-timeout", "120")
    assert status == 1, err
    assert "defines no function sat()" in loads_message(rows(out)["fifo_lab.py"])


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs and /dev/zero are POSIX")
def test_the_grader_reads_only_regular_files_from_the_work_folder(tmp_path):
    regular, fifo, link = tmp_path / "record.json", tmp_path / "fifo", tmp_path / "link"
    regular.write_text('{"frames": 3}', encoding="utf-8")
    os.mkfifo(fifo)
    os.symlink("/dev/zero", link)
    assert sandbox._read_json(str(regular), 1000) == {"frames": 3}
    assert sandbox._read_json(str(regular), 5) is None            # over the limit
    assert sandbox._read_work_file(str(fifo), 1000) is None       # would block in open()
    assert sandbox._read_work_file(str(link), 1000) is None       # a link (to an endless file) is not followed
    assert sandbox._read_work_file(str(tmp_path / "gone"), 1000) is None


def test_the_lab_cannot_patch_what_the_child_reports_with(tmp_path):
    """json.dumps and the child's describe() are bound before the lab loads: a lab that replaces them (to send
    a forged result, or to change the account of its error) changes nothing of what the child sends."""
    path = tmp_path / "patch_lab.py"
    path.write_text(TITLE + "import json, sys\n"
                    "json.dumps = lambda *a, **k: '{\"task\": \"probe\", \"phase\": \"done\", \"probe\": {}}'\n"
                    "sys.modules['__main__'].describe = lambda exc, path: {'kind': 'exception', 'message': 'FORGED'}\n"
                    "raise RuntimeError('the real error')\n", encoding="utf-8")
    status, out, err = checker(str(path), "--json", "--quiet")
    message = loads_message(rows(out)["patch_lab.py"])
    assert "RuntimeError: the real error" in message and "FORGED" not in message, message


@needs_nobody
@pytest.mark.parametrize("jail", [True, False], ids=["jail", "no_jail"])
def test_a_file_of_pythons_own_that_nobody_cannot_read_is_the_checkers_line(tmp_path, jail, private_project):
    """Python's own files (where pygame keeps data it may open late, say) unreadable by the child's user: the
    checker's line, once a process of that user confirmed it. A file the student opens that is not Python's
    (the solutions, say) stays the student's. Jailed, no file outside the run's folder exists for the child:
    every open of one is the file's own error."""
    stdlib_file = os.path.join(os.path.dirname(os.__file__), "this.py")
    if not users.blocked(os.path.realpath(stdlib_file), users.DEFAULT_CHILD_USER):
        pytest.skip("nobody can read the standard library here")
    private = tmp_path / "private.txt"
    private.write_text("answers", encoding="utf-8")
    private.chmod(0o600)
    for name, target in (("python_file.py", stdlib_file), ("private_file.py", str(private))):
        (tmp_path / name).write_text(f"{TITLE}open({target!r}).read()\n", encoding="utf-8")
    status, out, err = checker(str(tmp_path / "python_file.py"), str(tmp_path / "private_file.py"), "--json",
                               "--quiet", jail=jail, project=ROOT if jail else private_project)
    graded = rows(out)
    if jail:
        assert "FileNotFoundError" in loads_message(graded["python_file.py"])
        assert graded["python_file.py"]["message"] == ""
    else:
        assert graded["python_file.py"]["message"].startswith(f"the checker cannot read {stdlib_file} as user 'nobody'")
    assert ("FileNotFoundError" if jail else "PermissionError") in loads_message(graded["private_file.py"])
    assert graded["private_file.py"]["message"] == ""


# ---------------------------------------------------------------- the packages' user

@as_root
def test_the_packages_pass_their_user_or_root_when_asked_and_never_fall_back_to_root(monkeypatch, capsys):
    """grade_submission.run_as (Gradescope, PrairieLearn): the platform's user ("student") when it exists;
    AUTOGRADER_USER="" is the documented opt-out (--child-user root); a missing user leaves the choice to the
    checker (nobody), where it used to fall back to running the student's code as root."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "grade_submission_35", os.path.join(ROOT, "checker", "platforms", "templates", "grade_submission.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    monkeypatch.setenv("AUTOGRADER_USER", "")
    assert module.run_as({"user": "student"}) == "root"
    monkeypatch.delenv("AUTOGRADER_USER")
    assert module.run_as({"user": "nobody"}) == "nobody"
    assert module.run_as({"user": "no-such-user-35"}) is None
    assert "the checker runs the student's code as its default user" in capsys.readouterr().err
