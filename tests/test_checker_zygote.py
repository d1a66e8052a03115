"""The zygote (checker/isolation/zygote.py) changes how children start, never what the checker reports.

The same files are graded with CHECKER_ZYGOTE on and off and must get the same JSON (but for
the seconds taken); limits (CPU time, output) still end runs the same way when the child was
forked by the zygote; no zygote or child is left behind by a run.
"""
import json
import os
import re
import signal
import subprocess
import sys
import time
import uuid

import pytest

from checker import labs
from checker.isolation import sandbox
from checker.isolation import users
from checker.isolation.sandbox import Limits, run_child

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXTURES = os.path.join(ROOT, "tests", "fixtures", "checker")
# every lab whose scenes are cheap (at most CHEAP CPU s by its SCENE_SECONDS: today Ball on the Ramp, Bullets and
# Sleeping Crates, about 3 CPU s in all): every run kind goes through both paths; the rest of the suite grades the
# other labs through the zygote (the default) anyway
CHEAP = 2.0   # CPU s of a lab's scenes


def scene_seconds(lab):
    return sum(lab.scene_seconds(name, settings) for name, settings in lab.scenarios().items())


SOLUTIONS = [lab.solution for lab in labs.LABS if scene_seconds(lab) <= CHEAP]
BROKEN = [os.path.join(FIXTURES, name + ".py") for name in
          ("hostile_loop_at_import", "hostile_exception_at_import", "hostile_output_flood", "hostile_os_exit",
           "hostile_sys_exit", "hostile_memory_hog")]

pytestmark = pytest.mark.skipif(not sandbox.zygote_enabled() and os.environ.get("CHECKER_ZYGOTE", "1") != "0",
                                reason="no os.fork / Unix sockets here: the zygote is never used")


def processes_marked(mark):
    """Pids of live processes whose environment holds CHECKER_TEST_MARK=mark."""
    found = []
    needle = f"CHECKER_TEST_MARK={mark}".encode()
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/environ", "rb") as handle:
                if needle in handle.read().split(b"\0"):
                    with open(f"/proc/{pid}/stat", "rb") as stat:
                        if stat.read().rsplit(b")", 1)[1].split()[0] != b"Z":
                            found.append(int(pid))
        except OSError:
            pass
    return found


def grade(paths, zygote, mark):
    """The checker's --json document of paths, with the zygote on or off. As root the children run as root
    (--child-user root): the two ways of starting a child are compared here, not the user switch, whose
    default (nobody) cannot start this machine's Python without the zygote (tests/test_checker_safe_default.py)."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               CHECKER_ZYGOTE="1" if zygote else "0", CHECKER_TEST_MARK=mark)
    as_root = ["--child-user", "root"] if users.is_root() else []
    # one seed for both runs: the probes' drawn inputs (and so a message's last digits) are then the same
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--timeout", "8", "--memory", "512",
                           "--seed", "11", *as_root, *paths], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=900)
    document = json.loads(proc.stdout)
    return proc.returncode, without_seconds(document)


def without_seconds(value):
    """The document without what timing decides: "seconds" fields, the ms of physics Bullets' messages report,
    and which line of an endless loop the CPU limit stopped it at."""
    if isinstance(value, dict):
        return {key: without_seconds(item) for key, item in value.items() if key != "seconds"}
    if isinstance(value, list):
        return [without_seconds(item) for item in value]
    if isinstance(value, str):
        value = re.sub(r"\d+ ms\b", "(timed) ms", value)
        return re.sub(r"\(it was at [^)]*\)", "(it was at: the loop)", value)
    return value


@pytest.mark.skipif(not os.path.isdir("/proc"), reason="looks for stray processes in /proc")
def test_same_verdicts_with_and_without_the_zygote_and_nothing_left_behind():
    mark = uuid.uuid4().hex
    on_status, on = grade(SOLUTIONS + BROKEN, True, mark)
    assert processes_marked(mark) == []  # the zygote and every child it forked are gone
    off_status, off = grade(SOLUTIONS + BROKEN, False, mark)
    assert processes_marked(mark) == []
    assert on_status == off_status == 1
    # every verdict and score the same; every message the same for the solutions (a hostile file's message
    # may name another line of its endless loop, or the other limit, when the machine is loaded)
    differences = [(a["path"], ca["id"], ca["status"], ca["message"], cb["status"], cb["message"])
                   for a, b in zip(on["labs"], off["labs"]) for ca, cb in zip(a["criteria"], b["criteria"])
                   if (ca["status"], ca["score"]) != (cb["status"], cb["score"])
                   or (a["path"].startswith("solutions") and ca != cb)]
    assert differences == []
    assert [(a["path"], a["status"], a["score"]) for a in on["labs"]] == \
        [(b["path"], b["status"], b["score"]) for b in off["labs"]]
    rows = {os.path.basename(lab["path"]): lab for lab in on["labs"]}
    for path in SOLUTIONS:
        lab = rows[os.path.basename(path)]
        assert all(c["status"] == "pass" for c in lab["criteria"]), lab


# ---------------------------------------------------------------- limits, through the zygote

LOOP = "x = 0\nwhile True:\n    x += 1\n"
PRINT_FLOOD = "while True:\n    print('crate ' * 40)\n"
RAW_FLOOD = "import os\nwhile True:\n    os.write(1, b'crate ' * 1000)\n"
PARENT = "import os\nprint('parent', os.getppid())\n"


@pytest.fixture
def lab(tmp_path):
    def write(source):
        path = tmp_path / "lab.py"
        path.write_text(source, encoding="utf-8")
        return str(path)
    return write


@pytest.fixture
def zygote(monkeypatch):
    """The zygote on, started afresh for the test and stopped after it."""
    monkeypatch.setenv("CHECKER_ZYGOTE", "1")
    monkeypatch.setattr(sandbox, "USE_ZYGOTE", True)
    sandbox.stop_zygote()
    client = sandbox._zygote_client()
    assert client is not None, "the zygote did not start"
    yield client
    sandbox.stop_zygote()
    assert client.process.poll() is not None


def probe(path, limits):
    return run_child(path, "probe", {"probes": "checker.labs.tumbling_crates.probes"}, limits)


def test_the_child_is_forked_by_the_zygote(zygote, lab):
    run = probe(lab(PARENT), Limits(timeout=5))
    assert run.status == "done" and run.returncode == 0, run
    assert run.stdout.strip() == f"parent {zygote.process.pid}"


def test_cpu_time_limit_through_the_zygote(zygote, lab):
    path = lab(LOOP)
    run = probe(path, Limits(timeout=1))
    assert run.status == "timeout", run
    assert run.returncode == -signal.SIGKILL  # SIGXCPU dumped the stack, the hard limit a second later killed it
    # the stack shows the loop wherever the CPU limit caught it: its test (line 2) or its body (line 3)
    assert any(f'File "{path}", line {n}' in run.timeout_trace for n in (2, 3)), run.timeout_trace
    assert run.seconds < sandbox.wall_limit(Limits(timeout=1))


def test_print_flood_through_the_zygote(zygote, lab):
    run = probe(lab(PRINT_FLOOD), Limits(timeout=5, max_output=64 * 1024))
    assert run.status == "error", run
    assert run.result["error"]["kind"] == "flood" and run.result["error"]["line"] == 2
    assert len(run.stdout) <= 64 * 1024


def test_raw_flood_is_killed_through_the_zygote(zygote, lab):
    run = probe(lab(RAW_FLOOD), Limits(timeout=5, max_output=64 * 1024))
    assert run.status == "flood", run
    assert run.returncode == -signal.SIGKILL
    assert len(run.stdout) <= 64 * 1024


def test_a_dead_zygote_is_replaced_and_then_subprocess_again(zygote, lab):
    """A zygote that dies (or stops answering on a busy machine) is replaced by a new one, ZYGOTE_RESTARTS
    times in a grading run: the subprocess path cannot run a child user who may not read Python's files.
    After that, children start with subprocess."""
    pids = [zygote.process.pid]
    for _ in range(sandbox.ZYGOTE_RESTARTS):
        sandbox._zygote.process.kill()
        sandbox._zygote.process.wait()
        run = probe(lab(PARENT), Limits(timeout=5))
        assert run.status == "done" and run.returncode == 0, run
        assert sandbox._zygote.process.pid not in pids   # a new zygote forked it
        assert run.stdout.strip() == f"parent {sandbox._zygote.process.pid}"
        pids.append(sandbox._zygote.process.pid)
    sandbox._zygote.process.kill()
    sandbox._zygote.process.wait()
    run = probe(lab(PARENT), Limits(timeout=5))
    assert run.status == "done" and run.returncode == 0, run
    assert run.stdout.strip() == f"parent {os.getpid()}"  # started by subprocess from this process
    assert sandbox._zygote_client() is None
    sandbox.stop_zygote()
    assert sandbox._retired == []


def test_checker_zygote_0_means_subprocess(monkeypatch, lab):
    monkeypatch.setenv("CHECKER_ZYGOTE", "0")
    sandbox.stop_zygote()
    run = probe(lab(PARENT), Limits(timeout=5))
    assert run.stdout.strip() == f"parent {os.getpid()}"
    assert sandbox._zygote is None  # never started


def test_the_zygote_leaves_when_its_grader_does(tmp_path):
    """A grader killed outright (no atexit) still takes its zygote with it: EOF on the zygote's socket."""
    mark = uuid.uuid4().hex
    script = ("import os, signal\nfrom checker.isolation import sandbox\n"
              "assert sandbox._zygote_client() is not None\nos.kill(os.getpid(), signal.SIGKILL)\n")
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               CHECKER_ZYGOTE="1", CHECKER_TEST_MARK=mark)
    done = subprocess.run([sys.executable, "-c", script], env=env, cwd=str(tmp_path), timeout=120)
    assert done.returncode == -signal.SIGKILL   # it got as far as killing itself, its zygote started
    for _ in range(100):
        if not processes_marked(mark):
            break
        time.sleep(0.1)
    assert processes_marked(mark) == []


def test_started_early_the_zygote_serves_the_first_run(zygote_off_at_start, lab):
    """start_zygote() (what `python -m checker` does before importing the labs) only starts the process;
    the first run waits for it to be ready and is forked by it."""
    sandbox.start_zygote()
    client = sandbox._zygote
    assert client and client.ready is None and client.process.poll() is None  # started, not waited for
    run = probe(lab(PARENT), Limits(timeout=5))
    assert client.ready is True
    assert run.stdout.strip() == f"parent {client.process.pid}"
    sandbox.start_zygote()
    assert sandbox._zygote is client  # one zygote per grading process


def test_a_usage_error_leaves_no_zygote_behind(tmp_path):
    """A path that exists makes `python -m checker` start the zygote early; a wrong option then stops the
    run with exit 2, and the zygote goes with it."""
    mark = uuid.uuid4().hex
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               CHECKER_ZYGOTE="1", CHECKER_TEST_MARK=mark)
    proc = subprocess.run([sys.executable, "-m", "checker", "--no-such-option", os.path.join(ROOT, "solutions")],
                          env=env, cwd=str(tmp_path), capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and "--no-such-option" in proc.stderr, proc.stderr
    for _ in range(100):
        if not processes_marked(mark):
            break
        time.sleep(0.1)
    assert processes_marked(mark) == []


@pytest.fixture
def zygote_off_at_start(monkeypatch):
    """The zygote on but not started; stopped after the test."""
    monkeypatch.setenv("CHECKER_ZYGOTE", "1")
    monkeypatch.setattr(sandbox, "USE_ZYGOTE", True)
    sandbox.stop_zygote()
    yield
    sandbox.stop_zygote()
