"""The child process that runs one lab file for the checker, isolated from the grader.

    python -m checker.child LAB_PATH TASK SETTINGS_JSON fd:N

TASK is "probe" (import the lab and test its own functions on the lesson's
cases) or "scenario" (configure the lab runtime with SETTINGS_JSON and run the
lab's main()). The child writes what happened, one JSON line per phase, to file
descriptor N, the write end of a pipe the parent (the grader) opened and reads;
the parent decides. The lab sees sys.argv as [its own path], as when run itself. The lab is compiled from its source under its own
file name (so tracebacks name the student's file and line) and imported under
the module name "lab_under_test", so its `if __name__ == "__main__":` guard does
not run main(). No bytecode is written next to the submitted file.

The parent sets the resource limits and the wall-clock timeout; this file only
arms faulthandler (on SIGXCPU, the CPU-time limit, and shortly before the
wall-clock limit) so that a run killed for taking too long leaves a traceback
(where the lab was looping) in "timeout_traceback.txt" in the working directory.
"""
import faulthandler
import importlib
import io
import json
import os
import sys
import signal
import traceback
import types

from checker.source import read as read_source   # imported here, so the zygote has it warm

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


def where(exc, lab_path):
    """(line, source text) of the innermost traceback frame inside the lab file, or (None, None)."""
    if isinstance(exc, SyntaxError) and exc.filename == lab_path:
        return exc.lineno, (exc.text or "").strip()
    found = (None, None)
    for frame in traceback.extract_tb(exc.__traceback__):
        if frame.filename == lab_path:
            found = (frame.lineno, (frame.line or "").strip())
    return found


def describe(exc, lab_path):
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
    tail = traceback.format_exception(type(exc), exc, exc.__traceback__)
    return {"kind": kind, "message": message, "line": line, "text": text,
            "traceback": "".join(tail)[-4000:]}


def load_lab(lab_path, copy_path):
    """Compile and run the lab's source as module MODULE_NAME; returns the module.

    It compiles the text the grader read and numbered (checker/source.py), never the bytes under a coding
    of the file's choosing, so the lines the grader's rules read are the lines that run.
    """
    code = compile(read_source(lab_path), lab_path, "exec", dont_inherit=True)
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
    """func(*args), interrupted with FunctionTimeout after `seconds` of CPU time (SIGPROF)."""
    previous = signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        return func(*args)
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)


def run_probe(module, lab_path, probes, seconds, settings):
    """Each of the lab's probes in turn, recorded on a tape (checker/tape.py); a failing one gets its own error.

    `probes.PROBES` maps a probe's name to (the lab function it needs, probe(module, lab_path)).
    The probe sees the lab through a tape.Recorder, which records every call of a step function
    (settings["steps"]). Returns {"missing": [...], "constants": {name: value}, "tapes": {probe name:
    {"tape": [...]} or {"tape": [...], "error": ...}}}: what the student's functions did, and no
    verdict or reference value; the parent replays each tape through the same probe and judges.
    A probe that runs longer than `seconds` of CPU is stopped and reported with the line it was at.
    """
    from checker import tape
    result = {"tapes": {}, "constants": constants_of(module),
              "missing": [m for m in probes.REQUIRED if not callable(getattr(module, m, None))]}
    recorder = tape.Recorder(module, settings.get("steps") or (), settings.get("splices"), lab_path,
                             settings.get("seed", 0))
    for name, (function, probe) in probes.PROBES.items():
        if not callable(getattr(module, function, None)):
            continue
        try:
            call_limited(probe, seconds, recorder, lab_path)
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
    from checker import tape
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


def main(argv):
    lab_path, task, settings_path, channel = argv
    result_pipe = os.fdopen(int(channel.split(":", 1)[1]), "w", encoding="utf-8")
    sys.argv[:] = [lab_path]
    faulthandler.enable()
    budget = float(os.environ.get("CHECKER_FAULT_SECONDS", "0") or 0)
    trace = open("timeout_traceback.txt", "w")
    if budget > 0:
        faulthandler.dump_traceback_later(budget, exit=True, file=trace)
    faulthandler.register(signal.SIGXCPU, file=trace, all_threads=False)  # the CPU-time limit: where it looped
    os._exit = _blocked_os_exit
    with open(settings_path, encoding="utf-8") as handle:
        settings = json.load(handle)
    # the checker's own settings; what is left goes to the lab runtime
    probes = importlib.import_module(settings.pop("probes"))
    output_limit = int(settings.pop("max_output", 0) or 0)
    if output_limit:
        counter = [0]
        sys.stdout = LimitedStream(sys.stdout, counter, output_limit)
        sys.stderr = LimitedStream(sys.stderr, counter, output_limit)
    copy_path = os.path.abspath(os.path.basename(lab_path))
    result = {"task": task, "phase": "import"}

    def save():
        result_pipe.write(json.dumps(result) + "\n")
        result_pipe.flush()

    save()
    try:
        module = load_lab(lab_path, copy_path)
        result["phase"] = "run"
        save()
        if task == "probe":
            result["probe"] = run_probe(module, lab_path, probes, PROBE_SECONDS, settings)
        else:
            missing = [m for m in probes.REQUIRED if not callable(getattr(module, m, None))]
            if missing:
                raise AttributeError(f"the lab defines no {missing[0]}()")
            run_scenario(module, settings)
        result["phase"] = "done"
    except BaseException as exc:  # anything the lab raises, SystemExit included, becomes a result
        result["error"] = describe(exc, lab_path)
    faulthandler.cancel_dump_traceback_later()
    sys.stdout = sys.__stdout__
    sys.stderr = sys.__stderr__
    save()
    # leave without running the lab's atexit handlers twice or waiting on its threads
    sys.stdout.flush()
    sys.stderr.flush()
    os.__dict__["_exit"] = _real_exit
    _real_exit(0)


_real_exit = os._exit

if __name__ == "__main__":
    main(sys.argv[1:])
