"""What --show and --pictures draw for Billiards: SERIES, each scene check's quantity per frame and its bound;
CASES, a failed step's cases: the balls and each answer's normal, or the velocities before and after."""
import math

import pygame
from pygame import Vector2

from checker.judging.declared import listed
from checker.replay.show_kit import BACK, GREY, LESSON, STUDENT, TEXT, Case, arrow, cross, data, numbered, text_font
from checker.replay.show_series import FASTEST, Quantity
from lesson11 import records as metrics
from . import checks, probes, scenes

SERIES = {
    "runs": FASTEST,
    "speeds_exchange": Quantity("head-on cue ball's speed (px/s)", lambda f: metrics.speed(metrics.dynamic(f)[0]),
                                checks.CUE_KEEPS * scenes.HEAD_ON_SPEED, at_end=True),
    "momentum_kept": Quantity("total momentum (px/s, mass 1 each)", lambda f: math.hypot(*scenes.momentum(f))),
    "no_overlap": Quantity("deepest overlap (px)", lambda f: scenes.overlap(f)[0], checks.OVERLAP),
    "comes_to_rest": Quantity("balls rolling", lambda f: sum(metrics.speed(b) > 0 for b in metrics.dynamic(f)), 0.0,
                              at_end=True),
}


class BallsCase(Case):
    """One failing case of a Billiards step, drawn by its kind: "contact", "bounce" or "cloth"."""

    def __init__(self, case, number, count, kind):
        super().__init__(case, number, count)
        self.kind = kind

    def said(self, value):
        if not isinstance(value, list):
            return str(value)
        if self.kind == "contact":
            return f"normal {listed(value[:2])}, depth {value[2]:.2f} px"
        return f"{'vA, vB' if self.kind == 'bounce' else 'v'} {listed(value)} px/s"

    def lines(self):
        return [self.head(), f"yours (magenta): {self.said(self.case['got'])}",
                f"the lesson's (yellow): {self.said(self.case['want'])}"]

    def draw(self, surface):
        surface.fill(BACK)
        case, font, centre = self.case, text_font(20), Vector2(450, 220)
        rows = [(v, c) for v, c in ((case["want"], LESSON), (case["got"], STUDENT)) if isinstance(v, list)]
        if self.kind == "contact":   # the balls 4 x life size around their midpoint, each answer's normal x 60
            middle = (Vector2(case["ca"]) + Vector2(case["cb"])) / 2
            for c, r in ((case["ca"], case["ra"]), (case["cb"], case["rb"])):
                pygame.draw.circle(surface, GREY, centre + (Vector2(c) - middle) * 4, r * 4, 2)
            for value, colour in rows:
                arrow(surface, colour, centre, centre + Vector2(value[:2]) * 60)
            return self.finish(surface, "grey: the balls, arrows: the normal x 60")
        rows = [(case["va"] + case["vb"] if self.kind == "bounce" else case["vel"], GREY)] + rows
        scale = 85 / max([math.hypot(*v[k:k + 2]) for v, _ in rows for k in range(0, len(v), 2)] + [1e-9])
        for row, (value, colour) in enumerate(rows):   # a row each: before, the lesson's after, yours after
            surface.blit(font.render(("before", "lesson's", "yours")[row], True, colour), (40, 110 + 110 * row))
            for k in range(0, len(value), 2):
                at = Vector2(260 + 160 * k, 120 + 110 * row)
                pygame.draw.circle(surface, colour, at, 14, 2)
                surface.blit(font.render("AB"[k // 2] if len(value) > 2 else "", True, TEXT), at - (5, 8))
                if value[k:k + 2] == [0.0, 0.0]:
                    cross(surface, colour, at, 6, 2)
                arrow(surface, colour, at, at + Vector2(value[k:k + 2]) * scale)
        self.finish(surface, "grey: the case, arrows: velocities (the fastest 85 px), x: at rest")


def cases_of(probe, kind):
    return lambda functions, seed: numbered(BallsCase, [c for c in data(functions, probe) or [] if "want" in c
                                                        and not probes.same(c["got"], c["want"])], kind)


CASES = {"circle_circle_right": cases_of("circle_circle", "contact"), "bounce_right": cases_of("bounce", "bounce"),
         "cloth_slowing_right": cases_of("cloth_slowing", "cloth")}
