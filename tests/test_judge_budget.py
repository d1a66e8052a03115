"""The grader's own work on a file (the replay of its tapes, its checks) runs under a budget (checker/judging/budget.py).

Issue 39 item 3: a Bullets step that set BULLET_RADIUS = 1e9 during the last CCD shot made the grader's
replay take about 2e7 World steps per shot, with no limit: `python -m checker` never ended and wrote no
report. The replay now reads the handout's constants (tests/corpus_attacks.py grades that attack: a named
fail), so to exhaust the budget these tests put the grader back as it was for that one file, serving the
probe the child's reading, in-process (`tape.Replayer.__getattr__` patched), or give a probe a parent half
that never ends. What they check is what the budget owes: one error row naming the limit and what the file changed,
the other files graded, `--total-timeout` ending the batch. The real grader differs only by that patch.
"""
import json
import os
import time

import pytest

from checker.judging import budget, probing, tape
from checker import cli
from checker.grade import Grader
from checker.labs import Lab
from checker.isolation.sandbox import Limits

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEP_5 = ("    bullet.pos += bullet.vel * t\n"
          "    world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)\n")
# the attack of issue 39 item 3: the 16th shot at 12000 px/s (the last with CCD) is the only one that reaches the
# wall from x < 370 px in its hitting step; from then on the bullets are 1e9 px wide
SEED = 1   # the CCD shots start at a drawn phase: the attack fires only where the 16th reaches the wall from
# x < 370 px (at seed 1, not at seed 6)
ATTACK = ("    global BULLET_RADIUS\n    if bullet.vel.x > 11999 and bullet.pos.x < 370:\n"
          "        BULLET_RADIUS = 1e9\n")


def _files(tmp_path):
    with open(os.path.join(ROOT, "solutions", "bullets.py"), encoding="utf-8") as handle:
        solution = handle.read()
    assert STEP_5 in solution
    (tmp_path / "attack").mkdir()
    (tmp_path / "honest").mkdir()
    attack = tmp_path / "attack" / "bullets.py"
    attack.write_text(solution.replace(STEP_5, ATTACK + STEP_5, 1), encoding="utf-8")
    honest = tmp_path / "honest" / "bullets.py"
    honest.write_text(solution, encoding="utf-8")
    return str(attack), str(honest)


def _the_old_replay(monkeypatch):
    """The replay of a file named .../attack/bullets.py serves the probe the constants its child's probe read (as the
    grader did before), not the handout's; returns [the path judged last]."""
    real_read, real_judge = tape.Replayer.__getattr__, probing.judge
    current = [""]

    def as_before(replay, name):
        value = real_read(replay, name)
        told = replay.read_constants().get(name)   # noted when the child's reading differs from the handout
        attacked = os.path.basename(os.path.dirname(current[0])) == "attack"
        return tape.decode(told, tape.Seen()) if attacked and told is not None else value

    def judge(lab, path, settings, child):
        current[0] = path
        return real_judge(lab, path, settings, child)

    monkeypatch.setattr(tape.Replayer, "__getattr__", as_before)
    monkeypatch.setattr(probing, "judge", judge)
    return current


def test_a_budget_stops_a_loop_that_catches_every_exception():
    start = time.monotonic()
    with pytest.raises(budget.Exhausted) as caught:
        with budget.Budget(cpu=0.3):
            while True:
                try:
                    sum(range(1000))
                except Exception:  # noqa: BLE001 - the probes' code catches Exception: the budget is no Exception
                    pass
    assert "0.3 s of CPU time" in caught.value.message()
    assert time.monotonic() - start < 5
    with budget.Budget(cpu=5, deadline=time.monotonic() + 5):   # a budget not used up leaves nothing behind
        sum(range(100_000))
    time.sleep(3 * budget.TICK)


def test_the_replay_past_its_budget_is_one_error_row_naming_the_constant(tmp_path, monkeypatch):
    attack, honest = _files(tmp_path)
    current = _the_old_replay(monkeypatch)
    grader = Grader(Limits(timeout=6.0), jobs=2, total_timeout=300, seed=SEED)
    lab = Lab("bullets")
    start = time.monotonic()
    row = grader.grade(attack, lab)
    assert time.monotonic() - start < 60, "the budget (6 s of CPU) did not stop the replay"
    assert current[0] == os.path.abspath(attack)
    assert row.status == "error" and row.score == 0, [(r.id, r.status, r.message) for r in row.results]
    message = row.results[0].message
    assert "budget (6 s of CPU time, replaying the probe of swept_move())" in message, message
    assert "swept_move() set BULLET_RADIUS to 1000000000.0" in message, message
    assert "\n" not in message
    good = grader.grade(honest, lab)   # the next file of the batch: graded as ever
    assert good.passed, [(r.id, r.status, r.message) for r in good.results]


def test_total_timeout_covers_judging(tmp_path, monkeypatch, capsys):
    """A probe whose grader half never ends: `--total-timeout` ends the batch with a report, the file one error row."""
    from checker.labs.bullets import probes
    attack, honest = _files(tmp_path)
    original = probes.PROBES["crate_hit"]

    def endless(module, lab_path):
        data = original[1](module, lab_path)
        while probes.judging(module):   # the grader's half only: the child's run is the real probe
            sum(range(1000))
        return data

    monkeypatch.setitem(probes.PROBES, "crate_hit", (original[0], endless))
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    monkeypatch.setenv("SDL_AUDIODRIVER", "dummy")
    start = time.monotonic()
    status = cli.main([honest, "--json", "--quiet", "--timeout", "60", "--total-timeout", "25"])
    assert time.monotonic() - start < 90, "--total-timeout did not end the batch"
    assert status == 1
    row = json.loads(capsys.readouterr().out)["labs"][0]
    assert row["status"] == "error" and row["score"] == 0
    first = row["criteria"][0]["message"]
    assert "went past its budget (the time it had left, replaying the probe of swept_move())" in first, first


def test_without_a_thread_clock_the_deadline_still_counts(monkeypatch):
    """Windows and macOS have no time.pthread_getcpuclockid: the CPU limit is dropped, the wall clock kept."""
    monkeypatch.setattr(budget, "_cpu_clock", lambda thread: None)
    start = time.monotonic()
    with pytest.raises(budget.Exhausted) as caught:
        with budget.Budget(cpu=0.05, deadline=time.monotonic() + 0.5):
            while True:
                sum(range(1000))
    assert "the time it had left" in caught.value.message()
    assert 0.4 < time.monotonic() - start < 5
