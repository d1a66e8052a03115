"""The Tumbling Crates starter is the solution with steps 2-6 left to write, and it runs as handed out.

Step regions are the lines between `# --- step N: ... ---` and
`# --- end of step N ---`. Outside them the two files must be identical line
by line (module docstring included); inside, the solution has code and the
starter only comments (plus step 2's placeholder `return None`).
"""
import re

import pytest

from lab_run import HEIGHT, SOLUTION, STARTER, clicks, run_lab

START = re.compile(r"^\s*# --- step (\d): .+ ---$")
END = re.compile(r"^\s*# --- end of step (\d) ---$")
STUDENT_STEPS = {"2", "3", "4", "5", "6"}
PLACEHOLDERS = {"return None"}  # the only code a starter region may hold


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


def test_both_files_mark_the_same_student_steps():
    assert set(split_regions(SOLUTION)[1]) == STUDENT_STEPS
    assert set(split_regions(STARTER)[1]) == STUDENT_STEPS


def test_files_are_identical_outside_the_step_regions():
    solution, _ = split_regions(SOLUTION)
    starter, _ = split_regions(STARTER)
    for number, (a, b) in enumerate(zip(solution, starter), 1):
        assert a == b, f"outside-region line {number} differs:\n solution: {a!r}\n starter:  {b!r}"
    assert len(solution) == len(starter)


@pytest.mark.parametrize("step", sorted(STUDENT_STEPS))
def test_solution_regions_hold_code(step):
    assert code_lines(split_regions(SOLUTION)[1][step])


@pytest.mark.parametrize("step", sorted(STUDENT_STEPS))
def test_starter_regions_hold_no_solution_code(step):
    region = split_regions(STARTER)[1][step]
    assert set(code_lines(region)) <= PLACEHOLDERS
    assert code_lines(region) != code_lines(split_regions(SOLUTION)[1][step])
    comments = [line.strip() for line in region if line.strip().startswith("#")]
    assert comments and comments[0].startswith(f"# Step {step} "), "the region's comment names its step"


def test_starter_comments_number_all_seven_steps():
    with open(STARTER, encoding="utf-8") as handle:
        text = handle.read()
    for step in range(1, 8):
        assert re.search(rf"# Step {step}\b", text), f"no comment for step {step}"


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
