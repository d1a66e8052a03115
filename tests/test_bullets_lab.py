"""Both Bullets files run headless; the starter's bullets, as handed out, pass the wall in every mode,
the solution's pass it with sub-steps x8 and never with CCD.

That the starter is the solution with steps 2-5 left to write is tested with every lab's in
test_lab_starter.py; the checker's verdicts in test_corpus_labs.py.
"""
import importlib.util
import os

from lab_run import ROOT, run_lab

from checker.labs.bullets.probes import shoot

SOLUTION = os.path.join(ROOT, "solutions", "bullets.py")
STARTER = os.path.join(ROOT, "starters", "bullets_starter.py")
WALL_X = 470.0


def _past_wall(frame):
    """Bullets (circles) beyond the wall's far face in one recorded frame."""
    return [b for b in frame["bodies"] if not b["static"] and not b["points"] and b["pos"][0] > WALL_X + 2]


def _shots(first, aims, mode_key):
    script = [{"frame": first, "type": "key", "key": mode_key}]
    return script + [{"frame": first + 1 + 2 * i, "type": "click", "pos": list(aim)} for i, aim in enumerate(aims)]


AIMS = [(600, 80 + 50 * i) for i in range(6)]


def test_starter_runs_and_its_bullets_pass_the_wall_even_with_ccd(tmp_path):
    """As handed out circle_toi() finds nothing, so under CCD (key 5) bullets fly through the wall; D, V, R run."""
    script = _shots(1, AIMS, "5") + [{"frame": 20, "type": "key", "key": "d"}, {"frame": 21, "type": "key", "key": "v"},
                                     {"frame": 25, "type": "key", "key": "r"}]
    run = run_lab(STARTER, {"frames": 30, "fps": 60, "seed": 11, "record_every": 1, "script": script}, tmp_path)
    assert run.record["frames_run"] == 30
    assert any(_past_wall(frame) for frame in run.frames[:20])


def test_solution_sub_steps_x8_miss_and_ccd_stops_every_bullet(tmp_path):
    """Key 4 (x8): six shots at 12000 px/s, some end beyond the wall; key 5 (CCD) at frame 30: six more, none does."""
    script = _shots(1, AIMS, "4") + _shots(30, AIMS, "5")
    run = run_lab(SOLUTION, {"frames": 50, "fps": 60, "seed": 11, "record_every": 1, "script": script}, tmp_path)
    by_frame = {frame["frame"]: frame for frame in run.frames}
    assert any(_past_wall(by_frame[n]) for n in range(2, 30))
    assert not _past_wall(by_frame[30])   # the x8 bullets have left the window
    assert not any(_past_wall(by_frame[n]) for n in range(31, 51))
    fired = max(sum(1 for b in by_frame[n]["bodies"] if not b["points"]) for n in range(31, 51))
    assert fired >= 2


def test_tunnelling_falls_with_sub_steps_and_ccd_stops_it():
    """At 12000 px/s, 24 shots each: plain >= x2 >= x4 >= x8 > 0 tunnelled, CCD 0; at 3000 px/s x8 already holds."""
    spec = importlib.util.spec_from_file_location("bullets_solution", SOLUTION)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    counts = [shoot(module, mode, 12000.0, 24)[0] for mode in ("plain", "x2", "x4", "x8", "ccd")]
    assert counts[0] >= counts[1] >= counts[2] >= counts[3] > 0 == counts[4], counts
    assert counts[0] >= 20   # a plain step moves 100 px: only a 10 px window of start points is caught
    assert shoot(module, "x8", 3000.0, 24)[0] == 0


def test_the_exact_tests_are_counted_per_file_when_files_are_judged_in_parallel_threads():
    """The checker judges a class's files in parallel threads: the broad test's count of exact swept tests is each
    probe's own (a count shared between threads once failed a right file with broad_missing)."""
    from concurrent.futures import ThreadPoolExecutor

    from checker.labs.bullets.probes import BROAD_TEST
    spec = importlib.util.spec_from_file_location("bullets_solution", SOLUTION)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    alone = [case["got"]["exact_tests"] for case in BROAD_TEST.probe(module, SOLUTION)]

    def counts(k):   # each thread its own copy of the file, as each graded file is its own module
        own = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(own)
        return [[case["got"]["exact_tests"] for case in BROAD_TEST.probe(own, SOLUTION)] for _ in range(40)]
    with ThreadPoolExecutor(max_workers=4) as pool:
        together = [run for runs in pool.map(counts, range(4)) for run in runs]
    # the seven fixed cases, then the two drawn ones (seed 0 for a plain module): a hit and a bullet out of reach
    assert alone == [1, 1, 0, 0, 1, 1, 1, 1, 0] and all(run == alone for run in together)
