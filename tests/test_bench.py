"""Smoke test of the accuracy-cost benchmark (lesson11/bench) at tiny sizes.

It checks the benchmark's measured accuracy figures, never its times: the
machine is shared, so wall time proves nothing here.
"""
import ast
from pathlib import Path

import pytest

from lesson11.bench import accuracy_cost as ac
from lesson11.bench import harness
from lesson11.bench import scenes
from lesson11.physics2d.world import LESSON_SUBSTEPS

TINY = ac.Settings(shots=8, speeds=(500, 3000, 12000), substeps=(2, 4, 16), iterations=(1, 6, 20),
                   pile_seconds=0.5, rule_scenes=("pyramid4",), compare_scenes=("pyramid4",),
                   effects_seconds=1.0, repeats=1, stack_seconds=0.1, heavy_seconds=0.1, ramp_seconds=0.1,
                   disc_seconds=1.5)


@pytest.fixture(scope="module")
def results():
    rows, notes = ac.run(TINY)
    return rows, notes


def by_variant(rows, text):
    return next(row for row in rows if text in row.variant)


def test_ccd_never_tunnels_while_discrete_steps_do(results):
    rows = results[0]["tunnelling"]
    ccd = by_variant(rows, "CCD")
    discrete = by_variant(rows, "discrete")
    assert all(share == 0 for share in ccd.accuracy.values()), ccd.accuracy
    assert discrete.accuracy[12000] == 1.0  # 100 px per step against a 10 px window: every shot passes
    assert discrete.accuracy[500] == 0.0    # 4.2 px per step: always caught


def test_more_sub_steps_tunnel_less(results):
    rows = results[0]["tunnelling"]
    chain = [by_variant(rows, "discrete")] + [by_variant(rows, f"×{n} ") for n in TINY.substeps]
    for speed in TINY.speeds:
        shares = [row.accuracy[speed] for row in chain]
        assert shares == sorted(shares, reverse=True), f"{speed} px/s: {shares}"
    totals = [sum(row.accuracy.values()) for row in chain]
    assert totals[-1] < totals[0]
    assert by_variant(rows, "×16").accuracy[12000] > 0  # sub-stepping still fails fast enough


def test_shot_geometry_starts_clear_of_the_wall_and_ends_past_it():
    for speed in (500, 12000):
        travel = speed * ac.FRAME
        start_x = scenes.WALL_X - scenes.WALL_WIDTH / 2 - scenes.BULLET_RADIUS - 1 - travel * 2
        end_x = start_x + speed * ac.FRAME * ac.shot_frames(speed)
        assert end_x > scenes.WALL_X + scenes.WALL_WIDTH / 2 + scenes.BULLET_RADIUS  # a free flight gets past


def test_more_iterations_sink_less(results):
    rows = [r for r in results[0]["iterations"] if r.variant.startswith("lesson")]
    penetration = [r.accuracy["penetration"] for r in rows]  # iterations 1, 6, 20
    assert penetration[0] > penetration[1] > penetration[2]
    # World's default (solve-first) order: measured 0.58 px with one pass, 0.010 px with 20 (the move-first
    # order measured 3.20 and 0.51 px: slop 0.5 px plus one step of gravity)
    assert penetration[0] > 0.4
    assert penetration[2] < 0.05
    baseline = [r for r in rows if r.baseline]
    assert len(baseline) == 1 and "6 iterations" in baseline[0].variant


def test_every_accuracy_figure_is_the_same_in_every_repeat():
    settings = ac.Settings(**{**TINY.__dict__, "speeds": (3000,), "shots": 4, "pile_seconds": 0.2,
                              "iterations": (2,), "effects_seconds": 0.2, "repeats": 2})
    rows, _ = ac.run(settings)
    assert all(row.consistent for group in rows.values() for row in group)
    assert all(len(row.times) == 2 for group in rows.values() for row in group)


def test_undeclared_effects_change_nothing_and_ccd_without_bullets_runs_no_swept_test(results):
    rows = results[0]["effects"]
    all_five, needed, ccd_idle, ccd_used = rows
    assert all_five.baseline
    assert needed.accuracy["difference"] < 1e-6       # same positions without friction and rotation
    assert ccd_idle.accuracy["difference"] == 0.0     # "ccd" with no bullet: bit-for-bit the same run
    assert ccd_idle.counters["swept_tests"] == 0
    assert needed.counters["pair_tests"] == all_five.counters["pair_tests"]
    # each of 24 bullets against the 27 other bodies, in each of the default World's 4 sub-steps
    assert ccd_used.counters["swept_tests"] == 24 * 27 * LESSON_SUBSTEPS


def test_table_has_a_row_per_case_and_names_the_baselines(results):
    rows, notes = results
    text = ac.table([row for group in rows.values() for row in group])
    body = text.splitlines()[2:]
    assert len(body) == sum(len(group) for group in rows.values())
    assert sum("1 (baseline)" in line for line in body) == sum(r.baseline for g in rows.values() for r in g)
    assert "no shot tunnels at any speed" in next(line for line in body if "CCD" in line)


def test_pymunk_pile_holds_up_like_the_lesson_world(results):
    pytest.importorskip("pymunk")
    rows = results[0]["pymunk"]
    mine = next(r for r in rows if "lesson solver" in r.variant)
    theirs = next(r for r in rows if "pymunk" in r.variant)
    assert theirs.accuracy["penetration"] < 0.2   # measured 0.06 px (pymunk's slop is 0.1 px)
    assert theirs.accuracy["drift"] < mine.accuracy["drift"]


def test_solvers_study_has_a_row_per_solver_and_shows_the_flat_bounce_turned_into_spin(results):
    """Study 6: a row per solver (pymunk when installed), the lesson default the baseline; the lesson
    solver's per-corner impulses send a flat e = 0.5 box up slow and spinning, the reference solver does not."""
    rows = results[0]["solvers"]
    engines = [row.variant for row in rows]
    assert engines[:4] == ["lesson solve-first", "lesson move-first", "reference corners", "reference clip"]
    assert engines[4:] == (["pymunk"] if ac.solver_probe.pymunk else [])
    assert [row.baseline for row in rows] == [True] + [False] * (len(rows) - 1)
    assert all(len(row.parts) == 7 and row.consistent for row in rows)
    for row in rows[:2]:                       # lesson solver, both orders: measured 0.071 and 0.076, spin 1.6 rad/s
        assert row.accuracy["flat 0.5"]["rebound"] < 0.2 and row.accuracy["flat 0.5"]["spin"] > 1
    for row in rows[2:4]:                      # reference solver: measured 0.500, spin 0.0001 rad/s
        assert row.accuracy["flat 0.5"]["rebound"] == pytest.approx(0.5, abs=0.01)
        assert row.accuracy["flat 0.5"]["spin"] < 0.01
    assert all(row.accuracy["disc 0.5"]["rebound"] == pytest.approx(0.5, abs=0.02) for row in rows)
    assert all(row.accuracy["disc 1"]["apexes"] == 1 for row in rows)  # 1.5 s: one apex, at 1.28 s
    table = ac.solvers_table(rows).splitlines()
    assert len(table) == 2 + len(rows) and "1 (baseline" in table[2] and "lesson, solve-first" in table[2]


def test_quick_run_writes_its_own_files_and_never_the_studys(results, tmp_path, monkeypatch):
    """--quick --out-dir writes bench_accuracy_cost_quick.md/.png, labelled a smoke run; the full study's
    bench_accuracy_cost.md/.png in the same folder stay as they were.

    The figures are the module's TINY run (`results`): the quick settings are TINY, so the study is not run twice.
    """
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(ac, "QUICK", TINY)

    def run(settings, progress=None):
        assert settings is TINY, "--quick runs the QUICK settings"
        return results

    monkeypatch.setattr(ac, "run", run)
    study = {"bench_accuracy_cost.md": b"the full study's table", "bench_accuracy_cost.png": b"the full study's plot"}
    for name, content in study.items():
        (tmp_path / name).write_bytes(content)
    assert ac.main(["--quick", "--out-dir", str(tmp_path)]) == 0
    for name, content in study.items():
        assert (tmp_path / name).read_bytes() == content, f"--quick overwrote {name}"
    table = (tmp_path / "bench_accuracy_cost_quick.md").read_text(encoding="utf-8")
    assert "| study | scene | variant |" in table and "Machine:" in table
    assert "Smoke run (`--quick`)" in table.splitlines()[2] and "not measurements" in table
    assert "## Solvers: accuracy and time" in table and '| reference, "clip" |' in table
    timed = [line for line in table.splitlines() if "ms/step |" in line or "ms per simulated s |" in line]
    assert timed and all("| n/a (1 repeat) |" in line for line in timed)  # no "spread 0 %" from one repeat
    png = (tmp_path / "bench_accuracy_cost_quick.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 20_000


def test_quick_run_without_out_dir_writes_nothing_and_says_it_is_a_smoke_run(results, tmp_path, monkeypatch,
                                                                           capsys):
    monkeypatch.setattr(ac, "run", lambda settings, progress=None: results)  # the figures are not the point here
    monkeypatch.setattr(harness, "default_out_dir", lambda: tmp_path)
    assert ac.main(["--quick"]) == 0
    assert list(tmp_path.iterdir()) == []
    out = capsys.readouterr().out
    assert "Smoke run (`--quick`)" in out and out.rstrip().splitlines()[-1].startswith("Smoke run:")


def test_bad_repeats_is_a_one_line_error(capsys):
    with pytest.raises(SystemExit) as stop:
        ac.main(["--repeats", "0"])
    assert stop.value.code == 2
    assert "must be a whole number >= 1, got 0" in capsys.readouterr().err


def bench_imports(folder):
    """{module: the lesson11/bench modules it imports, at the top or inside a function} for every module in folder."""
    modules = {path.stem: path for path in folder.glob("*.py")}
    graph = {}
    for name, path in modules.items():
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                found.update([node.module.split(".")[0]] if node.module else [alias.name for alias in node.names])
            elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("lesson11.bench"):
                found.update(node.module.split(".")[2:3] or [alias.name for alias in node.names])
        graph[name] = found & set(modules)
    return graph


def test_no_bench_module_imports_itself_round_a_circle():
    """Issue 34: accuracy_cost, frontier and plot imported each other; what they share lives in harness.py."""
    graph = bench_imports(Path(ac.__file__).parent)

    def reachable(start):
        seen, todo = set(), list(graph[start])
        while todo:
            module = todo.pop()
            if module not in seen:
                seen.add(module)
                todo.extend(graph[module])
        return seen

    assert [module for module in graph if module in reachable(module)] == []
    assert "harness" in graph["frontier"] and "accuracy_cost" not in graph["frontier"] | graph["plot"]
