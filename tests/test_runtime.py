"""The lab runtime: pass-through for a student's run, fixed and scripted under the checker.

In-process tests call lesson11.runtime directly (reset() between them); the
last tests run the solution under the runtime in a child process.
"""
import json
import math
import os
import subprocess
import sys

import pygame
import pytest

from lab_run import ROOT, SOLUTION, run_lab
from lesson11 import runtime
from lesson11.physics2d import Body, Circle, World, box_points


@pytest.fixture(autouse=True)
def fresh_runtime():
    runtime.reset()
    pygame.display.init()
    pygame.event.clear()
    yield
    runtime.reset()
    pygame.display.quit()


class FakeClock:
    """Stands in for pygame.time.Clock: remembers the fps it was asked for, returns 17 ms."""

    def __init__(self):
        self.calls = []

    def tick(self, fps):
        self.calls.append(fps)
        return 17


def statics_and_crate():
    floor = Body(box_points(900, 40), (450, 580), 0)
    crate = Body(box_points(60, 40), (300, 100), 2.4)
    return [floor, crate]


# ---------------------------------------------------------------- a student's run: every hook passes through

def test_student_run_passes_everything_through():
    assert not runtime.active()
    assert runtime.seed(11) == 11
    assert all(runtime.frame_budget() for _ in range(10000))
    clock = FakeClock()
    assert runtime.tick(clock, 60) == 17 and clock.calls == [60]
    bodies = statics_and_crate()
    assert runtime.scene(bodies) is bodies
    runtime.record(bodies, [])
    assert runtime._records == []


def test_student_run_gets_the_real_events_quit_included():
    pygame.event.post(pygame.event.Event(pygame.QUIT))
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_d, mod=0, unicode="d"))
    types = [event.type for event in runtime.events()]
    assert types == [pygame.QUIT, pygame.KEYDOWN]


# ---------------------------------------------------------------- checker mode

def test_checker_frame_budget_counts_frames():
    runtime.configure({"frames": 5})
    assert runtime.active()
    assert [runtime.frame_budget() for _ in range(7)] == [True] * 5 + [False, False]


def test_checker_tick_is_fixed_and_never_waits():
    runtime.configure({"frames": 5, "fps": 50})
    clock = FakeClock()
    assert runtime.tick(clock, 60) == 20.0
    assert clock.calls == []
    runtime.configure({"frames": 5})
    assert runtime.tick(clock, 60) == pytest.approx(1000 / 60)


def test_checker_seed_replaces_the_lab_seed():
    runtime.configure({"seed": 3})
    assert runtime.seed(11) == 3
    runtime.configure({})
    assert runtime.seed(11) == 11


def test_checker_scripted_events_arrive_on_their_frames_and_real_quit_is_dropped():
    runtime.configure({"frames": 4, "script": [
        {"frame": 2, "type": "click", "pos": [120, 80]},
        {"frame": 2, "type": "key", "key": "r"},
        {"frame": 3, "type": "quit"}]})
    seen = {}
    while runtime.frame_budget():
        pygame.event.post(pygame.event.Event(pygame.QUIT))  # a real close is ignored under the checker
        seen[runtime._frame] = runtime.events()
    assert seen[1] == [] and seen[4] == []
    click, key = seen[2]
    assert click.type == pygame.MOUSEBUTTONDOWN and click.pos == (120, 80) and click.button == 1
    assert key.type == pygame.KEYDOWN and key.key == pygame.K_r
    assert [event.type for event in seen[3]] == [pygame.QUIT]


def test_checker_scenario_keeps_statics_and_replaces_crates():
    runtime.configure({"scenario": [{"w": 50, "h": 30, "pos": [400, 200], "angle": 0.5, "vel": [10, 0]}]})
    bodies = runtime.scene(statics_and_crate())
    assert len(bodies) == 2 and bodies[0].inv_mass == 0
    crate = bodies[1]
    assert crate.mass == pytest.approx(50 * 30 / 1000)
    assert (crate.pos.x, crate.pos.y, crate.angle, crate.vel.x) == (400, 200, 0.5, 10)


def test_checker_scenario_uses_the_labs_own_builder():
    runtime.configure({"scenario": [{"pos": [300, 100], "r": 12}]})
    made = []

    def ball(item):
        made.append(item)
        return Body(Circle(item["r"]), item["pos"], mass=1.0)
    bodies = runtime.scene(statics_and_crate(), build=ball)
    assert len(bodies) == 2 and made == [{"pos": [300, 100], "r": 12}]
    assert bodies[1].shape.kind == "circle" and bodies[1].pos.x == 300


def test_scenario_crate_without_its_size_is_one_line():
    runtime.configure({"scenario": [{"w": 10, "pos": [0, 0]}]})
    with pytest.raises(ValueError) as info:
        runtime.scene(statics_and_crate())
    assert "a crate needs" in str(info.value) and "\n" not in str(info.value)


def test_checker_record_file_has_the_expected_keys(tmp_path):
    path = tmp_path / "record.json"
    runtime.configure({"frames": 7, "record": str(path), "record_every": 3})
    world = World(statics_and_crate())
    world.bodies[1].pos.y = 555  # resting on the floor: it has contacts
    while runtime.frame_budget():
        world.advance(1 / 60)
        runtime.record(world.bodies, world.contacts)
    runtime.write_record()
    data = json.loads(path.read_text())
    assert data["frames_run"] == 7
    assert [r["frame"] for r in data["records"]] == [1, 4, 7]  # every 3rd, and the last one always
    frame = data["records"][-1]
    assert set(frame) == {"frame", "contacts", "touching", "bodies"}
    assert frame["contacts"] == len(frame["touching"]) == 2
    assert set(frame["touching"][0]) == {"a", "b", "point", "normal", "depth"}
    assert (frame["touching"][0]["a"], frame["touching"][0]["b"]) == (0, 1)
    body = frame["bodies"][1]
    assert set(body) == {"static", "asleep", "pos", "vel", "angle", "omega", "points", "color"}
    assert body["color"] == list(world.bodies[1].color)   # the lab's own colour, for --show and --pictures
    assert body["static"] is False and len(body["points"]) == 4
    assert frame["bodies"][0]["static"] is True


def test_the_panel_notes_the_worlds_settings_only_while_recording(tmp_path):
    """panel.advance() tells the runtime the World's settings, read after the step (a change the lab makes shows);
    they go into the first recorded frame and into every recorded frame where they changed. A student's run (no
    checker) notes and records nothing."""
    from lesson11.panel import LabPanel
    world = World(statics_and_crate())
    LabPanel().advance(world, 1 / 60)
    assert not runtime.recording() and runtime._world is None
    path = tmp_path / "record.json"
    runtime.configure({"frames": 4, "record": str(path)})
    panel = LabPanel()
    while runtime.frame_budget():
        if runtime._frame == 3:
            world.iterations = 2   # as a lab's own code might
        panel.advance(world, 1 / 60)
        runtime.record(world.bodies, world.contacts)
    runtime.write_record()
    frames = json.loads(path.read_text())["records"]
    assert [("world" in f) for f in frames] == [True, False, True, False]
    assert frames[0]["world"] == {"solver": "lesson", "iterations": 6, "substeps": 4, "warm_starting": True,
                                  "correction": True, "contact_rule": "corners", "order": "solve-first",
                                  "effects": sorted(world.effects), "step_seconds": world.step_seconds}
    assert frames[2]["world"]["iterations"] == 2


def test_noted_settings_are_plain_data():
    """Whatever the lab's World holds, note_world keeps JSON data (a value that cannot be written as one is its
    repr, cut; one whose repr fails leaves {}), so writing the record never fails because of it."""
    class Odd:
        def __repr__(self):
            return "odd" * 100

    class Broken:
        def __repr__(self):
            raise RuntimeError("no")

    runtime.configure({"record": "unused.json"})
    runtime.note_world({"iterations": Odd(), "effects": frozenset({"gravity", Odd()}), "solver": "s" * 500})
    assert runtime._world["iterations"] == ("odd" * 100)[:runtime.WORLD_TEXT]
    assert len(runtime._world["solver"]) == runtime.WORLD_TEXT and "gravity" in runtime._world["effects"]
    json.dumps(runtime._world)
    runtime.note_world({"iterations": Broken()})
    assert runtime._world == {}


@pytest.mark.parametrize("settings, words", [
    ({"frams": 10}, "unknown setting 'frams'"),
    ({"frames": "10"}, "setting 'frames' has the wrong type"),
    ({"fps": 0}, "'fps' must be > 0"),
    ({"script": [{"frame": 1, "type": "jump"}]}, "bad script item"),
    ({"scenario": [{"w": 10, "h": 10}]}, "bad scenario body"),
    ([1, 2], "expected a JSON object"),
])
def test_bad_settings_are_named_in_one_line(settings, words):
    with pytest.raises(ValueError) as info:
        runtime.configure(settings, "my.json")
    message = str(info.value)
    assert message.startswith("my.json: ") and words in message and "\n" not in message


@pytest.mark.parametrize("content, words", [
    (None, "cannot read the settings file"),
    ("{not json", "not valid JSON"),
    ('{"frames": -1}', "'frames' must be >= 0"),
])
def test_bad_settings_file_stops_the_lab_with_one_line(tmp_path, content, words):
    path = tmp_path / "settings.json"
    if content is not None:
        path.write_text(content)
    env = dict(os.environ, LESSON11_LAB_SETTINGS=str(path), SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               PYGAME_HIDE_SUPPORT_PROMPT="1", PYTHONPATH=ROOT)
    proc = subprocess.run([sys.executable, SOLUTION], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=60)
    assert proc.returncode == 1
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"LESSON11_LAB_SETTINGS={path}: ") and words in lines[0]


# ---------------------------------------------------------------- the solution under the runtime

def test_solution_runs_600_frames_as_10_simulated_seconds(tmp_path):
    """600 frames at a fixed 1/60 s are 10 simulated s (1200 physics steps), recorded frame by frame."""
    run = run_lab(SOLUTION, {"frames": 600, "fps": 60, "seed": 11, "screenshot": str(tmp_path / "last.png")},
                  tmp_path)
    assert run.line is not None, run.stdout
    assert run.line[:2] == (10.0, 4)
    assert run.record["frames_run"] == 600
    assert [r["frame"] for r in run.frames] == list(range(1, 601))
    assert all(math.isfinite(v) for r in run.frames for b in r["bodies"] for v in b["pos"] + b["vel"])
    shot = pygame.image.load(str(tmp_path / "last.png"))
    assert shot.get_size() == (900, 600)


def test_solution_with_the_same_seed_runs_the_same(tmp_path):
    settings = {"frames": 120, "seed": 5, "record_every": 119}
    runs = []
    for name, seed in (("a", 5), ("b", 5), ("c", 6)):
        (tmp_path / name).mkdir()
        runs.append(run_lab(SOLUTION, dict(settings, seed=seed), tmp_path / name))
    first, second, other = runs
    assert first.frames[-1]["bodies"] == second.frames[-1]["bodies"]
    assert other.frames[0]["bodies"] != first.frames[0]["bodies"]


def test_a_lab_window_prints_no_sound_errors_on_a_machine_without_sound(tmp_path):
    """The labs play no sound: with SDL_AUDIODRIVER unset, pygame.init() in a lab must not try the sound card
    (on this machine, which has none, SDL's ALSA backend printed 9 'ALSA lib ...' lines)."""
    settings = tmp_path / "settings.json"
    settings.write_text(json.dumps({"frames": 3, "fps": 60, "seed": 11}), encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if k != "SDL_AUDIODRIVER"}
    env.update(SDL_VIDEODRIVER="dummy", LESSON11_LAB_SETTINGS=str(settings))
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    done = subprocess.run([sys.executable, os.path.join(root, "solutions", "tumbling_crates.py")], cwd=tmp_path,
                          env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "ALSA" not in done.stderr and "Simulated" in done.stdout


def test_only_a_colour_the_lab_draws_with_is_recorded():
    assert runtime._colour((200, 150, 90)) and runtime._colour([0, 0, 255])
    for odd in ((300, 0, 0), (1.5, 2, 3), "red", (True, 0, 0), (1, 2), None):
        assert not runtime._colour(odd), odd
