"""What --show and --pictures draw for Sleeping Crates' checks (checker/labs/__init__.py says how it is found).

SERIES: the quantity each behaviour check is plotted by (how many crates are awake). CASES: the failing cases
of its function checks, from the probe's judged data:

  TimerCase  sleep_timer(): speed and spin against their thresholds, the timer before and both timers after
  MovesCase  moves(): the body (static, awake, asleep) and whether each answer lets it fall
  WakeCase   wake_on_contact(): the two bodies touching, the ones each answer wakes outlined
"""
import math

import pygame

from lesson11 import records

from checker.replay.show_kit import BACK, BAD, GOOD, LESSON, STUDENT, TEXT, Case, arrow, data, numbered, text_font
from checker.replay.show_series import FASTEST, Quantity
from .probes import SLEEP_SPEED, SLEEP_SPIN


def awake_count(frame):
    """How many dynamic bodies are awake."""
    return float(sum(1 for b in records.dynamic(frame) if not b.get("asleep")))


AWAKE = Quantity("crates awake", awake_count)
SERIES = {
    "runs": FASTEST,
    "pile_sleeps": Quantity("crates awake", awake_count, 0.0, at_end=True),
    "no_sleep_in_air": AWAKE,
    "drop_wakes_pile": AWAKE,
}
TIMER_CLOSE = 1e-9   # s: the timer against the rule (same arithmetic, timer + dt), as timer_rule judges it


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
        font = text_font(20)
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
        font = text_font(20)
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
    """"static", "asleep" or "awake" for a moves() case by its name (probes.py)."""
    return "static" if "static" in name or "floor" in name else "asleep" if "sleeping" in name else "awake"


def _crate(surface, rect, kind, outline=None):
    colour = {"static": (130, 130, 140), "awake": (200, 150, 90), "asleep": (90, 68, 40)}[kind]
    pygame.draw.rect(surface, colour, rect)
    if kind == "asleep":
        at = rect.move(rect.width / 2 - 14, rect.height / 2 - 10).topleft
        surface.blit(text_font(26).render("z z", True, TEXT), at)


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
                arrow(surface, colour, (x, rect.top), (x, rect.bottom + 140), 4)
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
        font, small = text_font(24), text_font(20)
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


def timer_cases(functions, seed):
    wrong = [c for c in data(functions, "sleep_timer") or [] if "want" in c and
             (isinstance(c["got"], str) or not abs(c["got"] - c["want"]) <= TIMER_CLOSE)]
    return numbered(TimerCase, wrong, SLEEP_SPEED, SLEEP_SPIN)


def differing(functions, probe):
    """The probe's cases whose answer is not the lesson's."""
    return [c for c in data(functions, probe) or [] if "want" in c and c["got"] != c["want"]]


CASES = {
    "timer_rule": timer_cases,
    "skips_sleepers": lambda functions, seed: numbered(MovesCase, differing(functions, "moves")),
    "wakes_on_contact": lambda functions, seed: numbered(WakeCase, differing(functions, "wake_on_contact")),
}
