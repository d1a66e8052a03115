"""Every lab's starter is its solution with the student's steps left to write (one table, LABS).

Step regions are the lines between `# --- step N: ... ---` and
`# --- end of step N ---`. The solution is the lab's one source: each region
opens with its prompt block, and `python -m checker assign` (checker/authoring/assign.py)
writes the starter from it; the committed starter must be byte for byte what
it writes. Outside the regions the two files are then identical line by line
(module docstring included); inside, the solution has code and the starter
only comments and the one-line placeholders that keep it running.
How each starter runs as handed out is tested here for Tumbling Crates and
in test_more_shapes_starter.py / test_ball_on_ramp_starter.py for the others.
"""
import os
import re

import pytest

from checker.authoring import assign
from checker.reading import source
from lab_run import HEIGHT, ROOT, SOLUTION, STARTER, clicks, run_lab

START = re.compile(r"^\s*# --- step (\d): .+ ---$")
END = re.compile(r"^\s*# --- end of step (\d) ---$")


def split_regions(path):
    """(lines outside the step regions, marker lines kept; {step: lines inside}) of one file."""
    outside, regions, current = [], {}, None
    with open(path, encoding="utf-8") as handle:
        for number, line in enumerate(handle.read().splitlines(), 1):
            start, end = START.match(line), END.match(line)
            if start:
                assert current is None, f"{path}:{number}: step {start[1]} starts inside step {current}"
                assert start[1] not in regions, f"{path}:{number}: step {start[1]} appears twice"
                current = start[1]
                regions[current] = []
                outside.append(line)
            elif end:
                assert end[1] == current, f"{path}:{number}: end of step {end[1]} without its start"
                current = None
                outside.append(line)
            elif current is not None:
                regions[current].append(line)
            else:
                outside.append(line)
    assert current is None, f"{path}: step {current} is never ended"
    return outside, regions


def code_lines(lines):
    """The lines that are neither blank nor comments, stripped, with any trailing comment removed."""
    out = []
    for line in lines:
        text = line.split("#", 1)[0].strip()
        if text:
            out.append(text)
    return out


# Each lab: its solution, its starter, the steps the student writes, the only code a starter region
# may hold per step (placeholders that keep the starter running), and how many numbered steps its
# comments name (the steps to write plus "run it" first and "click and watch" last).
LABS = {
    "tumbling_crates": (SOLUTION, STARTER, {step: {"return None"} if step == "2" else set()
                                            for step in ("2", "3", "4", "5", "6")}, 7),
    "more_shapes": (os.path.join(ROOT, "solutions", "more_shapes.py"),
                    os.path.join(ROOT, "starters", "more_shapes_starter.py"),
                    {"2": {"return box_points(radius, radius)"}, "3": {"return Vector2()"}, "4": {"return 1e9"},
                     "5": {"axes = edge_normals(pa) + edge_normals(pb)"}}, 6),
    "ball_on_ramp": (os.path.join(ROOT, "solutions", "ball_on_ramp.py"),
                     os.path.join(ROOT, "starters", "ball_on_ramp_starter.py"),
                     {step: {"return pygame.Vector2(math.inf, math.inf)", "return math.inf", "return center"}
                      for step in ("2", "3", "4", "5", "6", "7")}, 8),
    "bullets": (os.path.join(ROOT, "solutions", "bullets.py"), os.path.join(ROOT, "starters", "bullets_starter.py"),
                {"2": {"return None"}, "3": {"return math.inf"}, "4": set(), "5": {"bullet.pos += bullet.vel * dt"}}, 6),
    "sleeping_crates": (os.path.join(ROOT, "solutions", "sleeping_crates.py"),
                        os.path.join(ROOT, "starters", "sleeping_crates_starter.py"),
                        {"2": {"return 0.0"}, "3": {"return body.inv_mass != 0"}, "4": {"return []"}}, 5),
}
STEPS = [(lab, step) for lab, (_, _, placeholders, _) in LABS.items() for step in sorted(placeholders)]


def test_every_registered_lab_is_in_the_table():
    from checker.labs import LABS as REGISTERED
    assert {lab.id for lab in REGISTERED} == set(LABS)
    for lab in REGISTERED:
        assert (lab.solution, lab.starter) == LABS[lab.id][:2]


@pytest.mark.parametrize("lab", LABS)
def test_the_committed_starter_is_exactly_what_assign_writes(lab):
    solution, starter = LABS[lab][:2]
    with open(starter, "rb") as handle:
        committed = handle.read()
    written = assign.starter_text(source.read(solution), os.path.relpath(solution, ROOT)).encode("utf-8")
    assert committed == written, (f"{os.path.relpath(starter, ROOT)} drifted from its solution: edit "
                                  f"{os.path.relpath(solution, ROOT)} and run `python -m checker assign`")


@pytest.mark.parametrize("lab", LABS)
def test_both_files_mark_the_same_student_steps(lab):
    solution, starter, placeholders, _ = LABS[lab]
    assert set(split_regions(solution)[1]) == set(placeholders)
    assert set(split_regions(starter)[1]) == set(placeholders)


@pytest.mark.parametrize("lab", LABS)
def test_files_are_identical_outside_the_step_regions(lab):
    solution, starter = (split_regions(path)[0] for path in LABS[lab][:2])
    for number, (a, b) in enumerate(zip(solution, starter), 1):
        assert a == b, f"outside-region line {number} differs:\n solution: {a!r}\n starter:  {b!r}"
    assert len(solution) == len(starter)


@pytest.mark.parametrize("lab, step", STEPS)
def test_starter_regions_hold_no_solution_code(lab, step):
    solution_path, starter_path, placeholders, _ = LABS[lab]
    region = split_regions(starter_path)[1][step]
    solution = code_lines(split_regions(solution_path)[1][step])
    assert solution, f"the solution's step {step} is empty"
    assert set(code_lines(region)) <= placeholders[step]
    assert set(solution) - set(code_lines(region)), "the starter's region holds the whole solution"
    comments = [line.strip() for line in region if line.strip().startswith("#")]
    assert comments and comments[0].startswith(f"# Step {step} "), "the region's comment names its step"


def lesson_headings(lab=None):
    """The headings of the student's lesson, lesson11/README.md, and of the lab's page, lesson11/labs/<lab>.md
    (when it has one), without their #s."""
    paths = [os.path.join(ROOT, "lesson11", "README.md"), os.path.join(ROOT, "lesson11", "labs", f"{lab}.md")]
    headings = set()
    for path in paths:
        if os.path.exists(path):
            with open(path, encoding="utf-8") as handle:
                headings |= {line.lstrip("#").strip() for line in handle if line.startswith("#")}
    return headings


@pytest.mark.parametrize("lab", LABS)
def test_step_comments_cite_sections_the_lesson_has(lab):
    """Each step's comment names a heading of lesson11/README.md or of the lab's page, as written there (not the
    seed's names)."""
    _, starter, placeholders, _ = LABS[lab]
    regions = split_regions(starter)[1]
    headings = lesson_headings(lab)
    for step in placeholders:
        cited = re.findall(r'lesson: "([^"]+)"', " ".join(line.strip("# ") for line in regions[step]))
        assert cited, f"step {step}'s comment cites no section of the lesson"
        assert set(cited) <= headings, f"step {step} cites {set(cited) - headings}, not a heading of the lesson"


@pytest.mark.parametrize("lab, step", STEPS)
def test_every_placeholder_says_to_replace_it(lab, step):
    _, starter, placeholders, _ = LABS[lab]
    with open(starter, encoding="utf-8") as handle:
        header = handle.read().split('"""')[1]
    assert "replace that line with your code" in header and "wasted" in " ".join(header.split())
    for line in split_regions(starter)[1][step]:
        if line.strip() and not line.strip().startswith("#"):   # a placeholder: what it stands in for, and to replace it
            assert f"  # until you write step {step}, " in line and line.endswith(": replace this placeholder"), line


@pytest.mark.parametrize("lab", LABS)
def test_starter_comments_number_every_step(lab):
    _, starter, _, steps = LABS[lab]
    with open(starter, encoding="utf-8") as handle:
        text = handle.read()
    for step in range(1, steps + 1):
        assert re.search(rf"# Step {step}\b", text), f"no comment for step {step}"
    assert not re.search(rf"# Step {steps + 1}\b", text)


def test_starter_runs_to_the_end_and_the_crates_fall_through(tmp_path):
    """As handed out nothing collides: 10 s later every crate, clicked ones too, is below the window."""
    settings = {"frames": 600, "fps": 60, "seed": 11, "record_every": 60,
                "script": clicks([(600, 100), (300, 100)], 30, 30)}
    run = run_lab(STARTER, settings, tmp_path)
    assert run.line is not None, run.stdout
    seconds, crates, movers = run.line
    assert (seconds, crates) == (10.0, 6)
    assert run.record["frames_run"] == 600
    assert all(f["contacts"] == 0 for f in run.frames)
    last = run.crates(run.frames[-1])
    assert len(last) == crates
    assert all(min(p[1] for p in body["points"]) > HEIGHT for body in last)
    assert movers == crates  # all still falling
