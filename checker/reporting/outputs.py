"""Output files: where they may go (checked before anything is graded) and where each submission's goes.

An output is only written when its option asks for it, and never over an
input: a path that is one of the files being graded, a `.py` file, or lies
inside a folder being graded is refused, as is a folder where a file is
expected (and the reverse), a folder that does not exist, or the same path
for two outputs. An existing output file named by the user is replaced
(atomically: see report.write_atomic).
"""
import contextlib
import os


def relative(path, start=None):
    """path relative to start (default: the current folder) when it lies below start, else path as given: a
    path outside start (`/tmp/x.py`, `D:\\class\\x.py` on Windows, where relpath fails across drives) is shown
    as the user typed it, not as ../../tmp/x.py."""
    try:
        shown = os.path.relpath(path, start)
    except ValueError:
        return path
    return path if shown == os.path.pardir or shown.startswith(os.path.pardir + os.path.sep) else shown


def inside(path, folder):
    """Whether path lies in folder (both absolute); never on another drive."""
    try:
        return os.path.commonpath([path, folder]) == folder
    except ValueError:  # different drives
        return False


def check(outputs, paths, entries, graded_folders):
    """One-line problems with the outputs, [] when all can be written.

    outputs: [(option, path, kind)] with kind "file" or "folder"; paths: the
    command line's paths; entries: what will be graded; graded_folders:
    resolved folders being graded.
    """
    problems = []
    inputs = {os.path.realpath(p) for p in paths} | {e.real or os.path.realpath(e.path) for e in entries}
    inputs |= {os.path.abspath(e.path) for e in entries}
    used = {}
    for option, path, kind in outputs:
        where = f"{option} {path}"
        real = os.path.realpath(path)
        if path.lower().rstrip("/\\").endswith(".py"):
            problems.append(f"{where}: refusing to write to a .py file (it may be a submission); choose another name")
        elif real in inputs or os.path.abspath(path) in inputs:
            problems.append(f"{where}: that is one of the paths being graded; choose another place for the output")
        elif any(inside(real, folder) for folder in graded_folders):
            folder = next(f for f in graded_folders if inside(real, f))
            problems.append(f"{where}: inside {relative(folder)}, a folder being graded; "
                            f"write it outside that folder")
        elif kind == "folder" and any(inside(i, real) for i in inputs):
            problems.append(f"{where}: this folder holds files being graded; choose a folder outside them")
        elif real in used:
            problems.append(f"{where}: the same path as {used[real]}; give each output its own path")
        elif kind == "file" and os.path.isdir(path):
            problems.append(f"{where}: is a folder; give a file name")
        elif kind == "file" and os.path.lexists(path) and not os.path.isfile(path):
            problems.append(f"{where}: exists and is not a regular file")
        elif kind == "folder" and os.path.lexists(path) and not os.path.isdir(path):
            problems.append(f"{where}: exists and is not a folder")
        elif kind == "folder" and os.path.isdir(path):
            # an existing folder is written into, not created: its own permission is what counts (a grader
            # hands the unprivileged user a folder of its own inside a root-owned one)
            if not os.access(path, os.W_OK | os.X_OK):
                problems.append(f"{where}: cannot write in this folder")
        else:
            parent = os.path.dirname(os.path.abspath(path))
            if not os.path.isdir(parent):
                problems.append(f"{where}: the folder {os.path.dirname(path) or '.'} does not exist")
            elif not os.access(parent, os.W_OK):
                problems.append(f"{where}: cannot write in the folder {os.path.dirname(path) or '.'}")
        used.setdefault(real, option)
    return problems


def submission_names(paths):
    """{path: relative folder name} for one results.json per submission: each path relative to their common
    folder, without ".py" (with it where two would otherwise share a name)."""
    absolute = {p: os.path.abspath(p) for p in paths}
    if not absolute:
        return {}
    try:
        base = os.path.commonpath([os.path.dirname(a) for a in absolute.values()])
    except ValueError:  # Windows: submissions on two drives have no common folder; name each by its whole path
        base = None
    full = {p: relative(a, base) if base else os.path.splitdrive(a)[1].lstrip("\\/") for p, a in absolute.items()}
    full = {p: (name if name != "." else os.path.basename(absolute[p])) for p, name in full.items()}
    short = {p: name[:-3] if name.lower().endswith(".py") else name for p, name in full.items()}
    counts = {}
    for name in short.values():
        counts[name] = counts.get(name, 0) + 1
    names, taken = {}, set()
    for p in paths:
        name = short[p] if counts[short[p]] == 1 else full[p]
        candidate, k = name, 2
        while candidate in taken:
            candidate, k = f"{name}-{k}", k + 1
        taken.add(candidate)
        names[p] = candidate
    return names


class NotOurs(OSError):
    """A folder on the way to an output is a link, not a folder, or belongs to another user: not written into."""


def _can_use_dir_fd():
    return (hasattr(os, "O_DIRECTORY") and hasattr(os, "O_NOFOLLOW") and os.open in os.supports_dir_fd
            and os.mkdir in os.supports_dir_fd and os.rename in os.supports_dir_fd)


def _own(info, name):
    """NotOurs unless `info` (an fstat/lstat) is a folder this process's user owns."""
    import stat
    if not stat.S_ISDIR(info.st_mode):
        raise NotOurs(f"{name} is not a folder")
    if hasattr(os, "geteuid") and info.st_uid != os.geteuid():
        raise NotOurs(f"{name} is not the grader's folder (it belongs to another user)")


def write_below(base, relative_path, name, data):
    """Write `data` (bytes) to base/relative_path/name; returns that path.

    The folders below `base` (the output folder the user named) are made if missing and must be folders
    this user owns, none a link (NotOurs otherwise); the file is written to a new temporary file, opened
    exclusively and without following links, and renamed over `name`: a link planted where the file goes is
    replaced, never written through. Where the system has no dir_fd operations (Windows), the same checks
    are made by path.
    """
    parts = [p for p in relative_path.replace("\\", "/").split("/") if p not in ("", ".")]
    if ".." in parts or not name or name in (".", "..") or "/" in name or os.sep in name:
        raise NotOurs(f"{os.path.join(relative_path, name)} is not a name below {base}")
    target = os.path.join(base, *parts, name)
    os.makedirs(base, exist_ok=True)   # the folder the user named (created if needed, as the user typed it)
    if not _can_use_dir_fd():
        return _write_below_by_path(base, parts, name, data, target)
    fd = os.open(base, os.O_RDONLY | os.O_DIRECTORY)
    try:
        for part in parts:
            try:
                os.mkdir(part, 0o777, dir_fd=fd)
            except FileExistsError:
                pass
            try:
                inner = os.open(part, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW, dir_fd=fd)
            except OSError as exc:   # ELOOP: a link; ENOTDIR: a file
                raise NotOurs(f"{part} is a link or not a folder ({exc.strerror})") from None
            os.close(fd)
            fd = inner
            _own(os.fstat(fd), part)
        temp = f".{name}.{os.urandom(6).hex()}.tmp"
        out = os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o666, dir_fd=fd)
        with temporary_removed_on_failure(temp, dir_fd=fd):
            with os.fdopen(out, "wb") as handle:
                handle.write(data)
            os.replace(temp, name, src_dir_fd=fd, dst_dir_fd=fd)
    finally:
        os.close(fd)
    return target


def _write_below_by_path(base, parts, name, data, target):
    import tempfile
    folder = base
    for part in parts:
        folder = os.path.join(folder, part)
        try:
            os.mkdir(folder)
        except FileExistsError:
            pass
        if os.path.islink(folder):
            raise NotOurs(f"{part} is a link")
        _own(os.lstat(folder), part)
    fd, temp = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=folder)
    with temporary_removed_on_failure(temp):
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.replace(temp, target)
    return target


@contextlib.contextmanager
def temporary_removed_on_failure(temp, dir_fd=None):
    """Whatever goes wrong inside (a full disk, Ctrl-C), the temporary file `temp` is not left behind."""
    try:
        yield
    except BaseException:
        try:
            os.unlink(temp, dir_fd=dir_fd)
        except OSError:
            pass
        raise
