"""Resource faults reach the grader as one clear error row for that file (issue 35, item 8).

What the child sends is untrusted: a result line nested deeper than json reads
(RecursionError, not ValueError), a line of many megabytes, a tape of millions of
calls, NaN or infinity in a scene's record. Each must end as a clear error (or a
failed check) for that file, with the grader's memory and time bounded, and the
batch going on with the next file.
"""
import copy
import json
import math
import os
import subprocess
import sys
import types

import pytest

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

from checker import labs
from checker.judging import probing
from checker.isolation import sandbox   # noqa: E402
from checker.judging.checks import Error, Fail   # noqa: E402
from checker.isolation.sandbox import RunResult   # noqa: E402
from test_probe_tape import ROOT, lab_by_id, recorded  # noqa: E402

DONE = b'{"task": "probe", "phase": "run"}\n'


def test_a_result_line_nested_too_deep_is_the_runs_error():
    nested = b"[" * 200_000 + b"]" * 200_000
    result = sandbox._read_channel(DONE + nested + b"\n")[0]
    assert result["error"]["message"].startswith("a result the checker cannot read (nested deeper than it reads)")
    nested_dict = b'{"a":' * 100_000 + b"1" + b"}" * 100_000
    assert "nested deeper" in sandbox._read_channel(DONE + nested_dict + b"\n")[0]["error"]["message"]


def test_a_huge_result_line_is_refused_before_it_is_parsed():
    huge = b'{"phase": "done", "probe": {"tapes": {"x": {"tape": [' + b'{"k":"clock","t":0},' * 500_000 + \
        b'{"k":"clock","t":0}]}}}}'
    assert len(huge) > sandbox.RESULT_LINE_LIMIT
    result = sandbox._read_channel(DONE + huge + b"\n")[0]
    assert "MB on one line" in result["error"]["message"] and "phase" in result and result["phase"] != "done"


def test_the_ordinary_lines_still_read():
    assert sandbox._read_channel(DONE + b'{"phase": "done"}\n')[0] == {"phase": "done"}
    assert sandbox._read_channel(DONE + b'{"phase": "done"}\n{"cut sh')[0] == {"phase": "done"}   # stopped mid-write
    assert sandbox._read_channel(DONE + b"not json\n")[0] == {"task": "probe", "phase": "run"}


def test_a_record_nested_too_deep_reads_as_none(tmp_path):
    path = tmp_path / "record.json"
    path.write_bytes(b'{"records": ' + b"[" * 200_000 + b"]" * 200_000 + b"}")
    assert sandbox._read_json(str(path), sandbox.RECORD_LIMIT) is None


def test_a_tape_of_millions_of_calls_is_an_error_not_replayed(tmp_path):
    lab = lab_by_id("tumbling_crates")
    path = os.path.join(ROOT, "solutions", "tumbling_crates.py")
    settings, result, _ = recorded(lab, path, 2, tmp_path)
    forged = copy.deepcopy(result)
    call = forged["tapes"]["apply_impulse"]["tape"][0]
    forged["tapes"]["apply_impulse"]["tape"] = [call] * 3_000_000
    judged = probing.judge(lab, path, settings, forged)
    entry = judged["functions"]["apply_impulse"]
    assert not entry["ok"] and "3000000 calls" in entry["error"]["message"]
    assert judged["functions"]["sat"]["ok"]   # the other probes are judged as usual


@pytest.mark.parametrize("constants", [[1, 2], {"RESTING_SPEED": {"v": [1]}}, {"RESTING_SPEED": "[" * 50}])
def test_forged_constants_are_an_error_row_not_a_crash(constants, tmp_path):
    lab = lab_by_id("tumbling_crates")
    path = os.path.join(ROOT, "solutions", "tumbling_crates.py")
    settings, result, _ = recorded(lab, path, 2, tmp_path)
    judged = probing.judge(lab, path, settings, dict(result, constants=constants))
    assert judged["functions"], judged
    for entry in judged["functions"].values():
        assert entry["ok"] or entry["error"]["message"], entry


# ---------------------------------------------------------------- NaN and infinity in a scene's record


def _record(bad=None):
    """Three frames of one falling square; `bad` = (field, value) puts value into frame 2's body."""
    frames = []
    for number in (1, 2, 3):
        y = 100.0 + number
        body = {"static": False, "pos": [100.0, y], "vel": [0.0, 60.0], "angle": 0.0, "omega": 0.0,
                "points": [[80.0, y - 20], [120.0, y - 20], [120.0, y + 20], [80.0, y + 20]]}
        if bad and number == 2:
            field, value = bad
            if field == "points":
                body["points"][1][0] = value
            elif field in ("pos", "vel"):
                body[field][1] = value
            else:
                body[field] = value
        frames.append({"frame": number, "contacts": 0, "touching": [], "bodies": [body]})
    return {"records": frames}


@pytest.mark.parametrize("lab_id", [lab.id for lab in labs.LABS])
@pytest.mark.parametrize("field, value", [("pos", math.nan), ("vel", math.inf), ("angle", -math.inf),
                                          ("omega", math.nan), ("points", math.nan), ("points", math.inf)])
def test_nan_or_infinity_in_a_scene_record_fails_runs_and_never_raises(lab_id, field, value):
    lab = lab_by_id(lab_id)
    record = json.loads(json.dumps(_record((field, value))))   # through JSON, as the grader reads it
    scenes = lab.scenarios()
    sub = types.SimpleNamespace(name=f"{lab_id}.py", source="", options={}, flags=(), function_steps={},
                                scenarios={name: RunResult(status="done", record=record) for name in scenes})
    check = lab.checks.by_id("runs")
    with pytest.raises((Fail, Error)) as raised:
        check.call(sub, *([None] * len(check.depends)))
    assert "infinite or NaN" in str(raised.value.rationale) or "cannot be what the lab runtime wrote" in \
        str(raised.value.rationale), raised.value.rationale


# ---------------------------------------------------------------- the way it is used: one bad file in a batch

FORGER = '''
import os, stat
line = b"[" * 300000 + b"]" * 300000 + b"\\n"
for fd in range(3, 64):
    try:
        if stat.S_ISFIFO(os.fstat(fd).st_mode):
            os.write(fd, line)
    except OSError:
        pass
os.kill(os.getpid(), 9)   # so the checker's own last line never follows
'''


def test_a_forged_nested_result_is_one_error_row_and_the_batch_goes_on(tmp_path):
    with open(os.path.join(ROOT, "solutions", "bullets.py"), encoding="utf-8") as handle:
        solution = handle.read()
    forger = tmp_path / "a" / "bullets.py"
    forger.parent.mkdir()
    forger.write_text(solution.replace("\nimport math\n", "\nimport math\n" + FORGER, 1), encoding="utf-8")
    honest = tmp_path / "b" / "bullets.py"
    honest.parent.mkdir()
    honest.write_text(solution, encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", str(forger), str(honest)],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 1, proc.stderr[-2000:]
    rows = {os.path.basename(os.path.dirname(lab["path"])): lab for lab in json.loads(proc.stdout)["labs"]}
    forged = rows["a"]
    assert forged["status"] == "error" and "internal error" not in proc.stderr
    loads = next(c for c in forged["criteria"] if c["id"] == "loads")
    assert "a result the checker cannot read (nested deeper than it reads)" in loads["message"], loads
    assert rows["b"]["status"] == "pass" and rows["b"]["score"] == rows["b"]["max_score"]
