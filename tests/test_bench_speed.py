"""The speed benchmark (lesson11/bench/speed.py) in its --quick mode, and listing.py against the lesson.

Times are never asserted (the machine is shared): only that every engine ran,
that every ratio is a finite positive number, and that the engines left the
pile a pile. listing.py's behaviour is checked on the lesson's own cases.
"""
import math

import pytest
from pygame import Vector2

from lesson11.bench import listing
from lesson11.bench import harness
from lesson11.bench import speed as sp

FLOOR_TOP = 560.0
RAMP_ANGLE = math.radians(22)


@pytest.fixture(scope="module")
def quick():
    return sp.run(sp.QUICK)


def expected_engines():
    return ["listing", "lab", "reference"] + (["pymunk"] if sp.pymunk_available() else [])


def test_every_engine_runs_the_lab_pile_from_the_same_snapshot_and_leaves_a_pile(quick):
    pile, _ = quick
    assert list(pile) == expected_engines()
    for name, result in pile.items():
        assert result.finite, name
        assert len(result.times) == sp.QUICK.repeats and all(t > 0 for t in result.times), name
        assert result.steps == sp.QUICK.pile_steps
        # 5 crates on the floor touch it at 2 points each, and crates touch crates: measured 46-66 points
        assert result.contacts >= 10, (name, result.contacts)
        assert result.sunk < 2.0, (name, result.sunk)   # measured 0.10-0.51 px (the listing keeps its 0.5 px slop)
        assert result.moved < 5.0, (name, result.moved)  # measured under 1 px in 8 steps


def test_the_listing_and_the_lab_find_about_the_same_contacts(quick):
    pile, _ = quick
    listing_points, lab_points = pile["listing"].contacts, pile["lab"].contacts
    assert 0.5 < listing_points / lab_points < 2, (listing_points, lab_points)  # measured 46 and 47


def test_every_ratio_is_finite_and_positive_and_every_target_has_a_verdict(quick):
    pile, scaling = quick
    figures = sp.ratios(pile)
    assert set(figures) >= {"lab_vs_listing", "frame_share", "reference_vs_listing"}
    assert all(math.isfinite(v) and v > 0 for v in figures.values()), figures
    assert ("reference_vs_pymunk" in figures) == sp.pymunk_available()
    rows = sp.targets(pile, scaling)
    assert len(rows) == 6
    assert [met for _, _, met in rows[-2:]] == [None, None]  # --quick stops at 100 crates: growth not judged
    table = sp.targets_table(rows)
    assert table.count("not judged (this run stops below 1000 crates)") == 2


def test_scaling_rows_cover_every_size_and_engine(quick):
    _, scaling = quick
    assert list(scaling) == list(sp.QUICK.sizes)
    for n, results in scaling.items():
        assert list(results) == expected_engines(), n
        for name, result in results.items():
            assert result.finite and result.sunk < 2.0, (n, name, result.sunk)
            assert result.contacts >= n, (n, name, result.contacts)  # every crate touches something
    for name in expected_engines():
        ratio, last = sp.growth(scaling, name)
        assert math.isfinite(ratio) and ratio > 0 and last == max(sp.QUICK.sizes)
    text = sp.scaling_table(scaling, sp.QUICK)
    assert len(text.splitlines()) == 2 + len(expected_engines())


def test_wide_box_is_two_crates_deep_at_every_size():
    for n in (14, 1000):
        snapshot, floor_top = sp.wide_box_snapshot(n)
        crates = [b for b in snapshot if b["mass"] > 0]
        assert len(crates) == n and len(snapshot) == n + 3
        tops = {round(b["pos"][1] - sp.BOX / 2, 3) for b in crates}
        assert len(tops) == 2 and min(tops) > floor_top - 2 * sp.BOX - 1


def test_quick_run_writes_only_quick_files_and_labels_itself(quick, tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sp, "run", lambda settings, progress=None: quick)  # the figures are not the point here
    full = {"bench_speed.md": b"the full run's table", "bench_speed.png": b"the full run's plot"}
    for name, content in full.items():
        (tmp_path / name).write_bytes(content)
    assert sp.main(["--quick", "--out-dir", str(tmp_path)]) == 0
    for name, content in full.items():
        assert (tmp_path / name).read_bytes() == content, f"--quick overwrote {name}"
    text = (tmp_path / "bench_speed_quick.md").read_text(encoding="utf-8")
    assert "Smoke run (`--quick`)" in text and "Machine:" in text and "`python -m lesson11.bench.speed --quick`" in text
    for name in expected_engines():
        assert f"| {sp.ENGINE_NAMES[name]} |" in text
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return
    assert (tmp_path / "bench_speed_quick.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_quick_run_without_out_dir_writes_nothing(quick, tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sp, "run", lambda settings, progress=None: quick)
    monkeypatch.setattr(harness, "default_out_dir", lambda: tmp_path)  # output_folder looks it up there
    assert sp.main(["--quick"]) == 0
    assert list(tmp_path.iterdir()) == []
    assert capsys.readouterr().out.rstrip().splitlines()[-1].startswith("Smoke run:")


# ---------------------------------------------------------------- listing.py against the lesson

def lab_floor():
    return listing.Crate(listing.box_points(900, 40), (450, FLOOR_TOP + 20), 0)


def test_listing_keeps_the_lessons_numbers():
    assert (listing.STEP, listing.ITERATIONS, listing.SLOP, listing.PERCENT, listing.RESTING_SPEED) == \
        (1 / 120, 6, 0.5, 0.4, 30)
    box = listing.Crate(listing.box_points(40, 40), (0, 0), 1.6)
    assert 1 / box.inv_inertia == pytest.approx(1.6 * (40 ** 2 + 40 ** 2) / 12)


def test_listing_crate_dropped_flat_comes_to_rest_on_the_floor():
    crate = listing.Crate(listing.box_points(40, 40), (450, FLOOR_TOP - 20 - 50), 1.6)
    bodies = [lab_floor(), crate]
    for _ in range(240):  # 2 s
        listing.step_world(bodies)
    bottom = max(p.y for p in crate.world_points())
    # measured: 0.503 px into the floor (the 0.5 px slop), 0.05 px/s, tilted 0.005 rad by the per-corner impulses
    assert 0 < bottom - FLOOR_TOP < 0.6
    assert crate.vel.length() < 1.0 and abs(crate.omega) < 0.05 and abs(crate.angle) < 0.02


def ramp_run(friction):
    """A 40 px crate resting on the lesson's 22° ramp; returns (px moved down the slope in the 2nd second,
    speed at the end)."""
    ramp = listing.Crate(listing.box_points(420, 24), (230, 380), 0, angle=RAMP_ANGLE, friction=friction)
    up = Vector2(math.sin(RAMP_ANGLE), -math.cos(RAMP_ANGLE))
    slope = Vector2(math.cos(RAMP_ANGLE), math.sin(RAMP_ANGLE))
    crate = listing.Crate(listing.box_points(40, 40), Vector2(230, 380) + up * (12 + 20), 1.6, angle=RAMP_ANGLE,
                          friction=friction)
    bodies = [ramp, crate]
    for _ in range(60):
        listing.step_world(bodies)
    before = Vector2(crate.pos)
    for _ in range(120):
        listing.step_world(bodies)
    return (crate.pos - before).dot(slope), crate.vel.length()


def test_listing_crate_on_the_ramp_is_held_by_friction_and_slides_without_enough():
    """tan 22° = 0.40: μ 0.6 holds the crate, μ 0.2 does not. The listing moves before it solves, so a held
    crate still creeps g sin θ h² per step = 3.1 px/s (measured 3.4 px in the second second, 0.5 px/s)."""
    crept, speed = ramp_run(0.6)
    assert 0 <= crept < 5.0 and speed < 2.0
    slid, speed = ramp_run(0.2)  # measured 188 px in the second second, 280 px/s
    assert slid > 100 and speed > 200
