"""What a student sees of a failed function check (issue 40): --pictures and --show show the failure.

  * The scene drawn for a failed function check is one where the student's run visibly differs from the
    solution's (--pictures and --show choose it the same way, in the grader: checker/replay/preview.py).
  * The scene runs the student's failing step with the lesson's other steps (spliced as text in the parent,
    run in the isolated child) and says so: a student working in order (step 5 wrong, step 6 not written) sees
    step 5's symptom, not step 6's crates frozen on their corners.
  * --show says what it is doing while it prepares; the case views draw spin with its size and sign and
    friction as slip and impulse arrows on the boxes; the replay keeps the lab's colours; its key line and
    panel name no key that does nothing.

Headless: SDL's dummy video and audio drivers are set here; a desktop window differs only in that
pygame.event.get() delivers the keys. Each grading here runs the probe and one to four scenes in the child
(5-15 CPU s per file).
"""
import importlib
import math
import os
import sys

import pytest

os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ["SDL_AUDIODRIVER"] = "dummy"
import pygame  # noqa: E402
from pygame import Vector2  # noqa: E402

from checker import labs
from checker.replay import pictures, preview, show, show_cases, show_kit, show_view   # noqa: E402
from checker.grade import Grader  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

SEED = 3


def lab_of(lab_id):
    return next(lab for lab in labs.LABS if lab.id == lab_id)


def apart(frame, other):
    """(px, degrees): the largest distance and angle difference of moving bodies of the same index (computed
    here, not with checker/replay/preview.py)."""
    pairs = [(a, b) for a, b in zip(frame["bodies"], other["bodies"]) if not a["static"]]
    return (max([math.dist(a["pos"], b["pos"]) for a, b in pairs] + [0.0]),
            max([abs(math.degrees(a["angle"] - b["angle"])) for a, b in pairs] + [0.0]))


def nearest(frames, number):
    return min(frames, key=lambda f: abs(f["frame"] - number))


def differs_visibly(frames, reference):
    return any(max(apart(f, nearest(reference, f["frame"]))) >= 5 for f in frames)


def in_order(folder, wrong_step5):
    """A Tumbling Crates file as a student working in order has it: steps 2-4 done, step 5 written wrong
    (the corpus's entry), step 6 still the starter's TODO."""
    corpus = importlib.import_module("corpus_tumbling_crates")
    solution = open(corpus.SOLUTION, encoding="utf-8").read()
    starter = open(corpus.STARTER, encoding="utf-8").read()
    codes = {step: code for step, code in corpus.step_code(solution).items() if step in (2, 3, 4)}
    codes.update(corpus.BY_NAME[wrong_step5].steps)
    path = os.path.join(str(folder), "tumbling_crates.py")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(corpus.fill(starter, codes))
    return path


# ---------------------------------------------------------------- the scene: one where the run differs

@pytest.fixture(scope="module")
def unclamped(tmp_path_factory):
    """Ball on the Ramp with the closest point never clamped to the edge (step 2), graded with pictures."""
    corpus = importlib.import_module("corpus_ball_on_ramp")
    path = tmp_path_factory.mktemp("unclamped") / "ball_on_ramp.py"
    path.write_text(corpus.build("closest_not_clamped"), encoding="utf-8")
    lab = lab_of("ball_on_ramp")
    return lab, str(path), Grader(keep_records=True, seed=SEED).grade(str(path), lab)


def test_pictures_draw_a_scene_where_the_students_run_differs(unclamped):
    """The lab's preview scene ('ramp') runs exactly like the solution's with this mistake; the picture is of a
    scene where the ball visibly goes elsewhere ('knock': it hangs in mid-air), as --show shows."""
    lab, path, row = unclamped
    first = next(r for r in row.results if r.status == "fail")
    assert first.id == "closest_point"
    ramp = preview.runner(Grader().run, path, lab)(lab.preview_scene)   # the old choice, run here for comparison
    assert lab.preview_scene == "ramp" and not differs_visibly(ramp["records"],
                                                              pictures.reference_record(lab, "ramp")["records"])
    assert row.preview and row.preview != "ramp"
    mine = row.records[row.preview]["records"]
    assert differs_visibly(mine, pictures.reference_record(lab, row.preview)["records"])
    drawn = pictures.all_pictures([row])[row.path]
    assert [p.scene for p in drawn[first.id]] == [row.preview]
    replay = show.build_replay(row, first)
    assert replay.scene == row.preview and not replay.graded


def test_the_picture_caption_says_what_ran(unclamped):
    lab, path, row = unclamped
    assert row.preview_note == "your step 2 with the lesson's steps 3-7"
    first = next(r for r in row.results if r.status == "fail")
    replay = show.build_replay(row, first)
    assert replay.spliced == row.preview_note
    assert any(row.preview_note in line for line in replay.summary())


# ---------------------------------------------------------------- the failing step alone

def test_the_spliced_steps_are_named_in_ranges():
    assert preview.describe(5, [2, 3, 4, 6]) == "your step 5 with the lesson's steps 2-4, 6"
    assert preview.describe(2, [3]) == "your step 2 with the lesson's step 3"
    assert preview.describe(4, [2, 3, 5, 6]) == "your step 4 with the lesson's steps 2, 3, 5, 6"
    assert preview.describe(4, []) == ""


def test_replay_source_splices_every_other_step_as_text():
    lab = lab_of("tumbling_crates")
    corpus = importlib.import_module("corpus_tumbling_crates")
    solution = open(lab.solution, encoding="utf-8").read()
    starter = open(lab.starter, encoding="utf-8").read()
    mine = corpus.fill(starter, {5: "jt = max(-mu * k, min(mu * k, jt))"})
    text, taken = preview.replay_source(mine, solution, 5)
    assert taken == [2, 3, 4, 6]
    assert corpus.step_code(text) == {**corpus.step_code(solution), 5: "jt = max(-mu * k, min(mu * k, jt))"}
    assert preview.replay_source(mine, solution, 9) is None                       # no such step
    assert preview.replay_source("# --- step 2: x ---\n", solution, 2) is None    # markers that do not close


def test_the_spliced_file_runs_only_in_the_child(tmp_path):
    """The parent writes the spliced text to a temporary file and hands it to the grader's child run; it never
    imports or runs it (the run function here only records what it was given)."""
    lab = lab_of("tumbling_crates")
    given = []

    class Run:
        status, record = "done", None

    def run(path, task, settings, seconds):
        given.append((path, task, open(path, encoding="utf-8").read()))
        return Run()

    source = tmp_path / "tumbling_crates.py"
    source.write_text("raise SystemExit('never run in the parent')\n", encoding="utf-8")
    assert preview.runner(run, str(source), lab, "SPLICED = 1\n")("corner") is None
    path, task, text = given[0]
    assert task == "scenario" and text == "SPLICED = 1\n" and os.path.basename(path) == "tumbling_crates.py"
    assert not os.path.exists(path)   # removed after the run


@pytest.fixture(scope="module")
def working_in_order(tmp_path_factory):
    lab = lab_of("tumbling_crates")
    path = in_order(tmp_path_factory.mktemp("in_order"), "friction_bound_k")
    lines = []
    row, replay, problem = show.prepare(path, lab, seed=SEED, announce=lines.append)
    return lab, path, row, replay, lines


def test_working_in_order_the_step5_replay_shows_friction_not_step6(working_in_order):
    """Step 5 wrong, step 6 not yet written: the replay runs step 5 with the lesson's steps 2-4 and 6, so the
    crates land and tip over as the solution's do (step 6's symptom, crates frozen on their corners, is gone)
    and they still differ from the solution's (friction); the window's title and the summary say so."""
    lab, path, row, replay, lines = working_in_order
    assert replay.check.id == "resolve_friction" and not replay.graded
    assert replay.spliced == "your step 5 with the lesson's steps 2-4, 6"
    crates = [i for i, b in enumerate(replay.frames[0]["bodies"]) if not b["static"]]
    turned = [abs(math.degrees(replay.frames[-1]["bodies"][i]["angle"] - replay.frames[0]["bodies"][i]["angle"]))
              for i in crates]
    assert min(turned) > 10, turned   # they tip (the spin updates of step 6 are the lesson's)
    assert differs_visibly(replay.frames, replay.reference)
    # the whole file, as the student has it, freezes the crates on their corners in the same scene
    whole = preview.runner(Grader().run, path, lab)(replay.scene)["records"]
    frozen = [abs(math.degrees(whole[-1]["bodies"][i]["angle"] - whole[0]["bodies"][i]["angle"])) for i in crates]
    assert max(frozen) < 1, frozen
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.Viewer(replay)
    viewer.showing_cases = False
    assert any(replay.spliced in line for line in viewer.hud_lines())
    assert any(replay.spliced in line for line in replay.summary())


def test_show_says_what_it_does_while_it_prepares(working_in_order):
    lab, path, row, replay, lines = working_in_order
    assert lines == [f"grading {path}...", "recording the replay (your run and the solution's)..."]


def test_another_function_check_is_replayed_with_its_own_step(working_in_order):
    """--show apply_impulse_spin on the same file: step 6 with the lesson's steps 2-5 (the crates freeze there)."""
    lab, path, row, replay, lines = working_in_order
    other = next(r for r in row.results if r.id == "apply_impulse_spin")
    assert other.status == "fail"
    def rerun(result):
        return preview.scene_for(Grader().run, path, open(path, encoding="utf-8").read(), lab, result,
                                 pictures.reference_record)

    spin = show.build_replay(row, other, rerun=rerun)
    assert spin.spliced == "your step 6 with the lesson's steps 2-5"
    assert spin.scene and differs_visibly(spin.frames, spin.reference)


def test_jump_lands_where_the_difference_is_visible(working_in_order):
    lab, path, row, replay, lines = working_in_order
    at = nearest(replay.frames, replay.fail_frame)
    assert max(apart(at, replay.reference_at(at["frame"]))) >= 5
    assert all(max(apart(f, replay.reference_at(f["frame"]))) < 5 for f in replay.frames if f["frame"] < at["frame"])
    assert replay.quantity.bound == 5 and replay.values[replay.index_of(replay.fail_frame)] >= 5


# ---------------------------------------------------------------- drawing

def arc_pixels(spin, largest, radius=40):
    pygame.font.init()
    surface = pygame.Surface((200, 200))
    surface.fill((0, 0, 0))
    show_kit.spin_arc(surface, (255, 0, 255), Vector2(100, 100), radius, spin, largest)
    return [(x, y) for x in range(200) for y in range(200) if surface.get_at((x, y))[:3] == (255, 0, 255)]


def test_spin_is_drawn_with_its_size_and_sign():
    """+9.5 and -100 rad/s in one case: the -100 arc is about ten times as long and turns the other way
    (positive: clockwise on screen from the top, so its pixels lie right of the centre first)."""
    small, big = arc_pixels(9.5, 100), arc_pixels(-100, 100)
    assert len(big) > 5 * len(small) > 0
    assert sum(1 for x, y in small if x > 100) > 0.8 * len(small)     # clockwise from the top: to the right
    assert sum(1 for x, y in big if x < 100) > sum(1 for x, y in big if x > 100)   # anticlockwise: left first
    mirrored = arc_pixels(-9.5, 100)   # the same size the other way: the mirror image
    assert abs(len(mirrored) - len(small)) <= 0.1 * len(small)
    assert sum(1 for x, y in mirrored if x < 100) > 0.8 * len(mirrored)


def test_friction_case_draws_the_slip_and_the_impulses_on_the_boxes(working_in_order):
    lab, path, row, replay, lines = working_in_order
    case = replay.cases[0]
    assert case.kind == "resolve" and case.check_id == "resolve_friction"
    a, b, normal, point = case.geometry
    t = case.tangent(a, b, normal, point)
    assert abs(t.length() - 1) < 1e-9 and abs(t.dot(normal)) < 1e-9
    pygame.font.init()
    surface = pygame.Surface(show_cases.SIZE)
    case.draw(surface)
    corners = [p for body in (a, b) for p in body.world_points()]
    scale, offset = show_kit.fit([(p.x, p.y) for p in corners], (260, 150, 380, 200))
    contact = Vector2(point) * scale + offset
    bound = case.case["mu"] * case.case["j"]
    lesson_jt = max(-bound, min(bound, case.case["friction"]["stop"]))
    on_b = contact + normal * 34 + t * (60 if lesson_jt > 0 else -60)   # along the lesson's arrow on B
    assert tuple(surface.get_at((round(on_b.x), round(on_b.y))))[:3] == show_cases.LESSON
    slip = contact + normal * 14 + t * 40
    assert tuple(surface.get_at((round(slip.x), round(slip.y))))[:3] == (170, 175, 190)


def test_the_replay_keeps_the_labs_colours(unclamped):
    """The runtime records each body's colour; the ball is drawn in Ball on the Ramp's BALL_COLOR, not the
    palette's tan; a colour the record cannot hold (out of range, not three ints) falls back to the palette."""
    lab, path, row = unclamped
    frame = row.records[row.preview]["records"][0]
    ball = next(b for b in frame["bodies"] if b.get("radius"))
    assert "BALL_COLOR = (90, 170, 230)" in open(lab.solution, encoding="utf-8").read()
    assert tuple(ball["color"]) == (90, 170, 230)
    drawn = show_view.bodies_of(frame)
    assert next(d for d in drawn if d.body is ball).color == (90, 170, 230)
    for forged in ([999, 0, 0], [1.5, 2, 3], "red", [True, 0, 0], [1, 2]):
        assert show_view.recorded_colour(dict(ball, color=forged)) is None
        shown = show_view.bodies_of({"bodies": [dict(ball, color=forged)]})[0]
        assert shown.color == show_view.PALETTE[0]


def test_the_key_line_and_the_replay_panel_name_only_keys_that_do_something(working_in_order):
    lab, path, row, replay, lines = working_in_order
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.Viewer(replay)
    viewer.showing_cases = False
    keys = viewer.hud_lines()[-1]
    assert "Left one back" in keys and "Right one frame on" in keys and "Left/Right " not in keys
    surface = pygame.Surface(show_view.SIZE)
    viewer.draw(surface)
    texts = [words for _, words in viewer.panel.placed]
    assert "solver panel (replay)" in texts
    assert not any(t.startswith("[") and t not in ("[H] more", "[H] hide") for t in texts), texts
    assert show_view.SCENE[0] - 10 > viewer.small.size(keys)[0]   # the key line fits the window


def test_ball_on_the_ramp_friction_case_draws_the_slip_and_both_friction_impulses(tmp_path):
    """Step 7 with jt's sign flipped: the lesson's friction on the ball opposes its slip, the student's pushes
    along it; both are drawn from the contact, with the slip."""
    corpus = importlib.import_module("corpus_ball_on_ramp")
    path = tmp_path / "ball_on_ramp.py"
    path.write_text(corpus.build("friction_sign_flipped"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("ball_on_ramp"), seed=SEED)
    assert replay.check.id == "friction_rolls" and replay.cases
    for case in replay.cases:
        friction = case.case["friction"]
        slip, yours, lesson = (Vector2(friction[k]) for k in ("slip", "yours", "lesson"))
        assert slip.length() > 0 and lesson.dot(slip) < 0 < yours.dot(slip), case.case["case"]
    pygame.font.init()
    surface = pygame.Surface(show_cases.SIZE)
    replay.cases[0].draw(surface)
    friction = replay.cases[0].case["friction"]
    largest = max(Vector2(friction["yours"]).length(), Vector2(friction["lesson"]).length())
    contact = Vector2(show_cases.SIZE[0] / 2, 230)
    along = contact + Vector2(friction["lesson"]) * (60 / largest)   # two thirds along the lesson's arrow
    assert tuple(surface.get_at((round(along.x), round(along.y))))[:3] == show_cases.LESSON


def test_a_splice_that_cannot_run_falls_back_to_the_whole_file(tmp_path):
    """The student's step 5 reads a name their own step 4 made (kk): with the lesson's step 4 spliced in it
    raises NameError in every scene, so the scene is the whole file's, and no splice is claimed."""
    lab = lab_of("tumbling_crates")
    corpus = importlib.import_module("corpus_tumbling_crates")
    solution = open(lab.solution, encoding="utf-8").read()
    codes = corpus.step_code(solution)
    codes[4] = codes[4] + "\nkk = k"
    codes[5] = "jt = max(-mu * j, min(mu * j, jt)) * 0.5 * kk / k"   # half the friction, and it needs kk
    path = tmp_path / "tumbling_crates.py"
    path.write_text(corpus.fill(open(lab.starter, encoding="utf-8").read(), codes), encoding="utf-8")
    row = Grader(keep_records=True, seed=SEED).grade(str(path), lab)
    first = next(r for r in row.results if r.status in ("fail", "error"))
    assert first.id == "resolve_friction", [(r.id, r.status) for r in row.results]
    assert row.preview and row.preview_note == ""
