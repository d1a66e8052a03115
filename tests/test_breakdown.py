"""The pieces of the pause on a student's error (lesson11/breakdown.py, pause_window.py) and the shared words
(lesson11/mistakes.py), in-process: the copy before a frame, the keys of the paused window, the meanings.
tests/test_lab_pause.py runs the labs themselves."""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import pygame  # noqa: E402
import pytest  # noqa: E402

from lesson11 import breakdown, mistakes, pause_window  # noqa: E402
from lesson11.physics2d import Body, World, box_points  # noqa: E402


def pile():
    floor = Body(box_points(400, 40), (200, 380), 0)
    crates = [Body(box_points(40, 30), (150 + 50 * k, 300 - 20 * k), 1.2, angle=0.3 * k) for k in range(3)]
    return World([floor] + crates)


def state(world):
    return ([(tuple(b.pos), tuple(b.vel), b.angle, b.omega) for b in world.bodies],
            world.time, world.accumulator, dict(world.counters), len(world.bodies))


def test_a_snapshot_puts_the_frame_back_bit_for_bit():
    """Restored and run again, a frame gives the same floats as the first time (what the replay relies on)."""
    world = pile()
    for _ in range(40):
        world.advance(1 / 60)
    kept, before = breakdown.Snapshot(world), state(world)
    world.advance(1 / 60)
    after = state(world)
    kept.restore()
    assert state(world) == before
    world.advance(1 / 60)
    assert state(world) == after
    kept.restore()   # a snapshot restores as often as asked
    assert state(world) == before


@pytest.mark.parametrize("message, text, said", [
    ("ZeroDivisionError: float division by zero", "k += ran * ran / a.inv_inertia", mistakes.DIVIDED_BY_INERTIA),
    ("ZeroDivisionError: float division by zero", "push / (b.inv_mass)", mistakes.DIVIDED_BY_MASS),
    ("TypeError: unsupported operand type(s) for -=: 'float' and 'pygame.math.Vector2'",
     "a.omega -= impulse * a.inv_inertia", mistakes.SPIN_VECTOR),
    ("AttributeError: 'NoneType' object has no attribute 'x'", "rel = b.vel - a.vel", mistakes.VEL_NONE),
    ("ZeroDivisionError: float division by zero", "k += ran * ran / a.inertia", mistakes.BY_STATIC_INERTIA),
    ("ZeroDivisionError: float division by zero", "a.vel -= impulse / a.mass", mistakes.BY_STATIC_MASS),
    ("ZeroDivisionError: float division by zero", "t = d / speed", ""),   # not a known one: nothing said
    ("ZeroDivisionError: float division by zero", "t = d / a.inertia_ratio", ""),
    ("ValueError: math domain error", "t = (-b - math.sqrt(disc)) / (2 * a)", mistakes.SQRT_NEGATIVE),
    ("ValueError: math domain error", "math.acos(c)", ""),
    ("TypeError: unsupported operand type(s) for +: 'int' and 'pygame.math.Vector2'", "c = sum(pb) / len(pb)",
     mistakes.SUM_OF_VECTORS),
])
def test_the_meaning_of_a_raised_error(message, text, said):
    assert mistakes.meaning(message, text) == said


def test_the_meaning_of_a_value_left():
    omega = Body(box_points(10, 10), (0, 0), 1)
    omega.omega = pygame.Vector2(1, 2)
    vel = Body(box_points(10, 10), (0, 0), 1)
    vel.vel = None
    nan = Body(box_points(10, 10), (0, 0), 1)
    nan.omega = float("nan")
    assert mistakes.meaning(problem=mistakes.motion_problem([omega])) == mistakes.SPIN_VECTOR
    assert mistakes.meaning(problem=mistakes.motion_problem([vel])) == mistakes.VEL_NONE
    assert mistakes.meaning(problem=mistakes.motion_problem([nan])) == mistakes.NOT_FINITE
    assert mistakes.motion_problem([Body(box_points(10, 10), (0, 0), 1)]) == ""
    assert mistakes.return_problem((pygame.Vector2(1, 0), float("inf"))).startswith("returned")
    assert mistakes.return_problem((pygame.Vector2(1, 0), 2.0)) == mistakes.return_problem(None) == ""


def paused_window(monkeypatch, key):
    """pause() on a finding, with `key` pressed in the window; what happened: "restart", "closed" (exit code)."""
    pygame.init()
    pygame.display.set_mode((400, 300))
    world = pile()
    try:
        1 / world.bodies[0].inv_inertia
    except ZeroDivisionError as error:
        finding = breakdown.from_error(error)
    monkeypatch.setattr(pause_window, "restart", lambda: (_ for _ in ()).throw(RuntimeError("restart")))
    monkeypatch.delenv(pause_window.REPORT_VAR, raising=False)
    pygame.event.clear()
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=key, mod=0, unicode=""))
    try:
        pause_window.pause(world, finding, 7)
    except RuntimeError as done:
        return str(done)
    except SystemExit as done:
        return f"closed {done.code}"
    finally:
        pygame.quit()


def test_r_restarts_and_escape_closes(monkeypatch):
    assert paused_window(monkeypatch, pygame.K_r) == "restart"
    assert paused_window(monkeypatch, pygame.K_ESCAPE) == "closed 1"


def test_restart_runs_the_same_command_again(monkeypatch):
    """R: the same Python, the same arguments (`python starters/x.py`, or `python -m ...`), so a fix is in."""
    ran = []
    monkeypatch.setattr(os, "execv", lambda program, argv: ran.append((program, argv)))
    monkeypatch.setattr("sys.orig_argv", ["python3", "starters/tumbling_crates_starter.py"])
    pause_window.restart()
    import sys
    assert ran == [(sys.executable, [sys.executable, "starters/tumbling_crates_starter.py"])]


def test_the_terminal_without_a_window(tmp_path, capsys, monkeypatch):
    """An error before the window opens (no display): the student's lines are printed, no engine frame, no pause."""
    lab = tmp_path / "lab.py"
    lab.write_text("def resolve(body):\n    return 1 / body.inv_inertia\n", encoding="utf-8")
    namespace = {"__name__": "lab"}
    exec(compile(lab.read_text(), str(lab), "exec"), namespace)
    monkeypatch.setattr(breakdown, "lab_file", lambda: str(lab))
    try:
        namespace["resolve"](pile().bodies[0])
    except ZeroDivisionError as error:
        finding = breakdown.from_error(error)
    breakdown.print_report(finding)
    printed = capsys.readouterr().err
    assert 'lab.py", line 2, in resolve' in printed and "return 1 / body.inv_inertia" in printed
    assert mistakes.DIVIDED_BY_INERTIA in printed and "test_breakdown.py" not in printed


LAB = """
import pygame
from lesson11 import runtime as lab
from lesson11.panel import LabPanel
from lesson11.physics2d import Body, World, box_points


def resolve(a, b, normal, point):
    return 1 / a.inv_inertia


pygame.init()
pygame.display.set_mode((400, 300))
floor = Body(box_points(400, 40), (200, 280), 0)
world = World([floor, Body(box_points(40, 40), (200, 230), 1.0)], resolve=resolve)
panel = LabPanel()
panel.mode = "{mode}"
while lab.frame_budget():
    panel.advance(world, 1 / 60)
"""


@pytest.mark.parametrize("mode", ["compact", "full"])
def test_the_full_panels_timers_do_not_hide_the_phase(tmp_path, mode):
    """In the full view the panel wraps the lab's hooks in timers (hook_clock): the pause still names the World's
    resolve pass as the caller, and no timer frame is printed."""
    import json
    import subprocess
    import sys
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    (tmp_path / "lab.py").write_text(LAB.format(mode=mode), encoding="utf-8")
    report = tmp_path / "pause.json"
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYTHONPATH=root,
               LESSON11_PAUSE_REPORT=str(report))
    env.pop("LESSON11_LAB_SETTINGS", None)
    done = subprocess.run([sys.executable, "lab.py"], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=120)
    shown = json.loads(report.read_text(encoding="utf-8"))
    assert (shown["function"], shown["line"]) == ("resolve", 9)
    assert shown["phase"].startswith("called by the World's resolve pass, contact 1 of ")
    assert "hook_clock" not in done.stderr and "timed" not in done.stderr
