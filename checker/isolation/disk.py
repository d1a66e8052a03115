"""A run's disk quota: how much its out/ folder (sandbox.OUT, the only place its user may write) may hold.

Without one, a run that filled the temporary folder made a classmate graded beside it lose its marks (its
settings and record could not be written). Limits.disk_mb sets the quota (--disk MB); two ways enforce it:

- mounted (Linux, a root grader that may mount, not the portable path): out/ is a tmpfs of disk_mb MB and at
  most MAX_ENTRIES files and folders, owned by the run's uid with out/'s mode, mounted before the child starts
  and unmounted (lazily if busy) once the parent has read the run's files. A write past it fails with ENOSPC in
  that run alone. The tmpfs lives in memory: --jobs runs at once hold at most jobs x disk_mb MB of it.
- watched (the mount refused, as in a container without CAP_SYS_ADMIN; a grader that is not root; the
  portable path, macOS, Windows): the parent adds up out/'s files every POLL_SECONDS while it waits on the
  child and stops the run once they are over the quota. That is a poll, not a limit: a fast writer overshoots
  by what it writes between two looks (tests/test_run_disk.py measures it); a file the run deleted while it
  keeps it open is not seen; and an unjailed run (no chroot, not root) may still write where every user may
  (/tmp, /dev/shm) -- the quota covers out/ only.

Either way a run over its quota is stopped with the status "disk" and its row says so (message()).
"""
import errno
import functools
import os
import sys
import threading
import time

from checker.isolation import users

DEFAULT_MB = 64        # measured: the five solutions' runs leave at most 1.4 MB in out/ (a scene's record.json);
                       # 64 MB is also the largest file a run may write (sandbox.FILE_LIMIT)
MAX_ENTRIES = 1000     # files and folders out/ may hold (honest runs: 2 or 3); bounds the watcher's walk too
POLL_SECONDS = 0.05    # s between two looks at out/ while the parent waits on the child


def check_mb(value, name="disk_mb"):
    """value if it is a whole number of MB >= 1, else ValueError naming `name` and the value (one line)."""
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError(f"{name} must be a whole number of MB >= 1, got {value!r}")
    return value


def message(what, mb):
    """The row's words for a run stopped over its quota: the file's own doing, never the checker's."""
    return f"{what} wrote more than {mb} MB (or {MAX_ENTRIES} files) into its working folder and was stopped."


# ---------------------------------------------------------------- the mount (Linux, root)

MS_NOSUID, MS_NODEV = 2, 4
MNT_DETACH, UMOUNT_NOFOLLOW = 2, 8
_lock = threading.Lock()
_refused = None        # this process's first refused mount, "EPERM: Operation not permitted": not tried again
_mounted = set()       # the out/ folders this process mounted and has not unmounted


@functools.lru_cache(maxsize=None)
def _libc():
    import ctypes
    libc = ctypes.CDLL(None, use_errno=True)
    libc.mount.argtypes = (ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulong, ctypes.c_char_p)
    libc.umount2.argtypes = (ctypes.c_char_p, ctypes.c_int)
    return libc


def mount_wanted(portable):
    """True when a run's out/ should be a tmpfs: Linux, root, not the portable path (it stands for Windows and
    macOS), CHECKER_NO_MOUNT != "1" (the tests take the path of a system that refuses it), none refused yet."""
    return (sys.platform.startswith("linux") and users.is_root() and not portable
            and os.environ.get("CHECKER_NO_MOUNT") != "1" and _refused is None)


def mount(out, mb):
    """Mount a tmpfs of `mb` MB (and MAX_ENTRIES inodes) on the folder `out`, with its owner and mode; True if
    mounted. A refusal is remembered: later runs of this process are watched instead (refused())."""
    global _refused
    import ctypes
    info = os.stat(out)
    options = (f"size={mb}m,nr_inodes={MAX_ENTRIES + 1},mode={info.st_mode & 0o7777:o},uid={info.st_uid},"
               f"gid={info.st_gid}").encode()
    try:
        libc = _libc()
        failed = libc.mount(b"tmpfs", os.fsencode(out), b"tmpfs", MS_NOSUID | MS_NODEV, options) != 0
        code = ctypes.get_errno() if failed else 0
    except (OSError, AttributeError) as exc:   # no libc with mount(2) here
        failed, code = True, getattr(exc, "errno", None) or errno.ENOSYS
    if failed:
        with _lock:
            _refused = _refused or f"{errno.errorcode.get(code, code)}: {os.strerror(code)}"
        return False
    with _lock:
        _mounted.add(out)
    return True


def refused():
    """Why this process's mount was refused ("EPERM: Operation not permitted"), or None."""
    return _refused


def release(out):
    """Unmount the tmpfs mount() put on `out` (lazily if a process still holds it); nothing if there is none.
    Called after the parent read the run's files and before its work folder is removed."""
    with _lock:
        if out not in _mounted:
            return
        _mounted.discard(out)
    libc = _libc()
    if libc.umount2(os.fsencode(out), UMOUNT_NOFOLLOW) != 0:   # busy: a process of the run still holds it
        libc.umount2(os.fsencode(out), UMOUNT_NOFOLLOW | MNT_DETACH)


# ---------------------------------------------------------------- measuring

def usage(folder, max_entries=MAX_ENTRIES):
    """Bytes the files and folders under `folder` take on disk (st_blocks x 512; st_size where there is no
    st_blocks, Windows), or None when that cannot be told: more than max_entries of them, or one the parent
    cannot look into (a folder made unreadable, a path too long). Links are not followed; no recursion."""
    total, entries, stack = 0, 0, [folder]
    while stack:
        try:
            with os.scandir(stack.pop()) as listing:
                found = list(listing)
        except FileNotFoundError:
            continue   # removed between two looks
        except OSError:
            return None
        for entry in found:
            entries += 1
            if entries > max_entries:
                return None
            try:
                info = entry.stat(follow_symlinks=False)
            except FileNotFoundError:
                continue
            except OSError:
                return None
            blocks = getattr(info, "st_blocks", None)
            total += blocks * 512 if blocks is not None else info.st_size
            if entry.is_dir(follow_symlinks=False):
                stack.append(entry.path)
    return total


class Quota:
    """One run's quota on its out/ folder: mounted where mount_wanted(), else watched. over() says whether the
    run went past it; release(out) unmounts (sandbox.run_child, in a finally, after the run's files were read)."""

    def __init__(self, out, mb, portable):
        self.out, self.mb = out, mb
        self.mounted = mount_wanted(portable) and mount(out, mb)
        # a root grader's mount was refused (this run's or an earlier one's): the run's notes say it is watched
        self.tried = not self.mounted and not portable and refused() is not None
        self.next_look = 0.0

    def notes(self):
        """A note for the run's record when a root grader's mount was refused and the run was watched."""
        if self.tried:
            return [f"disk quota ({self.mb} MB): the system refused a tmpfs on the run's folder ({refused()}); "
                    f"the folder was watched every {POLL_SECONDS:g} s instead"]
        return []

    def over(self, now=None):
        """True when the run went past its quota. Mounted: the tmpfs is full (its blocks or its inodes). Watched:
        out/ holds more than mb MB, or more than MAX_ENTRIES entries, or cannot be measured. `now`
        (time.monotonic()): look only when POLL_SECONDS have passed since the last look, or ten times what the
        last look took of CPU (a walk of MAX_ENTRIES files took 6 ms: the watcher keeps under a tenth of a core);
        None: look now."""
        if now is not None and now < self.next_look:
            return False
        cost = time.thread_time()
        over = self._look()
        cost = time.thread_time() - cost   # CPU time of this look (a busy machine's waits do not count)
        if now is not None:
            self.next_look = time.monotonic() + max(POLL_SECONDS, 10 * cost)
        return over

    def _look(self):
        if self.mounted:
            try:
                info = os.statvfs(self.out)
            except OSError:
                return False
            return info.f_bavail == 0 or info.f_favail == 0
        used = usage(self.out)
        return used is None or used > self.mb * 1024 * 1024
