"""The frontier study (lesson11/bench/frontier.py): its Pareto front, its verdicts, the file the panel reads.

The full sweep takes minutes (python -m lesson11.bench.accuracy_cost --frontier);
here the front and the verdicts are checked on made-up points whose answer is
known, one real point is measured, and the JSON the study writes is read back
by the lab panel exactly as the lab reads it.
"""
import importlib.util
import math
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

from lesson11 import panel
from lesson11.bench import accuracy_cost, frontier
from lesson11.physics2d import World


def point(solver, substeps, iterations, ms, pile, other=1.0):
    return {"solver": solver, "substeps": substeps, "iterations": iterations, "ms_per_step": ms,
            "pile": pile, "ramp": other, "stack": other, "bounce": other}


ROWS = [point("lesson solve-first", 1, 6, 2.0, 15.0), point("lesson solve-first", 4, 6, 8.0, 4.0),
        point("lesson solve-first", 1, 20, 7.0, 6.0), point("lesson solve-first", 2, 4, 3.0, 20.0),
        point("reference", 1, 2, 1.5, 0.001)]


def test_the_front_keeps_what_nothing_cheaper_beats():
    kept = frontier.front([dict(r) for r in ROWS], "pile")
    assert [(r["solver"], r["substeps"], r["iterations"]) for r in kept] == [("reference", 1, 2)]
    lesson = [dict(r) for r in ROWS if r["solver"] != "reference"]
    kept = frontier.front(lesson, "pile")
    # 2 × 4 costs more than 1 × 6 and errs more: off; 1 × 20 is cheaper than 4 × 6 but errs more: both on
    assert [(r["substeps"], r["iterations"]) for r in kept] == [(1, 6), (1, 20), (4, 6)]


def test_each_setting_is_judged_against_its_own_solver():
    rows = [dict(r) for r in ROWS]
    frontier.mark_fronts(rows)
    verdict = {(r["solver"], r["substeps"], r["iterations"]): r for r in rows}
    assert verdict[("lesson solve-first", 4, 6)]["own_front"]          # reference is cheaper and better, but
    assert "pile" not in verdict[("lesson solve-first", 4, 6)]["fronts"]  # another solver: only overall
    off = verdict[("lesson solve-first", 2, 4)]
    assert not off["own_front"] and off["better_setting"] == "1×6"
    assert off["better"] == "lesson solve-first 1×6"
    assert verdict[("reference", 1, 2)]["fronts"] == ["pile", "ramp", "stack", "bounce"]


def test_the_panel_reads_what_the_study_writes(tmp_path, monkeypatch):
    rows = [dict(r) for r in ROWS]
    frontier.mark_fronts(rows)
    path = tmp_path / "frontier.json"
    frontier.write_json(rows, path)
    monkeypatch.setattr(panel, "STUDY_FILE", str(path))
    monkeypatch.setattr(panel, "_study", None)
    world = World()
    assert panel.study_lines(world, {"solver": "lesson", "substeps": 2, "iterations": 4}) == [
        "study: 3.00 ms/step, pile 20.0 px/s", "off the front: 1×6 costs less, errs less"]
    assert panel.study_lines(world, {"solver": "accumulated", "substeps": 1, "iterations": 2})[1] == \
        "on the front: nothing cheaper errs less"
    monkeypatch.setattr(panel, "_study", None)


def test_one_real_point_is_measured():
    row = frontier.measure("reference", 1, 2)
    assert set(frontier.ERRORS) <= set(row) and row["ms_per_step"] > 0
    assert all(math.isfinite(row[key]) and row[key] >= 0 for key in frontier.ERRORS)
    assert row["ramp"] < 0.5 and row["stack"] < 10  # the reference solver holds both (0.03 and 3.9 px measured)


def test_accuracy_cost_hands_frontier_to_the_study(monkeypatch):
    seen = []
    monkeypatch.setattr(frontier, "main", lambda argv: seen.append(argv) or 0)
    assert accuracy_cost.main(["--frontier", "--quick", "--no-plot"]) == 0
    assert seen == [["--quick", "--no-plot"]]


def test_replot_redraws_from_the_points_the_sweep_kept(tmp_path, monkeypatch):
    rows = [dict(r) for r in ROWS] + [point("pymunk", 1, 10, 0.02, 1e-6)]
    frontier.mark_fronts(rows)
    path = tmp_path / "frontier.json"
    frontier.write_json(rows, path, "made-up machine")
    again, machine = frontier.read_points(path)
    assert machine == "made-up machine"
    assert [(r["solver"], r["ms_per_step"], r["pile"], r["own_front"]) for r in again] == \
        [(r["solver"], r["ms_per_step"], r["pile"], r["own_front"]) for r in rows]   # pymunk kept for the plot
    monkeypatch.setattr(frontier, "STUDY_JSON", path)
    out = tmp_path / "out"
    if importlib.util.find_spec("matplotlib"):     # the plot needs the compare extra
        assert frontier.main(["--replot", "--out-dir", str(out)]) == 0
        assert (out / "bench_frontier.png").stat().st_size > 10_000
    assert path.read_text(encoding="utf-8").count('"solver": "pymunk"') == 1   # in "points" only: not a panel setting


def test_replot_of_a_file_without_points_is_one_line(tmp_path, monkeypatch, capsys):
    path = tmp_path / "frontier.json"
    path.write_text('{"settings": []}', encoding="utf-8")
    monkeypatch.setattr(frontier, "STUDY_JSON", path)
    assert frontier.main(["--replot", "--out-dir", str(tmp_path / "out")]) == 2
    error = capsys.readouterr().err.strip()
    assert error.startswith(str(path)) and "run the sweep again" in error and "\n" not in error
    assert not (tmp_path / "out").exists()
