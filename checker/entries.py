"""What to grade: the command line's paths become entries, each a lab file to grade or the reason it cannot be.

A path on the command line is a file (any file: it is one entry) or a folder
(every `*.py` file under it is one entry, hidden files and folders and
__pycache__, .git, venv, .venv, node_modules, __MACOSX skipped). An entry
that cannot be graded (a dangling symbolic link, a link loop, an unreadable
file, a file that is not UTF-8 or declares another coding, a `.py` that is no lab, ...) is kept with its
reason, so it becomes a row of every output instead of vanishing or stopping
the batch. Only a path that does not exist at all, or a folder with no `.py`
file in it, is a usage error (the command line is wrong, nothing is graded).

Nothing here writes anything: files are only stat()ed and read.
"""
import errno
import os
import stat
from dataclasses import dataclass

from checker import labs
from checker.reading import source
from checker.labs import identify

SKIP_DIRS = {"__pycache__", ".git", ".venv", "venv", "node_modules", "__MACOSX"}
MAX_BYTES = 2_000_000  # a lab file is ~15 KB; anything past this is not one


@dataclass
class Entry:
    """One thing to grade: its path (as given or found), its Lab (or None) and, if it cannot be graded, why."""
    path: str
    lab: object = None
    problem: str = ""
    real: str = ""      # the resolved path, to tell outputs from inputs
    counted: bool = False   # a file meant as a submission that cannot be graded (empty, unreadable): it scores 0

    @property
    def gradable(self):
        return not self.problem


def known_labs():
    return ", ".join(lab.title for lab in labs.LABS)


def examine(path):
    """The Entry for one file path (which may be a symbolic link, dangling or not)."""
    real = os.path.realpath(path)
    by_name = identify(path, "")  # the lab a file belongs to by its name alone, for rows that cannot be read
    try:
        info = os.lstat(path)
    except OSError as exc:
        return Entry(path, by_name, f"cannot read: {exc.strerror}", real, counted=True)
    if stat.S_ISLNK(info.st_mode):
        try:
            info = os.stat(path)
        except OSError as exc:
            if exc.errno == errno.ELOOP:
                problem = "a symbolic link loop (following it leads back to itself)"
            elif exc.errno == errno.ENOENT:
                problem = f"a dangling symbolic link (its target {os.readlink(path)} does not exist)"
            else:
                problem = f"a symbolic link that cannot be followed: {exc.strerror}"
            return Entry(path, by_name, problem, real)
    if stat.S_ISDIR(info.st_mode):
        return Entry(path, None, "a symbolic link to a folder: not followed (name the folder itself to grade it)",
                     real)
    if not stat.S_ISREG(info.st_mode):
        return Entry(path, by_name, "not a regular file (a pipe, device or socket)", real)
    if info.st_size > MAX_BYTES:
        return Entry(path, by_name, f"too large for a lab file ({info.st_size / 1e6:.1f} MB; the limit is "
                                    f"{MAX_BYTES / 1e6:g} MB)", real, counted=True)
    try:
        with open(path, "rb") as handle:
            raw = handle.read(MAX_BYTES + 1)
    except OSError as exc:
        return Entry(path, by_name, f"cannot read: {exc.strerror}", real, counted=True)
    try:   # the compiler's reading (checker/reading/source.py): a coding other than UTF-8 or uncounted line breaks refused
        text = source.decode(raw, "the file")
        source.check(text, "the file")
    except source.SourceError as exc:
        return Entry(path, by_name, str(exc), real, counted=True)
    if not text.strip() and by_name is None:   # nothing submitted in it: 0, not "no lab" (discover() names the lab)
        return Entry(path, None, "the file is empty: nothing to grade", real, counted=True)
    lab = identify(path, text)
    if lab is None:
        what = "" if path.lower().endswith(".py") else "not a .py file, and "
        return Entry(path, None, f"{what}not a lab this checker knows ({known_labs()}): neither its file name nor "
                                 f"its text names one", real)
    return Entry(path, lab, "", real)


def walk(folder):
    """Entries for every .py file under folder (sorted), plus one for each subfolder that cannot be read."""
    found = []

    def unreadable(exc):
        found.append(Entry(exc.filename, None, f"cannot read this folder: {exc.strerror}",
                           os.path.realpath(exc.filename)))

    for here, dirs, files in os.walk(folder, onerror=unreadable):
        for name in sorted(dirs):
            if os.path.islink(os.path.join(here, name)) and name not in SKIP_DIRS and not name.startswith("."):
                found.append(examine(os.path.join(here, name)))
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith(".")
                         and not os.path.islink(os.path.join(here, d)))
        for name in sorted(files):
            if name.lower().endswith(".py") and not name.startswith("."):
                found.append(examine(os.path.join(here, name)))
    return found


def discover(paths):
    """(entries, usage errors) for the command line's paths; entries in order, each file once."""
    entries, errors, seen = [], [], set()
    for given in paths:
        if not os.path.lexists(given):
            errors.append(f"{given}: no such file or folder")
            continue
        found = walk(given) if os.path.isdir(given) else [examine(given)]
        if not found:
            errors.append(f"{given}: no .py file in this folder, nothing to grade")
        for entry in found:
            key = os.path.abspath(entry.path)
            if key not in seen:
                seen.add(key)
                entries.append(entry)
    # an empty or unreadable file in a batch of one lab counts 0 of that lab's points (an empty nina.py in a
    # class folder of Tumbling Crates is nina's 0/17, not "0/0, not a lab")
    known = {entry.lab.id: entry.lab for entry in entries if entry.lab is not None}
    if len(known) == 1:
        for entry in entries:
            if entry.counted and entry.lab is None:
                entry.lab = next(iter(known.values()))
    return entries, errors


def graded_folders(paths):
    """The resolved folders among the command line's paths (no output may be written inside them)."""
    return [os.path.realpath(p) for p in paths if os.path.isdir(p)]
