"""Which user runs the student's code, and the one-line account of a user that cannot run it.

A grader running as root runs the child processes as an unprivileged user without being told:
DEFAULT_CHILD_USER ("nobody"), another user with `--child-user NAME`, or root itself only with an explicit
`--child-user root`. A grader that is not root (or a system without users to switch to, such as Windows)
runs the child as itself, as before.

The forked children (checker/zygote.py) need no file after they switch user: the zygote, still root,
imported everything a lab and its probes use. What a child can still need to open is a module it imports
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
FIX = "install Python where that user can read it, choose another --child-user, or --child-user root to opt out"


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
                          "for a grader running as root): create it, choose a user with --child-user NAME, or "
                          "--child-user root to run it as root")
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


def drop_user(user):
    """Run as `user` from now on (groups first, then group, then user); the caller must be root."""
    entry = _entry(user)
    os.setgroups([])
    os.setgid(entry.pw_gid)
    os.setuid(entry.pw_uid)


@functools.lru_cache(maxsize=None)
def python_problem(user, project):
    """None if `user` can start this Python and import the child (the subprocess path); else the one line.

    Starts `python -c "import checker.child"` once as that user (cached per user).
    """
    env = dict(os.environ, PYTHONPATH=project, PYTHONDONTWRITEBYTECODE="1")
    try:
        probe = subprocess.run([sys.executable, "-c", "import checker.child"], cwd="/", env=env,
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


def unreadable_import(error, user, path):
    """The one line when `error` (a child's account of an exception) is an import the child's user could not
    read although the module is there, on the child's own `path`; else None.

    The grader (root) looks the module up itself, on the child's path only (never the submission's folder),
    so a student's import of a module that does not exist stays the student's error.
    """
    message = (error or {}).get("message") or ""
    if not user or not message.startswith(("ModuleNotFoundError: No module named ", "PermissionError: ")):
        return None
    if message.startswith("PermissionError: "):
        return None if "Errno 13" not in message else _unreadable_file(message, user)
    name = message.split("No module named ", 1)[1].strip().strip("'\"")
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
    where = blocked(origin, user) if origin else None
    if not where:
        return None
    return f"the checker cannot import {name!r} as user {user!r}: {where} is not readable by it; {FIX}"


def _unreadable_file(message, user):
    """The one line for a PermissionError on a file of Python's own installation (not the student's)."""
    if "'" not in message:
        return None
    path = message.rsplit("'", 2)[-2]
    prefixes = {os.path.realpath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix)}
    if not any(os.path.realpath(path).startswith(p + os.sep) for p in prefixes):
        return None
    where = blocked(path, user)
    return f"the checker cannot read {path} as user {user!r}: {where} is not readable by it; {FIX}" if where else None
