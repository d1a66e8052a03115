"""Pictures of failed behaviour checks (issue 14 §2): checker/replay/pictures.py and --pictures.

One Ball on the Ramp file fails one scene cheaply: the solution with the
push-out's SLOP raised from 0.5 to 6 px (graded with allow_edits), so a ball
started inside a crate stays 5.9 px into it and pushed_out_of_crate fails
while every function check passes. It is graded once (about 3 CPU s, plus
one run of the solution's scene for the bottom row); the solution itself once
more to show a passing file gets no picture. The --pictures refusals stop
before anything is graded.
"""
import io
import os
import subprocess
import tempfile
import sys

import pygame
import pytest

from checker import labs
from checker.replay import pictures, show_series
from checker.reporting import report
from checker.grade import Grader

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "ball_on_ramp.py")
LAB = next(lab for lab in labs.LABS if lab.id == "ball_on_ramp")
MAX_BYTES = 150_000


def slop_file(folder):
    """The solution with SLOP = 6.0: passes every function check, fails pushed_out_of_crate."""
    with open(SOLUTION, encoding="utf-8") as handle:
        text = handle.read()
    assert "SLOP = 0.5 " in text
    path = os.path.join(folder, "ball_on_ramp.py")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(text.replace("SLOP = 0.5 ", "SLOP = 6.0 ", 1))
    return path


@pytest.fixture(scope="module")
def failing(tmp_path_factory):
    path = slop_file(str(tmp_path_factory.mktemp("slop")))
    report = Grader(options={"allow_edits": True}, keep_records=True).grade(path, LAB)
    by_id = {r.id: r for r in report.results}
    assert by_id["closest_point"].status == "pass" and by_id["pushed_out_of_crate"].status == "fail", \
        [(r.id, r.status) for r in report.results]
    return report


def load(png):
    return pygame.image.load(io.BytesIO(png), "picture.png")


def test_failed_criterion_gets_a_small_filmstrip_of_frames(failing):
    assert [r.id for r in pictures.pictured_results(failing)] == ["pushed_out_of_crate"]
    shown = pictures.pictures_for(failing, "pushed_out_of_crate")
    assert [p.scene for p in shown] == ["inside"]
    png = shown[0].png
    assert png.startswith(b"\x89PNG") and 2_000 < len(png) < MAX_BYTES
    image = load(png)
    width, height = image.get_size()
    # a row of frames for the file and one for the solution
    assert width >= pictures.FRAMES * pictures.TILE[0] and height >= 2 * pictures.TILE[1]
    assert width <= 1600 and height <= 500
    colours = {tuple(image.get_at((x, y)))[:3] for x in range(0, width, 3) for y in range(0, height, 3)}
    assert len(colours) > 8, "the picture is blank"
    # moving bodies are drawn in both rows in the lab's own colours (recorded with the frames), contacts in red
    half = height // 2
    rows = [{tuple(image.get_at((x, y)))[:3] for x in range(0, width, 2) for y in range(lo, hi, 2)}
            for lo, hi in ((0, half), (half, height))]
    own = {tuple(b["color"]) for b in failing.records["inside"]["records"][0]["bodies"] if not b["static"]}
    assert own and all(own & row for row in rows)
    assert pictures.CONTACT in rows[0]


def test_base64_and_prairielearn_images(failing):
    import base64
    strings = pictures.base64_pngs(failing, "pushed_out_of_crate")
    assert len(strings) == 1 and base64.b64decode(strings[0]).startswith(b"\x89PNG")
    images = pictures.prairielearn_images(failing, "pushed_out_of_crate")
    assert images[0]["url"].startswith("data:image/png;base64,") and "inside" in images[0]["label"]
    assert pictures.pictures_for(failing, "closest_point") == []   # a passing function check: none


def test_marked_frame_is_read_from_the_message():
    class R:
        message = "the ball sank 3.2 px into the ramp (at frame 42; bound 1 px)."
    assert show_series.marked_frame(R) == 42
    frames = [{"frame": k, "bodies": [], "touching": []} for k in range(1, 101)]
    picked = pictures._pick(frames, 42)
    assert len(picked) == pictures.FRAMES and any(f["frame"] == 42 for f in picked)
    # from a little before the failing frame to a little after it (issue 30 item 4)
    assert picked[0]["frame"] == 42 - pictures.LEAD and picked[-1]["frame"] == 42 + pictures.TRAIL
    whole = pictures._pick(frames)
    assert whole[0]["frame"] == 1 and whole[-1]["frame"] == 100


def test_passing_file_gets_no_picture():
    report = Grader(keep_records=True).grade(SOLUTION, LAB)
    assert report.passed and report.records == {}    # nothing failed: no scene kept ...
    assert pictures.all_pictures([report]) == {}     # ... and no picture


def test_records_are_kept_only_when_asked(failing):
    assert set(failing.records) == {"inside"}       # only the failed check's scene is kept
    assert Grader().keep_records is False


def test_every_lab_declares_scenes_it_has():
    for lab in labs.LABS:
        ids = {c.id for c in lab.checks.checks}
        for check_id, scenes in lab.picture_scenes.items():
            assert check_id in ids and set(scenes) <= set(lab.scenarios()), (lab.id, check_id)


def run_checker(*args):
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               PYTHONDONTWRITEBYTECODE="1")
    proc = subprocess.run([sys.executable, "-m", "checker", *args], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=300)
    return proc.returncode, proc.stdout, proc.stderr


def test_pictures_refuses_bad_folders(tmp_path):
    graded = tmp_path / "class"
    graded.mkdir()
    lab = graded / "ball_on_ramp.py"
    lab.write_text("# not a lab\n")
    for target, words in ((graded / "pics", "a folder being graded"), (graded, "being graded"),
                          (lab, "refusing to write to a .py file"), (tmp_path / "no" / "pics", "does not exist")):
        status, out, err = run_checker(str(graded), "--pictures", str(target))
        assert status == 2 and words in err, (target, err)
    status, out, err = run_checker(str(graded), "--pictures", "")
    assert status == 2 and "needs a path" in err
    assert sorted(os.listdir(graded)) == ["ball_on_ramp.py"] and not (tmp_path / "no").exists()


def test_cli_writes_links_and_embeds_in_gradescope(tmp_path):
    folder = tmp_path / "bob"
    folder.mkdir()
    path = slop_file(str(folder))
    out = tmp_path / "pics"
    status, text, err = run_checker(path, "--allow-edits", "--pictures", str(out),
                                    "--gradescope", str(tmp_path / "results.json"))
    assert status == 1, err
    png = out / "ball_on_ramp" / "pushed_out_of_crate.png"
    assert png.is_file() and png.stat().st_size < MAX_BYTES
    assert f"picture {png}" in text
    import json
    tests = json.loads((tmp_path / "results.json").read_text())["tests"]
    pictured = [t for t in tests if t.get("output_format") == "html"]
    assert len(pictured) == 1 and 'src="data:image/png;base64,' in pictured[0]["output"]
    assert "<pre>" in pictured[0]["output"] and "depth 5.9 px" in pictured[0]["output"]


def test_json_lists_picture_paths_only_with_pictures(failing):
    plain = report.to_json([failing])
    assert all("pictures" not in c for c in plain["labs"][0]["criteria"])
    shown = report.to_json([failing], pictures={failing.path: {"pushed_out_of_crate": ["p/x.png"]}})
    criteria = {c["id"]: c for c in shown["labs"][0]["criteria"]}
    assert criteria["pushed_out_of_crate"]["pictures"] == ["p/x.png"]
    assert all(c["pictures"] == [] for i, c in criteria.items() if i != "pushed_out_of_crate")
    for c in criteria.values():  # otherwise the schema is unchanged
        del c["pictures"]
    assert shown == plain


def test_a_file_failing_a_function_check_gets_its_labs_scene_ungraded():
    """Scenes run only when every function check passes, so the files that need a picture most had none. With
    pictures asked for, a file that loads but fails a step gets the lab's first scene, run for the picture only:
    its crates beside the solution's, titled "not graded"; its score is the same as without pictures."""
    import corpus_tumbling_crates as corpus
    crates = next(lab for lab in labs.LABS if lab.id == "tumbling_crates")
    starter = open(os.path.join(ROOT, "starters", "tumbling_crates_starter.py"), encoding="utf-8").read()
    codes = corpus.step_code(open(crates.solution, encoding="utf-8").read())
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "tumbling_crates.py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(corpus.fill(starter, {2: codes[2]}))    # step 2 done: step 3's normal still unflipped
        with_pictures = Grader(keep_records=True).grade(path, crates)
        without = Grader().grade(path, crates)
    assert [(r.id, r.status, r.score) for r in with_pictures.results] == \
        [(r.id, r.status, r.score) for r in without.results]      # the picture's run grades nothing
    assert with_pictures.preview == crates.preview_scene == "corner" and not without.preview
    found = pictures.all_pictures([with_pictures])[with_pictures.path]
    assert list(found) == ["sat_normal"]                          # the first failed check, one picture
    picture = found["sat_normal"][0]
    assert picture.scene == "corner" and picture.png.startswith(b"\x89PNG")
    frames = with_pictures.records["corner"]["records"]
    assert all(body["pos"][1] > 600 for body in frames[-1]["bodies"] if not body["static"])   # fell through


def test_a_file_that_does_not_load_gets_no_picture():
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "ball_on_ramp.py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write("raise RuntimeError('boom')\n")
        report = Grader(keep_records=True).grade(path, LAB)
    assert report.preview == "" and pictures.all_pictures([report]) == {}


def test_pictures_follow_the_failure(failing, monkeypatch):
    """Issue 30 item 4: the filmstrip starts a little before the failing frame and ends after it, frames the
    bodies the check is about, and its caption names the frame and the quantity; the HTML report links it."""
    from checker.reporting import html_report
    frames = failing.records["inside"]["records"]
    result = next(r for r in failing.results if r.id == "pushed_out_of_crate")
    reference = pictures.reference_record(LAB, "inside")["records"]
    fail_frame, why, quantity, values = show_series.failure(LAB, result, frames, reference, True)
    assert fail_frame == frames[-1]["frame"] and quantity.bound == LAB.module.INSIDE_DEPTH   # judged at the end
    drawn = {}
    original = pictures.filmstrip

    def spy(record, reference=None, marked=None, title="", count=pictures.FRAMES, focus=None):
        drawn.update(marked=marked, title=title, focus=focus, shown=pictures._pick(record["records"], marked))
        return original(record, reference, marked, title, count, focus)

    monkeypatch.setattr(pictures, "filmstrip", spy)
    assert pictures.pictures_for(failing, "pushed_out_of_crate")
    assert drawn["marked"] == fail_frame
    assert f"frame {fail_frame} " in drawn["title"] and f"{quantity.label} {values[-1]:.3g}" in drawn["title"]
    numbers = [f["frame"] for f in drawn["shown"]]
    assert numbers[0] >= fail_frame - pictures.LEAD and fail_frame in numbers
    ball = next(i for i, b in enumerate(frames[-1]["bodies"]) if b.get("radius"))
    assert ball in drawn["focus"]   # the ball, which ends elsewhere than the solution's, is framed
    made = {failing.path: {"pushed_out_of_crate": pictures.pictures_for(failing, "pushed_out_of_crate")}}
    page = html_report.html_text([failing], made)
    anchor = html_report.picture_id(0, "pushed_out_of_crate")
    assert f'href="#{anchor}"' in page and f'id="{anchor}"' in page
