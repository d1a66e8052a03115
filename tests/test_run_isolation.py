"""Each run alone (issue 39 items 1 and 7): one file cannot write, signal or outlive into another run, nor read the
answers, in every way the checker grades as root.

The attacks, each graded beside the honest work it contains (the starter: 3/17) and beside classmates:
- `daemon`: at import the file double-forks a process that leaves its session (setsid), so the run's killpg
  misses it, and for 40 s rewrites every lab copy, settings file and record it can open in any run's work folder
  (`raise SystemExit`) and sends SIGSTOP to every process it may signal. Issue 39 measured such a file giving a
  classmate's starter 17/17 and a solution 0/17. Now each run has a uid of its own, its folder is root's (only
  its out/ is the uid's), the child is chrooted in it where root may, and everything of the uid is killed when
  the run ends: the classmates' rows are their usual ones and no process of a run's uid is left after the batch.
- `forks`: 300 forks that each leave their session and sleep 60 s: the run's uid may have NPROC processes
  (RLIMIT_NPROC), so fork fails first, and none of them outlives the batch.
- `answers`: top-level code that reads solutions/tumbling_crates.py through the path of the checker's own
  package and puts its step 2 in its error message (the JSON report): it must get no answer, in any mode.
Modes: the CLI as root with no option (the child: a uid of its own, nobody's group, jailed), `--child-user nobody`,
CHECKER_NO_JAIL=1 (a system that refuses chroot: the folders' modes alone), CHECKER_PORTABLE=1 (the Windows
path emulated; what real Windows and macOS guarantee is in checker/README.md), and Gradescope's procedure (the
package's run_autograder, as root, the student's code as nobody: this machine has no `student`).
They need root: run as a normal user the daemon's signals would reach the grader itself, which is the documented
limit of a grader that is not root.
"""
import json
import os
import shutil
import subprocess
import sys

import pytest

import gradescope_procedure as gradescope
from checker.isolation import users

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")

pytestmark = pytest.mark.skipif(not users.is_root() or users.choose(None)[0] is None,
                                reason="needs a grader running as root and a user nobody")

DAEMON = '''
import glob as _glob, os as _os, posix as _posix, signal as _signal, time as _time


def _haunt(run):
    me, end = _os.getpid(), _time.time() + 40
    tmp = _os.environ.get("TMPDIR") or "/tmp"
    while _time.time() < end:
        for pattern in ("checker-*/*.py", "checker-*/settings.json", "checker-*/out/*", "checker-*/*"):
            for path in _glob.glob(_os.path.join(tmp, pattern)):
                try:
                    with open(path, "w") as handle:
                        handle.write('raise SystemExit("haunted")\\n')
                except OSError:
                    pass
        for pid in range(2, 70000):
            try:
                if pid != me and _os.getpgid(pid) != run:   # every process but its own run's (threads too)
                    _os.kill(pid, _signal.SIGSTOP)
            except OSError:
                pass
        _time.sleep(0.2)


_run = _os.getpid()
if _os.fork() == 0:
    _os.setsid()
    if _os.fork() == 0:
        try:
            _haunt(_run)
        finally:
            _posix._exit(0)
    _posix._exit(0)
_time.sleep(5)   # its run stays alive, so the daemon has the classmates running beside it
'''

FORKS = '''
import os as _os, posix as _posix, time as _time
_forked = 0
for _ in range(300):
    try:
        if _os.fork() == 0:
            _os.setsid()
            _time.sleep(60)
            _posix._exit(0)
        _forked += 1
    except OSError:
        break
raise RuntimeError(f"FORKED {_forked}")
'''

ANSWERS = '''
import os as _os
import checker as _checker
_path = _os.path.join(_os.path.dirname(_os.path.dirname(_checker.__file__)), "solutions", "tumbling_crates.py")
try:
    _text = open(_path).read()
    _seen = _text[_text.index("# --- step 2"):][:400]
except OSError as _exc:
    _seen = "NO-ANSWER " + type(_exc).__name__
raise RuntimeError("SEEN " + _seen)
'''


def with_attack(attack):
    starter = open(STARTER, encoding="utf-8").read()
    at = starter.index('if __name__ == "__main__"')
    return starter[:at] + attack + "\n\n" + starter[at:]


def run_uid_processes():
    """The pids of live processes running as a uid of users.RUN_UIDS (a run's own) that outlived the process that
    started them (their parent is now init, pid 1), from /proc. Anything a run leaves behind has such a process at
    its root; a run still going (another test's, beside this one under pytest-xdist) has the grader or its zygote as
    parent and is not counted. A zombie (killed, its exit not yet collected by init) is not alive: it runs nothing."""
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open(f"/proc/{name}/status", encoding="utf-8") as handle:
                fields = dict(line.split(":", 1) for line in handle if ":" in line)
        except OSError:
            continue
        uids = fields.get("Uid", "").split()
        orphan = fields.get("PPid", "").strip() == "1"
        if orphan and fields.get("State", "").split()[:1] != ["Z"] and any(int(uid) in users.RUN_UIDS for uid in uids):
            found.append(int(name))
    return found


def class_folder(base):
    """A private class folder: the daemon first (so it runs while its classmates do), then alice's starter,
    bob's solution, carol's starter, the file reaching for the answers and the fork bomb."""
    files = {"a_mallory": with_attack(DAEMON), "b_alice": open(STARTER, encoding="utf-8").read(),
             "c_bob": open(SOLUTION, encoding="utf-8").read(), "d_carol": open(STARTER, encoding="utf-8").read(),
             "e_eve": with_attack(ANSWERS), "f_frank": with_attack(FORKS)}
    os.makedirs(base, mode=0o700)
    paths = {}
    for name, text in files.items():
        os.mkdir(os.path.join(base, name))
        paths[name] = os.path.join(base, name, "tumbling_crates.py")
        with open(paths[name], "w", encoding="utf-8") as handle:
            handle.write(text)
    return paths


MODES = {"root": ([], {}), "child_user": (["--child-user", "nobody"], {}), "no_jail": ([], {"CHECKER_NO_JAIL": "1"}),
         "portable": ([], {"CHECKER_PORTABLE": "1"})}


@pytest.fixture(scope="module")
def private_project():
    """A copy of the project in a 700 folder: without the jail the repository's world-readable solutions/ is
    refused (tests/test_checker_safe_default.py), so that mode grades from a copy the run's user cannot reach."""
    from test_project_folder_mode import clone_in_private_folder
    private, project = clone_in_private_folder()
    yield project
    shutil.rmtree(private)


@pytest.mark.parametrize("mode", sorted(MODES))
def test_a_daemon_in_a_class_folder_changes_no_other_row_and_is_gone_when_the_batch_ends(tmp_path, mode,
                                                                                         private_project):
    argv, env = MODES[mode]
    project = private_project if mode == "no_jail" else ROOT
    paths = class_folder(str(tmp_path / "class"))
    environment = dict(os.environ, PYTHONPATH=project, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", **env)
    proc = subprocess.run([sys.executable, "-m", "checker", *paths.values(), "--json", "--quiet", "--jobs", "2",
                           "--timeout", "10", *argv], cwd=project, env=environment, capture_output=True, text=True,
                          timeout=900)
    left = run_uid_processes()   # right when the batch ended: nothing of any run is left
    assert proc.returncode == 1, proc.stderr[-3000:]
    rows = {os.path.basename(os.path.dirname(row["path"])): row for row in json.loads(proc.stdout)["labs"]}
    assert not left, f"processes of a run's uid outlived the batch: {left}"
    for name in ("b_alice", "d_carol"):   # the starter's usual row, step 2 failing
        row = rows[name]
        status = {c["id"]: c["status"] for c in row["criteria"]}
        assert (row["score"], status["loads"], status["sat_axes"]) == (3, "pass", "fail"), row
    assert (rows["c_bob"]["score"], rows["c_bob"]["status"]) == (17, "pass"), rows["c_bob"]
    assert rows["a_mallory"]["score"] <= 3   # no more than the starter it holds
    frank = next(c["message"] for c in rows["f_frank"]["criteria"] if c["id"] == "loads")
    assert int(frank.split("FORKED ", 1)[1].split()[0].rstrip(".")) < users.NPROC, frank   # RLIMIT_NPROC held
    eve = next(c["message"] for c in rows["e_eve"]["criteria"] if c["id"] == "loads")
    assert "NO-ANSWER" in eve and "def sat" not in eve and rows["e_eve"]["score"] <= 3, eve


def test_on_gradescopes_procedure_a_daemon_is_gone_and_the_answers_unread(tmp_path):
    """The package's run_autograder (copied to the root and run from there, as Gradescope does), as root with the
    student's code as nobody (AUTOGRADER_USER=nobody; Gradescope's image has `student`): the daemon file scores no
    more than its starter and nothing of its run is left when run_autograder returns; the file reaching for the
    package's solutions gets none."""
    bundle = tmp_path / "autograder.zip"
    gradescope.build(bundle, ["tumbling_crates"])
    for name, attack, most in (("daemon", DAEMON, 3), ("answers", ANSWERS, 3)):
        done, results = gradescope.run(bundle, tmp_path / name, "tumbling_crates.py", with_attack(attack))
        left = run_uid_processes()
        assert done.returncode == 0, done.stderr
        assert not left, f"processes of a run's uid outlived run_autograder: {left}"
        assert results["score"] <= most, results["output"]
        text = json.dumps(results)
        assert "def sat" not in text and "SEEN # --- step 2" not in text
