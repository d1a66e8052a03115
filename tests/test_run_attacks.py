"""Each run alone, attacked again after the fixes of issue 39 (a student who read checker/, grading as root).

- `peek`: top-level code that, while a classmate's file is graded beside it (--jobs 2), reads every lab copy it can
  open in the other runs' work folders (/tmp/checker-*/NAME.py) and puts the classmate's step 2 in its own error
  message (the JSON report). Jailed, the child cannot see /tmp at all; without the jail (CHECKER_NO_JAIL=1, a
  system that refuses chroot; macOS; the zygote off) the copies used to be root's, mode 644, in a folder of mode
  755: any run's uid read a classmate's submission. Now the copy and the settings are the run's uid's, mode 400.
The honest twin is the starter the attack sits in (3/17); the classmate is a solution marked ROW-OF-BOB (17/17).
"""
import json
import os
import shutil
import subprocess
import sys

import pytest

from checker.isolation import users
from test_run_isolation import SOLUTION, STARTER, with_attack

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

pytestmark = pytest.mark.skipif(not users.is_root() or users.choose(None)[0] is None,
                                reason="needs a grader running as root and a user nobody")

PEEK = '''
import glob as _glob, os as _os, time as _time
_mine = _os.path.dirname(_os.path.abspath(__file__))
_seen = "NOTHING"
_end = _time.time() + 8
while _time.time() < _end and _seen == "NOTHING":
    for _p in _glob.glob(_os.path.join(_os.environ.get("TMPDIR") or "/tmp", "checker-*", "*.py")):
        if _os.path.dirname(_p) != _mine:
            try:
                _t = open(_p).read()
                if "ROW-OF-BOB" in _t:
                    _seen = _t[_t.index("# --- step 2"):][:300]
            except OSError as _e:
                _seen = "DENIED " + type(_e).__name__
    _time.sleep(0.05)
raise RuntimeError("PEEK " + _seen)
'''

MODES = {"root": {}, "no_jail": {"CHECKER_NO_JAIL": "1"}, "portable": {"CHECKER_PORTABLE": "1"},
         "portable_no_jail": {"CHECKER_PORTABLE": "1", "CHECKER_NO_JAIL": "1"}}
# (CHECKER_ZYGOTE=0 is not a mode here: this machine's Python sits under /root, which nobody cannot run: refused)


@pytest.fixture(scope="module")
def private_project():
    """A copy of the project in a 700 folder: unjailed, a world-readable solutions/ is refused before grading."""
    from test_project_folder_mode import clone_in_private_folder
    private, project = clone_in_private_folder()
    yield project
    shutil.rmtree(private)


@pytest.mark.parametrize("mode", sorted(MODES))
def test_a_run_cannot_read_a_classmates_submission_while_it_is_graded(tmp_path, mode, private_project):
    paths = {"a_mallory": with_attack(PEEK), "b_bob": "# ROW-OF-BOB\n" + open(SOLUTION, encoding="utf-8").read()}
    for name, text in paths.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "tumbling_crates.py").write_text(text, encoding="utf-8")
    environment = dict(os.environ, PYTHONPATH=private_project, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
                       **MODES[mode])
    proc = subprocess.run([sys.executable, "-m", "checker", *(str(tmp_path / n / "tumbling_crates.py") for n in paths),
                           "--json", "--quiet", "--jobs", "2", "--timeout", "10"], cwd=private_project,
                          env=environment, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 1, proc.stderr[-3000:]
    rows = {os.path.basename(os.path.dirname(row["path"])): row for row in json.loads(proc.stdout)["labs"]}
    assert (rows["b_bob"]["score"], rows["b_bob"]["status"]) == (17, "pass"), rows["b_bob"]
    mallory = rows["a_mallory"]
    message = next(c["message"] for c in mallory["criteria"] if c["id"] == "loads")
    assert "PEEK " in message, message   # the attack ran
    assert "PEEK NOTHING" in message or "PEEK DENIED" in message, message
    assert "# --- step 2" not in json.dumps(mallory) and "ROW-OF-BOB" not in json.dumps(mallory), message
    assert mallory["score"] <= 3, mallory   # no more than the starter it holds


DEEP = '''
import os as _os
for _ in range(3000):
    _os.mkdir("deep-mallory")
    _os.chdir("deep-mallory")
'''


def test_a_folder_chain_thousands_deep_is_removed_and_blames_no_checker(tmp_path):
    """`deep`: top-level code makes a chain of 3000 folders in its working folder (out/). Removing the work folder
    with shutil.rmtree (one recursion per level) raised RecursionError in the grader: the row said "this is a bug
    in the checker" and the tree stayed in the temporary folder. Now the row is the file's own (its twin, the
    starter it sits in, 3/17; the top-level edit fails handout_unchanged) and nothing of it is left."""
    import glob
    tmp = os.environ.get("TMPDIR") or "/tmp"
    paths = {"a_mallory": with_attack(DEEP), "b_alice": open(STARTER, encoding="utf-8").read()}
    for name, text in paths.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "tumbling_crates.py").write_text(text, encoding="utf-8")
    environment = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", *(str(tmp_path / n / "tumbling_crates.py") for n in paths),
                           "--json", "--quiet", "--jobs", "2", "--timeout", "10"], cwd=ROOT, env=environment,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 1, proc.stderr[-3000:]
    rows = {os.path.basename(os.path.dirname(row["path"])): row for row in json.loads(proc.stdout)["labs"]}
    assert "bug in the checker" not in proc.stdout + proc.stderr, proc.stderr[-3000:]
    assert rows["a_mallory"]["criteria"], rows["a_mallory"]   # graded, not an error row of ours
    assert rows["a_mallory"]["score"] <= rows["b_alice"]["score"] == 3, rows
    assert not glob.glob(os.path.join(tmp, "checker-*", "out", "deep-mallory")), "the deep tree was left behind"


FILL = '''
import os as _os, time as _time
_block = b"x" * (1 << 20)
for _i in range(100000):
    try:
        with open(f"fill{_i}", "wb") as _h:
            for _ in range(60):
                _h.write(_block)
    except OSError:
        break
_time.sleep(25)
'''


@pytest.fixture
def small_tmp():
    """A 300 MB tmpfs as the grader's TMPDIR (a small /tmp, as many systems have), where root may mount one (in
    the system's temporary folder: pytest's own is closed to the run's user)."""
    import tempfile
    folder = tempfile.mkdtemp(prefix="l11-small-tmp-")
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=300m,mode=1777", "tmpfs", folder],
                      capture_output=True).returncode != 0:
        os.rmdir(folder)
        pytest.skip("cannot mount a tmpfs here")
    yield folder
    subprocess.run(["umount", "-l", folder], check=False)
    os.rmdir(folder)


@pytest.mark.parametrize("mode", ["root", "no_mount", "portable"])
def test_a_run_filling_the_disk_changes_no_classmates_row(tmp_path, small_tmp, mode):
    """`fill`: top-level code writes 60 MB files into its out/ folder until the disk is full and keeps its run
    alive 25 s. Graded beside a solution with TMPDIR on a 300 MB tmpfs, the solution's runs could not write their
    settings (or their records): measured before the quota, bob's row "not graded: the checker's temporary folder
    is full", 0/17, and mallory 2/17. Now each run's out/ holds at most --disk MB (64): "root" mounts a tmpfs of
    64 MB on it (the writer meets ENOSPC in its own run); "no_mount" (a system refusing the mount, as
    CHECKER_NO_MOUNT=1 makes it) and "portable" watch it every 0.05 s (measured 1-63 MB past the quota,
    tests/test_run_disk.py): 64 MB + the overshoot stays well under 300 MB, so there too the solution keeps
    17/17. The fill run is stopped with a row naming the quota, and no tmpfs of a run is left mounted."""
    paths = {"a_mallory": with_attack(FILL), "b_bob": open(SOLUTION, encoding="utf-8").read()}
    for name, text in paths.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "tumbling_crates.py").write_text(text, encoding="utf-8")
    environment = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
                       TMPDIR=small_tmp, **{"root": {}, "no_mount": {"CHECKER_NO_MOUNT": "1"},
                                            "portable": {"CHECKER_PORTABLE": "1"}}[mode])
    proc = subprocess.run([sys.executable, "-m", "checker", *(str(tmp_path / n / "tumbling_crates.py") for n in paths),
                           "--json", "--quiet", "--jobs", "2", "--timeout", "10"], cwd=ROOT, env=environment,
                          capture_output=True, text=True, timeout=600)
    rows = {os.path.basename(os.path.dirname(row["path"])): row for row in json.loads(proc.stdout)["labs"]}
    assert rows["a_mallory"]["score"] <= 3, rows["a_mallory"]
    loads = next(c["message"] for c in rows["a_mallory"]["criteria"] if c["id"] == "loads")
    assert loads == "The file wrote more than 64 MB (or 1000 files) into its working folder and was stopped.", loads
    assert "cannot read" not in rows["b_bob"]["message"], rows["b_bob"]["message"]   # never the file's fault
    assert (rows["b_bob"]["score"], rows["b_bob"]["status"]) == (17, "pass"), rows["b_bob"]["message"]
    with open("/proc/self/mounts", encoding="utf-8") as handle:
        assert not [line for line in handle if small_tmp + "/" in line], "a run's tmpfs was left mounted"


SYSV = '''
import ctypes as _ct
_libc = _ct.CDLL(None, use_errno=True)
_libc.shmat.restype = _ct.c_void_p
_made = []
for _k in range(4):
    _id = _libc.shmget(0x4c310000 + _k, 32 << 20, 0o1666)
    _p = _libc.shmat(_id, None, 0)
    if _p not in (None, _ct.c_void_p(-1).value):
        _ct.memset(_p, 1, 32 << 20)
        _libc.shmdt(_ct.c_void_p(_p))
    _made.append(_id)
_made.append(_libc.semget(0x4c320000, 4, 0o1666))
_made.append(_libc.msgget(0x4c330000, 0o1666))
raise RuntimeError(f"SYSV {_made}")
'''


def sysv_objects_of_runs():
    """[(kind, id, creator uid)] of the System V IPC objects a run's uid (users.RUN_UIDS) created or owns."""
    found = []
    for kind, column in (("shm", "shmid"), ("sem", "semid"), ("msg", "msqid")):
        try:
            with open(f"/proc/sysvipc/{kind}", encoding="ascii") as handle:
                header, *rows = handle.read().splitlines()
        except (OSError, ValueError):
            continue
        for row in rows:
            fields = dict(zip(header.split(), row.split()))
            if int(fields["cuid"]) in users.RUN_UIDS or int(fields["uid"]) in users.RUN_UIDS:
                found.append((kind, int(fields[column]), int(fields["cuid"])))
    return found


@pytest.mark.skipif(not os.path.exists("/proc/sysvipc/shm"), reason="Linux's /proc/sysvipc")
@pytest.mark.parametrize("mode", ["root", "portable"])
def test_a_run_leaves_no_shared_memory_behind(tmp_path, mode):
    """`sysv`: top-level code (jailed: it needs no file, ctypes is in memory) makes four 32 MB System V shared
    memory segments, mode 666, touches every page, and a semaphore set and a message queue. They outlived the
    run and the batch (128 MB resident, readable and writable by any later run). Now everything its uid created
    is removed when the run ends; the row is its twin's (the starter with a top-level error: 0/17)."""
    (tmp_path / "a_mallory").mkdir()
    (tmp_path / "a_mallory" / "tumbling_crates.py").write_text(with_attack(SYSV), encoding="utf-8")
    environment = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
                       **({"CHECKER_PORTABLE": "1"} if mode == "portable" else {}))
    proc = subprocess.run([sys.executable, "-m", "checker", str(tmp_path / "a_mallory" / "tumbling_crates.py"),
                           "--json", "--quiet", "--timeout", "10"], cwd=ROOT, env=environment, capture_output=True,
                          text=True, timeout=600)
    left = sysv_objects_of_runs()
    row = json.loads(proc.stdout)["labs"][0]
    message = next(c["message"] for c in row["criteria"] if c["id"] == "loads")
    assert "SYSV [" in message and "-1" not in message.split("SYSV", 1)[1], message   # the attack made them all
    assert not left, f"System V objects of a run's uid outlived the batch: {left}"
    assert row["score"] == 0, row


MQUEUE = '''
import ctypes as _ct
import os as _os
_rt = _ct.CDLL(None, use_errno=True)   # glibc 2.34+ has mq_open in libc (librt is not in the jail)
_made = []
for _k in range(3):
    _q = _rt.mq_open(("/l11-left-%d" % _k).encode(), _os.O_CREAT | _os.O_RDWR, 0o666, None)
    _made.append(_q if _q >= 0 else -_ct.get_errno())
raise RuntimeError(f"MQUEUE {_made}")
'''


def message_queues_of_runs():
    """[(name, owner uid)] of the POSIX message queues a run's uid owns, read from a private mount of the mqueue
    file system (Linux, root), or None where it cannot be mounted here."""
    import tempfile
    where = tempfile.mkdtemp(prefix="l11-mqueue-")
    try:
        if subprocess.run(["mount", "-t", "mqueue", "mqueue", where], capture_output=True).returncode:
            return None
        try:
            return [(name, os.stat(os.path.join(where, name)).st_uid) for name in os.listdir(where)
                    if os.stat(os.path.join(where, name)).st_uid in users.RUN_UIDS]
        finally:
            subprocess.run(["umount", where], capture_output=True)
    finally:
        os.rmdir(where)


@pytest.mark.skipif(not sys.platform.startswith("linux") or not users.is_root(), reason="Linux's mqueue, as root")
def test_a_run_makes_no_message_queue_that_outlives_it(tmp_path):
    """`mqueue`: top-level code (jailed: ctypes is in memory) opens three POSIX message queues, mode 666. Like System
    V objects they outlive every process of the run. The child's RLIMIT_MSGQUEUE is 0: each mq_open fails (EMFILE),
    none is left, and the row is its twin's (a top-level error: 0/17)."""
    (tmp_path / "a_mallory").mkdir()
    (tmp_path / "a_mallory" / "tumbling_crates.py").write_text(with_attack(MQUEUE), encoding="utf-8")
    environment = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", str(tmp_path / "a_mallory" / "tumbling_crates.py"),
                           "--json", "--quiet", "--timeout", "10"], cwd=ROOT, env=environment, capture_output=True,
                          text=True, timeout=600)
    row = json.loads(proc.stdout)["labs"][0]
    message = next(c["message"] for c in row["criteria"] if c["id"] == "loads")
    made = message.split("MQUEUE [", 1)[1].split("]", 1)[0]
    assert made and all(int(value) < 0 for value in made.split(", ")), message   # every mq_open refused
    left = message_queues_of_runs()
    assert not left, f"message queues of a run's uid outlived the batch: {left}"
    assert row["score"] == 0, row


LEAVE = '''
import os as _os
_made = []
for _d in ("/dev/shm", "/tmp", "/var/tmp"):
    try:
        with open(_os.path.join(_d, "l11-left-behind"), "wb") as _h:
            _h.write(b"x" * (8 << 20))
        _os.mkdir(_os.path.join(_d, "l11-left-folder"))
        _made.append(_d)
    except OSError as _e:
        _made.append(type(_e).__name__)
raise RuntimeError(f"LEFT {_made}")
'''


@pytest.mark.parametrize("mode", ["no_jail", "portable_no_jail"])
def test_unjailed_a_run_leaves_nothing_where_everyone_may_write(tmp_path, mode, private_project):
    """`leave`: unjailed, top-level code writes an 8 MB file and a folder into /dev/shm (memory), /tmp and
    /var/tmp. They outlived the batch, owned by a run uid that a later run gets again. Now what the run's uid
    owns at the top of those folders is removed when the run ends; the row is its twin's (a top-level error:
    0/17)."""
    (tmp_path / "a_mallory").mkdir()
    (tmp_path / "a_mallory" / "tumbling_crates.py").write_text(with_attack(LEAVE), encoding="utf-8")
    environment = dict(os.environ, PYTHONPATH=private_project, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
                       **MODES[mode])
    proc = subprocess.run([sys.executable, "-m", "checker", str(tmp_path / "a_mallory" / "tumbling_crates.py"),
                           "--json", "--quiet", "--timeout", "10"], cwd=private_project, env=environment,
                          capture_output=True, text=True, timeout=600)
    row = json.loads(proc.stdout)["labs"][0]
    message = next(c["message"] for c in row["criteria"] if c["id"] == "loads")
    left = [os.path.join(d, n) for d in ("/dev/shm", "/tmp", "/var/tmp") for n in ("l11-left-behind", "l11-left-folder")
            if os.path.lexists(os.path.join(d, n))]
    for path in left:   # not left for the next test either
        shutil.rmtree(path) if os.path.isdir(path) else os.unlink(path)
    assert "LEFT ['/dev/shm', '/tmp', '/var/tmp']" in message, message   # the attack wrote all three
    assert not left, f"left behind after the batch: {left}"
    assert row["score"] == 0, row
