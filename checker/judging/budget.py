"""A budget on the grader's own work for one file: the replay of its tapes and its checks.

The child's runs have their limits (checker/isolation/sandbox.py); the grader's replay of what a child
reported, and the checks on it, run in the grading process itself. What they cost depends on
the file through the tape, which the file's code can write, so they get a budget too: `cpu`
seconds of the judging thread's CPU time and a wall-clock `deadline` (time.monotonic(); the
whole run's --total-timeout among them). Past either, Exhausted (a BaseException, so no
`except Exception` of the probes' code swallows it) is raised in that thread, and
checker/grade.py turns it into one error row.

How: one watchdog thread looks at every budget in force each TICK s and raises Exhausted in
the thread that overran, with CPython's PyThreadState_SetAsyncExc (the exception arrives at
the thread's next bytecode; a C call that runs long is interrupted when it returns). The
judging itself runs untouched: no tracing, no cost. The thread's CPU time is read from its
own clock (time.pthread_getcpuclockid); where there is none (Windows, macOS) only the
deadline counts.
"""
import ctypes
import threading
import time

TICK = 0.05   # s between two looks of the watchdog


class Exhausted(BaseException):
    """The grader's work on one file ran past its budget; `what` says which limit, `notes` what the file did."""

    def __init__(self, what="its budget"):
        super().__init__(what)
        self.what = what
        self.notes = []

    def message(self):
        """The row's one-line message."""
        tail = "; ".join(self.notes)
        return (f"not graded: the checker's own replay of this file's runs went past its budget ({self.what})"
                + (f"; the file's code: {tail}" if tail else "") + ".")


def _raise_in(thread_id, exception):
    """Raise `exception` (a class, or None to take back one not yet raised) in the thread `thread_id`."""
    ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(thread_id),
                                               ctypes.py_object(exception) if exception else ctypes.c_void_p(0))


def _cpu_clock(thread_id):
    """A function giving the thread's CPU seconds, or None where the system has no per-thread clock."""
    try:
        clock = time.pthread_getcpuclockid(thread_id)
        time.clock_gettime(clock)
    except (AttributeError, OSError, ValueError):
        return None
    return lambda: time.clock_gettime(clock)


class _Watchdog(threading.Thread):
    """Raises Exhausted in a thread whose budget ran out (one watchdog for the whole grading process)."""

    def __init__(self):
        super().__init__(name="checker-budget", daemon=True)
        self.lock = threading.Lock()
        self.budgets = {}   # id(budget) -> budget in force

    def run(self):
        while True:
            time.sleep(TICK)
            with self.lock:
                for key, budget in list(self.budgets.items()):
                    try:
                        what = budget.overrun()
                    except (OSError, ValueError):   # the thread's clock is gone: the thread has ended
                        what, budget.fired = "", "its budget"
                    if what:
                        budget.fired = what
                        _raise_in(budget.thread, Exhausted)
                    if budget.fired:   # raised once; __exit__ may never come to take it off the list
                        del self.budgets[key]


_WATCHDOG = []
_START = threading.Lock()


def _watchdog():
    with _START:
        if not _WATCHDOG:
            _WATCHDOG.append(_Watchdog())
            _WATCHDOG[0].start()
        return _WATCHDOG[0]


class Budget:
    """A context manager: the code run inside it, in this thread, within `cpu` s of this thread's CPU time and
    before `deadline` (time.monotonic()); each None for no such limit. Not re-entrant."""

    def __init__(self, cpu=None, deadline=None):
        self.cpu, self.deadline = cpu, deadline
        self.thread, self.fired = None, ""
        self._clock, self._until = None, None

    def overrun(self):
        """Which limit has run out ("" for none); called by the watchdog."""
        if self._until is not None and self._clock() > self._until:
            return f"{self.cpu:g} s of CPU time"
        if self.deadline is not None and time.monotonic() > self.deadline:
            return "the time it had left"
        return ""

    def __enter__(self):
        self.thread = threading.get_ident()
        self._clock = _cpu_clock(self.thread)
        self._until = None if self.cpu is None or self._clock is None else self._clock() + self.cpu
        watchdog = _watchdog()
        with watchdog.lock:
            watchdog.budgets[id(self)] = self
        return self

    def __exit__(self, kind, exc, traceback):
        watchdog = _watchdog()
        with watchdog.lock:
            watchdog.budgets.pop(id(self), None)
            fired = self.fired
        if not fired:
            return False
        if isinstance(exc, Exhausted):   # it arrived: say which limit ran out
            exc.what = fired + (exc.what[len("its budget"):] if exc.what.startswith("its budget") else "")
            return False
        _raise_in(self.thread, None)   # fired as the block ended: take it back, and raise it here instead
        raise Exhausted(fired)
