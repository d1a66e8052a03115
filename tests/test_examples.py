"""The lesson's programs in lesson11/examples print the lesson's numbers."""
import os
import subprocess
import sys

import pytest

from lesson11.examples import EXAMPLES
from lesson11.physics2d import Body, Circle, circle_polygon, separate

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The lines each script must print, in order: the lesson's numbers in the lesson's format.
LESSON_LINES = {
    "sat_three_pairs": [
        "side by side, 10 px overlap: overlap 10.00 px along (1.00, 0.00)",
        "diamond near a corner: apart",
        "diamond pushed closer: overlap 5.86 px along (0.71, 0.71)",
    ],
    "box_inertia": [
        "box formula m (w² + h²) / 12:  I = 216.67",
        "polygon_inertia(corners, m):   I = 216.67",
        "Body(...).inertia:             I = 216.67, inv_inertia = 0.004615",
    ],
    "ball_on_ramp": [
        "normal (0.29, 0.96), depth 4.34 px",
        "after the push: apart",  # the lesson's listing printed "depth 0.000 px": see TOUCH_TOLERANCE
        "ball moved to (98.75, 57.85); the static ramp stayed at (133.33, 80.00)",
    ],
    "bullet_swept": [
        "discrete: bullet jumps from x=0 to x=100; overlaps at the end? False",
        "swept: first contact at t = 17.67 ms, bullet at x = 53.0",
        "sub-stepping x2: checks every 50.0 px; catches the hit? False",
        "sub-stepping x4: checks every 25.0 px; catches the hit? False",
        "sub-stepping x8: checks every 12.5 px; catches the hit? True",
    ],
}


def run_module(*args):
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.run([sys.executable, "-m", *args], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=60)


def test_every_example_is_listed_and_checked():
    names = {name for name, _ in EXAMPLES}
    files = {f[:-3] for f in os.listdir(os.path.join(ROOT, "lesson11", "examples"))
             if f.endswith(".py") and not f.startswith("__")}
    assert names == files == set(LESSON_LINES)


@pytest.mark.parametrize("name", sorted(LESSON_LINES))
def test_example_prints_the_lesson_numbers(name):
    result = run_module(f"lesson11.examples.{name}")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert result.stdout.splitlines() == LESSON_LINES[name]


def test_runner_runs_all_with_headings_and_rejects_unknown_names():
    result = run_module("lesson11.examples")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    headings = [line for line in lines if line.startswith("== ")]
    assert [h.split(":")[0][3:] for h in headings] == [name for name, _ in EXAMPLES]
    for expected in LESSON_LINES.values():
        assert all(line in lines for line in expected)
    picked = run_module("lesson11.examples", "bullet_swept")
    assert picked.stdout.splitlines()[1:3] == LESSON_LINES["bullet_swept"][:2]
    assert sum(line.startswith("== ") for line in picked.stdout.splitlines()) == 1
    bad = run_module("lesson11.examples", "no_such_example")
    assert bad.returncode == 2
    assert bad.stdout == ""
    assert bad.stderr.strip().count("\n") == 0 and "no_such_example" in bad.stderr


def test_ball_push_out_moves_only_the_ball_by_exactly_the_depth():
    ramp = Body.from_world_points([(0, 100), (200, 40), (200, 100)], mass=0)
    ball = Body(Circle(12), (100, 62), 2)
    normal, depth = circle_polygon(ball.pos, 12, ramp.world_points())
    start, ramp_start = ball.pos.copy(), ramp.pos.copy()
    separate(ball, ramp, normal, depth, slop=0, percent=1)
    assert (ball.pos - start).length() == pytest.approx(depth, abs=1e-9)
    assert (ball.pos - start).normalize().dot(normal) == pytest.approx(-1.0, abs=1e-12)
    assert ramp.pos == ramp_start
    assert circle_polygon(ball.pos, 12, ramp.world_points()) is None
    # one hundredth of a pixel back towards the ramp, and they overlap again by that much
    closer = circle_polygon(ball.pos + normal * 0.01, 12, ramp.world_points())
    assert closer is not None and closer[1] == pytest.approx(0.01, abs=1e-6)


def test_lesson_text_quotes_what_the_examples_print_and_its_links_resolve():
    import re
    text = open(os.path.join(ROOT, "lesson11", "README.md"), encoding="utf-8").read()
    # the ball's push-out is quoted on its lab's page, beside the lab that builds it
    text += open(os.path.join(ROOT, "lesson11", "labs", "ball_on_ramp.md"), encoding="utf-8").read()
    for name, lines in LESSON_LINES.items():
        for line in lines:
            if not line.startswith("Body(") and not line.startswith("box formula") and \
                    not line.startswith("polygon_inertia("):
                assert line in text, f"lesson11/README.md (or a lab page) does not quote {name}: {line!r}"
    assert "I = 216.67" in text
    for folder, readme in (("lesson11", "README.md"), ("lesson11/examples", "README.md")):
        body = open(os.path.join(ROOT, folder, readme), encoding="utf-8").read()
        targets = re.findall(r"\]\(([^)#\s]+)", body)
        assert targets
        for target in targets:
            path = os.path.normpath(os.path.join(ROOT, folder, target))
            if path.startswith(os.path.join(ROOT, "starters")) or path.startswith(os.path.join(ROOT, "checker")):
                continue  # the exercise's starter and the checker are other parts of the bundle
            assert os.path.exists(path), f"{folder}/{readme} links to missing {target}"
