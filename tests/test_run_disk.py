"""A run's disk quota (checker/isolation/disk.py, issue 39): out/ is a tmpfs of --disk MB where root may mount, else the
parent watches it and stops the run past its quota.

The modes: "mounted" (root on Linux, this machine), "watched" (the mount refused, as in a container without
CAP_SYS_ADMIN: emulated by a mount(2) that fails with EPERM, or CHECKER_NO_MOUNT=1 for the CLI) and "portable"
(CHECKER_PORTABLE=1, the Windows/macOS path: always watched). A grader that is not root takes the watched path
too (mount_wanted() is false); it is not run here (the tests run as root). The attack beside a classmate, through
the CLI in every mode, is tests/test_run_attacks.py::test_a_run_filling_the_disk_changes_no_classmates_row.
"""
import ctypes
import errno
import json
import os
import subprocess
import sys

import labs_found
import pytest

from checker.isolation import disk, users
from checker.isolation.sandbox import Limits, run_child

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SETTINGS = {"probes": "checker.labs.tumbling_crates.probes"}
USER = users.DEFAULT_CHILD_USER if users.is_root() and users.choose(None)[0] else None
CAP_MB = 512   # the writer stops itself here, so a watcher that never stops it cannot fill this machine's disk

# top-level code writing 1 MB at a time into its working folder (out/), saying on stderr how many it wrote (W n)
# and the error that stopped it (E n errno)
WRITER = f'''
import os as _os, time as _time
_block = b"x" * (1 << 20)
_n = 0
for _i in range(100000):
    try:
        with open(f"w{{_i}}", "wb") as _h:
            for _ in range(32):
                _h.write(_block)
                _n += 1
                _os.write(2, b"W %d\\n" % _n)
                if _n >= {CAP_MB}:
                    raise SystemExit
    except OSError as _e:
        _os.write(2, b"E %d %d\\n" % (_n, _e.errno))
        break
_time.sleep(20)
'''

# top-level code describing its working folder: the file system's size and inodes, the folder's owner and mode
LOOK = '''
import os as _os
_v, _s = _os.statvfs("."), _os.stat(".")
raise RuntimeError(f"LOOK {_v.f_blocks * _v.f_frsize} {_v.f_files} {_s.st_uid} {_s.st_mode & 0o7777:o}")
'''


@pytest.fixture
def lab(tmp_path):
    def write(source):
        path = tmp_path / "lab.py"
        path.write_text(source, encoding="utf-8")
        return str(path)
    return write


@pytest.fixture
def refused(monkeypatch):
    """A system that refuses the mount (EPERM, as Docker without CAP_SYS_ADMIN): counts the mounts tried."""
    tried = []

    class Refusing:
        @staticmethod
        def mount(*args):
            tried.append(args[1])
            ctypes.set_errno(errno.EPERM)
            return -1

    monkeypatch.setattr(disk, "_libc", lambda: Refusing)
    monkeypatch.setattr(disk, "_refused", None)
    return tried


def met(run):
    """The errno the writer says it met, None if it says it met none, "unread" when the parent stopped the run
    before it read that stderr (a run stopped over its quota is not drained, as a flood is not)."""
    lines = [line.split() for line in run.stderr.splitlines() if line[:2] in ("W ", "E ")]
    return "unread" if not lines else int(lines[-1][2]) if lines[-1][0] == "E" else None


@pytest.fixture
def left(monkeypatch):
    """[MB each run left in its out/ folder once stopped], measured as the grader releases the folder (before
    its tmpfs is unmounted and before the work folder is removed)."""
    sizes, release = [], disk.release

    def measuring(out):
        sizes.append(disk.usage(out, max_entries=10 ** 6) / 2 ** 20)
        release(out)
    monkeypatch.setattr(disk, "release", measuring)
    return sizes


@pytest.fixture(autouse=True)
def own_temp(monkeypatch, tmp_path_factory):
    """This test's runs make their work folders in a temporary folder of its own (mode 755, as /tmp is for the
    run's user), for this process and the checkers it starts: under pytest-xdist another worker's runs have
    their tmpfs mounted in /tmp meanwhile, and checker_mounts() must not count them."""
    import shutil
    import tempfile
    tmp_path_factory.getbasetemp()   # pytest's own temporary folders stay where they are
    folder = tempfile.mkdtemp(prefix="l11-disk-", dir="/tmp" if os.path.isdir("/tmp") else None)
    os.chmod(folder, 0o755)
    monkeypatch.setattr(tempfile, "tempdir", folder)
    monkeypatch.setenv("TMPDIR", folder)
    yield folder
    monkeypatch.undo()
    shutil.rmtree(folder, ignore_errors=True)


def checker_mounts():
    """The mount points of this test's runs' work folders (…/checker-*/out, in own_temp) this machine has now."""
    import tempfile
    mine = tempfile.gettempdir() + os.sep
    with open("/proc/self/mounts", encoding="utf-8") as handle:
        return [line.split()[1] for line in handle
                if "/checker-" in line.split()[1] and line.split()[1].startswith(mine)]


# ---------------------------------------------------------------- the setting

@pytest.mark.parametrize("value", [0, -5, 1.5, "64", True, None])
def test_the_quota_setting_refuses_a_bad_value_naming_it(value):
    with pytest.raises(ValueError) as caught:
        Limits(disk_mb=value)
    assert str(caught.value) == f"disk_mb must be a whole number of MB >= 1, got {value!r}"
    assert Limits().disk_mb == disk.DEFAULT_MB == 64 and Limits(disk_mb=1).disk_mb == 1


@pytest.mark.parametrize("value, said", [("0", "--disk must be >= 1 MB, got 0"),
                                         ("-3", "--disk must be >= 1 MB, got -3"),
                                         ("lots", "argument --disk: invalid int value: 'lots'")])
def test_the_disk_option_refuses_a_bad_value_in_one_line(value, said):
    proc = subprocess.run([sys.executable, "-m", "checker", os.path.join(ROOT, "solutions", "tumbling_crates.py"),
                           "--disk", value], cwd=ROOT, capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy"))
    assert proc.returncode == 2 and proc.stdout == "", proc.stderr
    assert proc.stderr.splitlines() == [f"checker: error: {said} (python -m checker --help lists the options)"]


def test_the_row_of_a_run_over_its_quota_names_the_quota():
    from types import SimpleNamespace
    from checker.judging.common import describe_run_failure
    run = SimpleNamespace(status="disk", result={}, disk_mb=64, returncode=-9, stderr="", stdout="")
    said = describe_run_failure(run, "lab.py", "The file")
    assert said == "The file wrote more than 64 MB (or 1000 files) into its working folder and was stopped."
    assert "checker" not in said


# ---------------------------------------------------------------- mounted (root on Linux)

mounting = pytest.mark.skipif(not disk.mount_wanted(False), reason="needs root on Linux")


@mounting
def test_mounted_the_run_writes_into_a_tmpfs_of_its_quota_owned_by_its_uid(lab):
    run = run_child(lab(LOOK), "probe", SETTINGS, Limits(timeout=5, user=USER, disk_mb=8))
    size, inodes, uid, mode = run.result["error"]["message"].split("LOOK ")[1].split()
    assert (int(size), int(inodes), mode) == (8 << 20, disk.MAX_ENTRIES + 1, "700"), run.result["error"]
    assert int(uid) in users.RUN_UIDS if USER else int(uid) == 0
    assert checker_mounts() == [], "a run's tmpfs is left mounted"


@mounting
def test_mounted_a_write_past_the_quota_fails_in_the_run_and_stops_it(lab, left):
    run = run_child(lab(WRITER), "probe", SETTINGS, Limits(timeout=5, user=USER, disk_mb=8))
    assert left == [8.0], left   # not one byte more: the write itself failed
    assert met(run) in (errno.ENOSPC, "unread"), run.stderr[-300:]
    assert run.status == "disk" and run.notes == [], run
    assert run.seconds < 10   # stopped once full, not left to sleep to its wall-clock limit
    assert checker_mounts() == []


DAEMON = '''
import os as _os, signal as _signal, time as _time
_pid = _os.fork()
if _pid == 0:
    _os.setsid()   # out of the run's process group: its kill misses this one, which keeps out/ busy
    _time.sleep(60)
    _os.kill(_os.getpid(), _signal.SIGKILL)
raise RuntimeError(f"DAEMON {_pid}")
'''


@mounting
def test_mounted_a_tmpfs_still_busy_is_unmounted_lazily(lab):
    """As root with no child user (--child-user root), nothing kills a process that left the run's process
    group: it keeps its working folder, the tmpfs, busy. The tmpfs is detached all the same."""
    run = run_child(lab(DAEMON), "probe", SETTINGS, Limits(timeout=5))
    pid = int(run.result["error"]["message"].split("DAEMON ")[1])
    try:
        import tempfile
        held = os.stat(f"/proc/{pid}/cwd")   # the daemon lives, its working folder on a file system of its own
        assert held.st_dev != os.stat(tempfile.gettempdir()).st_dev and held.st_mode & 0o777 == 0o700, held
        assert checker_mounts() == [], "a run's tmpfs is left mounted"
    finally:
        os.kill(pid, 9)


# ---------------------------------------------------------------- watched (the mount refused; portable)

@mounting
def test_a_refused_mount_is_tried_once_and_the_runs_are_watched(lab, refused, left):
    """The overshoot of the watcher, what a stopped run left in out/: measured 5-48 MB past an 8 MB quota in 9 runs
    here and through the portable path (a writer on this machine's disk at about 0.2 GB/s from Python, looked at
    every 0.05 s; the writer's own count, 1-63 MB in 14 more); asserted: stopped, and less than 200 MB past the
    quota, where the writer alone would have gone on to its own cap of 512 MB."""
    runs = [run_child(lab(WRITER), "probe", SETTINGS, Limits(timeout=5, user=USER, disk_mb=8)) for _ in range(2)]
    assert len(refused) == 1, refused   # remembered: the second run tried no mount
    for run, mb in zip(runs, left):
        print(f"watched: {mb:.0f} MB left, {mb - 8:.0f} MB past the quota")
        assert run.status == "disk" and met(run) in (None, "unread") and 8 < mb < 8 + 200, (run.status, mb)
        assert any("refused a tmpfs" in note and "EPERM" in note for note in run.notes), run.notes


def test_portable_the_run_is_watched_and_stopped(lab, monkeypatch, left):
    monkeypatch.setenv("CHECKER_PORTABLE", "1")
    run = run_child(lab(WRITER), "probe", SETTINGS, Limits(timeout=5, user=USER, disk_mb=8))
    mb = left[0]
    print(f"portable: {mb:.0f} MB left, {mb - 8:.0f} MB past the quota")
    assert run.status == "disk" and met(run) in (None, "unread") and 8 < mb < 8 + 200, (run.status, mb)
    assert run.notes == [], run.notes   # nothing refused: the portable path never mounts


@pytest.mark.parametrize("entries", [disk.MAX_ENTRIES + 1, 3])
def test_watching_counts_files_and_bounds_its_walk(tmp_path, entries):
    for i in range(entries):
        (tmp_path / f"f{i}").write_bytes(b"x" * 5000)
    used = disk.usage(str(tmp_path))
    assert used is None if entries > disk.MAX_ENTRIES else used == 3 * os.stat(tmp_path / "f0").st_blocks * 512


def test_watching_a_path_too_long_to_measure_counts_as_over(tmp_path):
    """25 folders of 200-character names: a path longer than PATH_MAX, which the walk cannot look into (a run
    could hide files there): the run counts as over its quota."""
    fd = os.open(str(tmp_path), os.O_RDONLY)
    try:
        for _ in range(25):
            os.mkdir("d" * 200, dir_fd=fd)
            fd, old = os.open("d" * 200, os.O_RDONLY, dir_fd=fd), fd
            os.close(old)
    finally:
        os.close(fd)
    assert disk.usage(str(tmp_path)) is None


# ---------------------------------------------------------------- honest files keep their marks

@mounting
def test_every_solution_keeps_full_marks_under_a_4_mb_quota():
    """The solutions leave at most 1.4 MB in out/ (a scene's record.json); graded with --disk 4 (the default
    is 64), every row is full marks."""
    proc = subprocess.run([sys.executable, "-m", "checker", "solutions", "--json", "--quiet", "--disk", "4",
                           "--jobs", "2"], cwd=ROOT, capture_output=True, text=True, timeout=900,
                          env=dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy"))
    rows = json.loads(proc.stdout)["labs"]
    assert len(rows) == len(labs_found.LABS), [r["path"] for r in rows]
    assert all(r["score"] == r["max_score"] and r["status"] == "pass" for r in rows), \
        [(r["path"], r["score"], r["message"]) for r in rows]
    assert proc.returncode == 0 and checker_mounts() == []
