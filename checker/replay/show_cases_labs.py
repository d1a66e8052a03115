"""More failing function cases drawn by --show: More Shapes' regular_polygon and separating_axes, Bullets'
bounding_radius and time_of_impact, Ball on the Ramp's and Sleeping Crates' function checks (show_cases.py: SAT,
apply_impulse, resolve, polygons, circle_toi and swept_move).

As there, the data are the probe's, judged on the grading side: the student's answer ("got", recorded in the
child) beside the lesson's (computed in the grader). Shapes and bodies the data name but do not hold come from
the probe modules' fixed cases, which is grader-side code. Nothing of the student's code runs here.

  AxesCase      separating_axes(): both shapes, and every axis as a direction from one centre: the lesson's
                distinct directions (yellow lines) and the student's axes (magenta arrows, a repeated one shows
                as a second arrow)
  ClosestCase   closest_on_segment(): the edge, the point, both answers and the line from the point to each
  CircleCase    circle_polygon(): the polygon, the circle, both normals drawn as long as their depths
  SeparateCase  separate(): both bodies' centres and how far each moves, magnified, both answers
  ContactCase   contact_point(): the ball, the other body's surface, the normal, both points
  TimerCase     sleep_timer(): speed and spin against their thresholds, the timer before and both timers after
  MovesCase     moves(): the body (static, awake, asleep) and whether each answer lets it fall
  WakeCase      wake_on_contact(): the two bodies touching, the ones each answer wakes outlined
  CornersCase   More Shapes' regular_polygon(): both outlines on the circle of the radius, corner 0 marked
  BoundingCase  Bullets' bounding_radius(): the outline, its centre and both circles
  BroadCase     Bullets' time_of_impact(): the crate, its bounding circle, the path, both impacts, the exact tests
Ball on the Ramp's disc_inertia is drawn as show_cases.PolygonCase (a disc with both radii of gyration) and its
resolve() as show_cases.ImpulseCase (each body's velocity and spin change after the friction impulse).

failing_cases(lab, result, functions) -> [case] (each with draw(surface), key(key), lines()), or None when the
check is none of these.
"""
import math

import pygame
from pygame import Vector2

from checker.replay.show_cases import (LESSON, SIZE, STUDENT, TEXT, ImpulseCase, PolygonCase, SatCase, _arrow,
                                       _cross, _fit, _font, _footer, _vec)

BACK = (24, 26, 34)
GREY = (150, 155, 170)
BLUE, ORANGE = (70, 130, 235), (245, 150, 40)
GOOD, BAD = (90, 210, 120), (235, 80, 80)
HELP = "[ ]: case   Tab: scene   Esc: quit"
BOX = (80, 70, 740, 360)   # screen px (left, top, width, height) the drawing is fitted into, over the footer


class Case:
    """What the cases here share: their number, no keys of their own, the footer."""

    kind = ""

    def __init__(self, case, number, count):
        self.case, self.number, self.count = case, number, count

    def key(self, key):
        return False

    def head(self):
        return f"failing case {self.number} of {self.count}: {self.case.get('case', '')}"

    def finish(self, surface, legend):
        _footer(surface, self.lines(), f"{legend}   {HELP}")


def _view(points, box=BOX):
    """A function taking a point (px) to the screen, fitting `points` into `box`."""
    scale, offset = _fit([tuple(p) for p in points], box)
    return lambda p: Vector2(p) * scale + offset, scale


def _point_text(value):
    return value["bad"] if isinstance(value, dict) else _vec(value)


def _is_point(value):
    return isinstance(value, list) and len(value) == 2 and all(abs(v) < 1e7 for v in value)


# ---------------------------------------------------------------- More Shapes: separating_axes

def _parallel(u, v):
    return abs(u[0] * v[1] - u[1] * v[0]) <= 1e-6


def axes_wrong(case):
    """True when the student's axes for this pair are not every edge direction of both shapes once, unit length
    (as More Shapes' parallel_axes judges them)."""
    got = case.get("got")
    if isinstance(got, str):
        return True
    normals = case["normals_a"] + case["normals_b"]
    return (any(abs(math.hypot(*a) - 1) > 1e-6 for a in got)
            or any(not any(_parallel(a, n) for n in normals) for a in got)
            or any(not any(_parallel(a, n) for a in got) for n in normals)
            or any(_parallel(a, b) for i, a in enumerate(got) for b in got[i + 1:]))


def _axes_text(axes, most=5):
    shown = " ".join(_vec(a) for a in axes[:most])
    return shown + (f" and {len(axes) - most} more" if len(axes) > most else "")


class AxesCase(Case):
    """One separating_axes() pair: both shapes (left) and every axis as a direction from one centre (right)."""

    kind = "axes"
    RADIUS = 150   # screen px of the direction dial

    def __init__(self, case, number, count, shapes):
        super().__init__(case, number, count)
        self.shapes = shapes   # (A's world points, B's) from the probe's axis_pairs(), or None

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
            at, _ = _view([p for shape in self.shapes for p in shape], (40, 90, 380, 330))
            for points, colour in zip(self.shapes, (BLUE, ORANGE)):
                pygame.draw.polygon(surface, colour, [at(p) for p in points], 2)
            font = _font(20)
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
                    _arrow(surface, STUDENT, centre, centre + Vector2(axis).normalize() * length, 2)
        self.finish(surface, "directions: yellow lines the lesson's, magenta arrows yours")


def more_shapes_sat_wrong(case):
    """True when sat() on the student's axes differs from the lesson's for this pair (parallel_axes' rule)."""
    got, want = case.get("got"), case.get("want")
    if got is not None and "bad" in got:
        return True
    if want is None:
        return got is not None and not ("touching" in case["pair"] and abs(got["depth"]) <= 1e-6)
    if got is None:
        return True
    along = max(got["normal"][0] * t[0] + got["normal"][1] * t[1] for t in case.get("ties") or [want["normal"]])
    return abs(got["depth"] - want["depth"]) > 1e-7 + 1e-7 * abs(want["depth"]) or abs(along - 1) > 1e-6


def _more_shapes_pairs():
    from checker.labs.more_shapes import probes
    from checker.judging.probe_kit import sat_pairs
    return {name: (a, b) for name, a, b in probes.axis_pairs() + sat_pairs()}


def _ordered(pair, order):
    return pair if order != "B, A" else (pair[1], pair[0])


def parallel_axes_cases(functions):
    """The failing pairs of parallel_axes: the axes when they are wrong, else sat() on them, drawn as SAT cases."""
    from checker.replay.show_cases import _data
    pairs = _more_shapes_pairs()
    axes = [c for c in _data(functions, "separating_axes") or [] if "want" in c and axes_wrong(c)]
    if axes:
        return [AxesCase(c, k + 1, len(axes), _ordered(pairs[c["pair"]], c["order"]) if c["pair"] in pairs else None)
                for k, c in enumerate(axes)]
    sats = [c for c in _data(functions, "sat") or [] if "want" in c and c["pair"] in pairs and more_shapes_sat_wrong(c)]
    cases = []
    for k, c in enumerate(sats):
        a, b = _ordered(pairs[c["pair"]], c["order"])
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
        yours = got if isinstance(got, str) else f"{len(got)} corners, corner 0 at {_vec(got[0]) if got else '-'}" \
            + (f", corner 1 at {_vec(got[1])}" if len(got) > 1 else "")
        return [self.head(), f"yours (magenta): {yours}",
                f"the lesson's (yellow): {len(want)} corners, corner 0 at {_vec(want[0])}, corner 1 at {_vec(want[1])}"]

    def draw(self, surface):
        surface.fill(BACK)
        radius = self.case["radius"]
        got = self.case["got"] if not isinstance(self.case["got"], str) else []
        got = [p for p in got if _is_point(p)]
        at, scale = _view([(-radius, -radius), (radius, radius)] + got)
        pygame.draw.circle(surface, GREY, at((0, 0)), radius * scale, 1)
        for points, colour, width in ((self.case["want"], LESSON, 5), (got, STUDENT, 2)):
            if len(points) >= 2:
                pygame.draw.lines(surface, colour, True, [at(p) for p in points], width)
            if points:
                pygame.draw.circle(surface, colour, at(points[0]), 8 if colour == LESSON else 5)
        self.finish(surface, "grey: the circle of the radius, dots: corner 0")


def corners_wrong(case):
    """True when the student's corners are not the lesson's (More Shapes' polygon_corners rule)."""
    from checker.labs.more_shapes.checks import _close
    got, want, radius = case["got"], case["want"], case["radius"]
    return isinstance(got, str) or len(got) != len(want) or not all(
        _close(g[0], w[0], radius) and _close(g[1], w[1], radius) for g, w in zip(got, want))


# ---------------------------------------------------------------- Bullets: bounding_radius

class BoundingCase(Case):
    """bounding_radius(points, centre): the outline (the probe's fixed shapes; one drawn for the run has none
    here), its centre, the lesson's circle through the farthest corner (yellow) and the student's (magenta)."""

    kind = "bounding"

    def __init__(self, case, number, count, shape):
        super().__init__(case, number, count)
        self.shape = shape   # (points, centre) or None

    def lines(self):
        got = self.case["got"]
        yours = f"{got:.4g} px" if isinstance(got, float) else str(got)
        return [self.head(), f"yours (magenta): radius {yours}",
                f"the lesson's (yellow): radius {self.case['want']:.4g} px (the farthest corner)"]

    def draw(self, surface):
        surface.fill(BACK)
        points, centre = self.shape if self.shape else ([], Vector2())
        got = self.case["got"] if isinstance(self.case["got"], float) and 0 <= self.case["got"] < 1e6 else None
        want = self.case["want"]
        beyond = got is not None and got > 3 * want   # the student's circle is not fitted in: an arrow says so
        reach = max([want * 1.2] + ([got] if got is not None and not beyond else []))
        corner = Vector2(reach, reach)
        at, scale = _view([centre - corner, centre + corner] + [tuple(p) for p in points])
        if len(points) >= 3:
            pygame.draw.polygon(surface, (70, 130, 235), [at(p) for p in points])
            pygame.draw.polygon(surface, TEXT, [at(p) for p in points], 1)
        pygame.draw.circle(surface, TEXT, at(centre), 4)
        pygame.draw.circle(surface, LESSON, at(centre), max(2, self.case["want"] * scale), 4)
        if beyond:
            _arrow(surface, STUDENT, at(centre), Vector2(SIZE[0] - 20, at(centre).y), 2)
            surface.blit(_font(20).render(f"yours: {got:.4g} px, beyond the picture", True, STUDENT),
                         (SIZE[0] - 300, at(centre).y + 8))
        elif got is not None:
            pygame.draw.circle(surface, STUDENT, at(centre), max(2, got * scale), 2)
        self.finish(surface, "white: the centre" + ("" if points else " (the shape was drawn for the run)"))


def bounding_cases(functions):
    from checker.labs.bullets import checks, probes
    from checker.replay.show_cases import _data
    shapes = {name: (points, centre) for name, points, centre in probes.bounding_cases()}
    wrong = [c for c in _data(functions, "bounding_radius") or [] if "want" in c and
             not (isinstance(c["got"], float) and checks._close(c["got"], c["want"]))]
    return [BoundingCase(c, k + 1, len(wrong), shapes.get(c["case"])) for k, c in enumerate(wrong)]


class BroadCase(Case):
    """time_of_impact(bullet, other, dt): the crate with its bounding circle (grey), the bullet's path over the step,
    where the bullet is at the lesson's time of impact (yellow, with the normal) and at the student's (magenta), at
    the path's end for "no hit", and how many exact swept tests the student's ran (magenta ticks at its start)."""

    kind = "broad"

    def __init__(self, case, number, count, geometry):
        super().__init__(case, number, count)
        self.geometry = geometry   # (bullet, other body, dt) from the probe's impact_cases()

    def lines(self):
        from checker.labs.bullets.checks import _hit
        case = self.case
        reach = "the bullet reaches the bounding circle" if case["needs_exact"] else \
            "out of the bounding circle's reach: no exact test needed"
        return [self.head(), f"yours (magenta): {_hit(case['got'])}, {case['exact_tests']} exact swept test(s)",
                f"the lesson's (yellow): {_hit(case['want'])} ({reach})"]

    def draw(self, surface):
        surface.fill(BACK)
        bullet, other, dt = self.geometry
        corners = other.world_points()
        bounding = max(other.pos.distance_to(p) for p in corners)
        end = bullet.pos + bullet.vel * dt
        reach = Vector2(bounding, bounding)
        at, scale = _view([other.pos - reach, other.pos + reach, bullet.pos, end])
        pygame.draw.polygon(surface, BLUE, [at(p) for p in corners])
        pygame.draw.circle(surface, GREY, at(other.pos), bounding * scale, 1)
        pygame.draw.line(surface, GREY, at(bullet.pos), at(end), 1)
        pygame.draw.circle(surface, TEXT, at(bullet.pos), max(3, bullet.radius * scale), 1)
        for hit, colour, width in ((self.case["want"], LESSON, 4), (self.case["got"], STUDENT, 2)):
            if hit is None:   # no hit: the bullet ends the step where its path ends
                pygame.draw.circle(surface, colour, at(end), max(4, bullet.radius * scale) + width, width)
            elif isinstance(hit, dict) and "t" in hit and abs(hit["t"]) < 10 * dt:
                where = at(bullet.pos + bullet.vel * hit["t"])
                pygame.draw.circle(surface, colour, where, max(4, bullet.radius * scale), width)
                _arrow(surface, colour, where, where + Vector2(hit["normal"]) * 40, width)
        for k in range(min(self.case["exact_tests"], 10)):
            x = at(bullet.pos).x - 10 + 8 * k
            pygame.draw.line(surface, STUDENT, (x, at(bullet.pos).y - 30), (x, at(bullet.pos).y - 16), 3)
        self.finish(surface, "grey: the bounding circle and the path over dt, ticks: your exact tests")


def broad_cases(functions):
    from checker.labs.bullets import checks, probes
    from checker.replay.show_cases import _data
    geometry = {name: (bullet, other, dt) for name, bullet, other, dt, _ in probes.impact_cases()}
    wrong = [c for c in _data(functions, "time_of_impact") or [] if "want" in c and c["case"] in geometry and
             (not checks._hit_matches(c["got"], c["want"]) or (not c["needs_exact"] and c["exact_tests"]))]
    return [BroadCase(c, k + 1, len(wrong), geometry[c["case"]]) for k, c in enumerate(wrong)]


# ---------------------------------------------------------------- Ball on the Ramp

class ClosestCase(Case):
    """closest_on_segment(p, a, b): the edge a-b, the point p, the lesson's closest point and the student's."""

    kind = "closest"

    def lines(self):
        case = self.case
        return [f"{self.head()} (p {_vec(case['p'])}, edge {_vec(case['a'])} to {_vec(case['b'])})",
                f"yours (magenta): {_point_text(case['got'])}",
                f"the lesson's (yellow): {_vec(case['want'])} (t = {case['t']:.3f} along the edge)"]

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        got = case["got"] if _is_point(case["got"]) else None
        at, _ = _view([case["p"], case["a"], case["b"], case["want"]] + ([got] if got else []))
        pygame.draw.line(surface, GREY, at(case["a"]), at(case["b"]), 4)
        font = _font(20)
        for name in ("a", "b"):
            surface.blit(font.render(name, True, GREY), at(case[name]) + Vector2(6, 4))
        pygame.draw.circle(surface, TEXT, at(case["p"]), 6)
        surface.blit(font.render("p", True, TEXT), at(case["p"]) + Vector2(8, -18))
        pygame.draw.line(surface, LESSON, at(case["p"]), at(case["want"]), 3)
        _cross(surface, LESSON, at(case["want"]), 10, 4)
        if got:
            pygame.draw.line(surface, STUDENT, at(case["p"]), at(got), 1)
            _cross(surface, STUDENT, at(got), 8, 2)
        self.finish(surface, "grey: the edge, white: p")


class CircleCase(Case):
    """circle_polygon(center, radius, points): the polygon and the circle, each answer's normal drawn from the
    circle's center as long as its depth (at least 14 screen px, so a zero depth still shows its direction)."""

    kind = "circle"

    def lines(self):
        case = self.case

        def said(hit):
            if hit is None:
                return "None (apart)"
            return hit["bad"] if "bad" in hit else f"normal {_vec(hit['normal'])}, depth {hit['depth']:.3f} px"
        return [f"{self.head()} (center {_vec(case['center'])}, radius {case['radius']:g})",
                f"yours (magenta): {said(case['got'])}", f"the lesson's (yellow): {said(case['want'])}"]

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        centre, radius = Vector2(case["center"]), case["radius"]
        reach = Vector2(radius, radius) * 1.5
        at, scale = _view(case["points"] + [centre - reach, centre + reach])
        pygame.draw.polygon(surface, (70, 74, 90), [at(p) for p in case["points"]])
        pygame.draw.polygon(surface, GREY, [at(p) for p in case["points"]], 2)
        pygame.draw.circle(surface, ORANGE, at(centre), max(2, radius * scale), 2)
        for hit, colour, width in ((case["want"], LESSON, 5), (case["got"], STUDENT, 2)):
            if hit is None or "bad" in hit or Vector2(hit["normal"]).length() < 1e-12:
                continue
            length = max(abs(hit["depth"]) * scale, 14) * (1 if hit["depth"] >= 0 else -1)
            length = max(-300, min(300, length))
            _arrow(surface, colour, at(centre), at(centre) + Vector2(hit["normal"]).normalize() * length, width)
        self.finish(surface, "arrows: the normal, as long as the depth")


class SeparateCase(Case):
    """separate(a, b, normal, depth): where each body's center starts (white) and how far the lesson's push-out
    and the student's move it, magnified (the pushes are fractions of a px)."""

    kind = "separate"

    def moves(self, side):
        """(the student's move, the lesson's) of body `side` (px), the student's None when it is no point."""
        before = Vector2(self.case["before"][side])
        got = self.case["after"][side]
        return (Vector2(got) - before if _is_point(got) else None), Vector2(self.case["want"][side]) - before

    def lines(self):
        def said(move):
            return "no point" if move is None else _vec(move)
        yours = ", ".join(f"{s.upper()} moves {said(self.moves(s)[0])}" for s in ("a", "b"))
        lesson = ", ".join(f"{s.upper()} moves {_vec(self.moves(s)[1])}" for s in ("a", "b"))
        inv = self.case["inv"]
        return [f"{self.head()} (push {self.case['push']:.3f} px, inverse masses {inv['a']:.3g} and {inv['b']:.3g})",
                f"yours (magenta): {yours}", f"the lesson's (yellow): {lesson}"]

    def draw(self, surface):
        surface.fill(BACK)
        before = {s: Vector2(self.case["before"][s]) for s in ("a", "b")}
        middle = (before["a"] + before["b"]) / 2
        apart = max((before["b"] - before["a"]).length(), 1e-9)
        at = lambda p: Vector2(SIZE[0] / 2, 240) + (Vector2(p) - middle) * (360 / apart)   # noqa: E731
        longest = max([m.length() for s in ("a", "b") for m in self.moves(s) if m is not None] + [1e-9])
        magnify = min(150 / longest, 1e6)
        font = _font(20)
        for side, colour in (("a", BLUE), ("b", ORANGE)):
            start = at(before[side])
            static = self.case["inv"][side] == 0
            pygame.draw.circle(surface, colour, start, 14, 0 if not static else 3)
            surface.blit(font.render(side.upper() + (" (static)" if static else ""), True, colour),
                         start + Vector2(-10, 20))
            mine, lesson = self.moves(side)
            if lesson.length() > 0:
                _arrow(surface, LESSON, start, start + lesson * magnify, 5)
            if mine is not None and mine.length() > 0:
                _arrow(surface, STUDENT, start, start + mine * magnify, 2)
        self.finish(surface, f"arrows: each body's move x{magnify:.3g}")


class ContactCase(Case):
    """contact_point(center, radius, normal, depth): the ball, the other body's surface (depth px into the ball),
    the normal, the lesson's point (on the ball's surface) and the student's."""

    kind = "contact"

    def lines(self):
        case = self.case
        return [f"{self.head()} (radius {case['radius']:g}, normal {_vec(case['normal'])}, depth {case['depth']:g})",
                f"yours (magenta): {_point_text(case['got'])}",
                f"the lesson's (yellow): {_vec(case['want'])} (center + normal * radius)"]

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        centre, radius, normal = Vector2(case["center"]), case["radius"], Vector2(case["normal"])
        got = case["got"] if _is_point(case["got"]) else None
        reach = Vector2(radius, radius) * 1.6
        at, scale = _view([centre - reach, centre + reach] + ([got] if got else []))
        surface_at = centre + normal * (radius - case["depth"])
        along = normal.rotate(90) * radius * 1.5
        pygame.draw.line(surface, GREY, at(surface_at - along), at(surface_at + along), 3)
        pygame.draw.circle(surface, ORANGE, at(centre), max(2, radius * scale), 2)
        _arrow(surface, TEXT, at(centre), at(centre + normal * radius * 0.6), 2)
        pygame.draw.circle(surface, LESSON, at(case["want"]), 9, 3)
        if got:
            _cross(surface, STUDENT, at(got), 8, 2)
        self.finish(surface, "grey: the other body's surface, white: the normal")


def friction_case(case, number, count, geometry):
    """Ball on the Ramp's resolve() contact as an ImpulseCase: each body's velocity and spin change after the
    student's resolve() and after the lesson's (the "right" variant), the contact normal as the arrow."""
    a, b, normal, point = geometry
    before = {"a": {"vel": list(a.vel), "omega": a.omega}, "b": {"vel": list(b.vel), "omega": b.omega}}
    return ImpulseCase({"case": f"{case['case']} (mu = {case['mu']:.2g})", "before": before, "after": case["got"],
                        "expected": case["variants"]["right"], "impulse": list(normal), "impulse_label": "normal n",
                        "ra": case["ra"], "rb": case["rb"],
                        "friction": friction_arrows(a, b, Vector2(normal), case["ra"], case["rb"], case["got"],
                                                    case["variants"]["right"])}, number, count)


def friction_arrows(a, b, normal, ra, rb, got, want):
    """{"slip": B's contact point's velocity past A's along the surface before resolve() (px/s), "yours" /
    "lesson": the friction impulse on B (the part of B's impulse, or minus A's, across the normal) after the
    student's resolve() and the lesson's}, computed here from the probe's fixed bodies (grader-side code)."""
    from lesson11.physics2d import relative_velocity
    rel = relative_velocity(a, b, Vector2(ra), Vector2(rb))
    moving, sign = (b, 1) if b.inv_mass else (a, -1)
    side = "b" if moving is b else "a"

    def on_b(state):   # the impulse B got: its momentum change (or minus A's, when B is static), across n
        impulse = (Vector2(state[side]["vel"]) - moving.vel) * (moving.mass * sign)
        return impulse - normal * impulse.dot(normal)
    return {"slip": rel - normal * rel.dot(normal), "yours": on_b(got), "lesson": on_b(want)}


def _ramp_resolve_geometry():
    from checker.labs.ball_on_ramp import probes
    return {name: (a, b, normal, point) for name, a, b, normal, point in probes.resolve_cases()}


def _disc(case):
    """A disc_inertia case as a PolygonCase's: a 32-sided outline of the radius, mass, both inertias."""
    got = case["got"]
    points = [[case["radius"] * math.cos(2 * math.pi * k / 32), case["radius"] * math.sin(2 * math.pi * k / 32)]
              for k in range(32)]
    return {"case": f"a ball of mass {case['mass']:.4g} and radius {case['radius']:g} px", "points": points,
            "mass": case["mass"], "want": case["want"], "got": got["bad"] if isinstance(got, dict) else got}


def ball_on_ramp_cases(check_id, functions):
    from checker.labs.ball_on_ramp import checks
    from checker.replay.show_cases import _data

    def failing(probe, wrong):
        return [c for c in _data(functions, probe) or [] if ("want" in c or "variants" in c) and wrong(c)]

    def numbered(kind, cases, *extra):
        return [kind(c, k + 1, len(cases), *extra) for k, c in enumerate(cases)]
    if check_id == "closest_point":
        closest = failing("closest_on_segment", lambda c: not checks._same_point(c["got"], c["want"]))
        if closest:
            return numbered(ClosestCase, closest)
        return numbered(CircleCase, failing("circle_outside", lambda c: not checks._hit_matches(c["got"], c["want"])))
    if check_id == "inside_case":
        return numbered(CircleCase, failing("circle_inside", lambda c: not checks._hit_matches(c["got"], c["want"])))
    if check_id == "push_out_split":
        return numbered(SeparateCase, failing("separate", lambda c: any(
            not checks._same_point(c["after"][s], c["want"][s]) for s in ("a", "b"))))
    if check_id == "ball_inertia":
        wrong = failing("disc_inertia", lambda c: checks._bad(c["got"]) or not checks._close(c["got"], c["want"]))
        return [PolygonCase(_disc(c), k + 1, len(wrong), "inertia") for k, c in enumerate(wrong)]
    if check_id == "contact_on_surface":
        return numbered(ContactCase, failing("contact_point", lambda c: not checks._same_point(c["got"], c["want"])))
    if check_id == "friction_rolls":
        geometry = _ramp_resolve_geometry()
        wrong = failing("resolve", lambda c: c["case"] in geometry and
                        not checks._state_matches(c["got"], c["variants"]["right"]))
        return [friction_case(c, k + 1, len(wrong), geometry[c["case"]]) for k, c in enumerate(wrong)]
    return None


# ---------------------------------------------------------------- Sleeping Crates

class TimerCase(Case):
    """sleep_timer(timer, speed, spin, dt): the crate's speed and |spin| against the thresholds (green under,
    red over), and the timer: its value before the step (white), the lesson's after it and the student's."""

    kind = "timer"

    def __init__(self, case, number, count, speed_limit, spin_limit):
        super().__init__(case, number, count)
        self.limits = speed_limit, spin_limit

    def lines(self):
        case = self.case
        got = case["got"]
        yours = got if isinstance(got, str) else f"timer {got:.6g} s"
        return [f"{self.head()}: sleep_timer({case['timer']:g}, {case['speed']:g}, {case['spin']:g}, "
                f"{case['dt']:.4g})", f"yours (magenta): {yours}", f"the lesson's (yellow): timer {case['want']:.6g} s"]

    def _gauge(self, surface, top, label, value, limit, unit):
        """A bar from 0 with the threshold marked; a value beyond 4 x the threshold is drawn at the end, with ">>"."""
        font = _font(20)
        bar = pygame.Rect(260, top, 560, 10)
        reach = limit * 4
        pygame.draw.rect(surface, (60, 64, 80), bar)
        under = value < limit
        width = bar.width * min(value, reach) / reach
        pygame.draw.rect(surface, GOOD if under else BAD, (bar.left, bar.top, width, bar.height))
        x = bar.left + bar.width / 4
        pygame.draw.line(surface, TEXT, (x, bar.top - 8), (x, bar.bottom + 8), 2)
        surface.blit(font.render(f"threshold {limit:g}", True, TEXT), (x - 30, bar.bottom + 10))
        words = f"{label} {value:g} {unit}: {'under' if under else 'not under'}" + (" >>" if value > reach else "")
        surface.blit(font.render(words, True, GOOD if under else BAD), (20, top - 4))

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        self._gauge(surface, 90, "speed", case["speed"], self.limits[0], "px/s")
        self._gauge(surface, 170, "|spin|", abs(case["spin"]), self.limits[1], "rad/s")
        font = _font(20)
        got = case["got"] if not isinstance(case["got"], str) and math.isfinite(case["got"]) else None
        values = [case["timer"], case["want"]] + ([got] if got is not None else [])
        top = max(max(abs(v) for v in values) * 1.15, 0.05)
        bar = pygame.Rect(260, 300, 560, 10)
        pygame.draw.rect(surface, (60, 64, 80), bar)
        x_of = lambda v: bar.left + bar.width * max(-0.05, min(1.05, v / top))   # noqa: E731
        surface.blit(font.render(f"the timer (s), 0 to {top:.3g}", True, TEXT), (20, bar.top - 4))
        for value, colour, label, rise in ((case["timer"], TEXT, "before", 62), (case["want"], LESSON, "lesson's", 44),
                                           (got, STUDENT, "yours", 26)):
            if value is None:
                continue
            pygame.draw.line(surface, colour, (x_of(value), bar.top - 14), (x_of(value), bar.bottom + 14), 3)
            surface.blit(font.render(label, True, colour), (x_of(value) - 16, bar.top - rise))
        if got is None:   # no number to place on the bar: say what came back, under it
            pygame.draw.rect(surface, STUDENT, (bar.left, bar.bottom + 20, 12, 12))
            surface.blit(font.render(f"yours: {case['got']}", True, STUDENT), (bar.left + 18, bar.bottom + 18))
        self.finish(surface, "green: under the threshold, red: not")


def _kind_of(name):
    """"static", "asleep" or "awake" for a moves() case by its name (checker/labs/sleeping_crates/probes.py)."""
    return "static" if "static" in name or "floor" in name else "asleep" if "sleeping" in name else "awake"


def _crate(surface, rect, kind, outline=None):
    colour = {"static": (130, 130, 140), "awake": (200, 150, 90), "asleep": (90, 68, 40)}[kind]
    pygame.draw.rect(surface, colour, rect)
    if kind == "asleep":
        surface.blit(_font(26).render("z z", True, TEXT), rect.move(rect.width / 2 - 14, rect.height / 2 - 10).topleft)


class MovesCase(Case):
    """moves(body): the body as the lab draws it (static grey, awake in colour, asleep dark, "z z"), and an
    arrow down for each answer that lets it fall (True: the step integrates it)."""

    kind = "moves"

    def lines(self):
        got = self.case["got"]
        def said(v):
            return v if isinstance(v, str) else f"moves() = {v}" + (": integrated" if v else ": left alone")
        return [self.head(), f"yours (magenta): {said(got)}", f"the lesson's (yellow): {said(self.case['want'])}"]

    def draw(self, surface):
        surface.fill(BACK)
        rect = pygame.Rect(330, 120, 120, 80)
        _crate(surface, rect, _kind_of(self.case["case"]))
        answers = ((self.case["want"], LESSON, rect.left - 30), (self.case["got"], STUDENT, rect.right + 30))
        for answer, colour, x in answers:
            if answer is True:
                _arrow(surface, colour, (x, rect.top), (x, rect.bottom + 140), 4)
            else:
                pygame.draw.line(surface, colour, (x - 12, rect.centery), (x + 12, rect.centery), 4)
        self.finish(surface, "arrow down: integrated, bar: left where it is")


class WakeCase(Case):
    """wake_on_contact(a, b): the two bodies touching, each in its kind; the bodies the lesson wakes outlined in
    yellow (outside), the ones the student's wakes in magenta (inside); under each body one chip per answer."""

    kind = "wake"

    def head(self):
        return f"failing case {self.number} of {self.count}: a {self.case['a']}, b {self.case['b']}"

    def lines(self):
        got = self.case["got"]
        said = lambda v: v if isinstance(v, str) else "wakes " + (" and ".join(v) or "nothing")   # noqa: E731
        return [self.head(), f"yours (magenta): {said(got)}", f"the lesson's (yellow): {said(self.case['want'])}"]

    def draw(self, surface):
        surface.fill(BACK)
        font, small = _font(24), _font(20)
        got = self.case["got"] if not isinstance(self.case["got"], str) else []
        for name, left in (("a", 260), ("b", 440)):
            rect = pygame.Rect(left, 160, 180, 110)
            _crate(surface, rect, self.case[name])
            surface.blit(font.render(f"{name} ({self.case[name]})", True, TEXT), (left + 10, rect.bottom + 12))
            if name in self.case["want"]:
                pygame.draw.rect(surface, LESSON, rect.inflate(16, 16), 5)
            if name in got:
                pygame.draw.rect(surface, STUDENT, rect.inflate(-10, -10), 3)
            answers = ((self.case["want"], LESSON, "lesson"), (got, STUDENT, "yours"))
            for row, (woken, colour, whose) in enumerate(answers):
                chip = pygame.Rect(left + 10, rect.bottom + 44 + 30 * row, 160, 24)
                pygame.draw.rect(surface, colour, chip, 0 if name in woken else 2)
                surface.blit(small.render(f"{whose}: {'wakes' if name in woken else 'leaves'}", True,
                                          BACK if name in woken else colour), chip.move(8, 5).topleft)
        self.finish(surface, "outlined, filled chip: woken")


def sleeping_crates_cases(check_id, functions):
    from checker.labs.sleeping_crates import checks, probes
    from checker.replay.show_cases import _data
    if check_id == "timer_rule":
        wrong = [c for c in _data(functions, "sleep_timer") or [] if "want" in c and
                 (isinstance(c["got"], str) or not abs(c["got"] - c["want"]) <= checks.ABS)]
        return [TimerCase(c, k + 1, len(wrong), probes.SLEEP_SPEED, probes.SLEEP_SPIN) for k, c in enumerate(wrong)]
    if check_id == "skips_sleepers":
        wrong = [c for c in _data(functions, "moves") or [] if "want" in c and c["got"] != c["want"]]
        return [MovesCase(c, k + 1, len(wrong)) for k, c in enumerate(wrong)]
    if check_id == "wakes_on_contact":
        wrong = [c for c in _data(functions, "wake_on_contact") or [] if "want" in c and c["got"] != c["want"]]
        return [WakeCase(c, k + 1, len(wrong)) for k, c in enumerate(wrong)]
    return None


def failing_cases(lab, result, functions):
    """The failing cases of one of the checks drawn here ([] when there are none to draw), or None for others."""
    from checker.replay.show_cases import _data
    if lab.id == "more_shapes" and result.id == "parallel_axes":
        return parallel_axes_cases(functions)
    if lab.id == "more_shapes" and result.id == "polygon_corners":
        wrong = [c for c in _data(functions, "regular_polygon") or [] if "want" in c and corners_wrong(c)]
        return [CornersCase(c, k + 1, len(wrong)) for k, c in enumerate(wrong)]
    if lab.id == "bullets" and result.id == "bounding_circle":
        return bounding_cases(functions)
    if lab.id == "bullets" and result.id == "broad_test":
        return broad_cases(functions)
    if lab.id == "ball_on_ramp":
        return ball_on_ramp_cases(result.id, functions)
    if lab.id == "sleeping_crates":
        return sleeping_crates_cases(result.id, functions)
    return None
