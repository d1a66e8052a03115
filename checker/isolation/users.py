"""Which user runs the student's code, and the one-line account of a user that cannot run it.

A grader running as root runs the child processes as an unprivileged user without being told:
DEFAULT_CHILD_USER ("nobody"), another user with `--child-user NAME`, or root itself only with an explicit
`--child-user root`. A grader that is not root (or a system without users to switch to, such as Windows)
runs the child as itself, as before.

Each run takes a uid of its own from RUN_UIDS (take_uid: locked, so no two runs share one) with the user's group,
and everything running as that uid is killed when the run ends (kill_uid); where root may chroot (jail_works) the
forked child is jailed in its work folder before it switches. The forked children (checker/isolation/zygote.py) need no file
after they switch user: the zygote, still root, imported everything a lab and its probes use. What a child can still need to open is a module it imports
that the zygote did not, or all of Python when the zygote is off; when the child's user cannot read it,
the checker says so in one line (ChildUserError) and does not blame the student.
"""
import functools
import os
import stat
import subprocess
import sys

DEFAULT_CHILD_USER = "nobody"
OPT_OUT = "root"     # --child-user root: the child runs as the grader's own user (root)
PRIVATE = ("solutions", "starters")   # the project's folders a grader keeps from the child's user (the answers)
FIX = "install Python where that user can read it, or choose another --child-user"   # never: run it as root
RUN_UIDS = range(64100, 64900)   # each run's own uid (with --child-user's group): reserved, in no passwd entry
NPROC = 64   # processes (and threads) a run's uid may have at once (RLIMIT_NPROC): a fork bomb stops there


class ChildUserError(Exception):
    """The child's user cannot run Python or read a module the lab imports; the message is one line with the fix."""


def is_root():
    """True when this process can switch users (POSIX, effective uid 0)."""
    return hasattr(os, "geteuid") and os.geteuid() == 0


def choose(name):
    """(the user to run children as, or None for the grader's own user; a one-line problem or None).

    name: --child-user's value, or None when it was not given.
    """
    if not is_root():
        if name is None:
            return None, None
        return None, (f"--child-user {name}: only a grader running as root can run the student's code as another "
                      "user")
    if name == OPT_OUT:
        return None, None
    wanted = name or DEFAULT_CHILD_USER
    try:
        import pwd
        pwd.getpwnam(wanted)
    except (ImportError, KeyError):
        if name is None:
            return None, (f"no user {DEFAULT_CHILD_USER!r} on this machine to run the student's code as (the default "
                          "for a grader running as root): create it, or choose a user with --child-user NAME")
        return None, f"--child-user {name}: no such user on this machine"
    return wanted, None


def _entry(user):
    import pwd
    return pwd.getpwnam(user)


def blocked(path, user):
    """The first folder on the way to `path` (or the file itself) that `user` may not enter or read; None if none.

    Judged from owner, group and mode bits (what the kernel checks for a plain user); no ACLs.
    """
    entry = _entry(user)
    groups = {entry.pw_gid} | {g.gr_gid for g in _groups() if user in g.gr_mem}
    path = os.path.abspath(path)
    parts = path.split(os.sep)
    for end in range(2, len(parts) + 1):
        here = os.sep.join(parts[:end]) or os.sep
        try:
            info = os.stat(here)
        except OSError:
            return None   # gone or unreachable for root too: not a question of the user
        need = stat.S_IXOTH if stat.S_ISDIR(info.st_mode) else stat.S_IROTH
        if info.st_uid == entry.pw_uid:
            need <<= 6
        elif info.st_gid in groups:
            need <<= 3
        if not info.st_mode & need:
            return here
    return None


def _groups():
    try:
        import grp
        return grp.getgrall()
    except ImportError:
        return []


def python_blocked(user, *more):
    """The first folder or file of this Python (its executable, its standard library) or of `more` that `user`
    cannot enter or read, symbolic links followed (a venv's python links into the interpreter's folder); or None."""
    for path in (sys.executable, os.path.dirname(os.__file__)) + more:
        where = blocked(os.path.realpath(path), user)
        if where:
            return where
    return None


def cannot_run_python(user, where=None):
    """The one line for a child user that cannot start this Python (`where`: what it cannot read, if known)."""
    where = where or python_blocked(user)
    because = f": {where} is not readable by it" if where else ""
    return f"the checker cannot run Python as user {user!r}{because}; {FIX}"


def drop_user(user, uid=None):
    """Run as `user` from now on (groups first, then group, then user; `uid`: the run's own uid in place of the
    user's, RUN_UIDS); the caller must be root."""
    entry = _entry(user)
    drop_to(entry.pw_uid if uid is None else uid, entry.pw_gid)


def drop_to(uid, gid):
    """Run as uid and gid from now on, with no other group; the caller must be root."""
    os.setgroups([])
    os.setgid(gid)
    os.setuid(uid)


def enter_jail(folder, inside="/"):
    """chroot into `folder` (the run's work folder, root's, readable by the child) and go to `inside` it: from
    here the process opens nothing outside it (no project, no answers, no other run's folder, no /proc)."""
    os.chroot(folder)
    os.chdir(inside)


# ---------------------------------------------------------------- one uid per run

class RunUid:
    """A uid of RUN_UIDS held by one run (a lock file of root's, flock'ed): no other run, in this grader or in
    another one on the machine, gets it until release(). Whatever runs as it is killed when it is taken (a
    grader that died may have left something) and when the run ends (kill())."""

    def __init__(self, uid, fd):
        self.uid, self.fd = uid, fd

    def kill(self):
        kill_uid(self.uid)

    def release(self):
        """Give the uid back (the run's end killed what ran as it: a uid with no process cannot start one)."""
        if self.fd is not None:
            os.close(self.fd)
            self.fd = None


def _lock_folder():
    """A folder of root's alone for the uid locks (/run where there is one, else the temporary folder)."""
    import tempfile
    for base in ("/run", "/var/lock", tempfile.gettempdir()):
        folder = os.path.join(base, "lesson11-checker-uids")
        try:
            os.mkdir(folder, 0o700)
        except FileExistsError:
            pass
        except OSError:
            continue
        info = os.lstat(folder)
        if stat.S_ISDIR(info.st_mode) and info.st_uid == 0 and not info.st_mode & 0o077:
            return folder
    raise ChildUserError("the checker cannot reserve a uid for a run: no folder of root's alone in /run, /var/lock "
                         "or the temporary folder to lock it in; make /run writable by root")


def take_uid():
    """A RunUid free in every grader on this machine, with nothing left running as it."""
    import fcntl
    import random
    folder = _lock_folder()
    start = random.randrange(len(RUN_UIDS))   # graders started together do not all try the same uids first
    for i in range(len(RUN_UIDS)):
        uid = RUN_UIDS[(start + i) % len(RUN_UIDS)]
        if _has_entry(uid):
            continue
        fd = os.open(os.path.join(folder, str(uid)), os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0), 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            os.close(fd)
            continue
        kill_uid(uid)   # a run of a grader that died may have left something
        return RunUid(uid, fd)
    raise ChildUserError(f"the checker cannot reserve a uid for a run: all {len(RUN_UIDS)} of "
                         f"{RUN_UIDS.start}-{RUN_UIDS.stop - 1} are in use; lower --jobs")


def _has_entry(uid):
    try:
        import pwd
        pwd.getpwuid(uid)
        return True
    except (ImportError, KeyError):
        return False


def kill_uid(uid, rounds=3):
    """SIGKILL every process running as `uid` (a daemon that left its process group and session included).

    A helper forked from here becomes that uid and calls kill(-1, SIGKILL), which reaches every process of the
    uid and never the helper itself. A process with SIGKILL pending cannot fork (the kernel checks it before the
    new process is visible), so one round leaves nothing; `rounds` more are cheap insurance. (kill(-1) reports
    success whenever any other process exists, so its answer cannot say when none is left.)"""
    import signal
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            os.setgroups([])
            os.setuid(uid)   # as root: real, effective and saved uid alike (macOS has no setresuid)
            for _ in range(rounds):
                try:
                    os.kill(-1, signal.SIGKILL)
                except OSError:
                    pass
            code = 0
        finally:
            os._exit(code)
    os.waitpid(pid, 0)
    remove_ipc(uid)


IPC_KINDS = (("shm", "shmid"), ("sem", "semid"), ("msg", "msqid"))   # /proc/sysvipc/<kind>: its id column


def remove_ipc(uid):
    """Remove every System V shared memory segment, semaphore set and message queue `uid` created or owns.

    Unlike its processes they outlive a run (jailed too: they need no file): a run left 4 × 32 MB of resident
    memory, mode 666, after the batch, readable and writable by every later run. The owner can be changed
    (IPC_SET), the creator cannot. Linux as root (/proc/sysvipc); elsewhere nothing to do here."""
    try:
        import ctypes
        libc = ctypes.CDLL(None, use_errno=True)
        removers = {"shm": lambda i: libc.shmctl(i, 0, None), "sem": lambda i: libc.semctl(i, 0, 0),
                    "msg": lambda i: libc.msgctl(i, 0, None)}   # IPC_RMID is 0
    except (ImportError, OSError, AttributeError):
        return
    for kind, column in IPC_KINDS:
        try:
            with open(f"/proc/sysvipc/{kind}", encoding="ascii") as handle:
                header, *rows = handle.read().splitlines() or [""]
        except (OSError, ValueError):
            continue
        names = header.split()
        for row in rows:
            fields = dict(zip(names, row.split()))
            try:
                if uid in (int(fields["uid"]), int(fields["cuid"])):
                    removers[kind](int(fields[column]))
            except (KeyError, ValueError):
                continue


def as_run_user(user, work):
    """Run work() in a process forked from here that has become what a run becomes (`user`'s group, a uid of
    RUN_UIDS, taken for the moment); returns what work() returned (JSON-able), or None if it failed."""
    import json
    entry = _entry(user)   # everything the forked process needs is at hand before the fork (threads: no imports)
    held = take_uid()
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        try:
            os.close(read)
            drop_to(held.uid, entry.pw_gid)
            os.write(write, json.dumps(work()).encode())
        finally:
            os._exit(0)
    os.close(write)
    chunks = []
    while True:
        data = os.read(read, 65536)
        if not data:
            break
        chunks.append(data)
    os.close(read)
    os.waitpid(pid, 0)
    held.release()
    try:
        return json.loads(b"".join(chunks) or b"null")
    except ValueError:
        return None


@functools.lru_cache(maxsize=None)
def jail_works():
    """True where a process of root's may chroot (Linux and macOS as root; a container that keeps CAP_SYS_CHROOT,
    Docker's default): tried once in a forked process."""
    if not is_root() or not hasattr(os, "chroot"):
        return False
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            os.chroot("/")
            code = 0
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status) == 0


def readable_answers(user, project):
    """The first file of the project's solutions/ that `user` (a run's uid, its group) can really open (tried
    as that user, not judged from the mode bits), or None."""
    folder = os.path.join(project, PRIVATE[0])
    try:
        names = sorted(os.listdir(folder))   # listed as root: a folder the user may cross but not list counts too
    except OSError:
        return None

    def attempt():
        for name in names:
            path = os.path.join(folder, name)
            try:
                os.close(os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)))
                return path
            except OSError:
                continue
        return None

    return as_run_user(user, attempt)


def answers_problem(user, project):
    """The one line when the child's user can read the answers where the checker cannot keep them from it, else None."""
    where = readable_answers(user, project)
    if not where:
        return None
    return (f"the student's code would run as user {user!r}, which can read the answers ({where}); make them root's "
            f"alone: chmod -R go-rwx {os.path.join(project, PRIVATE[0])}")


@functools.lru_cache(maxsize=None)
def python_problem(user, project):
    """None if `user` can start this Python and import the child (the subprocess path); else the one line.

    Starts `python -c "import checker.isolation.child"` once as that user (cached per user).
    """
    env = dict(os.environ, PYTHONPATH=project, PYTHONDONTWRITEBYTECODE="1")
    try:
        probe = subprocess.run([sys.executable, "-c", "import checker.isolation.child"], cwd="/", env=env,
                               stdin=subprocess.DEVNULL, capture_output=True, timeout=60,
                               preexec_fn=lambda: drop_user(user))
    except (OSError, subprocess.SubprocessError):
        return cannot_run_python(user)
    if probe.returncode == 0:
        return None
    where = python_blocked(user, project)
    if where:
        return cannot_run_python(user, where)
    said = probe.stderr.decode("utf-8", "replace").strip().splitlines()
    return f"the checker cannot run Python as user {user!r} ({said[-1] if said else 'it exits at once'}); {FIX}"


def unreadable_import(error, user, path, jailed=False, warm=()):
    """The one line when `error` (a child's account of an exception) is an import the child's user could not
    read although the module is there, on the child's own `path`; else None.

    Nothing the child says is believed: the grader (root) looks the module up on the child's path only (never
    the submission's folder), then a process of the child's user and group tries to open it; only when that
    fails is it the checker's problem. A student's import of a module that does not exist, or of one the user
    can read (a forged ModuleNotFoundError), stays the student's error. `jailed`: the child ran chrooted in its
    work folder, where nothing but what the zygote imported is there to import: every import error is the file's.
    `warm`: the modules the child imported before it left root (zygote.warm_names()); importing one again cannot
    fail for want of a file, so an error naming one is the file's own (forged, or its own sys.modules edit).
    """
    message = (error or {}).get("message") or ""
    if jailed or not user or not message.startswith(("ModuleNotFoundError: No module named ", "PermissionError: ")):
        return None
    if message.startswith("PermissionError: "):
        return None if "Errno 13" not in message else _unreadable_file(message, user)
    name = message.split("No module named ", 1)[1].strip().strip("'\"")
    if name in warm:
        return None
    import importlib.machinery
    top = name.split(".")[0]
    if top in PRIVATE:   # kept from the child on purpose: importing it is the file's doing, not our failure
        return None
    try:
        spec = importlib.machinery.PathFinder.find_spec(top, path)
    except (ImportError, ValueError):
        spec = None
    if spec is None:
        return None
    origin = spec.origin or next(iter(spec.submodule_search_locations or []), None)
    if not origin or _user_can_open(user, origin):
        return None
    where = blocked(origin, user) or origin
    return f"the checker cannot import {name!r} as user {user!r}: {where} is not readable by it; {FIX}"


def _user_can_open(user, path):
    """True if a process of the child's user and group can open `path` (a file, or a package's folder)."""
    def attempt():
        try:
            if os.path.isdir(path):
                os.listdir(path)
            else:
                os.close(os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)))
            return True
        except OSError:
            return False
    return bool(as_run_user(user, attempt))


def _unreadable_file(message, user):
    """The one line for a PermissionError on a file of Python's own installation (not the student's)."""
    if "'" not in message:
        return None
    path = message.rsplit("'", 2)[-2]
    prefixes = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix)}
    if not any(os.path.realpath(path).startswith(p + os.sep) for p in prefixes):
        return None
    if _user_can_open(user, path):
        return None   # the user can read it: the error was the file's own (or forged)
    where = blocked(path, user) or path
    return f"the checker cannot read {path} as user {user!r}: {where} is not readable by it; {FIX}"
