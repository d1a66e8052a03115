"""python -m checker FILE --show (issue 30), driven headless as a student would use it.

The tests set SDL's dummy video and audio drivers themselves and script the keys through the viewer's
event source (checker/replay/show_view.py run(events=...)); a real desktop window differs only in that
pygame.event.get() delivers the keys. For every lab one file of its mistake corpus (tests/corpus_<lab>.py)
with one wrong step is shown: --show opens on that step's check, the student's replayed run is the
graded record frame for frame, the ghost is the solution's run (a run of solutions/<lab>.py made here
independently), and the failing frame the summary names is the first frame where the student's bodies
are visibly (> 1 px) away from the solution's, which J lands on. The labs are every lab in checker/labs/
(tests/labs_found.py); the file shown is its corpus's SHOW_ENTRY. Each lab costs one grading (probe and
one scene), one grading more to compare with and the solution's scene: about 5-15 CPU s.
"""
import importlib
import math
import os
import sys

import pytest

os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ["SDL_AUDIODRIVER"] = "dummy"
import pygame  # noqa: E402

from checker import cli, labs
from checker.judging import lab_checks
from checker.replay import pictures, show, show_cases, show_kit, show_series, show_view   # noqa: E402
from checker.labs.ball_on_ramp import show as ball_on_ramp_show  # noqa: E402
from checker.labs.bullets import show as bullets_show  # noqa: E402
from checker.labs.more_shapes import show as more_shapes_show  # noqa: E402
from checker.labs.sleeping_crates import show as sleeping_crates_show  # noqa: E402
from checker.labs.tumbling_crates import show as tumbling_crates_show  # noqa: E402
from lesson11 import records  # noqa: E402
from checker.grade import Grader  # noqa: E402
from checker.isolation.sandbox import Limits, run_child   # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import labs_found  # noqa: E402  (every lab in checker/labs/)

SEED = 3


def show_entry(lab):
    """The corpus entry with one wrong step that --show is tried on: the lab's corpus's SHOW_ENTRY."""
    corpus = labs_found.need_corpus(lab)
    name = getattr(corpus, "SHOW_ENTRY", None)
    assert name, (f"{lab.id}: set SHOW_ENTRY in tests/corpus_{lab.id}.py to a wrong entry with one wrong step "
                  "whose scene differs visibly from the solution's (the file --show is tested on)")
    return next(e for e in corpus.WRONG if e.name == name)


def key(k):
    return pygame.event.Event(pygame.KEYDOWN, key=k, mod=0, unicode="")


def scripted(*frames):
    """An event source: the i-th call returns frames[i] (a list of events), then nothing."""
    queue = list(frames)
    return lambda: queue.pop(0) if queue else []


lab_of = labs_found.by_id


def wrong_file(folder, lab_id):
    lab = lab_of(lab_id)
    entry = show_entry(lab)
    path = os.path.join(folder, f"{lab_id}.py")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(labs_found.corpus(lab).build(entry.name))
    return path


def distance(frame, other):
    """Largest distance (px) between bodies of the same index in two recorded frames (computed here)."""
    if len(frame["bodies"]) != len(other["bodies"]):
        return math.inf
    return max(math.hypot(a["pos"][0] - b["pos"][0], a["pos"][1] - b["pos"][1])
               for a, b in zip(frame["bodies"], other["bodies"]))


@pytest.fixture(scope="module", params=labs_found.IDS)
def shown(request, tmp_path_factory):
    lab = lab_of(request.param)
    path = wrong_file(str(tmp_path_factory.mktemp(request.param)), request.param)
    row, replay, problem = show.prepare(path, lab, seed=SEED)
    assert problem == "" and replay is not None
    return lab, path, row, replay


def test_opens_on_the_wrong_steps_check(shown):
    lab, path, row, replay = shown
    expected = show_entry(lab).check   # the corpus's own verdict for this file
    first_failed = next(r for r in row.results if r.status in ("fail", "error"))
    assert replay.check.id == expected == first_failed.id
    assert replay.seed == row.seed == SEED
    assert any(f"--seed {SEED}" in line for line in replay.summary())


def test_replay_is_the_graded_record_frame_for_frame(shown):
    lab, path, row, replay = shown
    graded = Grader(keep_records=True, seed=SEED).grade(path, lab)   # the checker's own grading, again
    assert replay.scene in graded.records, (replay.scene, list(graded.records))
    recorded = graded.records[replay.scene]["records"]
    assert len(replay.frames) == len(recorded) > 10
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.Viewer(replay)
    viewer.playing = False
    for k, frame in enumerate(recorded):   # O steps one recorded frame at a time
        assert viewer.frame == frame, f"frame {frame['frame']} differs"
        viewer.handle(key(pygame.K_o))
    assert viewer.frame == recorded[-1]


def test_ghost_is_the_solutions_run(shown):
    lab, path, row, replay = shown
    settings = lab.scenarios()[replay.scene]
    solution = run_child(lab.solution, "scenario", dict(settings, probes=lab.probes), Limits()).record["records"]
    assert replay.reference == solution
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.Viewer(replay)
    viewer.handle(key(pygame.K_j))
    assert viewer.reference_frame["frame"] == viewer.frame["frame"]   # lockstep
    surface = pygame.Surface(show_view.SIZE)
    viewer.draw(surface)
    ghost = next(b for b in viewer.reference_frame["bodies"] if not b["static"])
    if ghost["points"]:   # the solution's outline passes through the middle of its first edge
        a, b = ghost["points"][0], ghost["points"][1]
        middle = (round((a[0] + b[0]) / 2), round((a[1] + b[1]) / 2))
    else:                 # a circle: through its rightmost point
        middle = (round(ghost["pos"][0] + ghost["radius"] - 1), round(ghost["pos"][1]))
    around = {tuple(surface.get_at((middle[0] + dx, middle[1] + dy)))[:3] for dx in (-1, 0, 1) for dy in (-1, 0, 1)}
    assert show_view.GHOST in around


def turned(frame, other):
    """Largest difference (degrees) between the angles of moving bodies of the same index (computed here)."""
    return max([abs(math.degrees(a["angle"] - b["angle"])) for a, b in zip(frame["bodies"], other["bodies"])
                if not a["static"]] + [0.0])


def test_jump_lands_on_the_first_frame_that_differs_visibly_from_the_solution(shown):
    """J: the first frame where a body is 5 px from the solution's or turned 5 degrees differently (a difference
    seen at the window's scale; 1-3 px is not), and no frame before it; none where no frame differs (a step that
    only reads the world, as new-lab's template's, changes no body)."""
    lab, path, row, replay = shown
    named = replay.fail_frame
    if all(distance(f, replay.reference_at(f["frame"])) < 5 and turned(f, replay.reference_at(f["frame"])) < 5
           for f in replay.frames):
        assert named is None, f"failing frame {named} named where no body differs visibly from the solution's"
        return
    assert named is not None and any(f"failing frame {named} " in line for line in replay.summary())
    before = [f for f in replay.frames if f["frame"] < named]
    at = next(f for f in replay.frames if f["frame"] == named)
    theirs = replay.reference_at(named)
    assert distance(at, theirs) >= 5 or turned(at, theirs) >= 5
    assert all(distance(f, replay.reference_at(f["frame"])) < 5 and turned(f, replay.reference_at(f["frame"])) < 5
               for f in before)
    viewer = show_view.run(replay, events=scripted([], [key(pygame.K_p)], [key(pygame.K_j)], []), frames=4)
    assert viewer.frame["frame"] == named and not viewer.playing


def test_keys_pause_step_and_toggle(shown):
    lab, path, row, replay = shown
    viewer = show_view.run(replay, events=scripted([key(pygame.K_p)], [key(pygame.K_o)], [key(pygame.K_o)],
                                                   [key(pygame.K_g)], []), frames=6)
    assert viewer.index == 2 and not viewer.playing and viewer.side_by_side
    viewer = show_view.run(replay, events=scripted([], [], [], [pygame.event.Event(pygame.QUIT)]), frames=50)
    assert viewer.index == 3   # played three frames (lockstep with the display), then the window closed


# ---------------------------------------------------------------- a behaviour check

def test_failed_behaviour_check_jumps_to_the_frame_it_judges(tmp_path):
    """Ball on the Ramp with the push-out's SLOP raised to 6 px (as tests/test_checker_pictures.py): every
    function check passes, pushed_out_of_crate fails at the end of the 'inside' scene."""
    from test_checker_pictures import slop_file
    lab = lab_of("ball_on_ramp")
    row, replay, problem = show.prepare(slop_file(str(tmp_path)), lab, seed=SEED, options={"allow_edits": True})
    assert replay.check.id == "pushed_out_of_crate" and replay.graded and replay.scene == "inside"
    assert replay.quantity.bound == lab.module.INSIDE_DEPTH
    last = replay.frames[-1]
    ball = next(b for b in last["bodies"] if b.get("radius"))
    crate_depth = max(records.circle_depth(ball["pos"], ball["radius"], b["points"])
                      for b in last["bodies"] if len(b["points"]) >= 3)
    assert replay.fail_frame == last["frame"] and crate_depth > lab.module.INSIDE_DEPTH
    assert replay.values[-1] == pytest.approx(crate_depth)
    viewer = show_view.run(replay, events=scripted([key(pygame.K_j)]), frames=2)
    assert viewer.frame["frame"] == replay.fail_frame


# ---------------------------------------------------------------- a function case drawn

def test_sat_case_draws_both_answers(tmp_path):
    corpus = importlib.import_module("corpus_tumbling_crates")
    path = tmp_path / "tumbling_crates.py"
    path.write_text(corpus.build("sat_largest_overlap"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("tumbling_crates"), seed=SEED)
    assert replay.check.id == "sat_axes" and replay.cases
    assert all(isinstance(c, show_cases.SatCase) for c in replay.cases)
    viewer = show_view.run(replay, events=scripted([]), frames=1)
    assert viewer.showing_cases   # a failed function check opens on its cases
    case = replay.cases[0]
    yours, lesson = case.answers()
    assert case.case["got"]["depth"] > case.case["lesson"]["depth"] + 1e-6   # the largest overlap, not the smallest
    assert f"{case.case['got']['depth']:.2f}" in yours and f"{case.case['lesson']['depth']:.2f}" in lesson
    surface = pygame.Surface(show_view.SCENE)
    case.draw(surface)
    colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900, 2) for y in range(0, 600, 2)}
    assert show_cases.STUDENT in colours and show_cases.LESSON in colours
    axis = case.view.axis_index
    case.key(pygame.K_n)
    assert case.view.axis_index == (axis + 1) % len(case.view.axes())


# ---------------------------------------------------------------- the command line

def test_no_display_is_refused_cleanly(monkeypatch, capsys, tmp_path):
    monkeypatch.setattr(pictures, "USER_VIDEO_DRIVER", None)
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    monkeypatch.setattr(sys, "platform", "linux")
    target = tmp_path / "tumbling_crates.py"
    target.write_text("# tumbling crates\n", encoding="utf-8")
    assert cli.main([str(target), "--show"]) == 2
    assert capsys.readouterr().err.strip() == "checker: error: no display: use --pictures DIR"
    assert show.display_problem({"DISPLAY": ":0"}, "linux") == ""
    assert show.display_problem({}, "win32") == ""


def test_a_file_that_does_not_load_gets_its_load_error(tmp_path, capsys):
    target = tmp_path / "tumbling_crates.py"
    target.write_text("import no_such_module_anywhere\n", encoding="utf-8")

    class Args:
        show, seed, timeout, memory, max_output, child_user, allow_edits = "", SEED, 20.0, 768, 256, None, False
        disk = 64

    from checker.entries import discover
    entries, _ = discover([str(target)])
    opened = []
    status = show.main(Args, entries, events=lambda: opened.append(1) or [], frames=1)
    out = capsys.readouterr().out
    assert status == 1 and not opened   # no window
    assert "no_such_module_anywhere" in out and ":( The file imports" in out
    assert "--show: the file does not load" in out


def test_centroid_case_draws_both_points(tmp_path):
    corpus = importlib.import_module("corpus_more_shapes")
    path = tmp_path / "more_shapes.py"
    path.write_text(corpus.build("centroid_average_of_corners"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("more_shapes"), seed=SEED)
    assert replay.check.id == "centroid" and replay.cases
    case = replay.cases[0]
    assert isinstance(case, show_cases.PolygonCase)
    assert case.case["got"] == pytest.approx(case.case["average"]) and case.case["got"] != case.case["want"]
    surface = pygame.Surface(show_view.SCENE)
    case.draw(surface)
    colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900) for y in range(0, 480)}
    assert show_cases.STUDENT in colours and show_cases.LESSON in colours


def test_failing_cases_draw_both_answers(shown):
    """Each lab's failed function check (impulse, inertia, swept move, sleep timer) opens on its cases, of the kind
    its corpus's SHOW_CASE names, and each case shows the student's answer (magenta) and the lesson's (yellow)."""
    lab, path, row, replay = shown
    kind = getattr(labs_found.corpus(lab), "SHOW_CASE", None)
    assert kind, f"{lab.id}: set SHOW_CASE in tests/corpus_{lab.id}.py to the class name of the case --show draws"
    assert replay.cases and all(type(c).__name__ == kind for c in replay.cases), (kind, replay.cases[:1])
    for case in replay.cases[:3]:
        surface = pygame.Surface(show_view.SCENE)
        case.draw(surface)
        colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900) for y in range(0, 470, 2)}
        assert show_cases.STUDENT in colours and show_cases.LESSON in colours, case.lines()
        assert case.lines()[1].startswith("yours") and case.lines()[2].startswith("the lesson")
    viewer = show_view.run(replay, events=scripted([key(pygame.K_RIGHTBRACKET)]), frames=1)
    assert viewer.showing_cases and viewer.case_index == min(1, len(replay.cases) - 1)


def test_time_of_impact_case_shows_both_times(tmp_path):
    corpus = importlib.import_module("corpus_bullets")
    path = tmp_path / "bullets.py"
    path.write_text(corpus.build("toi_later_root"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("bullets"), seed=SEED)
    assert replay.check.id == "toi_matches_root"
    case = next(c for c in replay.cases if c.geometry is not None)
    assert case.case["got"] > case.case["want"]   # the later root
    yours, lesson = case.lines()[1:3]
    assert f"{case.case['got'] * 1000:.4g} ms" in yours and f"{case.case['want'] * 1000:.4g} ms" in lesson
    surface = pygame.Surface(show_view.SCENE)
    case.draw(surface)
    colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900) for y in range(0, 470)}
    assert show_cases.STUDENT in colours and show_cases.LESSON in colours


@pytest.mark.parametrize("lab_id", labs_found.IDS)
def test_every_behaviour_check_has_a_quantity_the_solution_keeps(lab_id):
    """Each behaviour check with a scene has a quantity for the timeline; where it has a bound, the solution's
    own run of that scene never passes it (so a failing frame found by the bound is never a false mark)."""
    lab = lab_of(lab_id)
    for check_id, scenes in lab.picture_scenes.items():
        quantity = show_series.series_for(lab, check_id)
        assert quantity is not None, (lab_id, check_id)
        if quantity.bound is None:
            continue
        result = type("R", (), {"id": check_id, "message": ""})()
        for scene in scenes:
            frames = pictures.reference_record(lab, scene)["records"]
            fail_frame, why, _, values = show_series.failure(lab, result, frames, frames, True)
            assert fail_frame is None, (lab_id, check_id, scene, why, max(values))


def test_command_line_show_replays_and_returns(tmp_path):
    """`python -m checker FILE --show --seed N` as typed: with SDL's dummy driver the window plays the replay
    once and closes (a desktop keeps it open until Esc or the window is closed)."""
    from test_checker_pictures import run_checker
    path = wrong_file(str(tmp_path), "tumbling_crates")
    status, out, err = run_checker(path, "--show", "--seed", str(SEED))
    assert status == 1, err
    assert ":( Step 6" in out and f"graded with seed {SEED}" in out
    assert "--show: apply_impulse_spin (fail)" in out and "failing frame" in out
    # said while it prepares (the 2-10 s before the window), on stderr: the report on stdout stays as it was
    assert err.index(f"grading {path}...") < err.index("recording the replay")
    status, out, err = run_checker(path, "--show", "ramp_holds", "--seed", str(SEED))
    assert status == 1 and "--show: ramp_holds (skip)" in out


def test_resolve_case_draws_both_impulses(tmp_path):
    corpus = importlib.import_module("corpus_tumbling_crates")
    path = tmp_path / "tumbling_crates.py"
    path.write_text(corpus.build("k_only_a"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("tumbling_crates"), seed=SEED)
    assert replay.check.id == "resolve_k" and replay.cases
    case = replay.cases[0]
    assert isinstance(case, tumbling_crates_show.ResolveCase) and case.case["case"] in replay.check.message
    assert f"j = {case.case['j']:.4g}" in case.lines()[1] and not math.isclose(case.case["j"], case.lesson_j())
    surface = pygame.Surface(show_view.SCENE)
    case.draw(surface)
    colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900) for y in range(0, 470)}
    assert show_cases.STUDENT in colours and show_cases.LESSON in colours


def test_a_record_the_runtime_cannot_have_written_is_not_replayed():
    """The child writes the record the window replays: one that cannot be lesson11.runtime's (a string where a
    position belongs) is not drawn, and --show falls back to no scene instead of failing in the parent."""
    lab = lab_of("tumbling_crates")
    frames = pictures.reference_record(lab, "corner")["records"]
    forged = {"records": [dict(frames[0], bodies=[dict(b, pos=["x", 0]) for b in frames[0]["bodies"]])]}
    assert show.trusted_frames(lab, "corner", forged) == []
    assert show.trusted_frames(lab, "corner", {"records": frames}) == frames

    class Row:
        records, preview, seed, path = {"corner": forged}, "corner", SEED, "tumbling_crates.py"
        results = ()
    Row.lab = lab
    result = type("R", (), {"id": "apply_impulse_spin", "status": "fail", "message": "m"})()
    replay = show.build_replay(Row, result)
    assert replay.frames == [] and replay.scene is None and replay.fail_frame is None
    viewer = show_view.run(replay, events=scripted([key(pygame.K_j)]), frames=2)   # draws the "no scene" text
    assert viewer.frame is None


def test_sat_case_text_and_drawing_do_not_overlap(tmp_path):
    """Every failing sat() case, on every axis: nothing of the drawing (the shapes, both shadows, the overlap
    label, the lesson's MTV and the student's answer) lies under the explorer's explanation lines or the
    case's footer, which are drawn over it. Measured on the drawing alone (draw_scene), before the bands."""
    from lesson11 import explorer
    corpus = importlib.import_module("corpus_tumbling_crates")
    path = tmp_path / "tumbling_crates.py"
    path.write_text(corpus.build("sat_largest_overlap"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("tumbling_crates"), seed=SEED)
    colours = (explorer.BLUE, explorer.ORANGE, explorer.OVERLAP_RED, explorer.MTV_YELLOW, show_cases.STUDENT)
    for case in replay.cases:
        for axis in range(len(case.view.axes())):
            case.view.axis_index = axis
            surface = pygame.Surface(show_view.SCENE)
            case.draw_scene(surface)
            top, bottom = case.band()
            forbidden = pygame.mask.Mask(show_view.SCENE)
            # under the text: from below the status word (which the explorer draws in red) to the band,
            # and the footer
            forbidden.draw(pygame.mask.Mask((show_view.SCENE[0], top - case.MARGIN - 62), fill=True), (0, 62))
            footer = show_view.SCENE[1] - (bottom + case.MARGIN)
            forbidden.draw(pygame.mask.Mask((show_view.SCENE[0], footer), fill=True), (0, bottom + case.MARGIN))
            for colour in colours:
                drawn = pygame.mask.from_threshold(surface, colour, (2, 2, 2, 255))
                assert drawn.overlap_area(forbidden, (0, 0)) == 0, (case.lines()[0], axis, colour)
            assert max(case.font.size(line)[0] for line in case.header()) <= show_view.SCENE[0] - 20


def test_replay_title_fits_the_window(shown):
    """The replay's title lines (lab, check, scene, frame, mode) each fit the window's width."""
    lab, path, row, replay = shown
    viewer = show_view.Viewer(replay)
    viewer.showing_cases = False
    viewer.playing = False
    lines = viewer.hud_lines()
    if replay.frames:
        assert len(lines) >= 2 and replay.check.id in lines[0] and "PAUSED" in " ".join(lines)
    assert all(viewer.font.size(line)[0] <= show_view.SCENE[0] - 20 for line in lines[:-1])


# lab id, corpus entry with one wrong step, the check it fails, the kind of case --show draws for it
STEP_CASES = [
    ("more_shapes", "corners_in_degrees", "polygon_corners", more_shapes_show.CornersCase),
    ("more_shapes", "axes_same_way_only", "parallel_axes", more_shapes_show.AxesCase),
    ("bullets", "bounding_squared", "bounding_circle", bullets_show.BoundingCase),
    ("bullets", "broad_without_bullet_radius", "broad_test", bullets_show.BroadCase),
    ("bullets", "broad_test_missing", "broad_test", bullets_show.BroadCase),
    ("ball_on_ramp", "closest_not_clamped", "closest_point", ball_on_ramp_show.ClosestCase),
    ("ball_on_ramp", "inside_not_flipped", "inside_case", ball_on_ramp_show.CircleCase),
    ("ball_on_ramp", "push_not_split", "push_out_split", ball_on_ramp_show.SeparateCase),
    ("ball_on_ramp", "inertia_ring", "ball_inertia", show_cases.PolygonCase),
    ("ball_on_ramp", "contact_halfway", "contact_on_surface", ball_on_ramp_show.ContactCase),
    ("ball_on_ramp", "friction_not_clamped", "friction_rolls", show_cases.ImpulseCase),
    ("sleeping_crates", "timer_or", "timer_rule", sleeping_crates_show.TimerCase),
    ("sleeping_crates", "moves_ignores_sleep", "skips_sleepers", sleeping_crates_show.MovesCase),
    ("sleeping_crates", "wake_one_order", "wakes_on_contact", sleeping_crates_show.WakeCase),
]


@pytest.mark.parametrize("lab_id, entry, check, kind", STEP_CASES, ids=[c[1] for c in STEP_CASES])
def test_a_wrong_step_opens_on_its_case_with_both_answers(tmp_path, lab_id, entry, check, kind):
    """A file of the mistake corpus with one wrong step: --show (graded as the checker grades it, keys scripted)
    opens on that step's failing cases, the drawing above the case's text carries the student's answer (magenta)
    and the lesson's (yellow), the text names both and they differ, and ] steps to the next case.
    (Bullets' other steps: test_time_of_impact_case_shows_both_times, test_a_drawn_time_of_impact_case_has_its_geometry,
    and the swept move in test_failing_cases_draw_both_answers.)"""
    corpus = importlib.import_module(f"corpus_{lab_id}")
    assert next(e for e in corpus.WRONG if e.name == entry).check == check   # the corpus's own verdict
    path = tmp_path / f"{lab_id}.py"
    path.write_text(corpus.build(entry), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of(lab_id), seed=SEED)
    assert problem == "" and replay.check.id == check
    assert replay.cases and all(isinstance(c, kind) for c in replay.cases)
    viewer = show_view.run(replay, events=scripted([]), frames=1)
    assert viewer.showing_cases and viewer.case is replay.cases[0]
    for case in replay.cases[:3]:
        surface = pygame.Surface(show_view.SCENE)
        case.draw(surface)
        lines = case.lines()
        drawing = show_kit.footer_top(len(lines))   # the text band starts here: look above it only
        colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900) for y in range(0, drawing, 2)}
        assert show_cases.STUDENT in colours and show_cases.LESSON in colours, lines
        assert lines[1].startswith("yours") and lines[2].startswith("the lesson")
        yours = [line.split(":", 1)[1] for line in lines if line.startswith("yours")]
        lesson = [line.split(":", 1)[1] for line in lines if line.startswith("the lesson")]
        assert yours != lesson   # (an impulse case has a line per body: a static one may agree)
    if len(replay.cases) > 1:
        viewer = show_view.run(replay, events=scripted([key(pygame.K_RIGHTBRACKET)]), frames=1)
        assert viewer.case is replay.cases[1]


def test_a_drawn_time_of_impact_case_has_its_geometry(tmp_path):
    """circle_toi cases drawn for the run are redrawn on the grading side from the grading seed: the paths --show
    draws are the graded ones (their first contact, solved here, is the lesson's time the probe recorded)."""
    corpus = importlib.import_module("corpus_bullets")
    path = tmp_path / "bullets.py"
    path.write_text(corpus.build("toi_later_root"), encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("bullets"), seed=SEED)
    drawn = [c for c in replay.cases if "drawn for this run" in c.case["case"]]
    assert drawn and all(c.geometry is not None for c in drawn)
    for case in drawn:
        p1, v1, r1, p2, v2, r2 = case.geometry
        dp, dv = p2 - p1, v2 - v1
        a, b, c = dv.dot(dv), 2 * dp.dot(dv), dp.dot(dp) - (r1 + r2) ** 2
        first = (-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)
        assert first == pytest.approx(case.case["want"], abs=1e-9)
        surface = pygame.Surface(show_view.SCENE)
        case.draw(surface)
        colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900) for y in range(0, 390, 2)}
        assert show_cases.STUDENT in colours and show_cases.LESSON in colours   # both circles at both times
    other = bullets_show._toi_geometry(drawn[0].case, SEED + 1)   # another seed draws other paths: not used
    assert other is None


def test_more_shapes_sat_on_the_students_axes_is_drawn_as_a_sat_case():
    """parallel_axes also fails when every axis is right but sat() on them is not (the probe's "sat" data): those
    pairs are drawn as SAT cases with the pair's shapes from the probe's own list, both answers on the picture.
    The probe data here are made by hand (no corpus file fails that way): the lesson's answer from the grader's
    reference_sat, the student's with the depth doubled."""
    from checker.judging import probe_kit
    from checker.labs.more_shapes import probes
    name, a, b = probes.axis_pairs()[0]   # two aligned boxes, overlapping
    normal, depth = probe_kit.reference_sat(a, b)
    want = {"normal": list(normal), "depth": depth}
    wrong = {"pair": name, "order": "B, A", "got": {"normal": list(normal), "depth": 2 * depth}, "want": want,
             "ties": []}
    right = dict(wrong, order="A, B", got=want)
    functions = {"separating_axes": {"ok": True, "data": []}, "sat": {"ok": True, "data": [right, wrong]}}
    result = type("R", (), {"id": "parallel_axes", "status": "fail", "message": ""})()
    cases = show_cases.failing_cases(lab_of("more_shapes"), result, functions)
    assert len(cases) == 1 and isinstance(cases[0], show_cases.SatCase)
    case = cases[0]
    assert [list(p) for p in case.case["a"]] == [list(p) for p in b]   # B, A: the shapes swapped
    yours, lesson = case.answers()
    assert f"{2 * depth:.2f}" in yours and f"{depth:.2f}" in lesson
    surface = pygame.Surface(show_view.SCENE)
    case.draw(surface)
    top = case.band()[0]
    colours = {tuple(surface.get_at((x, y)))[:3] for x in range(0, 900, 2) for y in range(top, case.band()[1], 2)}
    assert show_cases.STUDENT in colours and show_cases.LESSON in colours


# ---------------------------------------------------------------- the lab's solver panel, read-only

PANEL_KEYS = (pygame.K_s, pygame.K_UP, pygame.K_DOWN, pygame.K_w, pygame.K_c, pygame.K_k, pygame.K_0)


def panel_text(viewer):
    """The texts on the --show window's solver panel as drawn now (after a draw)."""
    return [words for _, words in viewer.panel.placed]


def moving_boxes(frame, viewer):
    """Screen rectangles of a recorded frame's moving bodies (computed here from the record's corners)."""
    boxes = []
    for body in frame["bodies"]:
        if body["static"]:
            continue
        points = body["points"] or [[body["pos"][0] - body["radius"], body["pos"][1] - body["radius"]],
                                    [body["pos"][0] + body["radius"], body["pos"][1] + body["radius"]]]
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        boxes.append(pygame.Rect(min(xs), min(ys), max(xs) - min(xs) + 1, max(ys) - min(ys) + 1))
    return boxes


def test_the_panel_shows_the_recorded_settings(shown):
    """Every lab: the runtime recorded the World's settings with the frames (the panel's advance() noted them in
    the child), the window draws the lab's solver panel with them (the solution's agree: one wrong step changes
    no setting), says "replay" and shows no timing, and the panel stays clear of the title, of the timeline and
    of the moving bodies (both runs') at the failing frame."""
    lab, path, row, replay = shown
    assert replay.frames and all(s is not None for s in replay.settings) and not replay.settings_note
    mine, theirs = replay.settings_at(replay.index_of(replay.fail_frame))
    assert mine == theirs and set(mine) == set(lab_checks.WORLD_SETTINGS)
    assert mine["solver"] == "lesson" and mine["iterations"] == 6 and mine["step_seconds"] == pytest.approx(1 / 120)
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.run(replay, events=scripted([key(pygame.K_TAB)] * bool(replay.cases), [key(pygame.K_j)]),
                           frames=2)
    assert viewer.frame["frame"] == replay.fail_frame and not viewer.showing_cases
    texts = panel_text(viewer)
    assert "solver panel (replay)" in texts and "replay: recorded settings, no timing measured" in texts
    assert "lesson" in texts and str(mine["iterations"]) in texts and str(mine["substeps"]) in texts
    assert not any("ms/step" in t or "real time" in t or "PAUSED" in t for t in texts)
    box = viewer.panel.box
    assert box.top >= viewer.hud_bottom() and box.bottom <= show_view.SCENE[1] and box.right <= show_view.SCENE[0]
    for frame in (viewer.frame, viewer.reference_frame):
        assert box.collidelist(moving_boxes(frame, viewer)) == -1, (lab.id, box)


def test_panel_keys_change_nothing_in_a_replay_and_the_shows_keys_still_work(shown):
    """S, Up, Down, W, C, K and 0 (the live panel's setting keys) change neither the frame, nor the settings, nor
    the panel drawn; H cycles its size (compact, full, hidden); P, O, J, G and Tab do what they do without it."""
    lab, path, row, replay = shown
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.Viewer(replay)
    viewer.showing_cases = False
    viewer.playing = False
    surface = pygame.Surface(show_view.SIZE)
    viewer.draw(surface)
    before = (viewer.index, list(replay.settings), panel_text(viewer), surface.copy())
    for k in PANEL_KEYS:
        assert viewer.handle(key(k))
    viewer.draw(surface)
    assert (viewer.index, replay.settings, panel_text(viewer)) == before[:3]
    assert pygame.image.tobytes(surface, "RGB") == pygame.image.tobytes(before[3], "RGB")
    viewer.handle(key(pygame.K_h))
    viewer.draw(surface)
    assert viewer.panel.mode == "full" and "SOLVER PANEL (replay)" in panel_text(viewer)
    assert "keys S, Up/Down, W, C, K, 0 change nothing here" in panel_text(viewer)
    viewer.handle(key(pygame.K_h))
    viewer.draw(surface)
    assert viewer.panel.mode == "hidden" and viewer.panel.box is None
    viewer = show_view.run(replay, events=scripted([key(pygame.K_p)], [key(k) for k in PANEL_KEYS],
                                                   [key(pygame.K_o)], [key(pygame.K_g)]), frames=5)
    assert viewer.index == 1 and not viewer.playing and viewer.side_by_side
    viewer = show_view.run(replay, events=scripted([key(k) for k in PANEL_KEYS] + [key(pygame.K_j)]), frames=1)
    assert viewer.frame["frame"] == replay.fail_frame
    if replay.cases:
        viewer = show_view.run(replay, events=scripted([key(k) for k in PANEL_KEYS] + [key(pygame.K_TAB)]),
                               frames=1)
        assert viewer.showing_cases != (bool(replay.cases) and not replay.graded)


def with_swept_iterations(folder):
    """Bullets with step 5 wrong (the whole dt after the impact) and `world.iterations = 2` in that step, as a
    student trying things might write: a World the step is handed, changed at the first hit."""
    corpus = importlib.import_module("corpus_bullets")
    source = corpus.build("swept_whole_step_after")
    hit = "    bullet.pos += bullet.vel * t\n"
    assert source.count(hit) == 1
    path = os.path.join(folder, "bullets.py")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(source.replace(hit, "    world.iterations = 2\n" + hit))
    return path


def test_a_world_the_students_code_changed_shows_its_settings(tmp_path):
    """The student's swept_move() sets world.iterations = 2 at the first hit: the replay's settings say 6 until
    then and 2 after, the solution's stay 6, and the panel draws "2" with "solution 6" beside it."""
    row, replay, problem = show.prepare(with_swept_iterations(str(tmp_path)), lab_of("bullets"), seed=SEED)
    assert replay.check.id == "swept_move_resolves" and replay.frames
    counts = [s["iterations"] for s in replay.settings]
    assert counts[0] == 6 and counts[-1] == 2 and counts == sorted(counts, reverse=True)
    assert all(s["iterations"] == 6 for s in replay.reference_settings)
    changed = counts.index(2)
    pygame.display.init()
    pygame.font.init()
    viewer = show_view.Viewer(replay)
    viewer.showing_cases, viewer.playing, viewer.index = False, False, changed
    viewer.draw(pygame.Surface(show_view.SIZE))
    texts = panel_text(viewer)
    assert "2" in texts and "solution 6" in texts
    viewer.index = 0
    viewer.draw(pygame.Surface(show_view.SIZE))
    assert "solution 6" not in panel_text(viewer) and "6" in panel_text(viewer)


GOOD_WORLD = {"solver": "lesson", "order": "solve-first", "iterations": 6, "substeps": 4, "warm_starting": True,
              "correction": True, "contact_rule": "corners", "effects": ["correction", "gravity"],
              "step_seconds": 1 / 120}
FORGED_WORLDS = [
    ("not a mapping", "z" * 1_000_000, "not a mapping"),
    ("too many settings", {f"k{i}": i for i in range(10_000)}, "more than the 9"),
    ("one more setting", dict(GOOD_WORLD, speed_hack=1), "10 settings, more than the 9"),
    ("unknown setting", dict({k: v for k, v in GOOD_WORLD.items() if k != "order"}, speed_hack=1),
     "unknown setting 'speed_hack'"),
    ("a megabyte string", dict(GOOD_WORLD, solver="x" * 1_000_000), "solver cannot be 'xxxxxxxxxx"),
    ("a bool for a count", dict(GOOD_WORLD, iterations=True), "iterations cannot be True"),
    ("a count out of range", dict(GOOD_WORLD, substeps=10 ** 9), "substeps cannot be 1000000000"),
    ("a float count", dict(GOOD_WORLD, iterations=2.0), "iterations cannot be 2.0"),
    ("no step", dict(GOOD_WORLD, step_seconds=float("nan")), "step_seconds cannot be nan"),
    ("an unknown effect", dict(GOOD_WORLD, effects=["gravity", "telekinesis"]), "effects cannot be a list"),
    ("a repeated effect", dict(GOOD_WORLD, effects=["gravity"] * 5), "effects cannot be a list"),
    ("correction not in effects", dict(GOOD_WORLD, correction=False), "correction disagrees"),
    ("a setting missing", {k: v for k, v in GOOD_WORLD.items() if k != "order"}, "no order"),
    ("nested data", dict(GOOD_WORLD, order=[[["solve-first"]]] * 1000), "order cannot be a list"),
]


@pytest.mark.parametrize("what, forged, words", FORGED_WORLDS, ids=[w[0] for w in FORGED_WORLDS])
def test_a_forged_settings_record_is_ignored_with_a_short_note(what, forged, words):
    """The child writes "world": the parent keeps a good one, and ignores a forged one from its frame on (until a
    good one comes again) with a one-line note naming the frame and what is wrong, short whatever the forgery."""
    frames = [{"frame": 1, "world": GOOD_WORLD}, {"frame": 2}, {"frame": 3, "world": forged}, {"frame": 4},
              {"frame": 5, "world": dict(GOOD_WORLD, iterations=3)}]
    settings, note = lab_checks.world_settings(frames)
    assert settings[:2] == [GOOD_WORLD, GOOD_WORLD] and settings[2:4] == [None, None]
    assert settings[4] == dict(GOOD_WORLD, iterations=3)
    assert note.startswith("the World's settings recorded at frame 3 are ignored: ") and words in note, note
    assert len(note) < 160 and "\n" not in note


def test_a_forged_settings_record_from_the_child_is_ignored_in_the_window(tmp_path):
    """A file that writes the runtime's noted settings itself (an edit outside the steps, graded with
    --allow-edits: `lab._world = {...}` with ten thousand made-up settings and a megabyte string) and gets step 6
    wrong: --show replays the scene it ran, the forged settings are ignored with a note (printed, and on the
    panel instead of settings), and nothing crashes; the solution's settings stay as recorded."""
    corpus = importlib.import_module("corpus_tumbling_crates")
    source = corpus.build("spin_missing")
    advance = "        simulated += panel.advance(world, dt) * world.step_seconds"
    assert source.count(advance) == 1
    forged = '        lab._world = {"iterations": "x" * 1000000, **{f"k{i}": i for i in range(10000)}}\n'
    line_end = source.index("\n", source.index(advance)) + 1
    path = tmp_path / "tumbling_crates.py"
    path.write_text(source[:line_end] + forged + source[line_end:], encoding="utf-8")
    row, replay, problem = show.prepare(str(path), lab_of("tumbling_crates"), seed=SEED,
                                        options={"allow_edits": True})
    assert replay.check.id == "apply_impulse_spin" and replay.frames
    assert all(s is None for s in replay.settings) and all(s is not None for s in replay.reference_settings)
    note = replay.settings_note
    assert note == "yours: the World's settings recorded at frame 1 are ignored: 10001 settings, more than the 9 " \
                   "a World has"
    assert f"  solver panel: {note}" in replay.summary()
    viewer = show_view.run(replay, events=scripted([key(pygame.K_TAB)], [key(pygame.K_j)]), frames=2)
    texts = panel_text(viewer)
    assert "settings ignored for this frame:" in texts and "6" not in texts
    assert "replay: recorded settings, no timing measured" in texts


def test_a_run_without_the_panel_shows_no_settings():
    """A lab whose loop calls world.advance() itself (no panel line) records no "world": nothing is made up, the
    panel says so, and there is no note (nothing was ignored)."""
    lab = lab_of("tumbling_crates")
    frames = [{k: v for k, v in f.items() if k != "world"} for f in pictures.reference_record(lab, "corner")["records"]]

    class Row:
        records, preview, seed, path = {"corner": {"records": frames}}, "corner", SEED, "tumbling_crates.py"
        results = ()
    Row.lab = lab
    result = type("R", (), {"id": "apply_impulse_spin", "status": "fail", "message": "m"})()
    replay = show.build_replay(Row, result)
    assert replay.frames == frames and replay.settings == [None] * len(frames) and replay.settings_note == ""
    assert all(s is not None for s in replay.reference_settings)
    viewer = show_view.run(replay, events=scripted([key(pygame.K_p)]), frames=1)
    texts = panel_text(viewer)
    assert "settings not recorded for this frame" in texts and "lesson" not in texts
