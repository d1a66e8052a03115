"""The SAT explorer, driven headless with synthetic pygame events."""
import math
import os
import re

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import pygame
import pytest

from lesson11 import explorer as ex
from lesson11.physics2d import Vector2, edge_normals, project, sat


@pytest.fixture
def explorer():
    pygame.display.init()
    pygame.font.init()
    yield ex.Explorer()
    pygame.quit()


def key(k, mod=0):
    return pygame.event.Event(pygame.KEYDOWN, key=k, mod=mod)


def count_color(surface, color):
    """How many pixels of the surface have exactly this RGB colour."""
    return sum(1 for x in range(surface.get_width()) for y in range(surface.get_height())
               if surface.get_at((x, y))[:3] == color)


def gap_owners(blue_points, orange_points):
    """Owners of the edge normals whose shadows do not overlap, worked out here without the explorer."""
    owners = set()
    for owner, points in (("blue", blue_points), ("orange", orange_points)):
        for axis in edge_normals(points):
            (min_a, max_a), (min_b, max_b) = project(blue_points, axis), project(orange_points, axis)
            if min(max_a, max_b) - max(min_a, min_b) <= 1e-6:
                owners.add(owner)
    return owners


def test_starts_overlapping_with_eight_axes_and_the_mtv(explorer):
    assert explorer.status() == "OVERLAP"
    assert len(explorer.axes()) == 8
    assert [a[0] for a in explorer.axes()] == ["blue"] * 4 + ["orange"] * 4
    assert explorer.separating_axes() == []
    normal, depth = explorer.hit()
    # the MTV is the smallest overlap over all axes, oriented from blue to orange
    overlaps = [explorer.shadows(axis)[2] for _, _, axis in explorer.axes()]
    assert min(overlaps) == pytest.approx(depth)
    assert (explorer.orange.pos - explorer.blue.pos).dot(normal) > 0
    assert any(f"Minimum translation vector: {depth:.1f} px" in line for line in explorer.lines())


def test_move_right_until_apart_then_find_the_separating_axis(explorer):
    presses = 0
    while explorer.status() == "OVERLAP":
        assert explorer.hit() is not None
        explorer.handle_event(key(pygame.K_RIGHT))
        presses += 1
        assert presses < 60, "moving right never separated the boxes"
    start = Vector2(ex.ORANGE_START["pos"])
    assert explorer.orange.pos == start + Vector2(ex.MOVE_STEP * presses, 0)
    blue, orange = explorer.blue.world_points(), explorer.orange.world_points()
    assert sat(blue, orange) is None
    # one step back they overlapped: the label turned at this very press
    assert sat(blue, [p - Vector2(ex.MOVE_STEP, 0) for p in orange]) is not None
    expected = gap_owners(blue, orange)
    assert expected, "apart, yet no axis shows a gap"
    steps = 0
    while not explorer.separates(explorer.current_axis()[2]):
        explorer.handle_event(key(pygame.K_n))
        steps += 1
        assert steps < 8
    owner = explorer.current_axis()[0]
    assert owner in expected
    answer = explorer.lines()[-1]
    assert answer.startswith("Answer: the gap shows on the")
    for name in ("blue", "orange"):
        assert (f"{name} box" in answer or f"{name} and" in answer) == (name in expected)
    assert "gap of" in explorer.lines()[1]


def test_next_axis_by_key_space_and_button_wraps_around(explorer):
    for _ in range(8):
        explorer.handle_event(key(pygame.K_n))
    assert explorer.axis_index == 0
    explorer.handle_event(key(pygame.K_SPACE))
    assert explorer.axis_index == 1
    explorer.handle_event(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=explorer.button.center))
    assert explorer.axis_index == 2
    explorer.handle_event(key(pygame.K_p))
    explorer.handle_event(key(pygame.K_p))
    explorer.handle_event(key(pygame.K_p))
    assert explorer.axis_index == 7
    assert explorer.lines()[0].startswith("axis 8 of 8: the orange box's edge normal #3")


def test_shadow_lengths_are_the_box_sides_on_their_own_normals(explorer):
    # blue is 150 × 90 turned 10°: on its own normals its shadow is 90 (top edge) and 150 (right edge) long
    (_, _, top), (_, _, right) = explorer.axes()[0], explorer.axes()[1]
    low, high = explorer.shadows(top)[0]
    assert high - low == pytest.approx(ex.BLUE_START["h"])
    low, high = explorer.shadows(right)[0]
    assert high - low == pytest.approx(ex.BLUE_START["w"])


def test_keys_turn_both_boxes_and_shift_moves_one_pixel(explorer):
    orange_angle, blue_angle = explorer.orange.angle, explorer.blue.angle
    explorer.handle_event(key(pygame.K_e))
    explorer.handle_event(key(pygame.K_e))
    explorer.handle_event(key(pygame.K_q))
    assert explorer.orange.angle == pytest.approx(orange_angle + math.radians(5))
    explorer.handle_event(key(pygame.K_a))
    assert explorer.blue.angle == pytest.approx(blue_angle - math.radians(5))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEWHEEL, x=0, y=-2))
    assert explorer.orange.angle == pytest.approx(orange_angle - math.radians(5))
    pos = explorer.orange.pos.copy()
    explorer.handle_event(key(pygame.K_UP, pygame.KMOD_LSHIFT))
    assert explorer.orange.pos == pos + Vector2(0, -1)
    explorer.handle_event(key(pygame.K_r))
    assert explorer.orange.pos == Vector2(ex.ORANGE_START["pos"])
    assert explorer.blue.angle == pytest.approx(ex.BLUE_START["angle"])
    assert explorer.handle_event(key(pygame.K_ESCAPE)) is False
    assert explorer.handle_event(pygame.event.Event(pygame.QUIT)) is False


def test_drag_moves_orange_only_when_grabbed(explorer):
    start = explorer.orange.pos.copy()
    # a drag that starts on empty background moves nothing
    explorer.handle_event(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=(20, 400)))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEMOTION, pos=(60, 400), rel=(40, 0), buttons=(1, 0, 0)))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEBUTTONUP, button=1, pos=(60, 400)))
    assert explorer.orange.pos == start
    grab = (round(start.x), round(start.y))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEBUTTONDOWN, button=1, pos=grab))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEMOTION, pos=grab, rel=(30, -10), buttons=(1, 0, 0)))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEMOTION, pos=grab, rel=(5, 5), buttons=(1, 0, 0)))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEBUTTONUP, button=1, pos=grab))
    explorer.handle_event(pygame.event.Event(pygame.MOUSEMOTION, pos=grab, rel=(99, 99), buttons=(0, 0, 0)))
    assert explorer.orange.pos == start + Vector2(35, -5)


def test_drawing_shows_offset_shadows_mtv_and_highlighted_axis(explorer):
    surface = pygame.Surface((ex.WIDTH, ex.HEIGHT))
    explorer.draw(surface)
    # the MTV arrow and label are drawn while the boxes overlap ...
    assert count_color(surface, ex.MTV_YELLOW) > 100
    # ... and each shadow sits beside the axis line, not on it
    owner, edge, normal = explorer.current_axis()
    anchor = explorer.axis_anchor(normal)
    towards = 1 if (explorer.blue.pos - anchor).dot(Vector2(-normal.y, normal.x)) > 0 else -1
    blue_shadow, orange_shadow, _ = explorer.shadows(normal)
    blue_mid = sum(blue_shadow) / 2
    orange_mid = sum(orange_shadow) / 2
    def pixel(value, sideways):
        p = explorer.on_axis(value, normal, anchor, sideways)
        return surface.get_at((round(p.x), round(p.y)))[:3]
    assert pixel(blue_mid, towards * ex.SHADOW_GAP) == ex.BLUE
    assert pixel(orange_mid, -towards * ex.SHADOW_GAP) == ex.ORANGE
    assert pixel(blue_mid, 0) == ex.AXIS_GREY
    # apart: no MTV; an axis with a gap is drawn green and thick, one without is grey
    while explorer.status() == "OVERLAP":
        explorer.handle_key(pygame.K_RIGHT)
    explorer.draw(surface)
    assert count_color(surface, ex.MTV_YELLOW) == 0
    while explorer.separates(explorer.current_axis()[2]):
        explorer.next_axis()
    explorer.draw(surface)
    green_without = count_color(surface, ex.SEPARATING)
    while not explorer.separates(explorer.current_axis()[2]):
        explorer.next_axis()
    explorer.draw(surface)
    green_with = count_color(surface, ex.SEPARATING)
    assert green_with > green_without + 1500


def test_event_loop_runs_scripted_input_and_stops_on_quit(explorer):
    screen = pygame.display.set_mode((ex.WIDTH, ex.HEIGHT))
    pygame.event.clear()
    for _ in range(3):
        pygame.event.post(key(pygame.K_RIGHT))
    pygame.event.post(key(pygame.K_n))
    pygame.event.post(pygame.event.Event(pygame.QUIT))
    frames = ex.run(explorer, screen, frames=100)
    assert frames == 1  # everything, QUIT included, arrived in the first frame
    assert explorer.orange.pos == Vector2(ex.ORANGE_START["pos"]) + Vector2(3 * ex.MOVE_STEP, 0)
    assert explorer.axis_index == 1


def test_screenshots_are_saved_and_show_both_boxes(tmp_path):
    assert ex.main(["--screenshots", str(tmp_path)]) == 0
    for name in ("sat_explorer.png", "sat_explorer_overlap.png"):
        image = pygame.image.load(str(tmp_path / name))
        assert image.get_size() == (ex.WIDTH, ex.HEIGHT)
        assert count_color(image, ex.BLUE) > 200
        assert count_color(image, ex.ORANGE) > 200
    apart = pygame.image.load(str(tmp_path / "sat_explorer.png"))
    overlap = pygame.image.load(str(tmp_path / "sat_explorer_overlap.png"))
    assert count_color(apart, ex.MTV_YELLOW) == 0 < count_color(overlap, ex.MTV_YELLOW)


def test_screenshots_into_a_missing_folder_is_a_one_line_error(tmp_path, capsys):
    assert ex.main(["--screenshots", str(tmp_path / "missing")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "missing" in err


def printed_normal(explorer):
    """The (x, y) the first text line prints for the current axis."""
    printed = re.search(r"\((-?\d+\.\d\d), (-?\d+\.\d\d)\)$", explorer.lines()[0])
    assert printed, explorer.lines()[0]
    return Vector2(float(printed[1]), float(printed[2]))


def test_the_normal_arrow_points_the_way_the_printed_vector_says(explorer):
    """On every axis the arrow on the edge runs along the (x, y) printed in the first line, not against it."""
    for _ in range(len(explorer.axes())):
        start, end = explorer.normal_arrow()
        assert (end - start).length() == pytest.approx(ex.NORMAL_LENGTH)
        assert (end - start).normalize().distance_to(printed_normal(explorer)) < 0.01, explorer.lines()[0]
        explorer.next_axis()


def test_the_normal_arrow_on_screen_is_white_ahead_and_absent_behind(explorer):
    """Rendered headless (boxes apart, so no MTV is drawn over it): white pixels along the printed
    direction from the edge's middle, none the opposite way."""
    while explorer.status() == "OVERLAP":
        explorer.handle_key(pygame.K_RIGHT)
    surface = pygame.Surface((ex.WIDTH, ex.HEIGHT))
    for _ in range(len(explorer.axes())):
        explorer.draw(surface)
        start, _ = explorer.normal_arrow()
        said = printed_normal(explorer)
        for sign, expected in ((1, True), (-1, False)):
            p = start + said * sign * ex.NORMAL_LENGTH * 0.6
            near = [surface.get_at((round(p.x) + dx, round(p.y) + dy))[:3] == ex.TEXT
                    for dx in range(-2, 3) for dy in range(-2, 3)]
            assert any(near) == expected, (explorer.lines()[0], sign)
        explorer.next_axis()
