"""What --show and --pictures draw for Ball on the Ramp's checks (checker/labs/__init__.py says how it is found).

SERIES: the quantity each behaviour check is plotted by (how deep the ball is in a body). CASES: the failing
cases of its function checks, from the probe's judged data:

  ClosestCase   closest_on_segment(): the edge, the point, both answers and the line from the point to each
  CircleCase    circle_polygon(): the polygon, the circle, both normals drawn as long as their depths
  SeparateCase  separate(): both bodies' centres and how far each moves, magnified, both answers
  PolygonCase   disc_inertia(): a disc with both radii of gyration (show_cases.PolygonCase)
  ContactCase   contact_point(): the ball, the other body's surface, the normal, both points
  ImpulseCase   resolve(): each body's velocity and spin change after the friction impulse, and the friction
                at the contact (show_cases.ImpulseCase; the bodies are the probe's fixed contacts)
"""
import math

import pygame
from pygame import Vector2

from lesson11 import records
from lesson11.physics2d import relative_velocity

from checker.judging.declared_acts import body_of, fields, same_motion
from checker.judging.declared_hits import hit_text, same_hit
from checker.replay.show_cases import ImpulseCase, PolygonCase
from checker.replay.show_kit import (BACK, BLUE, GREY, LESSON, ORANGE, SIZE, STUDENT, TEXT, Case, arrow, close,
                                     cross, data, is_point, numbered, point_text, text_font, vec, view)
from checker.replay.show_series import FASTEST, Quantity
from .checks import INSIDE_DEPTH, SINK


def ball_depth(frame):
    """How deep (px) the first dynamic circle overlaps any polygon body (0 when none)."""
    balls = [b for b in records.dynamic(frame) if b.get("radius")]
    if not balls:
        return 0.0
    ball = balls[0]
    return max([records.circle_depth(ball["pos"], ball["radius"], b["points"])
                for b in frame["bodies"] if len(b["points"]) >= 3] + [0.0])


SERIES = {
    "runs": FASTEST,
    "rolls_without_slipping": Quantity("ball into a body (px)", ball_depth, SINK),
    "slides_without_friction": Quantity("ball into a body (px)", ball_depth, SINK),
    "knocks_crate_over": Quantity("ball into a body (px)", ball_depth, SINK),
    "pushed_out_of_crate": Quantity("ball into the crate (px)", ball_depth, INSIDE_DEPTH, at_end=True),
}


# ---------------------------------------------------------------- which answers are wrong, as the checks judge them

def _bad(got):
    return isinstance(got, dict) and "bad" in got


def _same_point(got, want):
    return isinstance(got, list) and all(close(g, w) for g, w in zip(got, want))


def failing(functions, probe, wrong):
    """The probe's cases with a lesson's answer ("want") that `wrong` finds wrong."""
    return [c for c in data(functions, probe) or [] if "want" in c and wrong(c)]


# ---------------------------------------------------------------- the cases

class ClosestCase(Case):
    """closest_on_segment(p, a, b): the edge a-b, the point p, the lesson's closest point and the student's."""

    kind = "closest"

    def lines(self):
        case = self.case
        return [f"{self.head()} (p {vec(case['p'])}, edge {vec(case['a'])} to {vec(case['b'])})",
                f"yours (magenta): {point_text(case['got'])}",
                f"the lesson's (yellow): {vec(case['want'])} (t = {case['t']:.3f} along the edge)"]

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        got = case["got"] if is_point(case["got"]) else None
        at, _ = view([case["p"], case["a"], case["b"], case["want"]] + ([got] if got else []))
        pygame.draw.line(surface, GREY, at(case["a"]), at(case["b"]), 4)
        font = text_font(20)
        for name in ("a", "b"):
            surface.blit(font.render(name, True, GREY), at(case[name]) + Vector2(6, 4))
        pygame.draw.circle(surface, TEXT, at(case["p"]), 6)
        surface.blit(font.render("p", True, TEXT), at(case["p"]) + Vector2(8, -18))
        pygame.draw.line(surface, LESSON, at(case["p"]), at(case["want"]), 3)
        cross(surface, LESSON, at(case["want"]), 10, 4)
        if got:
            pygame.draw.line(surface, STUDENT, at(case["p"]), at(got), 1)
            cross(surface, STUDENT, at(got), 8, 2)
        self.finish(surface, "grey: the edge, white: p")


class CircleCase(Case):
    """circle_polygon(center, radius, points): the polygon and the circle, each answer's normal drawn from the
    circle's center as long as its depth (at least 14 screen px, so a zero depth still shows its direction)."""

    kind = "circle"

    def lines(self):
        case = self.case
        return [f"{self.head()} (center {vec(case['center'])}, radius {case['radius']:g})",
                f"yours (magenta): {hit_text(case['got'])}", f"the lesson's (yellow): {hit_text(case['want'])}"]

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        centre, radius = Vector2(case["center"]), case["radius"]
        reach = Vector2(radius, radius) * 1.5
        at, scale = view(case["points"] + [centre - reach, centre + reach])
        pygame.draw.polygon(surface, (70, 74, 90), [at(p) for p in case["points"]])
        pygame.draw.polygon(surface, GREY, [at(p) for p in case["points"]], 2)
        pygame.draw.circle(surface, ORANGE, at(centre), max(2, radius * scale), 2)
        for hit, colour, width in ((case["want"], LESSON, 5), (case["got"], STUDENT, 2)):
            if hit is None or "bad" in hit or Vector2(hit["normal"]).length() < 1e-12:
                continue
            length = max(abs(hit["depth"]) * scale, 14) * (1 if hit["depth"] >= 0 else -1)
            length = max(-300, min(300, length))
            arrow(surface, colour, at(centre), at(centre) + Vector2(hit["normal"]).normalize() * length, width)
        self.finish(surface, "arrows: the normal, as long as the depth")


class SeparateCase(Case):
    """separate(a, b, normal, depth): where each body's center starts (white) and how far the lesson's push-out
    and the student's move it, magnified (the pushes are fractions of a px)."""

    kind = "separate"

    def moves(self, side):
        """(the student's move, the lesson's) of body `side` (px), the student's None when it is no point."""
        before = Vector2(self.case["before"][side])
        got = self.case["got"][side]
        return (Vector2(got) - before if is_point(got) else None), Vector2(self.case["want"][side]) - before

    def lines(self):
        def said(move):
            return "no point" if move is None else vec(move)
        yours = ", ".join(f"{s.upper()} moves {said(self.moves(s)[0])}" for s in ("a", "b"))
        lesson = ", ".join(f"{s.upper()} moves {vec(self.moves(s)[1])}" for s in ("a", "b"))
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
        font = text_font(20)
        for side, colour in (("a", BLUE), ("b", ORANGE)):
            start = at(before[side])
            static = self.case["inv"][side] == 0
            pygame.draw.circle(surface, colour, start, 14, 0 if not static else 3)
            surface.blit(font.render(side.upper() + (" (static)" if static else ""), True, colour),
                         start + Vector2(-10, 20))
            mine, lesson = self.moves(side)
            if lesson.length() > 0:
                arrow(surface, LESSON, start, start + lesson * magnify, 5)
            if mine is not None and mine.length() > 0:
                arrow(surface, STUDENT, start, start + mine * magnify, 2)
        self.finish(surface, f"arrows: each body's move x{magnify:.3g}")


class ContactCase(Case):
    """contact_point(center, radius, normal, depth): the ball, the other body's surface (depth px into the ball),
    the normal, the lesson's point (on the ball's surface) and the student's."""

    kind = "contact"

    def lines(self):
        case = self.case
        return [f"{self.head()} (radius {case['radius']:g}, normal {vec(case['normal'])}, depth {case['depth']:g})",
                f"yours (magenta): {point_text(case['got'])}",
                f"the lesson's (yellow): {vec(case['want'])} (center + normal * radius)"]

    def draw(self, surface):
        surface.fill(BACK)
        case = self.case
        centre, radius, normal = Vector2(case["center"]), case["radius"], Vector2(case["normal"])
        got = case["got"] if is_point(case["got"]) else None
        reach = Vector2(radius, radius) * 1.6
        at, scale = view([centre - reach, centre + reach] + ([got] if got else []))
        surface_at = centre + normal * (radius - case["depth"])
        along = normal.rotate(90) * radius * 1.5
        pygame.draw.line(surface, GREY, at(surface_at - along), at(surface_at + along), 3)
        pygame.draw.circle(surface, ORANGE, at(centre), max(2, radius * scale), 2)
        arrow(surface, TEXT, at(centre), at(centre + normal * radius * 0.6), 2)
        pygame.draw.circle(surface, LESSON, at(case["want"]), 9, 3)
        if got:
            cross(surface, STUDENT, at(got), 8, 2)
        self.finish(surface, "grey: the other body's surface, white: the normal")


def friction_case(case, number, count, geometry):
    """Ball on the Ramp's resolve() contact as an ImpulseCase: each body's velocity and spin change after the
    student's resolve() and after the lesson's (the "right" variant), the contact normal as the arrow."""
    a, b, normal, point = geometry
    before = {"a": {"vel": list(a.vel), "omega": a.omega}, "b": {"vel": list(b.vel), "omega": b.omega}}
    return ImpulseCase({"case": f"{case['case']} (mu = {case['mu']:.2g})", "before": before, "after": case["got"],
                        "expected": case["want"], "impulse": list(normal), "impulse_label": "normal n",
                        "ra": case["ra"], "rb": case["rb"],
                        "friction": friction_arrows(a, b, Vector2(normal), case["ra"], case["rb"], case["got"],
                                                    case["want"])}, number, count)


def friction_arrows(a, b, normal, ra, rb, got, want):
    """{"slip": B's contact point's velocity past A's along the surface before resolve() (px/s), "yours" /
    "lesson": the friction impulse on B (the part of B's impulse, or minus A's, across the normal) after the
    student's resolve() and the lesson's}, computed here from the probe's fixed bodies (grader-side code)."""
    rel = relative_velocity(a, b, Vector2(ra), Vector2(rb))
    moving, sign = (b, 1) if b.inv_mass else (a, -1)
    side = "b" if moving is b else "a"

    def on_b(state):   # the impulse B got: its momentum change (or minus A's, when B is static), across n
        impulse = (Vector2(state[side]["vel"]) - moving.vel) * (moving.mass * sign)
        return impulse - normal * impulse.dot(normal)
    return {"slip": rel - normal * rel.dot(normal), "yours": on_b(got), "lesson": on_b(want)}


def _resolve_geometry(c):
    """(A, B, normal, point) of a resolve() case, from the descriptions the case holds (drawn ones included)."""
    return body_of(c["a"]), body_of(c["b"]), Vector2(c["normal"]), Vector2(c["point"])


def _disc(case):
    """A disc_inertia case as a PolygonCase's: a 32-sided outline of the radius, mass, both inertias."""
    got = case["got"]
    points = [[case["radius"] * math.cos(2 * math.pi * k / 32), case["radius"] * math.sin(2 * math.pi * k / 32)]
              for k in range(32)]
    return {"case": f"a ball of mass {case['mass']:.4g} and radius {case['radius']:g} px", "points": points,
            "mass": case["mass"], "want": case["want"], "got": got["bad"] if isinstance(got, dict) else got}


# ---------------------------------------------------------------- which cases, per check

def closest_cases(functions, seed):
    """The closest point's failing cases; when every one is right, circle_polygon()'s outside cases."""
    closest = failing(functions, "closest_on_segment", lambda c: not _same_point(c["got"], c["want"]))
    if closest:
        return numbered(ClosestCase, closest)
    return numbered(CircleCase, failing(functions, "circle_outside", lambda c: not same_hit(c["got"], c["want"])))


def inside_cases(functions, seed):
    return numbered(CircleCase, failing(functions, "circle_inside", lambda c: not same_hit(c["got"], c["want"])))


def separate_cases(functions, seed):
    return numbered(SeparateCase, failing(functions, "separate", lambda c: any(
        not _same_point(c["got"][s], c["want"][s]) for s in ("a", "b"))))


def inertia_cases(functions, seed):
    wrong = failing(functions, "disc_inertia", lambda c: _bad(c["got"]) or not close(c["got"], c["want"]))
    return [PolygonCase(_disc(c), k + 1, len(wrong), True) for k, c in enumerate(wrong)]


def contact_cases(functions, seed):
    return numbered(ContactCase, failing(functions, "contact_point", lambda c: not _same_point(c["got"], c["want"])))


def friction_cases(functions, seed):
    wrong = failing(functions, "resolve", lambda c: all(key in c for key in ("a", "b", "normal", "point")) and
                    not fields(same_motion, "ab")(c["got"], c["want"]))
    return [friction_case(c, k + 1, len(wrong), _resolve_geometry(c)) for k, c in enumerate(wrong)]


CASES = {
    "closest_point": closest_cases,
    "inside_case": inside_cases,
    "push_out_split": separate_cases,
    "ball_inertia": inertia_cases,
    "contact_on_surface": contact_cases,
    "friction_rolls": friction_cases,
}
