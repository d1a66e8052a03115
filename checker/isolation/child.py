"""The child process that runs one lab file for the checker, isolated from the grader.

    python -m checker.isolation.child LAB_PATH TASK SETTINGS_JSON fd:N
    python -m checker.isolation.child LAB_PATH TASK SETTINGS_JSON stdout:FILE     (the portable path)

TASK is "probe" (import the lab and test its own functions on the lesson's
cases) or "scenario" (configure the lab runtime with SETTINGS_JSON and run the
lab's main()). The child writes what happened, one JSON line per phase, to file
descriptor N, the write end of a pipe the parent (the grader) opened and reads;
the parent decides. The child runs a copy of the file that sandbox.run_child put
alone in the child's working folder (copy_name()): the lab's `__file__` and
sys.argv name the copy, and only the project and Python's own folders are on
sys.path, so nothing beside the submission can be imported. The lab is compiled
from the copy's source under the submitted file's name (so tracebacks name the
student's file and line) and imported under the module name "lab_under_test",
so its `if __name__ == "__main__":` guard does not run main(). No bytecode is
written anywhere. What the child calls after the lab's code ran (json.dumps, the
pipe's write, describe(), ...) is bound before the lab loads. On the portable path
(Windows, CHECKER_PORTABLE=1: checker/isolation/sandbox.py) the result channel is the child's
own stdout, and the lab's stdout goes to FILE from before the lab loads; the child
then applies its limits itself (CHECKER_CHILD_LIMITS, see Watchdog).

On the POSIX path the parent sets the resource limits and the wall-clock timeout; this file only
arms faulthandler (on SIGXCPU, the CPU-time limit, and shortly before the
wall-clock limit) so that a run killed for taking too long leaves a traceback
(where the lab was looping) in "timeout_traceback.txt" in the working directory.
"""
import _thread
import faulthandler
import importlib
import io
import json
import math
import os
import sys
import signal
import traceback
import threading
import time
import types

from checker.isolation.confine import OUT, copy_name
from checker.reading.source import read as read_source   # imported here, so the zygote has it warm

sys.dont_write_bytecode = True

MODULE_NAME = "lab_under_test"
PROBE_SECONDS = 3.0   # s a lab function may run during the probe before it is stopped as an endless loop


class OutputFlood(Exception):
    """Raised from print() inside the lab once it has written more than its output allowance."""


class LimitedStream(io.TextIOBase):
    """A text stream that passes writes on and raises OutputFlood past `limit` characters in all.

    The exception comes out of the lab's own print() call, so its traceback names the line
    that was printing. The parent's hard byte limit stays as the second line of defence.
    """

    def __init__(self, stream, counter, limit):
        self.stream, self.counter, self.limit = stream, counter, limit

    def write(self, text):
        self.counter[0] += len(text)
        if self.counter[0] > self.limit:
            raise OutputFlood(f"printed more than {self.limit // 1024} KB")
        return self.stream.write(text)

    def flush(self):
        self.stream.flush()

    def fileno(self):
        return self.stream.fileno()

    @property
    def encoding(self):
        return self.stream.encoding

    def writable(self):
        return True


class LabExit(BaseException):
    """Raised in place of os._exit() so that an exit inside the lab still yields a result."""

    def __init__(self, code):
        super().__init__(code)
        self.code = code


def _blocked_os_exit(code=0):
    raise LabExit(code)


def where(exc, lab_path, _extract_tb=traceback.extract_tb):
    """(line, source text) of the innermost traceback frame inside the lab file, or (None, None).

    (traceback's functions are bound as defaults when this module loads, before any lab: a lab that
    replaces traceback.extract_tb does not change what the child reports.)
    """
    if isinstance(exc, SyntaxError) and exc.filename == lab_path:
        return exc.lineno, (exc.text or "").strip()
    found = (None, None)
    for frame in _extract_tb(exc.__traceback__):
        if frame.filename == lab_path:
            found = (frame.lineno, (frame.line or "").strip())
    return found


def describe(exc, lab_path, _format_exception=traceback.format_exception):
    """A JSON-ready account of an exception raised by lab code."""
    line, text = where(exc, lab_path)
    if isinstance(exc, LabExit):
        kind, message = "exit", f"os._exit({exc.code}) was called"
    elif isinstance(exc, SystemExit):
        kind, message = "exit", f"sys.exit({exc.code!r}) was called"
    elif isinstance(exc, MemoryError):
        kind, message = "memory", "MemoryError: the lab ran out of memory"
    elif isinstance(exc, OutputFlood):
        kind, message = "flood", str(exc)
    elif isinstance(exc, SyntaxError):
        kind, message = "syntax", f"SyntaxError: {exc.msg}"
    else:
        kind, message = "exception", f"{type(exc).__name__}: {exc}"
    tail = _format_exception(type(exc), exc, exc.__traceback__)
    return {"kind": kind, "message": message, "line": line, "text": text,
            "traceback": "".join(tail)[-4000:]}


def load_lab(lab_path, copy_path):
    """Compile and run the lab's source as module MODULE_NAME; returns the module.

    It compiles the text the grader read and numbered (checker/reading/source.py), never the bytes under a coding
    of the file's choosing, so the lines the grader's rules read are the lines that run. It reads the copy
    in the work folder (the child may not read the original); the grader checks the original is unchanged.
    """
    code = compile(read_source(copy_path), lab_path, "exec", dont_inherit=True)
    module = types.ModuleType(MODULE_NAME)
    module.__file__ = copy_path  # the lab sees a copy, never the submitted file
    sys.modules[MODULE_NAME] = module
    exec(code, module.__dict__)
    return module


# ---------------------------------------------------------------- probe: the student's own functions

class FunctionTimeout(Exception):
    """Raised inside a student's function that ran past its time budget (an endless loop, say)."""


def _alarm(signum, frame):
    raise FunctionTimeout()


def call_limited(func, seconds, *args):
    """func(*args), interrupted with FunctionTimeout after `seconds` of CPU time (SIGPROF, or the Watchdog)."""
    if _watchdog is not None:
        return _watchdog.call(func, seconds, *args)
    previous = signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        return func(*args)
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)


class Watchdog(threading.Thread):
    """The portable child's CPU-time limits, kept by a thread: no SIGPROF, setitimer or SIGXCPU needed.

    The whole run: past `budget` s of process CPU time it writes every thread's stack to `trace`
    (where the lab was looping) and ends the process, as RLIMIT_CPU with SIGXCPU does on POSIX.
    One probe call (call()): past its `seconds` of CPU it interrupts the main thread
    (_thread.interrupt_main), whose SIGINT handler raises FunctionTimeout inside the student's function.
    A tick is TICK s, so a limit is kept to about that.
    """
    TICK = 0.05

    def __init__(self, budget, trace):
        super().__init__(daemon=True)
        self.budget, self.trace = budget, trace
        self.until, self.call_id, self.fired = None, 0, -1   # the current call's CPU deadline and its number
        signal.signal(signal.SIGINT, self._interrupt)
        self.start()

    def run(self):
        while True:
            time.sleep(self.TICK)
            now = time.process_time()
            if now >= self.budget:
                faulthandler.dump_traceback(file=self.trace, all_threads=True)
                self.trace.flush()
                _real_exit(1)
            call_id, until = self.call_id, self.until
            if until is not None and now >= until and self.fired != call_id:
                self.fired = call_id
                _thread.interrupt_main()

    def _interrupt(self, signum, frame):
        # only the call the watchdog fired for, and only while it runs (a late interrupt is dropped)
        if self.until is not None and self.fired == self.call_id:
            self.until = None
            raise FunctionTimeout()

    def call(self, func, seconds, *args):
        self.call_id += 1
        self.until = time.process_time() + seconds
        try:
            return func(*args)
        finally:
            self.until = None


_watchdog = None   # the portable child's Watchdog


def _stdout_channel(path):
    """The portable result channel: the real stdout, kept on a new fd; fd 1 (the lab's stdout) now goes to `path`."""
    sys.stdout.flush()
    channel = os.dup(1)   # not inherited by anything the lab starts
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | getattr(os, "O_BINARY", 0), 0o600)
    os.dup2(fd, 1)
    os.close(fd)
    return os.fdopen(channel, "w", encoding="utf-8")


def _portable_limits(result_pipe, trace):
    """Apply the run's limits from inside (CHECKER_CHILD_LIMITS): the rlimits the system accepts (notes of the
    refused ones go to the parent) and the Watchdog for CPU time. Returns the confine.Limits."""
    from checker.isolation import confine
    global _watchdog
    limits = confine.Limits(**json.loads(os.environ.pop("CHECKER_CHILD_LIMITS", "{}")))
    confine.write_notes(result_pipe.fileno(), confine.set_rlimits(limits, cpu=False))
    _watchdog = Watchdog(max(1, math.ceil(limits.timeout)), trace)   # RLIMIT_CPU's soft limit on POSIX
    return limits


def run_probe(module, lab_path, probes, seconds, settings):
    """Each of the lab's probes in turn, recorded on a tape (checker/judging/tape.py); a failing one gets its own error.

    `probes.PROBES` maps a probe's name to (the lab function it needs, probe(module, lab_path)).
    The probe sees the lab through a tape.Recorder, which records every call of a step function
    (settings["steps"]). Returns {"missing": [...], "constants": {name: value}, "tapes": {probe name:
    {"tape": [...]} or {"tape": [...], "error": ...}}}: what the student's functions did, and no
    verdict or reference value; the parent replays each tape through the same probe and judges.
    A probe that runs longer than `seconds` of CPU is stopped and reported with the line it was at.
    """
    from checker.judging import tape
    result = {"tapes": {}, "constants": constants_of(module),
              "missing": [m for m in probes.REQUIRED if not callable(getattr(module, m, None))]}
    recorder = tape.Recorder(module, settings.get("steps") or (), settings.get("splices"), lab_path,
                             settings.get("seed", 0), constants=settings.get("constants"))
    for name, (function, probe) in probes.PROBES.items():
        if not callable(getattr(module, function, None)):
            continue
        try:
            call_limited(recorder.run, seconds, probe, lab_path)   # no reference helper runs here
            result["tapes"][name] = {"tape": recorder.take()}
        except FunctionTimeout as exc:
            error = describe(exc, lab_path)
            error.update(kind="timeout", message=f"{function}() was still running after {seconds:g} s of CPU time")
            result["tapes"][name] = {"tape": recorder.take(), "error": error}
        except Exception as exc:  # the student's function raised: report it with file and line
            result["tapes"][name] = {"tape": recorder.take(), "error": describe(exc, lab_path)}
    return result


def constants_of(module, limit=200):
    """The lab's top-level numbers, text and tuples of them (its constants), JSON-ready, for the replay."""
    from checker.judging import tape
    out = {}
    for name, value in list(vars(module).items())[:5000]:
        if not name.startswith("_") and tape._plain(value) and len(out) < limit:
            out[name] = tape.encode(value, tape.Seen())
    return out


# ---------------------------------------------------------------- scenario: the lab's main() under the runtime

def run_scenario(module, settings):
    from lesson11 import runtime
    runtime.configure(settings)
    try:
        module.main()
    finally:
        runtime.write_record()


def _only_the_project_on_path():
    """Take the working folder off sys.path (`python -m` puts it first): the lab's copy there is no module."""
    here = os.getcwd()
    sys.path[:] = [p for p in sys.path if p and os.path.abspath(p) != here]


def _keep_lines(lab_path, copy_path):
    """Serve the lab's source lines under its own name from the copy, so a traceback shows them even where
    the child's user cannot read the submitted file (linecache reads the copy as it would the file)."""
    import linecache
    lines = linecache.getlines(copy_path)
    linecache.cache[lab_path] = (sum(map(len, lines)), None, lines, lab_path)   # no mtime: never re-read


def main(argv):
    lab_path, task, settings_path, channel = argv
    kind, _, target = channel.partition(":")
    portable = kind == "stdout"
    result_pipe = _stdout_channel(target) if portable else os.fdopen(int(target), "w", encoding="utf-8")
    _only_the_project_on_path()
    faulthandler.enable()
    budget = float(os.environ.get("CHECKER_FAULT_SECONDS", "0") or 0)
    trace = open("timeout_traceback.txt", "w", encoding="utf-8")   # faulthandler writes to its fd: ASCII
    if budget > 0:
        faulthandler.dump_traceback_later(budget, exit=True, file=trace)
    if portable:
        limits = _portable_limits(result_pipe, trace)
    else:
        faulthandler.register(signal.SIGXCPU, file=trace, all_threads=False)  # the CPU-time limit: where it looped
    os._exit = _blocked_os_exit
    with open(settings_path, encoding="utf-8") as handle:
        settings = json.load(handle)
    # the checker's own settings; what is left goes to the lab runtime
    probes = importlib.import_module(settings.pop("probes"))
    if portable and limits.user:   # the POSIX path left root before the lab's interpreter started; here, now,
        from checker.isolation import confine, zygote   # after importing what a lab needs, as the zygote does
        zygote.warm_up()
        confine.leave_root(limits, inside="/" + OUT)
    # the copy sandbox.run_child put in the work folder, the parent of the child's own (root's: the child reads it)
    copy_path = os.path.abspath(os.path.join(os.pardir, copy_name(lab_path)))
    sys.argv[:] = [copy_path]
    output_limit = int(settings.pop("max_output", 0) or 0)
    if output_limit:
        counter = [0]
        sys.stdout = LimitedStream(sys.stdout, counter, output_limit)
        sys.stderr = LimitedStream(sys.stderr, counter, output_limit)
    _keep_lines(lab_path, copy_path)
    result = {"task": task, "phase": "import"}
    # what the child calls once the lab's code has run, taken now, before it runs: a lab that replaces
    # json.dumps, the pipe's write or a function of this module does not change the report
    dumps, write, flush, account = json.dumps, result_pipe.write, result_pipe.flush, describe
    probe_all, scenario, cancel = run_probe, run_scenario, faulthandler.cancel_dump_traceback_later
    stdout, stderr, real_exit = sys.__stdout__, sys.__stderr__, _real_exit

    def save():
        write(dumps(result) + "\n")
        flush()

    save()
    try:
        module = load_lab(lab_path, copy_path)
        result["phase"] = "run"
        save()
        if task == "probe":
            result["probe"] = probe_all(module, lab_path, probes, PROBE_SECONDS, settings)
        else:
            missing = [m for m in probes.REQUIRED if not callable(getattr(module, m, None))]
            if missing:
                raise AttributeError(f"the lab defines no {missing[0]}()")
            scenario(module, settings)
        result["phase"] = "done"
    except BaseException as exc:  # anything the lab raises, SystemExit included, becomes a result
        result["error"] = account(exc, lab_path)
    cancel()
    sys.stdout, sys.stderr = stdout, stderr
    save()
    # leave without running the lab's atexit handlers twice or waiting on its threads
    stdout.flush()
    stderr.flush()
    os.__dict__["_exit"] = real_exit
    real_exit(0)


_real_exit = os._exit

if __name__ == "__main__":
    main(sys.argv[1:])
