"""The solver panel (lesson11/panel.py): keys change the World, P and O hold and step it, the HUD reads well,
and a lab run that presses none of its keys is the very same run as without the panel.

In-process tests drive a LabPanel with synthetic key events on a small World;
the last tests run solutions/tumbling_crates.py under the lab runtime in a
child process, as the checker does (tests/lab_run.py).
"""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import json
import re

import pygame
import pytest

from lab_run import SOLUTION, clicks, run_lab
from lesson11 import panel as lp
from lesson11.physics2d import Body, World, box_points
from mutants import apply_edits


@pytest.fixture(autouse=True)
def pygame_fonts():
    pygame.display.init()
    pygame.font.init()
    yield
    pygame.quit()


def key(name):
    """A KEYDOWN event for a key named as pygame.key.key_code names it ("s", "up", "0")."""
    return pygame.event.Event(pygame.KEYDOWN, key=pygame.key.key_code(name), mod=0)


def small_world(**settings):
    """A static floor and two crates falling onto it (px, y down)."""
    floor = Body(box_points(900, 40), (450, 580), 0)
    crates = [Body(box_points(60, 40), (300, 500), 2.4, angle=0.3), Body(box_points(50, 50), (500, 300), 2.5)]
    return World([floor] + crates, **settings)


def state(world):
    return [(tuple(b.pos), tuple(b.vel), b.angle, b.omega) for b in world.bodies]


# ---------------------------------------------------------------- settings on keys

def test_without_keys_the_panel_sets_nothing_and_steps_as_world_advance():
    plain, panelled = small_world(), small_world()
    settings = ("solver", "iterations", "contact_rule", "effects", "substeps", "warm_starting")
    before = {name: getattr(panelled, name, None) for name in settings}
    panel = lp.LabPanel()
    for dt in (1 / 60, 1 / 60, 0.004, 1.0):
        assert panel.advance(panelled, dt) == plain.advance(dt)
        assert state(panelled) == state(plain)
    assert panel.overrides == {}
    for name in settings:
        assert getattr(panelled, name, None) == before[name] == getattr(plain, name, None)


def test_each_key_changes_its_world_setting_and_0_restores_the_worlds_own():
    world = small_world()
    own_substeps = world.substeps  # the lesson solver's default order, solve-first: LESSON_SUBSTEPS = 4
    panel = lp.LabPanel()
    panel.advance(world, 0)
    for name in ("s", "up", "up", "right", "w", "c", "k"):
        assert panel.handle(key(name)) is True
    assert world.solver == "accumulated"
    assert world.iterations == 8
    assert world.substeps == own_substeps + 1  # the panel steps from the world's own value
    assert world.warm_starting is False
    assert "correction" not in world.effects and "friction" in world.effects
    assert world.contact_rule == "clip"
    assert set(panel.overrides) == set(lp.SETTING_NAMES)
    panel.handle(key("0"))
    assert (world.solver, world.iterations, world.substeps, world.warm_starting, world.contact_rule) == \
        ("lesson", 6, own_substeps, True, "corners")
    assert "correction" in world.effects
    assert panel.overrides == {}


def test_counts_stay_between_one_and_their_maximum():
    world = small_world(iterations=2)
    panel = lp.LabPanel()
    panel.advance(world, 0)
    for _ in range(5):
        panel.handle(key("down"))
        panel.handle(key("left"))
    assert world.iterations == 1 and world.substeps == 1
    for _ in range(lp.MAX_ITERATIONS + 5):
        panel.handle(key("up"))
        panel.handle(key("right"))
    assert world.iterations == lp.MAX_ITERATIONS and world.substeps == lp.MAX_SUBSTEPS


def test_changing_a_setting_back_by_hand_drops_the_override():
    world = small_world()
    panel = lp.LabPanel()
    panel.advance(world, 0)
    panel.handle(key("k"))
    assert panel.overrides == {"contact_rule": "clip"}
    panel.handle(key("k"))
    assert panel.overrides == {} and world.contact_rule == "corners"


def test_a_new_world_after_reset_gets_the_settings_before_its_first_step():
    panel = lp.LabPanel()
    old = small_world()
    panel.advance(old, 0)
    panel.handle(key("s"))
    panel.handle(key("up"))
    new = small_world()  # what R does in a lab: a fresh World with the lab's own settings
    assert new.solver == "lesson" and new.iterations == 6
    panel.advance(new, 1 / 60)
    assert new.solver == "accumulated" and new.iterations == 7
    panel.handle(key("0"))
    assert new.solver == "lesson" and new.iterations == 6


def test_keys_other_than_the_panels_are_left_to_the_lab():
    panel = lp.LabPanel()
    panel.advance(small_world(), 0)
    for name in ("d", "r", "a"):
        assert panel.handle(key(name)) is False
    assert panel.handle(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=(10, 10), button=1)) is False
    assert panel.overrides == {}


@pytest.mark.parametrize("name, value", [("iterations", 0), ("iterations", True), ("substeps", 1.5),
                                         ("solver", "fast"), ("contact_rule", "edges"), ("warm_starting", 1)])
def test_a_value_the_panel_never_offers_is_a_one_line_error(name, value):
    with pytest.raises(ValueError) as error:
        lp.write_setting(small_world(), name, value)
    assert repr(value) in str(error.value) and name in str(error.value) and "\n" not in str(error.value)


def test_unknown_setting_is_named():
    with pytest.raises(ValueError, match="'gravity'"):
        lp.write_setting(small_world(), "gravity", 0)


# ---------------------------------------------------------------- pause and one step

def test_p_holds_the_world_and_o_runs_exactly_one_step():
    world = small_world()
    panel = lp.LabPanel()
    panel.advance(world, 1 / 60)
    panel.handle(key("p"))
    held = state(world)
    assert panel.advance(world, 1 / 60) == 0 and panel.advance(world, 0.25) == 0
    assert state(world) == held
    reference = small_world()
    reference.advance(1 / 60)
    reference.step()
    panel.handle(key("o"))
    assert panel.advance(world, 1 / 60) == 1
    assert state(world) == state(reference)
    assert panel.advance(world, 1 / 60) == 0  # still paused: one O, one step
    panel.handle(key("p"))
    assert panel.advance(world, 1 / 60) == 2  # running again, 2 steps of 1/120 s per 1/60 s frame


def test_o_while_running_pauses_and_steps():
    world = small_world()
    panel = lp.LabPanel()
    panel.advance(world, 1 / 60)
    panel.handle(key("o"))
    panel.handle(key("o"))
    assert panel.paused
    assert panel.advance(world, 1 / 60) == 2


# ---------------------------------------------------------------- the HUD

def hud(panel, world, frames=30):
    surface = pygame.Surface((900, 600))
    for _ in range(frames):
        panel.advance(world, 1 / 60)
        surface.fill((24, 26, 34))
        panel.draw(surface, world)
    return surface


def text_of(panel):
    return " | ".join(words for _, words in panel.placed)


@pytest.mark.parametrize("mode", ["compact", "full"])
def test_hud_text_stays_inside_the_panel_and_no_two_lines_overlap(mode):
    panel = lp.LabPanel()
    panel.mode = mode
    world = small_world()
    for keys in ((), ("s", "w", "right", "right"), ("s", "up", "k", "c", "p")):
        for name in keys:
            panel.handle(key(name))
        surface = hud(panel, world)
        panel.history.extend([1234.5] * 10)  # a slow machine: the graph's top label gets long
        panel.dirty = True
        panel.draw(surface, world)
        assert surface.get_rect().contains(panel.box)
        assert panel.box.top >= 30, "the lab's own HUD line (y 10-26) stays clear"
        rects = [rect for rect, _ in panel.placed]
        for rect, words in panel.placed:
            assert panel.box.contains(rect), f"{words!r} runs out of the panel"
        for i, a in enumerate(rects):
            for b in rects[i + 1:]:
                assert not a.colliderect(b), f"{panel.placed[i][1]!r} overlaps another line"


def full_panel():
    panel = lp.LabPanel()
    panel.handle(key("h"))  # compact -> full
    assert panel.mode == "full"
    return panel


def test_hud_shows_the_settings_measurements_and_who_solves():
    panel = full_panel()
    world = small_world()
    hud(panel, world)
    text = text_of(panel)
    for words in ("[S]", "[Up/Down]", "[Left/Right]", "[W]", "[C]", "[K]", "[P] pause", "[O] one step", "[H] hide",
                  "solver | lesson", "iterations | 6", "contact rule | corners", "ms/frame", "ms/step",
                  "real time", "study:", "contacts", "deepest", "kinetic energy", "60 fps budget"):
        assert words in text, words
    assert "physics2d's sat() and resolve()" in text  # this World has no hooks of a lab
    panel.handle(key("s"))
    hud(panel, world, 1)
    assert "accumulated (reference)" in text_of(panel) and "NOT used" not in text_of(panel)
    resolve_only = small_world(resolve=lambda a, b, normal, point: None)
    panel = full_panel()
    hud(panel, resolve_only, 1)
    assert "runs physics2d's sat() and your resolve()" in text_of(panel)
    lab_world = small_world(sat=lambda pa, pb: None, resolve=lambda a, b, normal, point: None)  # Tumbling Crates
    panel = full_panel()
    hud(panel, lab_world, 1)
    assert "runs your sat() and resolve()" in text_of(panel)
    panel.handle(key("s"))
    hud(panel, lab_world, 1)
    assert "your sat() and resolve() are NOT used" in text_of(panel)


def test_hud_says_when_this_world_has_no_substeps_yet():
    world = small_world()
    lacks = not hasattr(world, "substeps")
    panel = full_panel()
    hud(panel, world, 1)
    assert ("not in this World yet" in text_of(panel)) == lacks


def test_measurements_are_the_worlds():
    panel = lp.LabPanel()
    world = small_world()
    for _ in range(40):
        panel.advance(world, 1 / 60)
    m = panel.measure(world)
    assert m["contacts"] == len(world.contacts) > 0
    assert m["deepest"] == max(c.depth for c in world.contacts)
    assert m["energy"] == pytest.approx(sum(b.kinetic_energy() for b in world.bodies))
    assert m["ms"] > 0 and m["steps"] == 2
    assert m["ms_per_step"] == pytest.approx(sum(r[0] for r in panel.rates) / sum(r[1] for r in panel.rates))
    assert m["real_time"] == pytest.approx(1.0)


def test_a_slow_setting_slows_time_down_instead_of_spiralling():
    """Frames that take long (0.1 s each) run at most max_steps steps, and the panel says the lab fell behind."""
    panel = lp.LabPanel()
    world = small_world()
    steps = [panel.advance(world, 0.1) for _ in range(20)]
    assert max(steps) == world.max_steps == 4     # 12 steps' worth of time a frame, 4 run: no spiral
    m = panel.measure(world)
    assert m["real_time"] == pytest.approx(4 / 120 / 0.1)   # 0.33x real time
    surface = hud(panel, world, 0)
    panel.shown = None
    for _ in range(2):
        panel.advance(world, 0.1)
        panel.draw(surface, world)
    assert "0.3x real time" in text_of(panel)


def test_compact_panel_is_the_default_small_and_h_cycles_the_sizes():
    panel = lp.LabPanel()
    world = small_world()
    hud(panel, world)
    assert panel.mode == "compact"
    assert panel.box.width <= 320 and panel.box.height <= 101, panel.box   # the full one is 400 × 350
    text = text_of(panel)
    for words in ("[S]", "[Up/Down]", "[Left/Right]", "[H] more", "ms/step", "real time", "study:"):
        assert words in text, words
    sizes = []
    for _ in range(3):
        panel.handle(key("h"))
        hud(panel, world, 1)
        sizes.append((panel.mode, panel.box.width * panel.box.height))
    assert [mode for mode, _ in sizes] == ["full", "hidden", "compact"]
    assert sizes[1][1] < sizes[2][1] < sizes[0][1]


def test_the_compact_panel_hides_no_starting_crate():
    """Tumbling Crates drops four crates of up to 90 × 70 px from (150 + 180 i, 80 + 40 i): whatever their size
    and angle (seeds 0-199), none starts under the compact panel, and the 22° ramp stays clear too."""
    import importlib.util
    import random
    spec = importlib.util.spec_from_file_location("tumbling_crates_solution", SOLUTION)
    lab = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(lab)
    panel = lp.LabPanel()
    hud(panel, small_world(), 1)
    assert panel.mode == "compact"
    for seed in range(200):
        for body in lab.make_scene(random.Random(seed)):
            if body.inv_mass == 0 and body.pos.y > 500:
                continue   # the floor and the wall off the right edge
            left, top, right, bottom = body.aabb()
            assert not panel.box.colliderect(pygame.Rect(left, top, right - left, bottom - top)), (seed, body)


def test_study_line_reads_the_studys_table(monkeypatch, tmp_path):
    table = tmp_path / "frontier.json"
    table.write_text(json.dumps({"settings": [
        {"solver": "lesson", "order": "solve-first", "substeps": 4, "iterations": 6, "ms_per_step": 1.5,
         "pile_speed": 3.7, "on_front": True, "better": None},
        {"solver": "lesson", "order": "solve-first", "substeps": 4, "iterations": 7, "ms_per_step": 1.7,
         "pile_speed": 3.9, "on_front": False, "better": "4 x 6"}]}), encoding="utf-8")
    monkeypatch.setattr(lp, "STUDY_FILE", str(table))
    monkeypatch.setattr(lp, "_study", None)
    world = small_world()
    assert lp.study_lines(world, {"solver": "lesson", "substeps": 4, "iterations": 6}) == [
        "study: 1.50 ms/step, pile 3.7 px/s", "on the front: nothing cheaper errs less"]
    assert lp.study_lines(world, {"solver": "lesson", "substeps": 4, "iterations": 7})[1] == \
        "off the front: 4 x 6 costs less, errs less"
    assert lp.study_lines(world, {"solver": "lesson", "substeps": 3, "iterations": 7})[0] == \
        "study: this setting was not measured"
    assert lp.study_short(world, {"solver": "lesson", "substeps": 4, "iterations": 6}) == \
        "study: 1.50 ms, pile 3.7 px/s: on front"
    assert lp.study_short(world, {"solver": "lesson", "substeps": 4, "iterations": 7}) == \
        "study: 1.70 ms, pile 3.9 px/s: 4 x 6 beats it"
    assert lp.study_short(world, {"solver": "lesson", "substeps": 3, "iterations": 7}) == \
        "study: this setting was not measured"
    monkeypatch.setattr(lp, "STUDY_FILE", str(tmp_path / "missing.json"))
    monkeypatch.setattr(lp, "_study", None)
    assert lp.study_rows() == {}


def test_graph_shows_the_history_and_the_budget_line():
    panel = full_panel()
    surface = hud(panel, small_world(), 90)
    graph = [(x, y) for x in range(panel.box.left, panel.box.right) for y in range(panel.box.top, panel.box.bottom)
             if surface.get_at((x, y))[:3] == lp.GRAPH_LINE]
    assert len(graph) > 100
    assert sum(1 for x in range(panel.box.left, panel.box.right) for y in range(panel.box.top, panel.box.bottom)
               if surface.get_at((x, y))[:3] == lp.BUDGET_LINE) > 100


def test_h_hides_the_panel_but_leaves_a_hint():
    panel = full_panel()
    world = small_world()
    panel.handle(key("h"))
    hud(panel, world, 1)
    assert [words for _, words in panel.placed] == ["[H] show the solver panel"]


# ---------------------------------------------------------------- the lab under the runtime

NO_PANEL = [  # the solution as it was before the panel: every `# solver panel` line undone
    ("from lesson11.panel import LabPanel  # solver panel\n", ""),
    ("    panel = LabPanel()  # solver panel\n", ""),
    ("            panel.handle(event)  # solver panel: its keys\n", ""),
    ("        simulated += panel.advance(world, dt) * world.step_seconds  # solver panel: fixed steps, long frames "
     "clamped\n", "        simulated += world.advance(dt) * world.step_seconds  # fixed steps; long frames clamped\n"),
    ("        panel.draw(screen, world)  # solver panel: settings, ms, graph\n", ""),
]


def test_solution_marks_every_panel_line():
    with open(SOLUTION, encoding="utf-8") as handle:
        source = handle.read()
    body = source.split('"""', 2)[2]  # after the module docstring
    code = [line for line in body.splitlines() if "panel" in line.split("#")[0]]
    assert len(code) == len(NO_PANEL) and all("# solver panel" in line for line in code), code
    assert "panel" not in apply_edits(source, NO_PANEL, "no-panel copy").split('"""', 2)[2]


def test_checker_run_records_the_same_with_and_without_the_panel(tmp_path):
    """Same scene, script (clicks, D, R) and seed: the runtime's record is identical, frame for frame, but for
    the World's settings, which only the panel's advance() notes (on the first frame: no key changed them)."""
    with open(SOLUTION, encoding="utf-8") as handle:
        plain = tmp_path / "tumbling_crates_no_panel.py"
        plain.write_text(apply_edits(handle.read(), NO_PANEL, "no-panel copy"), encoding="utf-8")
    script = clicks([(600, 100), (300, 100), (700, 150)], 10, 15) + [
        {"frame": 50, "type": "key", "key": "d"}, {"frame": 80, "type": "key", "key": "r"},
        {"frame": 95, "type": "click", "pos": [450, 200]}]
    settings = {"frames": 120, "fps": 60, "seed": 11, "script": script}
    runs = []
    for name, path in (("panel", SOLUTION), ("plain", str(plain))):
        work = tmp_path / name
        work.mkdir()
        runs.append(run_lab(path, settings, work))
    with_panel, without = runs
    noted = [frame.pop("world", None) for frame in with_panel.record["records"]]
    assert noted[0]["iterations"] == 6 and noted[1:] == [None] * (len(noted) - 1)
    assert all("world" not in frame for frame in without.record["records"])
    assert with_panel.record == without.record
    assert with_panel.line == without.line and with_panel.line is not None
    assert len(with_panel.frames) == 120 and any(f["contacts"] for f in with_panel.frames)


def test_scripted_p_and_o_reach_the_panel_through_the_runtime(tmp_path):
    """P at frame 20 holds every body from then on; O at frame 30 moves them by exactly one step."""
    script = [{"frame": 20, "type": "key", "key": "p"}, {"frame": 30, "type": "key", "key": "o"}]
    run = run_lab(SOLUTION, {"frames": 40, "fps": 60, "seed": 11, "script": script}, tmp_path)
    bodies = [frame["bodies"] for frame in run.frames]  # bodies[k] is frame k + 1
    assert bodies[17] != bodies[18]                      # frame 19: still falling
    assert all(b == bodies[18] for b in bodies[19:29])  # P in frame 20: frames 20-29 stand still
    assert bodies[29] != bodies[28]                      # O in frame 30: one step
    assert all(b == bodies[29] for b in bodies[30:])
    assert run.line[0] == 0.3  # 19 frames of 2 steps and 1 step: 39 steps of 1/120 s = 0.325 s


# ---------------------------------------------------------------- where a frame goes (issue 31, item 4)

def solution_module():
    """solutions/tumbling_crates.py as a module (its main() does not run)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("panel_test_tumbling_crates", SOLUTION)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_full_view_says_where_a_frame_goes_and_changes_nothing():
    """With the lab's sat and resolve, the full view reads "physics X ms: your sat A, your resolve B, engine C" with
    A + B + C = X; the timers change no number of the run, and leave when the view does."""
    lab = solution_module()
    timed, plain = (small_world(sat=lab.sat, resolve=lab.resolve) for _ in range(2))
    panel = full_panel()
    surface = pygame.Surface((900, 600))
    for frame in range(40):
        panel.advance(timed, 1 / 60)
        plain.advance(1 / 60)
        panel.draw(surface, timed)
        assert state(timed) == state(plain), f"frame {frame}: the timers changed the run"
    assert timed.sat is not lab.sat and timed.sat.timed_function is lab.sat   # timed while the full view is open
    placed = [words for _, words in panel.placed]
    first = next(i for i, words in enumerate(placed) if words.startswith("physics") and "your sat" in words)
    line = ", ".join(placed[first:first + 2]) if "engine" not in placed[first] else placed[first]  # wrapped: 2 lines
    numbers = [float(n) for n in re.findall(r"\d+\.\d", line)]
    physics, sat, resolve, engine = numbers
    assert line == f"physics {physics:.1f} ms: your sat {sat:.1f}, your resolve {resolve:.1f}, engine {engine:.1f}"
    assert sat > 0 and resolve > 0 and engine > 0
    assert abs(sat + resolve + engine - physics) <= 0.15      # each figure rounded to 0.1 ms
    panel.handle(key("h"))  # full -> hidden: the lab's own functions again
    panel.advance(timed, 1 / 60)
    assert timed.sat is lab.sat and timed.resolve is lab.resolve
    assert panel.measure(timed)["split"] is None


def test_full_view_with_the_reference_solver_says_no_function_of_the_lab_runs():
    lab = solution_module()
    world = small_world(sat=lab.sat, resolve=lab.resolve)
    panel = full_panel()
    hud(panel, world, 1)
    panel.handle(key("s"))   # the accumulated solver: the lab's functions are not called
    panel.split.clear()      # forget the frame the lesson solver ran
    hud(panel, world, 30)
    assert any(re.fullmatch(r"physics \d+\.\d ms: all physics2d's own", words) for _, words in panel.placed)


def test_compact_cost_line_turns_orange_below_real_time():
    """At 1.0x real time the cost line is drawn in the text colour; at 0.3x (frames of 0.1 s, max_steps 4) in orange."""
    def rate_line_colours(frame_seconds):
        panel = lp.LabPanel()
        world = small_world()
        surface = pygame.Surface((900, 600))
        for _ in range(30):
            panel.advance(world, frame_seconds)
            surface.fill((24, 26, 34))
            panel.draw(surface, world)
        rect, words = next((rect, words) for rect, words in panel.placed if "real time" in words)
        colours = {tuple(surface.get_at((x, y)))[:3] for x in range(rect.left, rect.right)
                   for y in range(rect.top, rect.bottom)}
        return words, colours
    words, colours = rate_line_colours(1 / 60)
    assert "1.0x real time" in words and lp.TEXT in colours and lp.WARNING not in colours
    words, colours = rate_line_colours(0.1)
    assert "0.3x real time" in words and lp.WARNING in colours and lp.TEXT not in colours


def test_real_time_line_names_the_most_accurate_front_setting_this_machine_can_run(monkeypatch, tmp_path):
    """The study's ms/step scaled by this machine's (live ms/step ÷ the study's for the current setting); a setting
    runs in real time if that × 2 steps a frame fits REAL_TIME_SHARE of 16.7 ms."""
    def row(substeps, iterations, ms, pile, front=True, solver="lesson"):
        return {"solver": solver, "order": "solve-first" if solver == "lesson" else "-", "substeps": substeps,
                "iterations": iterations, "ms_per_step": ms, "pile_speed": pile, "on_front": front,
                "better": None if front else "1 x 6"}
    table = tmp_path / "frontier.json"
    table.write_text(json.dumps({"settings": [
        row(1, 6, 2.0, 15.0), row(2, 4, 4.0, 8.0), row(4, 6, 8.0, 4.0), row(8, 6, 16.0, 2.0),
        row(2, 6, 4.5, 9.0, front=False), row(8, 20, 1.0, 0.0, solver="accumulated")]}), encoding="utf-8")
    monkeypatch.setattr(lp, "STUDY_FILE", str(table))
    monkeypatch.setattr(lp, "_study", None)
    world = small_world()   # 1/120 s steps: 2 a frame; budget 0.8 × 16.7 = 13.3 ms a frame, 6.7 ms a step
    now = {"solver": "lesson", "substeps": 4, "iterations": 6}
    # this machine as fast as the study's: 4 × 6 (8 ms a step) does not fit, 2 × 4 (4 ms) does
    assert lp.real_time_line(world, now, 8.0) == "real time here: best on the front 2 × 4, 8.0 ms/frame"
    # twice as fast: 4 × 6 fits; 8 × 6 (16 ms at the study, 8 here) does not; the 2 × 6 off the front is never named
    assert lp.real_time_line(world, now, 4.0) == "real time here: best on the front 4 × 6, 8.0 ms/frame"
    # 8× slower: not even 1 × 6 fits
    assert lp.real_time_line(world, now, 64.0) == "real time here: no setting on the front"
    # a setting the study did not measure, or no step yet: no line
    assert lp.real_time_line(world, {"solver": "lesson", "substeps": 3, "iterations": 6}, 4.0) is None
    assert lp.real_time_line(world, now, 0.0) is None
    widest = "real time here: best on the front 16 × 20, 13.3 ms/frame"   # the longest a line gets
    assert lp.LabPanel().text(widest).get_width() <= lp.PANEL_WIDTH - 2 * lp.PADDING
