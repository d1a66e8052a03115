"""What confines one run, shared by the grader (sandbox), the zygote and the child: the run's limits, the
resource limits applied to a process, leaving root, and the names of the run's files in its work folder."""
import json
import math
import os
import sys
from dataclasses import dataclass

from checker.isolation import disk, users

FILE_LIMIT = 64 * 1024 * 1024   # bytes: largest file a child may write
OUT = "out"   # the run's own sub-folder of its work folder: the only place its user may write
STDOUT_FILE = "lab_stdout.txt"   # in the work folder: the lab's stdout on the portable path


@dataclass
class Limits:
    """Per-run limits: CPU seconds, address-space MB, output bytes (stdout + stderr), and the user it runs as.

    user: None runs the child as the grader's own user; a user name (the grader must be root) runs
    only the child as that user, so files the grader keeps to itself (the solutions) stay unreadable.
    The command line picks one for a root grader unless told otherwise (checker/isolation/users.py: nobody).
    """
    timeout: float = 20.0
    memory_mb: int = 768
    max_output: int = 256 * 1024
    user: str | None = None
    uid: int | None = None    # the run's own uid (users.RUN_UIDS, set by run_child): user's group, this uid
    jail: str | None = None   # the run's work folder, chrooted into before the switch where the system allows it
    disk_mb: int = disk.DEFAULT_MB   # MB of files the run may write into its out/ folder (disk.Quota)

    def __post_init__(self):
        disk.check_mb(self.disk_mb)


def set_rlimits(limits, cpu=True):
    """Apply the run's resource limits to this process where the system accepts them.

    Returns a note per limit not applied: the `resource` module missing (Windows), or setrlimit
    refusing it (macOS refuses RLIMIT_AS: "current limit exceeds maximum limit"). A refused limit is
    skipped, never an error: the run goes on, and the note goes to the run's record, not to the student.
    cpu=False leaves RLIMIT_CPU out (the portable child watches its CPU time with a thread instead).
    """
    try:
        import resource
    except ImportError:   # Windows: the parent limits memory with a Job Object instead
        missing = "file size" if sys.platform == "win32" else "memory, file size"
        return [f"resource limits ({missing}): no resource module on this system, not applied"]
    memory = limits.memory_mb * 1024 * 1024
    seconds = max(1, math.ceil(limits.timeout))
    wanted = [("RLIMIT_AS", (memory, memory), f"memory {limits.memory_mb} MB"),
              ("RLIMIT_CPU", (seconds, seconds + 1), f"CPU time {seconds} s"),
              ("RLIMIT_FSIZE", (FILE_LIMIT, FILE_LIMIT), f"file size {FILE_LIMIT >> 20} MB"),
              ("RLIMIT_CORE", (0, 0), "no core dumps")]
    if hasattr(resource, "RLIMIT_MSGQUEUE"):   # Linux: no POSIX message queue, which would outlive the run
        wanted.append(("RLIMIT_MSGQUEUE", (0, 0), "no message queues"))
    notes = []
    for name, value, what in wanted if cpu else [w for w in wanted if w[0] != "RLIMIT_CPU"]:
        try:
            resource.setrlimit(getattr(resource, name), value)
        except (AttributeError, ValueError, OSError) as exc:
            notes.append(f"{name} ({what}) refused by this system ({type(exc).__name__}: {exc}): not applied")
    return notes


def write_notes(fd, notes):
    """Send the notes of skipped limits to the parent as one line on the result channel (fd)."""
    if notes:
        os.write(fd, (json.dumps({"limits_skipped": notes}) + "\n").encode())


def limit_child(limits, note_fd=None):
    """The POSIX child's set-up after fork: its own session, the rlimits (notes of refused ones to note_fd),
    and last the student's user."""
    def apply():
        os.setsid()
        notes = set_rlimits(limits)
        if note_fd is not None:
            write_notes(note_fd, notes)
        if limits.user:   # last: drop root for the student's user
            leave_root(limits)
    return apply


def leave_root(limits, inside="/"):
    """The run's own uid gets a process limit, the run its jail (where it has one), then root is dropped."""
    if limits.uid is not None:
        import resource
        resource.setrlimit(resource.RLIMIT_NPROC, (users.NPROC, users.NPROC))
    entry = users._entry(limits.user)   # read now: a jail has no /etc/passwd
    if limits.jail:
        users.enter_jail(limits.jail, inside)
    users.drop_to(entry.pw_uid if limits.uid is None else limits.uid, entry.pw_gid)


# the checker's own names in the work folder (the child's files are in its OUT sub-folder)
RESERVED = ("settings.json", OUT)


def copy_name(lab_path):
    """The name of the lab's copy in the child's work folder: the file's own name, unless the checker uses it."""
    name = os.path.basename(lab_path)
    return name if name not in RESERVED and not name.startswith(".") else "lab_" + name.lstrip(".")
