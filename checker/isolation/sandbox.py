"""Run one lab file in a child process with limits, and collect what it left behind.

The child (checker/isolation/child.py) runs in a fresh temporary directory with SDL's
dummy video and audio drivers, in its own process group, with:
  - a CPU-time limit (`timeout`, s of CPU): at the soft limit the child's faulthandler dumps the
    lab's stack (SIGXCPU), so we can say where it looped, and a second later the kernel kills it.
    Counting CPU time, not wall time, keeps a busy shared machine from failing a correct lab;
  - a wall-clock limit of WALL_FACTOR × timeout + WALL_EXTRA s for a lab that sleeps or blocks: the
    whole group is killed when it runs out, its stack dumped half a second earlier;
  - RLIMIT_AS (`memory_mb`): a memory hog gets MemoryError or dies;
  - RLIMIT_FSIZE: no file the lab writes can grow past 64 MB;
  - a disk quota (`disk_mb`) on its out/ folder: a tmpfs of that size where root may mount, else watched
    by the parent, which stops the run past it (checker/isolation/disk.py);
  - an output cap (`max_output` bytes over stdout + stderr): the child raises at the print() that
    crosses it (so the report names the line); past FLOOD_SLACK more the parent kills the group.

Where os.fork and Unix sockets are available the child is forked from a zygote (checker/isolation/zygote.py),
a process started once per grading run that has already imported pygame, lesson11 and the probes,
so each run saves starting Python and those imports. CHECKER_ZYGOTE=0 in the environment (or
USE_ZYGOTE = False here) turns it off; whenever the zygote cannot be started or stops answering,
children are started with subprocess as before. The run and its RunResult are the same either way.
A limit the system refuses (macOS refuses RLIMIT_AS) is skipped and noted in RunResult.notes.

As root, each run has a uid of its own (users.take_uid), is chrooted in its work folder where root may, and
everything of that uid is killed when it ends (checker/README.md, "Each run alone").

The portable path (portable(): Windows, no fork or process groups, or CHECKER_PORTABLE=1) starts
the child with plain subprocess and no preexec_fn or pass_fds: the child's stdout is its result
channel (it moves the lab's stdout to a file first), threads read the pipes, the parent kills
the whole tree at the wall-clock limit or on a flood (a Job Object on Windows, else the process
group), and the child applies its own limits: rlimits where `resource` exists and the system
accepts them, CPU time by a watchdog thread, on Windows memory by the parent's Job Object.
"""
import json
import os
import atexit
import selectors
import shutil
import signal
import socket
import stat
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import asdict, dataclass, field

from checker.isolation import disk, users
from checker.project import PROJECT_ROOT
from checker.isolation.confine import OUT, STDOUT_FILE, Limits, copy_name, limit_child

RECORD_LIMIT = 48 * 1024 * 1024  # bytes: largest record the parent will read
RESULT_LIMIT = 32 * 1024 * 1024  # bytes: largest result (a probe's tapes) the parent will read
WALL_FACTOR, WALL_EXTRA = 3.0, 5.0   # the wall-clock limit: WALL_FACTOR × timeout + WALL_EXTRA s
FLOOD_SLACK = 64 * 1024          # bytes past max_output before the parent kills a run (the child stops first)
USE_ZYGOTE = True                # fork children from a warm zygote where possible (and CHECKER_ZYGOTE != "0")
ZYGOTE_START_SECONDS = 60.0      # s the zygote may take to import its modules before we do without it
ZYGOTE_REPLY_SECONDS = 10.0      # s the zygote may take to fork a child before we do without it


@dataclass
class RunResult:
    """What one child run produced."""
    status: str                     # "done", "error" (the lab raised), "timeout", "flood", "disk", "crash"
    result: dict = field(default_factory=dict)   # the child's result JSON
    record: dict | None = None      # the runtime's record, if the run wrote one
    stdout: str = ""
    stderr: str = ""
    returncode: int | None = None
    seconds: float = 0.0
    timeout_trace: str = ""         # faulthandler's stack dump when the run timed out
    notes: list = field(default_factory=list)   # limits the system refused (skipped), for the run's record


_CHILD_ENV = {
    "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy", "PYGAME_HIDE_SUPPORT_PROMPT": "1",
    "PYTHONDONTWRITEBYTECODE": "1", "PYTHONUNBUFFERED": "1", "PYTHONIOENCODING": "utf-8",
    "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
}


def wall_limit(limits):
    """Wall-clock seconds a run may take before it is killed (its CPU time is limited to `timeout`)."""
    return WALL_FACTOR * limits.timeout + WALL_EXTRA


def portable():
    """True when children are started the portable way (checker/README.md, "Windows and macOS").

    That is on Windows, wherever fork, setsid or process groups are missing, and whenever
    CHECKER_PORTABLE=1 is in the environment (then Linux takes the Windows path, so the tests run it).
    """
    return (os.environ.get("CHECKER_PORTABLE") == "1" or sys.platform == "win32"
            or not all(hasattr(os, name) for name in ("fork", "setsid", "killpg")))


def _start(lab_path, task, settings_path, result_fd, work, env, limits, preload=()):
    """Start the child: forked by the zygote if it is on and answers, else with subprocess.

    result_fd: the write end of the pipe the child writes its result to (the parent reads the other end).
    preload: modules the forked child imports before it leaves root (the lab's probes), so it needs no file of
    the project's afterwards (issue 44: a project folder the child's user cannot enter).
    """
    if zygote_enabled():
        for _ in range(1 + ZYGOTE_RESTARTS):   # a zygote that fails to fork is replaced (_zygote_client) and asked again
            client = _zygote_client()
            if client is None:
                break
            inside = "/" + os.path.relpath(work, limits.jail) if limits.jail else work
            proc = client.spawn(["checker.isolation.child", lab_path, task, settings_path, "fd:3"], inside, env, limits,
                                result_fd, preload)
            if proc is not None:
                return proc
    if limits.jail:   # a subprocess starts Python itself: no jail; then the answers must be out of the user's reach
        problem = users.answers_problem(limits.user, PROJECT_ROOT)
        if problem:
            raise users.ChildUserError(problem)
        limits = Limits(**dict(asdict(limits), jail=None))
    command = [sys.executable, "-X", "faulthandler", "-m", "checker.isolation.child", lab_path, task, settings_path,
               f"fd:{result_fd}"]
    return _Subprocess(subprocess.Popen(command, cwd=work, env=env, stdin=subprocess.DEVNULL,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, pass_fds=(result_fd,),
                                        preexec_fn=limit_child(limits, result_fd)))


class _Subprocess:
    """A child started with subprocess: its pid, pipe fds, wait() and returncode."""

    def __init__(self, popen):
        self.popen = popen
        self.pid = popen.pid
        self.stdout_fd, self.stderr_fd = popen.stdout.fileno(), popen.stderr.fileno()

    @property
    def returncode(self):
        return self.popen.returncode

    def wait(self, timeout=None):
        return self.popen.wait(timeout=timeout)

    def close(self):
        self.popen.stdout.close()
        self.popen.stderr.close()


class _Forked:
    """A child forked by the zygote: like _Subprocess; its exit status comes over `reply` from the zygote."""

    def __init__(self, pid, stdout_fd, stderr_fd, reply):
        self.pid, self.stdout_fd, self.stderr_fd, self.reply = pid, stdout_fd, stderr_fd, reply
        self.returncode = None
        self._waited = False

    def wait(self, timeout=None):
        """The child's returncode (None if the zygote died first); raises subprocess.TimeoutExpired."""
        if self._waited:
            return self.returncode
        self.reply.settimeout(timeout)
        try:
            data = self.reply.recv(4096)
        except socket.timeout:
            raise subprocess.TimeoutExpired("checker.isolation.child", timeout) from None
        except OSError:
            data = b""
        self._waited = True
        try:
            self.returncode = json.loads(data)["returncode"] if data else None
        except (ValueError, KeyError, TypeError):
            self.returncode = None
        if not data:
            _kill_group(self)  # the zygote died under it: make sure nothing of the run is left
        return self.returncode

    def close(self):
        for fd in (self.stdout_fd, self.stderr_fd):
            os.close(fd)
        self.reply.close()


def zygote_enabled():
    """True if children should be forked from the zygote: USE_ZYGOTE, CHECKER_ZYGOTE != "0", not portable(),
    and Unix sockets with SOCK_SEQPACKET (macOS has none: its children are started with subprocess)."""
    return (USE_ZYGOTE and os.environ.get("CHECKER_ZYGOTE", "1") != "0" and not portable()
            and hasattr(socket, "send_fds") and hasattr(socket, "AF_UNIX") and hasattr(socket, "SOCK_SEQPACKET"))


class ZygoteClient:
    """The grader's end of one zygote process (checker/isolation/zygote.py); shared by threads.

    Creating one starts the zygote; wait_ready() waits for it to finish its imports.
    """

    def __init__(self):
        self.lock = threading.Lock()
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        env = {key: value for key, value in os.environ.items() if not key.startswith("LESSON11_")}
        env.update(_CHILD_ENV, PYTHONPATH=PROJECT_ROOT)
        env.pop("CHECKER_FAULT_SECONDS", None)
        try:
            self.process = subprocess.Popen(
                [sys.executable, "-m", "checker.isolation.zygote", str(theirs.fileno())], cwd=PROJECT_ROOT, env=env,
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                pass_fds=(theirs.fileno(),), start_new_session=True)
        finally:
            theirs.close()
        self.control = ours
        self.broken = self.closed = False
        self.ready = None                 # None until the zygote has answered (or failed to)

    def wait_ready(self):
        """Wait (the first time only) for the zygote's {"ready": true}; a zygote that does not send it in
        ZYGOTE_START_SECONDS is closed (broken). Returns True if it is ready."""
        if self.ready is None:
            self.control.settimeout(ZYGOTE_START_SECONDS)
            try:
                ready = json.loads(self.control.recv(4096) or b"{}").get("ready")
            except (OSError, ValueError):
                ready = False
            self.control.settimeout(None)
            self.ready = bool(ready)
            if not self.ready:
                self.close()
        return self.ready

    def spawn(self, argv, cwd, env, limits, result_fd, preload=()):
        """Have the zygote fork a child running `python -m argv...` (result_fd becomes its fd 3); a _Forked or None.

        cwd: the child's folder as it sees it (inside its jail, when it has one)."""
        if self.broken:
            return None
        out_read, out_write = os.pipe()
        err_read, err_write = os.pipe()
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        request = {"argv": argv, "cwd": cwd, "env": env, "preload": list(preload), "limits": asdict(limits)}
        try:
            with self.lock:
                socket.send_fds(self.control, [json.dumps(request).encode()],
                                [out_write, err_write, theirs.fileno(), result_fd])
        except OSError:
            data = None
        else:
            data = b""
        finally:
            os.close(out_write)
            os.close(err_write)
            theirs.close()
        if data is not None:
            ours.settimeout(ZYGOTE_REPLY_SECONDS)
            try:
                data = ours.recv(4096)
            except OSError:
                data = b""
        try:
            pid = json.loads(data)["pid"] if data else None
        except (ValueError, KeyError, TypeError):
            pid = None
        if not isinstance(pid, int):
            for fd in (out_read, err_read):
                os.close(fd)
            ours.close()
            self.broken = True  # a zygote that fails once is not asked again (runs it started go on; stop_zygote ends it)
            return None
        return _Forked(pid, out_read, err_read, ours)

    def close(self):
        """Stop the zygote (closing our end ends it, and it kills the runs it still has) and reap it."""
        self.broken = True
        if self.closed:
            return
        self.closed = True
        try:
            self.control.close()
        except OSError:
            pass
        try:
            self.process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


_zygote = None          # this process's ZygoteClient, or False once it could not be started
_zygote_owner = None    # the pid that started it (a forked grader starts its own)
_zygote_lock = threading.Lock()
_retired = []           # zygotes that broke and were replaced: their runs go on, they are stopped at exit
ZYGOTE_RESTARTS = 2     # how many times a broken zygote is replaced before children start with subprocess


def _start_locked():
    global _zygote, _zygote_owner
    if _zygote_owner != os.getpid():
        _zygote_owner = os.getpid()
        _retired.clear()   # a forked grader's: its parent's zygotes are not its own
        try:
            _zygote = ZygoteClient()
        except OSError:
            _zygote = False


def start_zygote():
    """Start this process's zygote now without waiting for it (if zygote_enabled()).

    `python -m checker` calls this before it imports the labs, so the zygote's
    imports (about 0.3 s) run beside the grader's; otherwise the first child
    run starts it. A zygote that is never used is stopped at exit.
    """
    if zygote_enabled():
        with _zygote_lock:
            _start_locked()


def _zygote_client():
    """The zygote of this process, started on first use and ready; None if it could not be started or broke.

    A zygote that broke (it did not answer in time on a busy machine, say) is replaced by a new one up to
    ZYGOTE_RESTARTS times: the subprocess path it would fall back to cannot run as a child user who may
    not read Python's own files (checker/isolation/users.py)."""
    global _zygote
    with _zygote_lock:
        _start_locked()
        if _zygote and _zygote.broken and len(_retired) < ZYGOTE_RESTARTS:
            _retired.append(_zygote)   # not closed now: closing it would end the runs it still has
            try:
                _zygote = ZygoteClient()
            except OSError:
                _zygote = False
        if _zygote and not _zygote.broken and _zygote.wait_ready():
            return _zygote
        return None


def stop_zygote():
    """Stop this process's zygote if it started one (also done at exit); the next run starts a new one."""
    global _zygote, _zygote_owner
    with _zygote_lock:
        if _zygote_owner == os.getpid():
            for zygote in [_zygote, *_retired]:   # broken or not
                if zygote:
                    zygote.close()
        _zygote, _zygote_owner = None, None
        _retired.clear()


atexit.register(stop_zygote)


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _read_work_file(path, limit, whole=True):
    """At most `limit` bytes of a file the child left in its work folder, or None (whole: None when larger).

    The child's user owns that folder, so the name may have become a link (to /dev/zero, to a file of
    the grader's) or a FIFO (an open() that never returns): only a regular file is read, links not followed.
    """
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    with os.fdopen(fd, "rb") as handle:
        info = os.fstat(handle.fileno())
        if not stat.S_ISREG(info.st_mode) or (whole and info.st_size > limit):
            return None
        return handle.read(limit + 1 if whole else limit)


def _read_json(path, limit):
    data = _read_work_file(path, limit)
    try:
        return None if data is None or len(data) > limit else json.loads(data.decode("utf-8"))
    except (ValueError, RecursionError, MemoryError):
        return None


RESULT_LINE_LIMIT = 8 * 1024 * 1024   # bytes: the largest result line parsed (the solutions' probes: 0.6 MB at most)


def _unreadable(why):
    """A result saying the child's result could not be read: the run's error (the file's code wrote it)."""
    return {"phase": "run", "error": {"kind": "exception", "line": None, "text": None, "traceback": "",
                                      "message": f"a result the checker cannot read ({why}); the checker does not "
                                                 "grade what the child reports then"}}


def _read_channel(data):
    """(the last complete result line the child wrote on its result channel (one per phase) or {},
    the notes of limits the system refused) from the channel's bytes.

    A line that is not JSON is passed over (the child was stopped while writing). A line too big or
    nested too deep to read in bounded memory and time is the run's error: the child never writes one,
    so the file's code did.
    """
    result, notes = None, []
    for line in data.split(b"\n")[:-1]:
        if len(line) > RESULT_LINE_LIMIT:
            return _unreadable(f"{len(line) / 1e6:.0f} MB on one line, more than the "
                               f"{RESULT_LINE_LIMIT // (1024 * 1024)} MB it reads"), notes
        try:
            value = json.loads(line)
        except (RecursionError, MemoryError) as exc:
            return _unreadable("nested deeper than it reads" if isinstance(exc, RecursionError)
                               else "out of memory"), notes
        except ValueError:
            continue
        if isinstance(value, dict) and set(value) == {"limits_skipped"}:
            notes += [str(note) for note in value["limits_skipped"]][:10]
        else:
            result = value
    return (result if isinstance(result, dict) else {}), notes


@dataclass
class _Outcome:
    """What the parent collected from one child, either path: its end and its three streams (bytes)."""
    status: str | None      # "timeout" or "flood" when the parent stopped it, else None
    returncode: int | None
    stdout: bytes
    stderr: bytes
    channel: bytes | None   # the result channel, None when it was larger than RESULT_LIMIT
    notes: list = field(default_factory=list)   # limits the parent could not apply
    as_user: bool = False   # the interpreter itself was started as limits.user (the POSIX subprocess path)


def _copy_lab(lab_path, work):
    """Copy the submitted file into the child's work folder under its own name (child.copy_name); never the original."""
    shutil.copyfile(lab_path, os.path.join(work, copy_name(lab_path)))


def _check_user(result, limits, as_user, probes=None):
    """Raise users.ChildUserError when the run failed only because its user could not read Python or a module.

    A child whose interpreter was started as that user (the POSIX subprocess path) and that never reached
    its first result line failed before any lab code ran (a forked one needs no file of Python's); one whose
    lab (or a probe's call of it) raised ModuleNotFoundError for a module on the child's path that its user
    cannot read is not the student's error either.
    """
    if not limits.user:
        return
    if not result and as_user:
        problem = users.python_problem(limits.user, PROJECT_ROOT)
        if problem:
            raise users.ChildUserError(problem)
    tapes = ((result.get("probe") or {}).get("tapes") or {}) if isinstance(result.get("probe"), dict) else {}
    errors = [result.get("error")] + [t.get("error") for t in tapes.values() if isinstance(t, dict)]
    path = [PROJECT_ROOT] + [p for p in sys.path if p and os.path.abspath(p) != os.getcwd()]
    from checker.isolation.zygote import warm_names
    warm = () if as_user else warm_names(probes)   # forked or portable: these were imported before leaving root
    for error in errors:
        problem = users.unreadable_import(error if isinstance(error, dict) else None, limits.user, path,
                                          jailed=bool(limits.jail), warm=warm)
        if problem:
            raise users.ChildUserError(problem)


def jailed_runs():
    """True when a child user's runs are chrooted in their work folders: root may chroot here, and the child is
    forked by the zygote or is the portable one (a POSIX subprocess starts Python as the user: no jail).
    CHECKER_NO_JAIL=1 turns it off (the tests take the path of a system that refuses chroot)."""
    return (users.jail_works() and os.environ.get("CHECKER_NO_JAIL") != "1"
            and (zygote_enabled() or portable()))


def run_child(lab_path, task, settings, limits):
    """Run `python -m checker.isolation.child` on lab_path; returns a RunResult. Never raises for lab behaviour.

    The work folder is the grader's: the settings and the lab's copy, readable by the child, not writable;
    its OUT sub-folder is the child's (its working folder: the record, the traceback, what the lab writes).
    With a child user the run gets a uid of its own (users.take_uid), its group the user's, and everything
    running as that uid is killed when the run ends; where root may chroot, the child is jailed in the work
    folder before it leaves root, so it opens nothing of the project's, the answers' or another run's.
    """
    lab_path = os.path.abspath(lab_path)
    run_uid = users.take_uid() if limits.user else None
    try:
        work = tempfile.mkdtemp(prefix="checker-")
        try:
            return _run_in(work, lab_path, task, settings, limits, run_uid)
        finally:
            disk.release(os.path.join(work, OUT))   # the run's tmpfs, once its files were read (lazily if busy)
            remove_work(work)
    finally:
        if run_uid is not None:
            run_uid.release()


def remove_work(work):
    """Remove a run's work folder, whatever its child left in it (its processes are gone by now).

    shutil.rmtree recurses once per folder level: a child that made a chain of 3000 folders made it raise
    RecursionError in the grader ("a bug in the checker") and leave the tree in the temporary folder. A tree
    rmtree cannot remove is taken apart without recursion (remove_deep). Errors are ignored, as
    TemporaryDirectory(ignore_cleanup_errors=True) did: on Windows a file a dying process holds cannot go yet."""
    try:
        shutil.rmtree(work, ignore_errors=True)
    except RecursionError:
        pass
    if os.path.lexists(work):
        try:
            remove_deep(work)
        except OSError:
            pass


SHARED_FOLDERS = ("/tmp", "/var/tmp", "/dev/shm", "/run/lock", "/var/lock")   # where every user may write


def remove_left_behind(uid):
    """Remove what a run's uid left where every user may write (SHARED_FOLDERS and the temporary folder), once its
    processes are gone. Unjailed, a run wrote 8 MB files into /dev/shm (memory), /tmp and /var/tmp that outlived the
    batch, for a later run of the same uid to find. Those folders are sticky, so all a run made hangs from an entry
    at their top that the uid owns; nothing else is touched (the uids are reserved: no one else has them)."""
    seen = set()
    for folder in SHARED_FOLDERS + (tempfile.gettempdir(),):
        try:
            real = os.path.realpath(folder)
            info = os.stat(real)
            if real in seen or not stat.S_ISDIR(info.st_mode) or not info.st_mode & stat.S_IWOTH:
                continue
            seen.add(real)
            names = os.listdir(real)
        except OSError:
            continue
        for name in names:
            path = os.path.join(real, name)
            try:
                if os.lstat(path).st_uid != uid:
                    continue
                if stat.S_ISDIR(os.lstat(path).st_mode):
                    remove_work(path)
                else:
                    os.unlink(path)
            except OSError:
                continue


def remove_deep(top):
    """Remove the folder `top` and everything below it without recursion and with two folders open at a time:
    each pass lifts the folders two levels down into `top` (renamed, links never followed) and removes the
    level between, so a chain N folders deep takes N passes of constant depth."""
    flags = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | getattr(os, "O_NOFOLLOW", 0)
    top_fd, lifted = os.open(top, flags), 0
    try:
        while True:
            entries = list(os.scandir(top_fd))
            if not entries:
                break
            for entry in entries:
                if not entry.is_dir(follow_symlinks=False):
                    os.unlink(entry.name, dir_fd=top_fd)
                    continue
                sub = os.open(entry.name, flags, dir_fd=top_fd)
                try:
                    for inner in list(os.scandir(sub)):
                        if not inner.is_dir(follow_symlinks=False):
                            os.unlink(inner.name, dir_fd=sub)
                            continue
                        while True:   # a free name in top for it
                            lifted += 1
                            try:
                                os.rename(inner.name, f".lifted-{lifted}", src_dir_fd=sub, dst_dir_fd=top_fd)
                                break
                            except OSError:
                                if not os.path.lexists(os.path.join(top, f".lifted-{lifted}")):
                                    raise
                finally:
                    os.close(sub)
                os.rmdir(entry.name, dir_fd=top_fd)
    finally:
        os.close(top_fd)
    os.rmdir(top)


def _run_in(work, lab_path, task, settings, limits, run_uid):
    out = os.path.join(work, OUT)
    os.mkdir(out, 0o700)
    settings = dict(settings, max_output=limits.max_output)  # the child stops a flood at its print()
    if task == "scenario":
        settings["record"] = "record.json"   # in the child's working folder, OUT
    with open(os.path.join(work, "settings.json"), "w", encoding="utf-8") as handle:
        json.dump(settings, handle)
    env = {key: value for key, value in os.environ.items() if not key.startswith("LESSON11_")}
    env.update(_CHILD_ENV)
    _copy_lab(lab_path, work)   # the child runs a copy, alone in its folder: no file beside the submission
    env["HOME"] = out
    if limits.user:   # the run's uid owns OUT and nothing else
        import pwd
        entry = pwd.getpwnam(limits.user)
        # the copy is the run's uid's alone (0400): every run shares the user's group, so a copy readable by group or
        # others let another run (unjailed: CHECKER_NO_JAIL, macOS, the zygote off) read a classmate's submission
        # while it was graded. The settings (nothing private; read by the portable child while still root) stay
        # root's, and so does the folder: nothing in it is renamed or added
        copy = copy_name(lab_path)
        for name in os.listdir(work):
            os.chmod(os.path.join(work, name), 0o644 if name not in (OUT, copy) else 0o700 if name == OUT else 0o400)
        os.chown(os.path.join(work, copy), run_uid.uid, entry.pw_gid)
        os.chown(out, run_uid.uid, entry.pw_gid)
        os.chmod(work, 0o755)
        closed = users.blocked(work, limits.user)   # e.g. TMPDIR in a folder only root may enter
        if closed:
            raise users.ChildUserError(f"the checker's work folders in {os.path.dirname(work)} are not "
                                       f"reachable by user {limits.user!r}: {closed} is closed to it; set "
                                       "TMPDIR to a folder it can enter, or choose another --child-user")
        jail = work if jailed_runs() else None
        limits = Limits(**dict(asdict(limits), uid=run_uid.uid, jail=jail))
        if jail:
            env["HOME"] = "/" + OUT
    env.update({
        "PYTHONPATH": PROJECT_ROOT,   # only the project: the submission's own folder is not on the child's path
        "CHECKER_FAULT_SECONDS": str(max(wall_limit(limits) - 0.6, 0.2)),
    })
    start = time.monotonic()
    deadline = start + wall_limit(limits)
    collect = _run_portable if portable() else _run_posix
    settings_path = os.path.join(os.pardir, "settings.json")   # from OUT, inside a jail or not
    quota = disk.Quota(out, limits.disk_mb, portable())   # out/ a tmpfs of disk_mb where root may mount, else watched
    try:
        outcome = collect(lab_path, task, settings_path, out, env, limits, deadline, settings.get("probes"), quota)
    finally:
        if run_uid is not None:
            run_uid.kill()   # nothing of the run is left to write its files while they are read (or after)
            if not limits.jail:
                remove_left_behind(run_uid.uid)
    status = outcome.status
    seconds = time.monotonic() - start
    result, notes = _read_channel(outcome.channel) if outcome.channel is not None else ({}, [])
    notes = outcome.notes + quota.notes() + notes
    record = _read_json(os.path.join(out, settings["record"]), RECORD_LIMIT) if task == "scenario" else None
    trace = ""
    data = _read_work_file(os.path.join(out, "timeout_traceback.txt"), 1 << 20)
    if data:
        trace = data[:20000].decode("utf-8", "replace")
    if trace and not status:
        status = "timeout"  # faulthandler fired and ended the process just before our deadline
    if not status:
        if result.get("phase") == "done":
            status = "done"
        elif "error" in result:
            status = "error"
        else:
            status = "crash"
    _check_user(result, limits, outcome.as_user)   # an unreadable import is the checker's problem, not the student's
    return RunResult(status=status, result=result, record=record,
                     stdout=outcome.stdout.decode("utf-8", "replace"),
                     stderr=outcome.stderr.decode("utf-8", "replace"),
                     returncode=outcome.returncode, seconds=seconds, timeout_trace=trace, notes=notes)


def _run_posix(lab_path, task, settings_path, work, env, limits, deadline, probes=None, quota=None):
    """Start the child (zygote or subprocess) with a result pipe and read its three pipes with a selector;
    stop it past its output cap, its wall-clock limit or its disk quota (quota.over(), looked at between reads)."""
    result_read, result_write = os.pipe()   # the child's result comes over a pipe we opened, not a file
    try:
        proc = _start(lab_path, task, settings_path, result_write, work, env, limits, (probes,) if probes else ())
    except OSError as exc:   # the user cannot even start this Python (the subprocess path)
        os.close(result_read)
        if limits.user:
            raise users.ChildUserError(users.cannot_run_python(limits.user)) from exc
        raise
    finally:
        os.close(result_write)
    chunks = {"stdout": [], "stderr": []}
    result_chunks, result_size = [], 0
    total = 0
    status = None
    selector = selectors.DefaultSelector()
    selector.register(proc.stdout_fd, selectors.EVENT_READ, "stdout")
    selector.register(proc.stderr_fd, selectors.EVENT_READ, "stderr")
    selector.register(result_read, selectors.EVENT_READ, "result")
    if isinstance(proc, _Forked):
        selector.register(proc.reply, selectors.EVENT_READ, "exit")   # the zygote's word that the child ended
    open_streams, ended = 3, False
    while open_streams:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            status = "timeout"
            break
        if not ended and isinstance(proc, _Subprocess) and proc.popen.poll() is not None:
            ended = _ended(proc, limits)
        if quota is not None and quota.over(time.monotonic()):
            status = "disk"
            break
        for key, _ in selector.select(timeout=min(remaining, disk.POLL_SECONDS if quota is not None else 0.5)):
            if key.data == "exit":
                selector.unregister(key.fileobj)
                proc.wait(timeout=0)
                ended = _ended(proc, limits)
                continue
            data = os.read(key.fd, 65536)
            if not data:
                selector.unregister(key.fileobj)
                open_streams -= 1
                continue
            if key.data == "result":
                result_size += len(data)
                if result_size <= RESULT_LIMIT:
                    result_chunks.append(data)
                continue
            room = limits.max_output - total
            chunks[key.data].append(data[:max(room, 0)])
            total += len(data)
            if total > limits.max_output + FLOOD_SLACK:
                status = "flood"
                break
        if status:
            break
    if not status and quota is not None and quota.over():
        status = "disk"   # it ended (or closed its pipes) between two looks
    if status:
        _kill_group(proc)
    try:
        proc.wait(timeout=max(deadline - time.monotonic(), 0) + 2)
    except subprocess.TimeoutExpired:
        status = status or "timeout"
        _kill_group(proc)
        proc.wait()
    _kill_group(proc)  # anything the lab left running in its group
    selector.close()
    os.close(result_read)
    proc.close()
    return _Outcome(status, proc.returncode, b"".join(chunks["stdout"]), b"".join(chunks["stderr"]),
                    b"".join(result_chunks) if result_size <= RESULT_LIMIT else None,
                    as_user=not isinstance(proc, _Forked))


def _ended(proc, limits):
    """The child itself has ended: what it left running (in its group; as root, anything of the run's uid) is
    killed now, so a process holding its pipes open cannot keep the run waiting until the wall-clock limit."""
    _kill_group(proc)
    if limits.uid is not None:
        users.kill_uid(limits.uid)
    return True


# ---------------------------------------------------------------- the portable path (Windows; CHECKER_PORTABLE=1)

class _Drain(threading.Thread):
    """Reads a pipe to its end in a thread (Windows cannot select() on pipes): keeps `keep` bytes, counts all."""

    def __init__(self, stream, keep):
        super().__init__(daemon=True)
        self.stream, self.fd, self.keep = stream, stream.fileno(), keep
        self.chunks, self.kept, self.size = [], 0, 0
        self.start()

    def run(self):
        try:
            while True:
                data = os.read(self.fd, 65536)   # not the buffered stream: its close() would wait on this read
                if not data:
                    return
                self.size += len(data)
                if self.kept < self.keep:
                    self.chunks.append(data[:self.keep - self.kept])
                    self.kept += len(self.chunks[-1])
        except (OSError, ValueError):
            return   # the pipe was closed under us: what was read is kept

    def data(self):
        return b"".join(self.chunks)

    def close(self):
        """Wait up to 2 s for the end of the pipe, then close it; a grandchild the kill missed may hold it open,
        and then it is left to the thread (closing a pipe another thread reads is not safe everywhere)."""
        self.join(timeout=2.0)
        if not self.is_alive():
            self.stream.close()


def _run_portable(lab_path, task, settings_path, work, env, limits, deadline, probes=None, quota=None):
    """Start `python -m checker.isolation.child` with plain subprocess and watch it from here.

    The child's real stdout is its result channel (the child moves the lab's stdout to STDOUT_FILE
    before the lab loads); its stderr is the lab's. Both pipes are read by threads. The parent stops
    the whole process tree at the wall-clock limit, past max_output + FLOOD_SLACK bytes of output or past its
    disk quota (quota.over());
    the child applies its own resource limits and watches its CPU time (checker/isolation/child.py).
    """
    out_path = os.path.join(work, STDOUT_FILE)
    command = [sys.executable, "-X", "faulthandler", "-m", "checker.isolation.child", lab_path, task, settings_path,
               f"stdout:{STDOUT_FILE}"]
    env = dict(env, CHECKER_CHILD_LIMITS=json.dumps(asdict(limits)))
    if sys.platform == "win32":
        group = {"creationflags": subprocess.CREATE_NEW_PROCESS_GROUP}
    else:
        group = {"start_new_session": True}   # POSIX emulation: a process group to kill, set up by subprocess itself
    popen = subprocess.Popen(command, cwd=work, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, **group)
    job, notes = None, []
    if sys.platform == "win32":
        job = _windows_job(popen, limits)
        if job is None:
            notes.append(f"memory limit ({limits.memory_mb} MB): Windows refused a Job Object, not applied")
    channel, errors = _Drain(popen.stdout, RESULT_LIMIT + 1), _Drain(popen.stderr, limits.max_output)
    status = None
    while status is None:
        try:
            popen.wait(timeout=disk.POLL_SECONDS if quota is not None else 0.1)
            break
        except subprocess.TimeoutExpired:
            pass
        if time.monotonic() >= deadline:
            status = "timeout"
        elif _flooded(errors, out_path, limits):
            status = "flood"
        elif quota is not None and quota.over(time.monotonic()):
            status = "disk"
    if status is None and _flooded(errors, out_path, limits):
        status = "flood"   # it ended (the file-size limit, say) between two looks
    if status is None and quota is not None and quota.over():
        status = "disk"
    _kill_tree(popen, job)   # a stopped run, and anything the lab left running
    if limits.uid is not None:
        users.kill_uid(limits.uid)   # as root: what left the process group too, before its pipes are waited for
    try:
        popen.wait(timeout=5)
    except subprocess.TimeoutExpired:
        pass   # not killable from here: its returncode stays None and the run counts as stopped
    channel.close()
    errors.close()
    stderr = errors.data()
    stdout = _read_work_file(out_path, max(limits.max_output - len(stderr), 0), whole=False) or b""
    return _Outcome(status, popen.returncode, stdout, stderr, channel.data() if channel.size <= RESULT_LIMIT else None,
                    notes)


def _flooded(errors, out_path, limits):
    """True once the lab's stderr and stdout file hold more than max_output + FLOOD_SLACK bytes."""
    try:
        size = os.path.getsize(out_path)
    except OSError:
        size = 0
    return errors.size + size > limits.max_output + FLOOD_SLACK


def _kill_tree(popen, job):
    """Kill the child and everything it started: the Job Object (Windows), taskkill /T, or the process group."""
    if job is not None:
        job.close()   # KILL_ON_JOB_CLOSE ends every process in the job
    elif sys.platform == "win32":
        subprocess.run(["taskkill", "/T", "/F", "/PID", str(popen.pid)], stdin=subprocess.DEVNULL,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    elif hasattr(os, "killpg") and hasattr(signal, "SIGKILL"):
        _kill_group(popen)
    if popen.poll() is None and (sys.platform == "win32" or hasattr(signal, "SIGKILL")):
        popen.kill()
    elif popen.poll() is None:
        popen.terminate()   # a POSIX without SIGKILL (the Windows emulation in the tests)


class _WindowsJob:
    """A Windows Job Object holding the child: closing it kills every process in it (KILL_ON_JOB_CLOSE),
    and it caps each process's memory at limits.memory_mb (ProcessMemoryLimit).

    UNTESTED on this project's machines (Linux): written against the documented Win32 structures
    (JOBOBJECT_EXTENDED_LIMIT_INFORMATION). If any call fails the run goes on without it (no memory
    limit; the tree is then killed with taskkill /T /F).
    """

    KILL_ON_JOB_CLOSE, PROCESS_MEMORY, EXTENDED_LIMIT_INFORMATION = 0x2000, 0x100, 9

    def __init__(self, popen, limits):
        import ctypes
        from ctypes import wintypes
        self.kernel32 = kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
        kernel32.CreateJobObjectW.restype = wintypes.HANDLE
        kernel32.CreateJobObjectW.argtypes = (wintypes.LPVOID, wintypes.LPCWSTR)
        kernel32.SetInformationJobObject.argtypes = (wintypes.HANDLE, ctypes.c_int, wintypes.LPVOID, wintypes.DWORD)
        kernel32.AssignProcessToJobObject.argtypes = (wintypes.HANDLE, wintypes.HANDLE)
        kernel32.CloseHandle.argtypes = (wintypes.HANDLE,)

        class Basic(ctypes.Structure):
            _fields_ = [("PerProcessUserTimeLimit", ctypes.c_int64), ("PerJobUserTimeLimit", ctypes.c_int64),
                        ("LimitFlags", wintypes.DWORD), ("MinimumWorkingSetSize", ctypes.c_size_t),
                        ("MaximumWorkingSetSize", ctypes.c_size_t), ("ActiveProcessLimit", wintypes.DWORD),
                        ("Affinity", ctypes.c_size_t), ("PriorityClass", wintypes.DWORD),
                        ("SchedulingClass", wintypes.DWORD)]

        class Extended(ctypes.Structure):
            _fields_ = [("BasicLimitInformation", Basic), ("IoInfo", ctypes.c_uint64 * 6),
                        ("ProcessMemoryLimit", ctypes.c_size_t), ("JobMemoryLimit", ctypes.c_size_t),
                        ("PeakProcessMemoryUsed", ctypes.c_size_t), ("PeakJobMemoryUsed", ctypes.c_size_t)]

        self.handle = kernel32.CreateJobObjectW(None, None)
        if not self.handle:
            raise ctypes.WinError(ctypes.get_last_error())
        info = Extended()
        info.BasicLimitInformation.LimitFlags = self.KILL_ON_JOB_CLOSE | self.PROCESS_MEMORY
        info.ProcessMemoryLimit = limits.memory_mb * 1024 * 1024
        ok = kernel32.SetInformationJobObject(self.handle, self.EXTENDED_LIMIT_INFORMATION, ctypes.byref(info),
                                              ctypes.sizeof(info))
        # the child runs a moment before it joins the job (it is not started suspended): its start-up is not limited
        if not ok or not kernel32.AssignProcessToJobObject(self.handle, int(popen._handle)):
            error = ctypes.WinError(ctypes.get_last_error())
            self.close()
            raise error

    def close(self):
        if self.handle:
            self.kernel32.CloseHandle(self.handle)
            self.handle = None


def _windows_job(popen, limits):
    """A _WindowsJob for the child, or None where the system refuses one (then: taskkill, no memory limit)."""
    try:
        return _WindowsJob(popen, limits)
    except (OSError, AttributeError, ValueError):
        return None
