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
"""
import json
import math
import os
import selectors
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field

PROJECT_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FILE_LIMIT = 64 * 1024 * 1024   # bytes: largest file a child may write
RECORD_LIMIT = 48 * 1024 * 1024  # bytes: largest record the parent will read
WALL_FACTOR, WALL_EXTRA = 3.0, 5.0   # the wall-clock limit: WALL_FACTOR × timeout + WALL_EXTRA s
FLOOD_SLACK = 64 * 1024          # bytes past max_output before the parent kills a run (the child stops first)


@dataclass
class Limits:
    """Per-run limits: wall-clock seconds, address-space MB, output bytes (stdout + stderr)."""
    timeout: float = 20.0
    memory_mb: int = 768
    max_output: int = 256 * 1024


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
    return apply


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _read_json(path, limit):
    try:
        if os.path.getsize(path) > limit:
            return None
        with open(path, encoding="utf-8") as handle:
            return json.load(handle)
    except (OSError, ValueError):
        return None


def run_child(lab_path, task, settings, limits):
    """Run `python -m checker.child` on lab_path; returns a RunResult. Never raises for lab behaviour."""
    lab_path = os.path.abspath(lab_path)
    with tempfile.TemporaryDirectory(prefix="checker-") as work:
        settings = dict(settings, max_output=limits.max_output)  # the child stops a flood at its print()
        if task == "scenario":
            settings["record"] = os.path.join(work, "record.json")
        settings_path = os.path.join(work, "settings.json")
        result_path = os.path.join(work, "result.json")
        with open(settings_path, "w", encoding="utf-8") as handle:
            json.dump(settings, handle)
        env = {key: value for key, value in os.environ.items() if not key.startswith("LESSON11_")}
        env.update({
            "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy", "PYGAME_HIDE_SUPPORT_PROMPT": "1",
            "PYTHONDONTWRITEBYTECODE": "1", "PYTHONUNBUFFERED": "1", "PYTHONIOENCODING": "utf-8",
            "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
            "PYTHONPATH": os.pathsep.join([PROJECT_ROOT, os.path.dirname(lab_path)]),
            "CHECKER_FAULT_SECONDS": str(max(wall_limit(limits) - 0.6, 0.2)),
        })
        command = [sys.executable, "-X", "faulthandler", "-m", "checker.child",
                   lab_path, task, settings_path, result_path]
        start = time.monotonic()
        proc = subprocess.Popen(command, cwd=work, env=env, stdin=subprocess.DEVNULL,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                preexec_fn=_limit_child(limits))
        chunks = {"stdout": [], "stderr": []}
        total = 0
        status = None
        selector = selectors.DefaultSelector()
        selector.register(proc.stdout, selectors.EVENT_READ, "stdout")
        selector.register(proc.stderr, selectors.EVENT_READ, "stderr")
        open_streams = 2
        deadline = start + wall_limit(limits)
        while open_streams:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                status = "timeout"
                break
            for key, _ in selector.select(timeout=min(remaining, 0.5)):
                data = os.read(key.fileobj.fileno(), 65536)
                if not data:
                    selector.unregister(key.fileobj)
                    open_streams -= 1
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
        proc.stdout.close()
        proc.stderr.close()
        seconds = time.monotonic() - start
        result = _read_json(result_path, 1024 * 1024) or {}
        record = _read_json(settings["record"], RECORD_LIMIT) if task == "scenario" else None
        trace = ""
        try:
            with open(os.path.join(work, "timeout_traceback.txt"), encoding="utf-8", errors="replace") as handle:
                trace = handle.read(20000)
        except OSError:
            pass
        if trace and not status:
            status = "timeout"  # faulthandler fired and ended the process just before our deadline
        if not status:
            if result.get("phase") == "done":
                status = "done"
            elif "error" in result:
                status = "error"
            else:
                status = "crash"
        return RunResult(status=status, result=result, record=record,
                         stdout=b"".join(chunks["stdout"]).decode("utf-8", "replace"),
                         stderr=b"".join(chunks["stderr"]).decode("utf-8", "replace"),
                         returncode=proc.returncode, seconds=seconds, timeout_trace=trace)
