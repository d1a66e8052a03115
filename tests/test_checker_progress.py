"""A student who does the steps in order sees progress at each one (issue 9, §5).

The files are the starter with steps 2..N taken from the solution (the rest left as
handed out): after each step the score rises, the step's own check passes, and the
first failing check names the next step. Steps 4 and 5 are confirmed before step 6.
"""
import json
import os
import subprocess
import sys

import pytest

from checker.reading.handout import step_regions

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")
STEP_CHECK = {2: "sat_axes", 3: "sat_normal", 4: "resolve_k", 5: "resolve_friction", 6: "apply_impulse_spin"}


def with_steps_done(steps):
    """The starter with the inside of each step in `steps` taken from the solution."""
    starter = open(STARTER, encoding="utf-8").read().splitlines(keepends=True)
    solution = open(SOLUTION, encoding="utf-8").read().splitlines(keepends=True)
    mine, theirs = step_regions(starter), step_regions(solution)
    for step in sorted(steps, reverse=True):
        start, end, _ = mine[step]
        their_start, their_end, _ = theirs[step]
        starter[start + 1:end] = solution[their_start + 1:their_end]
    return "".join(starter)


@pytest.fixture(scope="module")
def progress(tmp_path_factory):
    """{N: the checker's results by check id} for the starter with steps 2..N done (N = 1: nothing done)."""
    folder = tmp_path_factory.mktemp("progress")
    paths = {}
    for last in range(1, 6):  # step 6 done as well is the solution, graded by test_checker.py
        path = folder / f"tumbling_crates_steps_to_{last}.py"
        path.write_text(with_steps_done(range(2, last + 1)), encoding="utf-8")
        paths[last] = str(path)
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", *paths.values()], cwd=ROOT,
                          env=env, capture_output=True, text=True, timeout=600)
    labs = {os.path.basename(lab["path"]): lab for lab in json.loads(proc.stdout)["labs"]}
    return {last: labs[os.path.basename(path)] for last, path in paths.items()}


def test_the_score_rises_with_every_step(progress):
    scores = [progress[last]["score"] for last in sorted(progress)]
    assert scores == sorted(scores) and len(set(scores)) == len(scores), scores
    assert scores[0] == 3  # the starter: loads, handout_unchanged, runtime_lines


@pytest.mark.parametrize("last", [1, 2, 3, 4, 5])
def test_each_step_passes_its_check_and_the_next_failure_names_the_next_step(progress, last):
    checks = {c["id"]: c for c in progress[last]["criteria"]}
    for step in range(2, last + 1):
        assert checks[STEP_CHECK[step]]["status"] == "pass", (step, checks[STEP_CHECK[step]])
    first = next(c for c in progress[last]["criteria"] if c["status"] not in ("pass", "skip"))
    assert first["id"] == STEP_CHECK[last + 1] and first["step"] == last + 1, first
    # a hint is shown once: no two failing checks carry the same full hint text
    hints = [c["hint"] for c in progress[last]["criteria"] if c["hint"]]
    assert len(hints) == len(set(hints)), hints
