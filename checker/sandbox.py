"""Run one lab file in a child process with limits, and collect what it left behind.

The child (checker/child.py) runs in a fresh temporary directory with SDL's
dummy video and audio drivers, in its own process group, with:
  - a CPU-time limit (`timeout`, s of CPU): at the soft limit the child's faulthandler dumps the
    lab's stack (SIGXCPU), so we can say where it looped, and a second later the kernel kills it.
    Counting CPU time, not wall time, keeps a busy shared machine from failing a correct lab;
  - a wall-clock limit of WALL_FACTOR × timeout + WALL_EXTRA s for a lab that sleeps or blocks: the
    whole group is killed when it runs out, its stack dumped half a second earlier;
  - RLIMIT_AS (`memory_mb`): a memory hog gets MemoryError or dies;
  - RLIMIT_FSIZE: no file the lab writes can grow past 64 MB;
  - an output cap (`max_output` bytes over stdout + stderr): the child raises at the print() that
    crosses it (so the report names the line); past FLOOD_SLACK more the parent kills the group.

Where os.fork and Unix sockets are available the child is forked from a zygote (checker/zygote.py),
a process started once per grading run that has already imported pygame, lesson11 and the probes,
so each run saves starting Python and those imports. CHECKER_ZYGOTE=0 in the environment (or
USE_ZYGOTE = False here) turns it off; whenever the zygote cannot be started or stops answering,
children are started with subprocess as before. The run and its RunResult are the same either way.
"""
import json
import math
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
from dataclasses import dataclass, field

from . import users

PROJECT_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FILE_LIMIT = 64 * 1024 * 1024   # bytes: largest file a child may write
RECORD_LIMIT = 48 * 1024 * 1024  # bytes: largest record the parent will read
RESULT_LIMIT = 32 * 1024 * 1024  # bytes: largest result (a probe's tapes) the parent will read
WALL_FACTOR, WALL_EXTRA = 3.0, 5.0   # the wall-clock limit: WALL_FACTOR × timeout + WALL_EXTRA s
FLOOD_SLACK = 64 * 1024          # bytes past max_output before the parent kills a run (the child stops first)
USE_ZYGOTE = True                # fork children from a warm zygote where possible (and CHECKER_ZYGOTE != "0")
ZYGOTE_START_SECONDS = 60.0      # s the zygote may take to import its modules before we do without it
ZYGOTE_REPLY_SECONDS = 10.0      # s the zygote may take to fork a child before we do without it


@dataclass
class Limits:
    """Per-run limits: CPU seconds, address-space MB, output bytes (stdout + stderr), and the user it runs as.

    user: None runs the child as the grader's own user; a user name (the grader must be root) runs
    only the child as that user, so files the grader keeps to itself (the solutions) stay unreadable.
    The command line picks one for a root grader unless told otherwise (checker/users.py: nobody).
    """
    timeout: float = 20.0
    memory_mb: int = 768
    max_output: int = 256 * 1024
    user: str | None = None


@dataclass
class RunResult:
    """What one child run produced."""
    status: str                     # "done", "error" (the lab raised), "timeout", "flood", "crash"
    result: dict = field(default_factory=dict)   # the child's result JSON
    record: dict | None = None      # the runtime's record, if the run wrote one
    stdout: str = ""
    stderr: str = ""
    returncode: int | None = None
    seconds: float = 0.0
    timeout_trace: str = ""         # faulthandler's stack dump when the run timed out


_CHILD_ENV = {
    "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy", "PYGAME_HIDE_SUPPORT_PROMPT": "1",
    "PYTHONDONTWRITEBYTECODE": "1", "PYTHONUNBUFFERED": "1", "PYTHONIOENCODING": "utf-8",
    "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
}


def wall_limit(limits):
    """Wall-clock seconds a run may take before it is killed (its CPU time is limited to `timeout`)."""
    return WALL_FACTOR * limits.timeout + WALL_EXTRA


def _limit_child(limits):
    def apply():
        import resource
        os.setsid()
        memory = limits.memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        cpu = max(1, math.ceil(limits.timeout))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
        resource.setrlimit(resource.RLIMIT_FSIZE, (FILE_LIMIT, FILE_LIMIT))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        if limits.user:   # last: drop root for the student's user (groups first, then group, then user)
            import pwd
            entry = pwd.getpwnam(limits.user)
            os.setgroups([])
            os.setgid(entry.pw_gid)
            os.setuid(entry.pw_uid)
    return apply


def _start(lab_path, task, settings_path, result_fd, work, env, limits):
    """Start the child: forked by the zygote if it is on and answers, else with subprocess.

    result_fd: the write end of the pipe the child writes its result to (the parent reads the other end).
    """
    if zygote_enabled():
        client = _zygote_client()
        if client is not None:
            proc = client.spawn(["checker.child", lab_path, task, settings_path, "fd:3"], work, env, limits, result_fd)
            if proc is not None:
                return proc
    command = [sys.executable, "-X", "faulthandler", "-m", "checker.child", lab_path, task, settings_path,
               f"fd:{result_fd}"]
    return _Subprocess(subprocess.Popen(command, cwd=work, env=env, stdin=subprocess.DEVNULL,
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, pass_fds=(result_fd,),
                                        preexec_fn=_limit_child(limits)))


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
            raise subprocess.TimeoutExpired("checker.child", timeout) from None
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
    """True if children should be forked from the zygote: USE_ZYGOTE, CHECKER_ZYGOTE != "0", POSIX with fork."""
    return (USE_ZYGOTE and os.environ.get("CHECKER_ZYGOTE", "1") != "0" and hasattr(os, "fork")
            and hasattr(socket, "send_fds") and hasattr(socket, "AF_UNIX") and hasattr(socket, "SOCK_SEQPACKET"))


class ZygoteClient:
    """The grader's end of one zygote process (checker/zygote.py); shared by threads.

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
                [sys.executable, "-m", "checker.zygote", str(theirs.fileno())], cwd=PROJECT_ROOT, env=env,
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

    def spawn(self, argv, cwd, env, limits, result_fd):
        """Have the zygote fork a child running `python -m argv...` (result_fd becomes its fd 3); a _Forked or None."""
        if self.broken:
            return None
        out_read, out_write = os.pipe()
        err_read, err_write = os.pipe()
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        request = {"argv": argv, "cwd": cwd, "env": env,
                   "limits": {"timeout": limits.timeout, "memory_mb": limits.memory_mb, "user": limits.user,
                              "max_output": limits.max_output}}
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


def _start_locked():
    global _zygote, _zygote_owner
    if _zygote_owner != os.getpid():
        _zygote_owner = os.getpid()
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
    """The zygote of this process, started on first use and ready; None if it could not be started or broke."""
    with _zygote_lock:
        _start_locked()
        if _zygote and not _zygote.broken and _zygote.wait_ready():
            return _zygote
        return None


def stop_zygote():
    """Stop this process's zygote if it started one (also done at exit); the next run starts a new one."""
    global _zygote, _zygote_owner
    with _zygote_lock:
        if _zygote and _zygote_owner == os.getpid():  # broken or not
            _zygote.close()
        _zygote, _zygote_owner = None, None


atexit.register(stop_zygote)


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _read_work_file(path, limit):
    """At most `limit` bytes of a file the child left in its work folder, or None.

    The child's user owns that folder, so the name may have become a link (to /dev/zero, to a file of
    the grader's) or a FIFO (an open() that never returns): only a regular file is read, links not followed.
    """
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    with os.fdopen(fd, "rb") as handle:
        info = os.fstat(handle.fileno())
        if not stat.S_ISREG(info.st_mode) or info.st_size > limit:
            return None
        return handle.read(limit + 1)


def _read_json(path, limit):
    data = _read_work_file(path, limit)
    try:
        return None if data is None or len(data) > limit else json.loads(data.decode("utf-8"))
    except (ValueError, RecursionError):
        return None


def _last_result(data):
    """The last complete JSON line the child wrote on its result pipe (it writes one per phase), or {}."""
    for line in reversed(data.split(b"\n")[:-1]):
        try:
            value = json.loads(line)
        except ValueError:
            continue
        return value if isinstance(value, dict) else {}
    return {}


def _copy_lab(lab_path, work):
    """Copy the submitted file into the child's work folder under its own name (child.copy_name); never the original."""
    from .child import copy_name
    shutil.copyfile(lab_path, os.path.join(work, copy_name(lab_path)))


def _check_user(result, limits, forked):
    """Raise users.ChildUserError when the run failed only because its user could not read Python or a module.

    A child started with subprocess that never reached its first result line failed before any lab code
    ran (a forked one needs no file of Python's); one whose lab (or a probe's call of it) raised
    ModuleNotFoundError for a module on the child's path that its user cannot read is not the student's
    error either.
    """
    if not limits.user:
        return
    if not result and not forked:
        problem = users.python_problem(limits.user, PROJECT_ROOT)
        if problem:
            raise users.ChildUserError(problem)
    tapes = ((result.get("probe") or {}).get("tapes") or {}) if isinstance(result.get("probe"), dict) else {}
    errors = [result.get("error")] + [t.get("error") for t in tapes.values() if isinstance(t, dict)]
    path = [PROJECT_ROOT] + [p for p in sys.path if p and os.path.abspath(p) != os.getcwd()]
    for error in errors:
        problem = users.unreadable_import(error if isinstance(error, dict) else None, limits.user, path)
        if problem:
            raise users.ChildUserError(problem)


def run_child(lab_path, task, settings, limits):
    """Run `python -m checker.child` on lab_path; returns a RunResult. Never raises for lab behaviour."""
    lab_path = os.path.abspath(lab_path)
    with tempfile.TemporaryDirectory(prefix="checker-") as work:
        settings = dict(settings, max_output=limits.max_output)  # the child stops a flood at its print()
        if task == "scenario":
            settings["record"] = os.path.join(work, "record.json")
        settings_path = os.path.join(work, "settings.json")
        with open(settings_path, "w", encoding="utf-8") as handle:
            json.dump(settings, handle)
        env = {key: value for key, value in os.environ.items() if not key.startswith("LESSON11_")}
        env.update(_CHILD_ENV)
        _copy_lab(lab_path, work)   # the child runs a copy, alone in its folder: no file beside the submission
        if limits.user:   # the child's own user owns its work folder (its record, its traceback) and nothing else
            import pwd
            entry = pwd.getpwnam(limits.user)
            os.chown(work, entry.pw_uid, entry.pw_gid)
            env["HOME"] = work
            closed = users.blocked(work, limits.user)   # e.g. TMPDIR in a folder only root may enter
            if closed:
                raise users.ChildUserError(f"the checker's work folders in {os.path.dirname(work)} are not "
                                           f"reachable by user {limits.user!r}: {closed} is closed to it; set "
                                           "TMPDIR to a folder it can enter, or choose another --child-user")
        env.update({
            "PYTHONPATH": PROJECT_ROOT,   # only the project: the submission's own folder is not on the child's path
            "CHECKER_FAULT_SECONDS": str(max(wall_limit(limits) - 0.6, 0.2)),
        })
        start = time.monotonic()
        result_read, result_write = os.pipe()   # the child's result comes over a pipe we opened, not a file
        try:
            proc = _start(lab_path, task, settings_path, result_write, work, env, limits)
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
        open_streams = 3
        deadline = start + wall_limit(limits)
        while open_streams:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                status = "timeout"
                break
            for key, _ in selector.select(timeout=min(remaining, 0.5)):
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
        seconds = time.monotonic() - start
        result = _last_result(b"".join(result_chunks)) if result_size <= RESULT_LIMIT else {}
        record = _read_json(settings["record"], RECORD_LIMIT) if task == "scenario" else None
        trace = ""
        data = _read_work_file(os.path.join(work, "timeout_traceback.txt"), 1 << 20)
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
        _check_user(result, limits, isinstance(proc, _Forked))   # an unreadable import is the checker's problem
        return RunResult(status=status, result=result, record=record,
                         stdout=b"".join(chunks["stdout"]).decode("utf-8", "replace"),
                         stderr=b"".join(chunks["stderr"]).decode("utf-8", "replace"),
                         returncode=proc.returncode, seconds=seconds, timeout_trace=trace)
