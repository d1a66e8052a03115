"""What --show and --pictures draw for Bullets' checks (checker/labs/__init__.py says how it is found).

SERIES: its whole run's quantity. CASES: the failing cases of its function checks, from the probe's judged
data (shapes and paths the data name but do not hold come from the probe's fixed cases, grader-side code):

  ToiCase       circle_toi(): both circles' paths, where they are at both times of impact, a bar of the step
  BoundingCase  bounding_radius(): the outline, its centre and both circles
  BroadCase     time_of_impact(): the crate, its bounding circle, the path, both impacts, the exact tests
  SweptCase     swept_move(): the bullet's path to the impact and both ends of the step
"""
import random

import pygame
from pygame import Vector2

from checker.replay.show_kit import (BACK, BLUE, GREY, LESSON, SIZE, STUDENT, TEXT, Case, arrow, close, cross,
                                     data, fit, footer, numbered, text_font, vec, view)
from checker.replay.show_series import FASTEST
from . import probes

SERIES = {"runs": FASTEST}


_hit = probes.hit_text   # a time_of_impact() answer written as the check writes it


# ---------------------------------------------------------------- circle_toi() and swept_move()

def _time(value):
    """A time answer as text: "None", "12.5 ms", or what was wrong with it."""
    if value is None:
        return "None (no hit)"
    if isinstance(value, dict):
        return f"returned {value.get('bad')}"
    return f"{value * 1000:.4g} ms"


class ToiCase(Case):
    """One circle_toi() case: both circles' paths over the step, where they are at the student's time of
    impact (magenta) and at the lesson's (yellow), and a bar of the step [0, dt] with both times on it.
    The geometry comes from the probe's cases (probes.py toi_cases(), and drawn_toi_cases()
    redrawn from the grading seed: _toi_geometry), grader-side code; without it only the times are shown."""

    kind = "toi"

    def __init__(self, case, number, count, geometry=None):
        super().__init__(case, number, count)
        self.geometry = geometry

    def lines(self):
        return [f"{self.head()} (dt = {self.case['dt'] * 1000:.4g} ms)",
                f"yours (magenta): t = {_time(self.case['got'])}",
                f"the lesson's (yellow): t = {_time(self.case['want'])}"]

    def draw(self, surface):
        surface.fill((24, 26, 34))
        dt = self.case["dt"]
        times = [(t, colour) for t, colour in ((self.case["want"], LESSON), (self.case["got"], STUDENT))
                 if isinstance(t, (int, float))]
        if self.geometry is not None:
            p1, v1, r1, p2, v2, r2 = self.geometry
            ends = [p1, p1 + v1 * dt, p2, p2 + v2 * dt]
            pad = max(r1, r2)
            scale, offset = fit([(p.x - pad, p.y - pad) for p in ends] + [(p.x + pad, p.y + pad) for p in ends],
                                 (80, 60, 740, 300))

            def at(p):
                return p * scale + offset
            for p, v, r, colour in ((p1, v1, r1, (70, 130, 235)), (p2, v2, r2, (245, 150, 40))):
                pygame.draw.line(surface, colour, at(p), at(p + v * dt), 1)
                pygame.draw.circle(surface, colour, at(p), max(2, r * scale))
                for t, mark in times:
                    if -dt <= t <= 2 * dt:
                        pygame.draw.circle(surface, mark, at(p + v * t), max(2, r * scale), 2)
        bar = pygame.Rect(80, 400, 740, 8)
        pygame.draw.rect(surface, (150, 155, 170), bar)
        font = text_font(20)
        surface.blit(font.render("0", True, TEXT), (bar.left - 4, bar.bottom + 4))
        surface.blit(font.render("dt", True, TEXT), (bar.right - 8, bar.bottom + 4))
        for t, colour in times:
            x = bar.left + max(-0.1, min(1.1, t / dt)) * bar.width
            pygame.draw.line(surface, colour, (x, bar.top - 14), (x, bar.bottom + 14), 3)
        footer(surface, self.lines(), "circles: where both are at each time   [ ]: case   Tab: scene   Esc: quit")


class SweptCase(Case):
    """One swept_move() case: the bullet's path over the step, the impact (at the lesson's time of impact),
    and where the bullet ends: the student's (magenta) and the lesson's (yellow)."""

    kind = "swept"

    def __init__(self, case, number, count, step):
        super().__init__(case, number, count)
        self.step = step

    def path(self):
        """(start, impact or None, lesson's end, student's end) in px, from the probe's data."""
        variants, t = self.case.get("forms") or {}, self.case.get("t")
        want = Vector2(self.case["want"]["bullet"]["pos"])
        got = Vector2(self.case["got"]["bullet"]["pos"])
        if t is None or "swept_stops" not in variants or "swept_old_velocity" not in variants or self.step - t <= 0:
            return None, None, want, got
        impact, through = (Vector2(_bullet_pos(variants[name])) for name in ("swept_stops", "swept_old_velocity"))
        velocity = (through - impact) / (self.step - t)
        return impact - velocity * t, impact, want, got

    def lines(self):
        t = self.case.get("t")
        got, want = self.case["got"]["bullet"], self.case["want"]["bullet"]
        return [self.head()
                + (f" (impact at t = {t * 1000:.4g} ms of {self.step * 1000:.4g})" if t is not None else ""),
                f"yours (magenta): the bullet ends at {vec(got['pos'])} moving {vec(got['vel'])} px/s",
                f"the lesson's (yellow): at {vec(want['pos'])} moving {vec(want['vel'])} px/s"]

    def draw(self, surface):
        surface.fill((24, 26, 34))
        start, impact, want, got = self.path()
        points = [p for p in (start, impact, want, got) if p is not None]
        others = [Vector2(o["pos"]) for o in self.case["want"].get("others", ())]
        scale, offset = fit([(p.x, p.y) for p in points] + [(p.x + 10, p.y + 10) for p in points],
                             (80, 80, 740, 330))

        def at(p):
            return p * scale + offset
        for other in others:   # the other bodies' centres (the wall, a crate) as grey crosses
            cross(surface, (150, 155, 170), at(other), 8, 2)
        if start is not None:
            pygame.draw.line(surface, (150, 155, 170), at(start), at(impact), 2)
            pygame.draw.circle(surface, (150, 155, 170), at(start), 5, 1)
            pygame.draw.circle(surface, (235, 80, 80), at(impact), 6)
            for end, colour in ((want, LESSON), (got, STUDENT)):
                pygame.draw.line(surface, colour, at(impact), at(end), 2)
        pygame.draw.circle(surface, LESSON, at(want), 9, 3)
        pygame.draw.circle(surface, STUDENT, at(got), 6, 2)
        footer(surface, self.lines(), "grey: the path to the impact (red)   [ ]: case   Tab: scene   Esc: quit")


def _bullet_pos(outcome):
    """The bullet's position in a swept_move outcome ({"bullet": state, "others": [...]}; older probes: a point)."""
    return outcome["bullet"]["pos"] if isinstance(outcome, dict) else outcome


def toi_wrong(case):
    got, want = case.get("got"), case.get("want")
    if isinstance(got, dict) or (got is None) != (want is None):
        return True
    return got is not None and abs(got - want) > 1e-9


def swept_wrong(case):
    got, want = case["got"], case["want"]
    pairs = [(got["bullet"], want["bullet"])] + list(zip(got.get("others", ()), want.get("others", ())))
    return any(not close(g, w) for a, b in pairs for key in ("pos", "vel") for g, w in zip(a[key], b[key]))


def _toi_geometry(case, seed=None):
    """(p1, v1, r1, p2, v2, r2) of a circle_toi case: a fixed one from the probe's toi_cases(), a drawn one
    redrawn here from the grading seed as the probe drew it (drawn_toi_cases with run_rng's Random), both
    grader-side code; a redrawn case counts only when its dt is the recorded one. None when neither fits."""
    drawn = probes.drawn_toi_cases(random.Random(f"{seed}:circle_toi")) if seed is not None else []
    for name, p1, v1, r1, p2, v2, r2, dt in probes.toi_cases() + drawn:
        if name == case["case"] and abs(dt - case["dt"]) <= 1e-12 * max(1.0, dt):
            return p1, v1, r1, p2, v2, r2
    return None


# ---------------------------------------------------------------- bounding_radius() and time_of_impact()

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
        at, scale = view([centre - corner, centre + corner] + [tuple(p) for p in points])
        if len(points) >= 3:
            pygame.draw.polygon(surface, (70, 130, 235), [at(p) for p in points])
            pygame.draw.polygon(surface, TEXT, [at(p) for p in points], 1)
        pygame.draw.circle(surface, TEXT, at(centre), 4)
        pygame.draw.circle(surface, LESSON, at(centre), max(2, self.case["want"] * scale), 4)
        if beyond:
            arrow(surface, STUDENT, at(centre), Vector2(SIZE[0] - 20, at(centre).y), 2)
            surface.blit(text_font(20).render(f"yours: {got:.4g} px, beyond the picture", True, STUDENT),
                         (SIZE[0] - 300, at(centre).y + 8))
        elif got is not None:
            pygame.draw.circle(surface, STUDENT, at(centre), max(2, got * scale), 2)
        self.finish(surface, "white: the centre" + ("" if points else " (the shape was drawn for the run)"))


def bounding_cases(functions, seed):
    shapes = {name: (points, centre) for name, points, centre in probes.bounding_cases()}
    wrong = [c for c in data(functions, "bounding_radius") or [] if "want" in c and
             not (isinstance(c["got"], float) and close(c["got"], c["want"]))]
    return [BoundingCase(c, k + 1, len(wrong), shapes.get(c["case"])) for k, c in enumerate(wrong)]


class BroadCase(Case):
    """time_of_impact(bullet, other, dt): the crate with its bounding circle (grey), the bullet's path over the step,
    where the bullet is at the lesson's time of impact (yellow, with the normal) and at the student's (magenta), at
    the path's end for "no hit", and how many exact swept tests the student's ran (magenta ticks at its start)."""

    kind = "broad"

    def __init__(self, case, number, count, geometry):
        super().__init__(case, number, count)
        self.geometry = geometry   # (bullet, other body, dt) from the case

    def lines(self):
        case = self.case
        reach = "the bullet reaches the bounding circle" if case["needs_exact"] else \
            "out of the bounding circle's reach: no exact test needed"
        return [self.head(), f"yours (magenta): {_hit(case['got']['hit'])}, {case['got']['exact_tests']} exact swept "
                "test(s)", f"the lesson's (yellow): {_hit(case['want']['hit'])} ({reach})"]

    def draw(self, surface):
        surface.fill(BACK)
        bullet, other, dt = self.geometry
        corners = other.world_points()
        bounding = max(other.pos.distance_to(p) for p in corners)
        end = bullet.pos + bullet.vel * dt
        reach = Vector2(bounding, bounding)
        at, scale = view([other.pos - reach, other.pos + reach, bullet.pos, end])
        pygame.draw.polygon(surface, BLUE, [at(p) for p in corners])
        pygame.draw.circle(surface, GREY, at(other.pos), bounding * scale, 1)
        pygame.draw.line(surface, GREY, at(bullet.pos), at(end), 1)
        pygame.draw.circle(surface, TEXT, at(bullet.pos), max(3, bullet.radius * scale), 1)
        for hit, colour, width in ((self.case["want"]["hit"], LESSON, 4), (self.case["got"]["hit"], STUDENT, 2)):
            if hit is None:   # no hit: the bullet ends the step where its path ends
                pygame.draw.circle(surface, colour, at(end), max(4, bullet.radius * scale) + width, width)
            elif isinstance(hit, dict) and "t" in hit and abs(hit["t"]) < 10 * dt:
                where = at(bullet.pos + bullet.vel * hit["t"])
                pygame.draw.circle(surface, colour, where, max(4, bullet.radius * scale), width)
                arrow(surface, colour, where, where + Vector2(hit["normal"]) * 40, width)
        for k in range(min(self.case["got"]["exact_tests"], 10)):
            x = at(bullet.pos).x - 10 + 8 * k
            pygame.draw.line(surface, STUDENT, (x, at(bullet.pos).y - 30), (x, at(bullet.pos).y - 16), 3)
        self.finish(surface, "grey: the bounding circle and the path over dt, ticks: your exact tests")


def broad_cases(functions, seed):
    wrong = [c for c in data(functions, "time_of_impact") or [] if "want" in c and
             not probes.BROAD_TEST.same(c["got"], c["want"])]
    return [BroadCase(c, k + 1, len(wrong), (c["bullet"], c["other"], c["dt"])) for k, c in enumerate(wrong)]


def toi_cases(functions, seed):
    wrong = [case for case in data(functions, "circle_toi") or [] if "want" in case and toi_wrong(case)]
    return [ToiCase(case, k + 1, len(wrong), _toi_geometry(case, seed)) for k, case in enumerate(wrong)]


def swept_cases(functions, seed):
    return numbered(SweptCase, [case for case in data(functions, "swept_move") or []
                                if "want" in case and swept_wrong(case)], probes.STEP)


CASES = {
    "toi_matches_root": toi_cases,
    "bounding_circle": bounding_cases,
    "broad_test": broad_cases,
    "swept_move_resolves": swept_cases,
}
