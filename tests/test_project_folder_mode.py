"""The same verdicts wherever the project sits (issue 44): a clone inside a folder of mode 700.

`mktemp -d` makes such a folder, and home folders are often 700 or 750: as root, the child's user (a uid of its
own per run, nobody's group) cannot enter it. What the child needs from the project reaches it without that:
the zygote imports the labs' probes (a lab added in-process too: its probes are imported by the forked child
before it leaves root), and the child then runs chrooted in its work folder, where it opens nothing of the
project's. The test copies the working tree (not the last commit, as `git clone` would) into such a folder and
runs the README's two commands' essentials there: `python -m checker solutions/` (with the star import of the
answers beside it, whose verdict used to change with the folder) and the plug-in test (a new lab graded from its
folder). As root with the default child user; again without the jail (CHECKER_NO_JAIL=1: a system that refuses
chroot), and through the portable path; and as a normal user where this machine has one that can run this Python.
The real difference from a user's fresh clone: no `pip install -e .` (PYTHONPATH names the copy), and the test's
Python is the one running the tests.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import labs_found
import pytest

from checker.isolation import users

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROJECT = ("checker", "lesson11", "solutions", "starters", "tests", "pyproject.toml", "README.md")
SKIP = shutil.ignore_patterns("__pycache__", "*.pyc", ".pytest_cache")
STAR = "from solutions.tumbling_crates import *\n"

needs_root = pytest.mark.skipif(not users.is_root(), reason="a folder the child's user cannot enter needs root")


def clone_in_private_folder(owner=None):
    """(the private folder, the project's copy in it): `mktemp -d` (mode 700) holding the working tree's files."""
    private = tempfile.mkdtemp(prefix="l11-private-")
    assert os.stat(private).st_mode & 0o777 == 0o700
    project = os.path.join(private, "c")
    os.mkdir(project)
    for name in PROJECT:
        source = os.path.join(ROOT, name)
        if os.path.isdir(source):
            shutil.copytree(source, os.path.join(project, name), ignore=SKIP)
        else:
            shutil.copy2(source, os.path.join(project, name))
    solution = open(os.path.join(project, "solutions", "tumbling_crates.py"), encoding="utf-8").read()
    at = solution.index('if __name__ == "__main__"')
    os.mkdir(os.path.join(private, "star"))
    with open(os.path.join(private, "star", "tumbling_crates.py"), "w", encoding="utf-8") as handle:
        handle.write(solution[:at] + STAR + solution[at:])
    if owner is not None:
        for base, folders, files in os.walk(private):
            for name in [base] + [os.path.join(base, n) for n in folders + files]:
                os.chown(name, owner.pw_uid, owner.pw_gid)
    return private, project


def run(command, project, env=None, user=None):
    environment = dict(os.environ, PYTHONPATH=project, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
                       **(env or {}))
    environment.pop("PYTEST_XDIST_WORKER", None)
    demote = None if user is None else (lambda: users.drop_to(user.pw_uid, user.pw_gid))
    if user is not None:
        environment["HOME"] = os.path.dirname(project)
    return subprocess.run(command, cwd=project, env=environment, capture_output=True, text=True, timeout=900,
                          preexec_fn=demote)


def grade_solutions_and_star(project, env=None, user=None, labs="solutions/"):
    proc = run([sys.executable, "-m", "checker", labs, os.path.join(os.path.dirname(project), "star",
                                                                     "tumbling_crates.py"),
                "--json", "--quiet", "--jobs", "2"], project, env, user)
    assert proc.returncode == 1, proc.stderr[-3000:]   # the star file fails; the solutions pass
    rows = {os.path.relpath(row["path"], os.path.dirname(project)): row for row in json.loads(proc.stdout)["labs"]}
    star = rows.pop(os.path.join("star", "tumbling_crates.py"))
    for path, row in rows.items():
        assert (row["status"], row["score"]) == ("pass", row["max_score"]), (path, row["message"], row["criteria"])
    checks = {c["id"]: c for c in star["criteria"]}
    flags = [flag["what"] for flag in star["flags"]]
    assert any("imports every name of solutions.tumbling_crates" in what for what in flags), flags
    return rows, checks


def plugin_test(project, env=None, user=None):
    proc = run([sys.executable, "-m", "pytest", "-n", "0", "-q", "-p", "no:cacheprovider",
                "tests/test_checker_plugin.py::test_a_new_lab_is_graded_from_its_folder"], project, env, user)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-2000:]


@needs_root
def test_as_root_a_clone_in_a_700_folder_grades_as_anywhere():
    """Both essentials as root, the child as its own uid (nobody's group): the solutions pass, the star import of
    the answers is the file's own ModuleNotFoundError (the child cannot reach them, jailed), the new lab passes."""
    private, project = clone_in_private_folder()
    try:
        rows, checks = grade_solutions_and_star(project)
        assert len(rows) == len(labs_found.LABS)   # every lab's solution
        assert checks["loads"]["status"] == "error"
        assert "ModuleNotFoundError: No module named 'solutions'" in checks["loads"]["message"]
        plugin_test(project)
    finally:
        shutil.rmtree(private)


@needs_root
@pytest.mark.parametrize("env", [{"CHECKER_NO_JAIL": "1"}, {"CHECKER_PORTABLE": "1"}], ids=["no_jail", "portable"])
def test_as_root_without_the_jail_or_through_the_portable_path_the_same_verdicts(env):
    """Without chroot the child's user cannot enter the 700 folder, so neither the project nor the answers are in
    its reach, and the verdicts are those above; the portable child imports the probes before it switches."""
    private, project = clone_in_private_folder()
    try:
        rows, checks = grade_solutions_and_star(project, env, labs="solutions/tumbling_crates.py")
        assert checks["loads"]["status"] == "error"
        assert "ModuleNotFoundError: No module named 'solutions'" in checks["loads"]["message"]
        plugin_test(project, env)
    finally:
        shutil.rmtree(private)


def _normal_user():
    """A user with a uid >= 1000 that can start this Python and read the test's modules, or None."""
    if not users.is_root():
        return None
    import pwd
    for entry in sorted(pwd.getpwall(), key=lambda e: e.pw_uid):
        if 1000 <= entry.pw_uid < 60000:
            try:
                probe = subprocess.run([sys.executable, "-c", "import pygame, pytest"], cwd="/", capture_output=True,
                                       preexec_fn=lambda: users.drop_to(entry.pw_uid, entry.pw_gid), timeout=120)
            except (OSError, subprocess.SubprocessError):
                continue
            if probe.returncode == 0:
                return entry
    return None


def test_as_a_normal_user_a_clone_in_its_own_700_folder_grades_as_anywhere():
    """Not root: the child runs as the grader's own user, which owns the folder; the star import then reads the
    answers (they are the grader's user's), and the step rules fail the step it replaces."""
    if not users.is_root():
        owner = None   # this test is already a normal user's
    else:
        owner = _normal_user()
        if owner is None:
            pytest.skip("no user with a uid >= 1000 here that can run this Python (it is installed under /root)")
    private, project = clone_in_private_folder(owner)
    try:
        rows, checks = grade_solutions_and_star(project, user=owner, labs="solutions/tumbling_crates.py")
        assert checks["apply_impulse_spin"]["status"] == "fail", checks["apply_impulse_spin"]
        plugin_test(project, user=owner)
    finally:
        shutil.rmtree(private)
