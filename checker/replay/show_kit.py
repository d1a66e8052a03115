"""The drawing kit of --show's failing cases: colours, text, arrows and crosses, fitting points to the window,
the footer every case writes its lines in, and Case, what most cases share.

A lab draws its own cases with it (checker/labs/<id>/show.py); the case classes several labs use are in
checker/replay/show_cases.py. The data drawn are the probe's, judged on the grading side: nothing here runs the
student's code. This module imports nothing of the checker.
"""
import math

import pygame
from pygame import Vector2

CLOSE = 1e-7        # relative and absolute: the function checks' tolerance
STUDENT = (235, 70, 200)   # the student's answer: magenta (the lesson's stays the explorer's yellow)
LESSON = (250, 220, 80)
TEXT = (230, 230, 230)
SIZE = (900, 600)          # px: the case view (the labs' window)
BACK = (24, 26, 34)
GREY = (150, 155, 170)
BLUE, ORANGE = (70, 130, 235), (245, 150, 40)
GOOD, BAD = (90, 210, 120), (235, 80, 80)
HELP = "[ ]: case   Tab: scene   Esc: quit"
BOX = (80, 70, 740, 360)   # screen px (left, top, width, height) a drawing is fitted into, over the footer


def close(got, want, scale=1.0):
    """True when got is want within the function checks' tolerance (CLOSE × max(scale, 1) + CLOSE × |want|)."""
    return abs(got - want) <= CLOSE * max(scale, 1.0) + CLOSE * abs(want)


def text_font(size=22):
    """pygame's default font at `size` px (pygame.font initialised on first use)."""
    if not pygame.font.get_init():
        pygame.font.init()
    return pygame.font.Font(None, size)


def vec(v):
    return f"({v[0] + 0.0:.2f}, {v[1] + 0.0:.2f})"


def point_text(value):
    """A point answer as text: "(x, y)", or what was wrong with it."""
    return value["bad"] if isinstance(value, dict) else vec(value)


def is_point(value):
    return isinstance(value, list) and len(value) == 2 and all(abs(v) < 1e7 for v in value)


def data(functions, name):
    """The judged data of probe `name` ({probe name: entry}), or None when it raised or did not run."""
    entry = functions.get(name) or {}
    return entry.get("data") if entry.get("ok") else None


def wrapped(font, lines, width, separator=" "):
    """The lines, each broken at `separator` where it is wider than `width` px in `font` (a piece that is
    wider on its own stays whole)."""
    out = []
    for line in lines:
        current = ""
        for piece in line.split(separator):
            joined = current + separator + piece if current else piece
            if current and font.size(joined)[0] > width:
                out.append(current)
                current = piece
            else:
                current = joined
        out.append(current)
    return out


# ---------------------------------------------------------------- shapes

def arrow(surface, colour, start, end, width=3):
    from lesson11.explorer import draw_arrow
    draw_arrow(surface, colour, start, end, width)


def cross(surface, colour, at, size=8, width=3):
    pygame.draw.line(surface, colour, at - Vector2(size, size), at + Vector2(size, size), width)
    pygame.draw.line(surface, colour, at - Vector2(size, -size), at + Vector2(size, -size), width)


FULL_TURN = 1.75 * math.pi   # the arc of the largest spin change in a case (a ring left open at the top)


def spin_arc(surface, colour, centre, radius, spin, largest, font=None):
    """An arc around `centre` from its top, with an arrowhead, for a spin change `spin` (rad/s): its length is
    FULL_TURN × |spin| / largest (the largest change drawn in the case, so sizes compare), clockwise on screen
    when positive (y down); `font`: the value is written at the arrowhead."""
    if abs(spin) < 1e-12 or not math.isfinite(spin):
        return
    sweep = max(FULL_TURN * min(abs(spin) / max(largest, 1e-12), 1.0), 0.2) * (1 if spin > 0 else -1)
    start = -math.pi / 2   # the top; the angle grows clockwise on screen
    steps = max(int(abs(sweep) * radius / 4), 2)
    points = [centre + Vector2(math.cos(start + sweep * k / steps), math.sin(start + sweep * k / steps)) * radius
              for k in range(steps + 1)]
    pygame.draw.lines(surface, colour, False, points, 3)
    tip = points[-1]
    along = (points[-1] - points[-2]).normalize() if points[-1] != points[-2] else Vector2(1, 0)
    side = Vector2(-along.y, along.x)
    pygame.draw.polygon(surface, colour, [tip + along * 9, tip - along * 3 + side * 6, tip - along * 3 - side * 6])
    if font is not None:
        text = font.render(f"{spin:+.3g}", True, colour)
        out = (tip - centre).normalize() if tip != centre else Vector2(0, -1)
        at = tip + out * 16
        surface.blit(text, (at.x - text.get_width() / 2, at.y - text.get_height() / 2))


def fit(points, box=(120, 90, 660, 380)):
    """(scale, offset) that fit the points into `box` (left, top, width, height; screen px)."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    width, height = max(max(xs) - min(xs), 1e-9), max(max(ys) - min(ys), 1e-9)
    scale = min(box[2] / width, box[3] / height)
    offset = Vector2(box[0] + box[2] / 2, box[1] + box[3] / 2) - Vector2((max(xs) + min(xs)) / 2,
                                                                         (max(ys) + min(ys)) / 2) * scale
    return scale, offset


def view(points, box=BOX):
    """(a function taking a point (px) to the screen, its scale), fitting `points` into `box`."""
    scale, offset = fit([tuple(p) for p in points], box)
    return lambda p: Vector2(p) * scale + offset, scale


# ---------------------------------------------------------------- the case's text

def footer_top(count):
    """The screen y where the footer's text of `count` lines starts."""
    return SIZE[1] - 30 - 24 * count - 6


def footer(surface, lines, help_text):
    """The case's text lines at the bottom of the case view, over a dark band."""
    writer = text_font()
    top = footer_top(len(lines)) + 6
    pygame.draw.rect(surface, (16, 18, 24), (0, top - 6, SIZE[0], SIZE[1] - top + 6))
    for row, line in enumerate(lines):
        colour = STUDENT if line.startswith("yours") else LESSON if line.startswith("the lesson") else TEXT
        surface.blit(writer.render(line, True, colour), (20, top + 24 * row))
    surface.blit(writer.render(help_text, True, (160, 165, 180)), (20, SIZE[1] - 26))


class Case:
    """What most failing cases share: their number among the failing ones, no keys of their own, the footer.

    A case is drawn by --show's window through draw(surface) (the SIZE view), key(key) (True when it used
    the key) and lines() (its text: a head, then "yours ..." and "the lesson's ..." lines)."""

    kind = ""

    def __init__(self, case, number, count):
        self.case, self.number, self.count = case, number, count

    def key(self, key):
        return False

    def head(self):
        return f"failing case {self.number} of {self.count}: {self.case.get('case', '')}"

    def finish(self, surface, legend):
        footer(surface, self.lines(), f"{legend}   {HELP}")


def numbered(kind, cases, *extra):
    """The cases as `kind` objects, numbered 1..n of n (extra: more arguments for each)."""
    return [kind(case, k + 1, len(cases), *extra) for k, case in enumerate(cases)]
