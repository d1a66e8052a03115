"""The checker's portable child path (issue 32): Windows, macOS, and CHECKER_PORTABLE=1 on Linux.

Where fork, preexec_fn, pass_fds or process groups are missing (Windows), the checker starts
its child with plain subprocess, reads the result from the child's own stdout, reads its pipes
with threads, kills the whole tree from the parent at the wall-clock limit, and lets the child
apply its own limits (checker/isolation/sandbox.py `_run_portable`, checker/isolation/child.py `Watchdog`).
CHECKER_PORTABLE=1 makes Linux take that path, so it runs here on every test run:

  - every lab's solution and starter (every lab in checker/labs/, tests/labs_found.py) get the same
    verdict per check as on the POSIX path;
  - every entry of every lab's mistake corpus and of the attack corpus gets its asserted verdict (one
    checker run over all of them, judged by tests/corpus_verdicts.py's rules and the attack corpus's own test);
  - an endless loop, a 2 GB allocation, a crash and output floods get their clear 0, as on POSIX.

Then the two systems this machine can only emulate, each in a fresh interpreter whose
sitecustomize removes what the system lacks before the checker is imported; the grader
starts its children (and the zygote) through a wrapper named as sys.executable that puts the
same sitecustomize first on their path, so the children run without it too:

  Windows: no os.fork/killpg/setsid/setpgid/getuid/setuid, no signal.SIGKILL/SIGXCPU/SIGPROF/
      setitimer, no socket.AF_UNIX, no `resource` or `pwd`; Popen raises ValueError for preexec_fn
      and asserts on pass_fds (as CPython's Windows Popen does); selectors refuse pipes. What real
      Windows does differently: sys.platform is "win32" there, so the child gets
      CREATE_NEW_PROCESS_GROUP and a Job Object (KILL_ON_JOB_CLOSE, a per-process memory limit)
      made with ctypes, or `taskkill /T /F` if the Job Object is refused; none of that can run
      here (untested). Here the emulated child is in its own POSIX session (subprocess's own
      start_new_session), and without os.killpg and SIGKILL the parent ends it with SIGTERM, so a
      grandchild the lab starts is not killed as the Job Object would kill it. Windows has no
      fork, so there is never a zygote; the emulation has none either (portable() sees no fork).
  macOS: setrlimit(RLIMIT_AS, ...) raises ValueError ("current limit exceeds maximum limit"), and
      Unix sockets refuse SOCK_SEQPACKET (the constant kept, socketpair refusing it; a missing
      constant is checked in-process). Real macOS forks and has process groups, so it takes the
      POSIX subprocess path (no zygote), as emulated; it does not enforce RLIMIT_AS at all. A student
      runs the checker under their own account there, so the emulated grader is told it is not root
      (os.geteuid) and switches no user, as on a Mac; this machine's test really runs as root.
      A second run keeps SOCK_SEQPACKET, so the zygote's children meet the same refusal.
"""
import json
import os
import subprocess
import sys
import textwrap

import pytest

pytestmark = pytest.mark.skipif(sys.platform != "linux", reason="emulates Windows and macOS on Linux; on those "
                                "systems the rest of the suite runs the checker's real portable or POSIX path")

import corpus_attacks
import corpus_verdicts
import labs_found
import mutants
import test_corpus_attacks as attacks_verdicts
from checker.isolation import confine, sandbox

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTIONS = [lab.solution for lab in labs_found.LABS]
STARTERS = [lab.starter for lab in labs_found.LABS]
SEED = "7"   # the same probe inputs on every path, so the verdicts can be compared check by check
HOSTILE_LAB = labs_found.by_id("tumbling_crates")   # the hostile files below are written against its step 2

# the mistake corpus of every lab that has one (a lab without one fails tests/test_corpus_labs.py)
CORPORA = {lab.id: labs_found.corpus(lab) for lab in labs_found.with_corpus()}


def run_checker(*args, env_extra=(), python=sys.executable, timeout=3600):
    """`python -m checker ARGS` from the repository root; returns (exit status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    env.pop("CHECKER_PORTABLE", None)
    env.update(env_extra)
    proc = subprocess.run([python, "-m", "checker", *args], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=timeout)
    return proc.returncode, proc.stdout, proc.stderr


def graded_json(*args, **kwargs):
    """{absolute path: the lab's JSON row} from one `--json` run; the run must end with status 0 or 1."""
    status, out, err = run_checker("--json", "--quiet", *args, **kwargs)
    assert status in (0, 1), f"the checker exited {status}: {err[-3000:]}"
    return {os.path.abspath(os.path.join(ROOT, row["path"])): row for row in json.loads(out)["labs"]}


def verdicts(row):
    """{check id: (status, step, hint)} of one graded file."""
    return {c["id"]: (c["status"], c["step"], c["hint"]) for c in row["criteria"]}


# ---------------------------------------------------------------- the emulations

WINDOWS = """
import os, selectors, signal, socket, stat, subprocess, sys
for name in ("fork", "forkpty", "killpg", "setsid", "setpgid", "getuid", "geteuid", "setuid", "setgid", "setgroups"):
    if hasattr(os, name):
        delattr(os, name)
for name in ("SIGKILL", "SIGXCPU", "SIGPROF", "setitimer", "ITIMER_PROF"):
    delattr(signal, name)
del socket.AF_UNIX
sys.modules["resource"] = None
sys.modules["pwd"] = None

class Popen(subprocess.Popen):
    def __init__(self, args, *rest, preexec_fn=None, pass_fds=(), **kwargs):
        log(args)
        if preexec_fn is not None:   # CPython's Windows Popen, word for word
            raise ValueError("preexec_fn is not supported on Windows platforms")
        assert not pass_fds, "pass_fds not supported on Windows."
        super().__init__(args, *rest, **kwargs)

class PipeRefusingSelector(selectors.DefaultSelector):
    def register(self, fileobj, events, data=None):
        fd = fileobj if isinstance(fileobj, int) else fileobj.fileno()
        if not stat.S_ISSOCK(os.fstat(fd).st_mode):
            raise OSError(10038, "An operation was attempted on something that is not a socket")
        return super().register(fileobj, events, data)

subprocess.Popen = Popen
selectors.DefaultSelector = PipeRefusingSelector
"""

MACOS_RLIMIT = """
import resource, subprocess, sys
_setrlimit = resource.setrlimit

def setrlimit(kind, limits):
    if kind == resource.RLIMIT_AS:
        raise ValueError("current limit exceeds maximum limit")
    return _setrlimit(kind, limits)

resource.setrlimit = setrlimit

class Popen(subprocess.Popen):
    def __init__(self, args, *rest, **kwargs):
        log(args, "preexec" if kwargs.get("preexec_fn") else "")
        super().__init__(args, *rest, **kwargs)

subprocess.Popen = Popen
"""

MACOS_SOCKETS = """
import errno, socket
_socketpair = socket.socketpair

def socketpair(family=socket.AF_UNIX, type=socket.SOCK_STREAM, proto=0):
    if type == socket.SOCK_SEQPACKET:
        raise OSError(errno.EPROTONOSUPPORT, "Protocol not supported")
    return _socketpair(family, type, proto)

socket.socketpair = socketpair
"""

# A student's Mac: the checker runs under the student's own account, never as root, so there is no user to
# switch to (checker/isolation/users.py). This machine's tests run as root: the grader is told it is not.
MACOS_STUDENT = """
import os
os.geteuid = lambda: 501
"""


def emulation(directory, *parts):
    """A python wrapper that runs with `parts` as its sitecustomize (and makes its children do the same).

    Every Popen the emulated grader makes is logged in directory/popen.log, one line per child:
    the module it runs and whether it was given a preexec_fn."""
    directory.mkdir()
    wrapper, log = directory / "python", directory / "popen.log"
    head = textwrap.dedent(f"""
        import sys
        sys.executable = {str(wrapper)!r}

        def log(args, how=""):
            module = args[args.index("-m") + 1] if isinstance(args, list) and "-m" in args else str(args)[:80]
            with open({str(log)!r}, "a", encoding="utf-8") as handle:
                handle.write(f"{{module}} {{how}}\\n")
        """)
    (directory / "sitecustomize.py").write_text(head + "".join(textwrap.dedent(part) for part in parts))
    path = f'PYTHONPATH="{directory}${{PYTHONPATH:+:$PYTHONPATH}}"'
    wrapper.write_text(f'#!/bin/sh\n{path} exec "{sys.executable}" "$@"\n')
    wrapper.chmod(0o755)
    return str(wrapper), log


def popens(log):
    """The logged Popen lines: [(module, how)]."""
    lines = log.read_text(encoding="utf-8").splitlines() if log.exists() else []
    return [tuple((line.split(" ", 1) + [""])[:2]) for line in lines]


# ---------------------------------------------------------------- solutions and starters on every path

@pytest.fixture(scope="module")
def linux():
    """The solutions and starters on the POSIX path (the zygote), the reference for every other path."""
    return graded_json("--seed", SEED, *SOLUTIONS, *STARTERS)


@pytest.fixture(scope="module")
def paths(tmp_path_factory):
    """{path name: ({file: JSON row}, [(module, how) per Popen] or None)} for the portable and emulated paths."""
    base = tmp_path_factory.mktemp("emulations")
    runs = {"portable": ({"CHECKER_PORTABLE": "1"}, None)}
    runs["windows"] = ({}, emulation(base / "windows", WINDOWS))
    runs["macos"] = ({}, emulation(base / "macos", MACOS_RLIMIT, MACOS_SOCKETS, MACOS_STUDENT))
    runs["rlimit_refused_zygote"] = ({}, emulation(base / "zygote", MACOS_RLIMIT))
    out = {}
    for name, (env, emulated) in runs.items():
        python, log = emulated or (sys.executable, None)
        out[name] = (graded_json("--seed", SEED, *SOLUTIONS, *STARTERS, env_extra=env, python=python),
                     popens(log) if log else None)
    return out


@pytest.mark.parametrize("path", ["portable", "windows", "macos", "rlimit_refused_zygote"])
def test_every_solution_passes_and_every_starter_gets_the_linux_verdicts(linux, paths, path):
    rows, _ = paths[path]
    assert set(rows) == set(linux) == set(SOLUTIONS + STARTERS)
    for solution in SOLUTIONS:
        failing = {cid: v for cid, v in verdicts(rows[solution]).items() if v[0] != "pass"}
        assert not failing and rows[solution]["score"] == rows[solution]["max_score"], (path, solution, failing)
    for file in SOLUTIONS + STARTERS:
        assert verdicts(rows[file]) == verdicts(linux[file]), (path, file)
        assert rows[file]["score"] == linux[file]["score"]


def test_the_emulated_windows_grader_never_asks_for_posix_only_parts(paths):
    rows, started = paths["windows"]
    assert started and {module for module, _ in started} == {"checker.isolation.child"}   # no zygote, children only
    for row in rows.values():   # the limits it cannot set are noted in the run's record
        assert any("no resource module" in note for note in row["notes"]), row["notes"]


@pytest.mark.parametrize("path", ["macos", "rlimit_refused_zygote"])
def test_a_refused_memory_limit_is_a_note_in_the_record_never_a_message(paths, path):
    rows, started = paths[path]
    modules = {module for module, _ in started}
    if path == "macos":   # no SOCK_SEQPACKET: the zygote cannot start, children start with subprocess
        assert ("checker.isolation.child", "preexec") in started and "checker.isolation.zygote" not in modules
    else:
        assert modules == {"checker.isolation.zygote"}, modules   # the zygote forks every child
    for row in rows.values():
        assert any(note.startswith("RLIMIT_AS (memory 768 MB) refused by this system (ValueError: current limit "
                                   "exceeds maximum limit)") for note in row["notes"]), row["notes"]
        for check in row["criteria"]:
            text = check["message"] + check["hint"]
            assert "RLIMIT" not in text and "limit exceeds" not in text, check


def test_the_posix_path_notes_nothing_where_every_limit_is_accepted(linux):
    assert all(row["notes"] == [] for row in linux.values())


def test_without_sock_seqpacket_there_is_no_zygote(monkeypatch):
    monkeypatch.delenv("CHECKER_PORTABLE", raising=False)
    monkeypatch.delenv("CHECKER_ZYGOTE", raising=False)
    assert sandbox.zygote_enabled()
    monkeypatch.delattr(sandbox.socket, "SOCK_SEQPACKET")
    assert not sandbox.zygote_enabled()


def test_checker_portable_selects_the_portable_path_and_no_zygote(monkeypatch):
    monkeypatch.delenv("CHECKER_ZYGOTE", raising=False)
    monkeypatch.setenv("CHECKER_PORTABLE", "1")
    assert sandbox.portable() and not sandbox.zygote_enabled()
    monkeypatch.setenv("CHECKER_PORTABLE", "0")
    assert not sandbox.portable()
    monkeypatch.delattr(sandbox.os, "fork")
    assert sandbox.portable() and not sandbox.zygote_enabled()


def test_refused_limits_are_skipped_with_a_note_each(monkeypatch):
    import resource
    applied = []

    def setrlimit(kind, value):
        if kind in (resource.RLIMIT_AS, resource.RLIMIT_CORE):
            raise ValueError("current limit exceeds maximum limit")
        applied.append(kind)

    monkeypatch.setattr(resource, "setrlimit", setrlimit)
    notes = confine.set_rlimits(confine.Limits(timeout=2.5, memory_mb=300))
    assert applied == [resource.RLIMIT_CPU, resource.RLIMIT_FSIZE] + (
        [resource.RLIMIT_MSGQUEUE] if hasattr(resource, "RLIMIT_MSGQUEUE") else [])
    assert [note.split(" (")[0] for note in notes] == ["RLIMIT_AS", "RLIMIT_CORE"]
    assert "memory 300 MB" in notes[0] and notes[0].endswith("not applied")
    applied.clear()
    assert confine.set_rlimits(confine.Limits(), cpu=False)[0].startswith("RLIMIT_AS")
    assert resource.RLIMIT_CPU not in applied


def test_the_result_channel_keeps_the_last_result_and_every_note():
    data = (b'{"limits_skipped": ["RLIMIT_AS refused"]}\n{"phase": "import"}\nnot json\n{"phase": "done"}\n'
            b'{"phase": "cut off')
    assert sandbox._read_channel(data) == ({"phase": "done"}, ["RLIMIT_AS refused"])
    assert sandbox._read_channel(b"") == ({}, [])


# ---------------------------------------------------------------- what the child does, on both paths

HOSTILE = {   # name: (source, words the loads check's message must hold)
    "loop": ('x = 0\nwhile True:\n    x += 1\n', "did not finish importing within 6 s of CPU time"),
    "two_gigabytes": ("hoard = bytearray(2 * 1024 ** 3)\n",
                      "ran out of memory (limit 512 MB).\nat two_gigabytes.py, line 2"),
    "crash": ("import ctypes\nctypes.string_at(0)\n", "ended the process unexpectedly"),
    "print_flood": ("while True:\n    print('x' * 1000)\n", "printed more than 64 KB of output and was stopped; it was "
                                                          "printing at print_flood.py, line 3"),
    "raw_flood": ("import os\nwhile True:\n    os.write(1, b'x' * 65536)\n",
                  "printed more than 64 KB of output and was stopped."),
    "sleeps": ("import time\ntime.sleep(60)\n", "did not finish importing within 6 s of CPU time"),
}
MARKER = "    # --- step 2: the SAT loop ---\n"
LOOPING_SAT = (MARKER, MARKER + "    while pa:\n        pa = pa\n")   # sat() never returns


@pytest.fixture(scope="module")
def hostile(tmp_path_factory):
    """The hostile files graded on the POSIX path and on the portable path: {path name: {file name: row}}."""
    folder = tmp_path_factory.mktemp("hostile")
    files = []
    for name, (source, _) in HOSTILE.items():
        files.append(folder / f"{name}.py")
        files[-1].write_text(f'"""Tumbling Crates (a hostile file: {name})."""\n' + source)
    looping = folder / "looping_sat.py"
    with open(HOSTILE_LAB.solution, encoding="utf-8") as handle:
        looping.write_text(mutants.apply_edits(handle.read(), [LOOPING_SAT], "looping_sat"))
    out = {}
    for path, env in (("posix", {}), ("portable", {"CHECKER_PORTABLE": "1"})):
        rows = graded_json("--timeout", "6", "--memory", "512", "--max-output", "64", *map(str, files), env_extra=env)
        # each probe that calls sat() waits out its 3 s: the run needs more than 6 s of CPU in all
        rows.update(graded_json(str(looping), env_extra=env))
        out[path] = {os.path.basename(file): row for file, row in rows.items()}
    return out


@pytest.mark.parametrize("path", ["posix", "portable"])
@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_a_hostile_file_gets_its_clear_zero(hostile, path, name):
    row = hostile[path][f"{name}.py"]
    loads = row["criteria"][0]
    assert row["score"] == 0 and loads["id"] == "loads" and loads["status"] == "error", loads
    assert HOSTILE[name][1] in loads["message"], loads["message"]
    assert all(c["status"] == "skip" for c in row["criteria"][1:])


@pytest.mark.parametrize("path", ["posix", "portable"])
def test_an_endless_loop_in_a_function_is_stopped_at_its_line(hostile, path):
    checks = {c["id"]: c for c in hostile[path]["looping_sat.py"]["criteria"]}
    assert checks["sat_axes"]["status"] in ("fail", "error")
    lines = open(HOSTILE_LAB.solution, encoding="utf-8").read().splitlines()
    loop = lines.index(LOOPING_SAT[0].rstrip("\n")) + 2   # the line after the step's marker
    message = checks["sat_axes"]["message"]
    assert "sat() was still running after 3 s of CPU time (it was at looping_sat.py, line " in message, message
    assert f"line {loop}:" in message or f"line {loop + 1}:" in message, message
    assert checks["resolve_k"]["status"] == "pass"   # the other functions are probed on


# ---------------------------------------------------------------- every corpus through the portable path

def _corpus_entries():
    return [pytest.param(lab, entry, id=f"{lab}-{entry.name}") for lab, corpus in CORPORA.items()
            for entry in corpus.ENTRIES]


def _attack_entries():
    """The attack corpus's entries graded as root (its open holes, if any, stay strict xfails here too)."""
    return [pytest.param(entry, id=f"attacks-{entry.name}",
                         marks=[pytest.mark.xfail(strict=True, reason=attacks_verdicts.OPEN[entry.name])]
                         if entry.name in attacks_verdicts.OPEN else [])
            for entry in corpus_attacks.ENTRIES if "root" in entry.modes]


@pytest.fixture(scope="module")
def corpora(tmp_path_factory):
    """{lab or "attacks": {entry name: its JSON row}}: every corpus file graded in ONE portable checker run."""
    folder = tmp_path_factory.mktemp("corpora")
    for lab in CORPORA:
        (folder / lab).mkdir()
    written = {(lab, name): path for lab, corpus in CORPORA.items()
               for name, path in corpus.write_corpus(folder / lab).items()}
    # generous limits, as the corpus tests give: no entry loops, and a busy machine must not fail a scene
    rows = graded_json("--jobs", "2", "--timeout", "120", "--total-timeout", "7000", *map(str, written.values()),
                       env_extra={"CHECKER_PORTABLE": "1"}, timeout=7500)
    by_path = {os.path.abspath(str(path)): key for key, path in written.items()}
    out = {}
    for path, row in rows.items():
        lab, name = by_path[path]
        out.setdefault(lab, {})[name] = row
    assert sum(map(len, out.values())) == len(written)
    return out


@pytest.mark.parametrize("lab, entry", _corpus_entries())
def test_each_corpus_entry_gets_its_verdict_on_the_portable_path(corpora, lab, entry):
    """Every corpus's verdict rules (tests/corpus_verdicts.py, as tests/test_corpus_labs.py), on the portable path's
    grades."""
    row = corpora[lab][entry.name]
    corpus_verdicts.assert_verdict(entry, {c["id"]: c for c in row["criteria"]}, CORPORA[lab])


@pytest.fixture(scope="module")
def attacks_portable(tmp_path_factory):
    """The attack corpus (and each attack's honest file) graded as root in one portable checker run."""
    return attacks_verdicts._grade(tmp_path_factory.mktemp("attacks-portable"), "root", {"CHECKER_PORTABLE": "1"})


@pytest.mark.parametrize("entry", _attack_entries())
def test_each_attack_gets_its_verdict_on_the_portable_path(attacks_portable, entry):
    """The attack corpus's own verdict test (as root, no option), on the portable path's grades."""
    attacks_verdicts.test_each_entry_gets_its_verdict("root", entry, lambda mode: attacks_portable)
