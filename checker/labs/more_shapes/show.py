"""What --show and --pictures draw for More Shapes' checks (checker/labs/__init__.py says how it is found).

SERIES: the quantity each behaviour check is plotted by (the triangle's and the hexagon's turn, the pile's
and the ramp's shapes). CASES: the failing cases of its function checks, from the probe's judged data:

  CornersCase  regular_polygon(): both outlines on the circle of the radius, corner 0 marked
  PolygonCase  polygon_centroid() and polygon_inertia() (show_cases.PolygonCase)
  AxesCase     separating_axes(): both shapes, and every axis as a direction from one centre: the lesson's
               distinct directions (yellow lines) and the student's axes (magenta arrows, a repeated one
               shows as a second arrow); when the axes are right, sat() on them as show_cases.SatCase
"""
import math

import pygame
from pygame import Vector2

from checker.judging.probe_kit import sat_pairs
from checker.replay.show_cases import PolygonCase, SatCase
from checker.replay.show_kit import (BACK, BLUE, CLOSE, GREY, LESSON, ORANGE, STUDENT, Case, arrow, close, data,
                                     is_point, numbered, text_font, vec, view)
from checker.replay.show_series import FASTEST, Moved, Quantity, sink_depth
from . import probes
from .checks import HEXAGON_TURN, PENETRATION, RAMP_SLIDE, TRIANGLE_TURN
from .scenes import ON_RAMP, PUSHED, TRIANGLE


class Turned(Moved):
    """How far (degrees) the dynamic body that turned most has turned since the run's first frame."""

    def __call__(self, frame):
        return max([abs(math.degrees(b["angle"] - a["angle"])) for a, b in zip(self.start, self.chosen(frame))]
                   + [0.0])


SERIES = {
    "runs": FASTEST,
    "triangle_tips": Quantity("turned since the start (deg)", Turned, math.degrees(TRIANGLE_TURN), above=False,
                              at_end=True, only=(TRIANGLE,)),
    "hexagon_tips": Quantity("turned since the start (deg)", Turned, math.degrees(HEXAGON_TURN), above=False,
                             at_end=True, only=(PUSHED,)),
    "pile_stable": Quantity("deepest into the floor (px)", sink_depth, PENETRATION),
    "ramp_holds": Quantity("moved since the start (px)", Moved, RAMP_SLIDE, only=tuple(ON_RAMP)),
}


# ---------------------------------------------------------------- regular_polygon() and separating_axes()

def axes_wrong(case):
    """True when the student's axes for this pair are not every edge direction of both shapes once, unit length
    (parallel_axes' own rule, probes.axes_fault)."""
    return isinstance(case.get("got"), str) or probes.axes_fault(case) is not None


def _axes_text(axes, most=5):
    shown = " ".join(vec(a) for a in axes[:most])
    return shown + (f" and {len(axes) - most} more" if len(axes) > most else "")


class AxesCase(Case):
    """One separating_axes() pair: both shapes (left) and every axis as a direction from one centre (right)."""

    kind = "axes"
    RADIUS = 150   # screen px of the direction dial

    def __init__(self, case, number, count, shapes):
        super().__init__(case, number, count)
        self.shapes = shapes   # (A's world points, B's) from the probe's pairs, or None

    def head(self):
        swapped = " with A and B swapped" if self.case.get("order") == "B, A" else ""
        return f"failing case {self.number} of {self.count}: '{self.case['pair']}'{swapped}"

    def lines(self):
        got, want = self.case["got"], self.case["want"]
        yours = got if isinstance(got, str) else f"{len(got)} axes {_axes_text(got)}"
        return [self.head(), f"yours (magenta): {yours}",
                f"the lesson's (yellow): {len(want)} directions {_axes_text(want)}"]

    def draw(self, surface):
        surface.fill(BACK)
        if self.shapes:
            at, _ = view([p for shape in self.shapes for p in shape], (40, 90, 380, 330))
            for points, colour in zip(self.shapes, (BLUE, ORANGE)):
                pygame.draw.polygon(surface, colour, [at(p) for p in points], 2)
            font = text_font(20)
            surface.blit(font.render("A", True, BLUE), at(self.shapes[0][0]) + Vector2(-16, -18))
            surface.blit(font.render("B", True, ORANGE), at(self.shapes[1][0]) + Vector2(4, -18))
        centre = Vector2(640, 255)
        pygame.draw.circle(surface, (60, 64, 80), centre, self.RADIUS, 1)
        for axis in self.case["want"]:
            direction = Vector2(axis).normalize()
            pygame.draw.line(surface, LESSON, centre - direction * self.RADIUS, centre + direction * self.RADIUS, 6)
        got = self.case["got"]
        if not isinstance(got, str):
            for k, axis in enumerate(got):   # staggered lengths: an axis given twice shows twice
                if Vector2(axis).length() > 1e-12:
                    length = self.RADIUS * (0.95 - 0.12 * (k % 5))
                    arrow(surface, STUDENT, centre, centre + Vector2(axis).normalize() * length, 2)
        self.finish(surface, "directions: yellow lines the lesson's, magenta arrows yours")


def sat_wrong(case):
    """True when sat() on the student's axes differs from the lesson's for this pair (parallel_axes' own rule,
    probes.sat_fault)."""
    got = case.get("got")
    return (got is not None and "bad" in got) or probes.sat_fault(case) is not None


def _pairs():
    return {name: (a, b) for name, a, b in probes.axis_pairs() + sat_pairs()}


def _ordered(pair, order):
    return pair if order != "B, A" else (pair[1], pair[0])


def _shapes(case, pairs):
    """(A's world points, B's) of a step-5 case in its order: a fixed pair's, else (a pair drawn for the run) the
    points the case holds; None when it holds none."""
    if case["pair"] in pairs:
        return _ordered(pairs[case["pair"]], case["order"])
    if "a" in case and "b" in case:
        return [Vector2(p) for p in case["a"]], [Vector2(p) for p in case["b"]]
    return None


def parallel_axes_cases(functions, seed):
    """The failing pairs of parallel_axes: the axes when they are wrong, else sat() on them, drawn as SAT cases."""
    pairs = _pairs()
    axes = [c for c in data(functions, "separating_axes") or [] if "want" in c and axes_wrong(c)]
    if axes:
        return [AxesCase(c, k + 1, len(axes), _shapes(c, pairs)) for k, c in enumerate(axes)]
    sats = [c for c in data(functions, "sat") or [] if "want" in c and _shapes(c, pairs) and sat_wrong(c)]
    cases = []
    for k, c in enumerate(sats):
        a, b = _shapes(c, pairs)
        cases.append(SatCase({"pair": c["pair"], "order": c["order"], "a": [list(p) for p in a],
                              "b": [list(p) for p in b], "got": c["got"], "lesson": c["want"]}, k + 1, len(sats)))
    return cases


class CornersCase(Case):
    """regular_polygon(sides, radius): the circle of the radius (grey), the lesson's outline (yellow, thick) and
    the student's (magenta), each with its corner 0 marked by a dot."""

    kind = "corners"

    def head(self):
        return f"failing case {self.number} of {self.count}: regular_polygon({self.case['sides']}, " \
               f"{self.case['radius']:g})"

    def lines(self):
        got, want = self.case["got"], self.case["want"]
        yours = got if isinstance(got, str) else f"{len(got)} corners, corner 0 at {vec(got[0]) if got else '-'}" \
            + (f", corner 1 at {vec(got[1])}" if len(got) > 1 else "")
        return [self.head(), f"yours (magenta): {yours}",
                f"the lesson's (yellow): {len(want)} corners, corner 0 at {vec(want[0])}, corner 1 at {vec(want[1])}"]

    def draw(self, surface):
        surface.fill(BACK)
        radius = self.case["radius"]
        got = self.case["got"] if not isinstance(self.case["got"], str) else []
        got = [p for p in got if is_point(p)]
        at, scale = view([(-radius, -radius), (radius, radius)] + got)
        pygame.draw.circle(surface, GREY, at((0, 0)), radius * scale, 1)
        for points, colour, width in ((self.case["want"], LESSON, 5), (got, STUDENT, 2)):
            if len(points) >= 2:
                pygame.draw.lines(surface, colour, True, [at(p) for p in points], width)
            if points:
                pygame.draw.circle(surface, colour, at(points[0]), 8 if colour == LESSON else 5)
        self.finish(surface, "grey: the circle of the radius, dots: corner 0")


def corners_wrong(case):
    """True when the student's corners are not the lesson's (More Shapes' polygon_corners rule)."""
    got, want, radius = case["got"], case["want"], case["radius"]
    return isinstance(got, str) or len(got) != len(want) or not all(
        close(g[0], w[0], radius) and close(g[1], w[1], radius) for g, w in zip(got, want))


# ---------------------------------------------------------------- polygon_centroid() and polygon_inertia()

def polygon_wrong(case, inertia):
    """True when the student's centroid or inertia differs from the lesson's (relative 1e-7 of the outline's size)."""
    got, want = case.get("got"), case.get("want")
    if isinstance(got, str) or got is None:
        return True
    if not inertia:
        size = max(abs(v) for p in case["points"] for v in p) or 1.0
        return any(abs(g - w) > CLOSE * size + CLOSE * abs(w) for g, w in zip(got, want))
    return not close(got, want)


def polygon_cases(probe, inertia):
    def cases(functions, seed):
        return numbered(PolygonCase, [case for case in data(functions, probe) or []
                                      if "want" in case and polygon_wrong(case, inertia)], inertia)
    return cases


def corners_cases(functions, seed):
    return numbered(CornersCase, [c for c in data(functions, "regular_polygon") or [] if "want" in c
                                  and corners_wrong(c)])


CASES = {
    "polygon_corners": corners_cases,
    "centroid": polygon_cases("polygon_centroid", False),
    "inertia_sum": polygon_cases("polygon_inertia", True),
    "parallel_axes": parallel_axes_cases,
}
