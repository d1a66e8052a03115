"""The failing cases of a function check, drawn by --show (python -m checker FILE --show): the lookup, and the
case classes several labs draw with.

The data are the probe's, judged on the grading side (checker/judging/probing.py): each case holds the inputs,
the student's answer ("got", recorded in the child) and the lesson's (computed in the grader). Nothing
of the student's code runs in this process.

  SatCase      a pair of shapes, every candidate axis with both shadows (lesson11/explorer.py's drawing),
               the lesson's axis and depth (yellow, the explorer's MTV) and the student's (magenta)
  ImpulseCase  two bodies around a contact, the impulse, each body's velocity change as arrows (the
               lesson's and the student's) and its spin change as arcs; optionally the friction at the contact
  PolygonCase  an outline with the student's centroid and the lesson's, or both radii of gyration (inertia)

Which cases a failed check draws is its lab's: failing_cases() looks up the check in the CASES of the lab's
checker/labs/<id>/show.py (see checker/labs/__init__.py); a lab without one draws none. Each case has
draw(surface), key(key) and lines() (checker/replay/show_kit.py's Case).
"""
import math
import re

import pygame
from pygame import Vector2

from lesson11.physics2d import Body, centre_of

from checker.replay.show_kit import (LESSON, SIZE, STUDENT, TEXT, Case, arrow, cross, fit, footer, footer_top,
                                     spin_arc, text_font, vec, wrapped)


def failing_cases(lab, result, functions, seed=None):
    """The failing cases of a failed function check, as drawable cases ([] for other checks, no data, or a lab
    that draws none): CASES[check id](functions, seed) of the lab's show module.

    functions: the probe's judged data {probe name: entry}; seed: the grading run's seed (the probe's drawn
    inputs, which a lab may redraw from it)."""
    if result.status not in ("fail", "error"):
        return []
    cases = getattr(lab.replay, "CASES", {}).get(result.id)
    return cases(functions, seed) if cases is not None else []


# ---------------------------------------------------------------- SAT

def _body(points, shift, colour):
    """A mass-0 Body whose world corners are `points` moved by `shift` (px)."""
    centre = centre_of([Vector2(p) for p in points])
    local = [Vector2(p) - centre for p in points]
    return Body(local, centre + shift, 0, color=colour)


PX = re.compile(r"(-?\d+(?:\.(\d+))?) px")
SHAPES_SPAN = 220   # screen px the pair of shapes spans when drawn (the probe's shapes are 20-80 px)


class ScaledFont:
    """A pygame Font whose text says "<n> px" in the case's px: the shapes are drawn `scale` times larger, so
    every length the explorer writes (shadows, overlap, gap, MTV) is divided by `scale` before it is shown."""

    def __init__(self, font, scale):
        self.font, self.scale = font, scale

    def _unscaled(self, found):
        decimals = len(found.group(2) or "")
        return f"{float(found.group(1)) / self.scale:.{decimals}f} px"

    def render(self, text, *args):
        return self.font.render(PX.sub(self._unscaled, text), *args)

    def size(self, text):
        return self.font.size(PX.sub(self._unscaled, text))

    def __getattr__(self, name):
        return getattr(self.font, name)


HEADER_TOP, HEADER_ROW = 66, 24   # screen px: the explorer's own text rows (covered by the case's header band)


class CaseExplorer:
    """The SAT explorer's drawing (lesson11/explorer.py) fitted between a header and a footer band.

    The explorer puts its axis AXIS_OFFSET px from the boxes, wherever the window has room, and its text at
    the top: in the case view the text has its own band, so the axis goes just beyond the shapes and the
    whole drawing (shapes, shadows, overlap label, both answers) is moved into the free band between."""

    GAP = 40   # screen px between the shapes and the axis line

    def __init__(self, explorer_class):
        self.view = explorer_class(*SIZE)
        self.view.axis_anchor = self.axis_anchor

    def axis_anchor(self, normal):
        """A point the axis line passes through: GAP px beyond the shapes, on the side of +side."""
        middle = (self.view.blue.pos + self.view.orange.pos) / 2
        side = Vector2(-normal.y, normal.x)
        if side.y > 1e-9 or (abs(side.y) <= 1e-9 and side.x > 0):
            side = -side   # above, else left of the shapes: one rule for every axis
        points = self.view.blue.world_points() + self.view.orange.world_points()
        reach = max((p - middle).dot(side) for p in points)
        return middle + side * (reach + self.GAP)


class SatCase:
    """One sat() case drawn as the SAT explorer draws two boxes, with both answers.

    The shapes are drawn `scale` times their size (they span at most about SHAPES_SPAN px, less when the
    drawing would not fit between the bands: layout()), and every length written on the picture is in the
    case's own px (ScaledFont).
    """

    kind = "sat"
    MARGIN = 12   # screen px kept free around the drawing

    def __init__(self, case, number, count):
        from lesson11 import explorer
        self.case, self.number, self.count = case, number, count
        text_font()   # the explorer's fonts need pygame.font ready
        self.explorer = CaseExplorer(explorer.Explorer)
        self.view = self.explorer.view
        self.colours = explorer.BLUE, explorer.ORANGE
        self.font = text_font(24)
        self.big = text_font(44)
        a, b = case["a"], case["b"]
        xs, ys = [p[0] for p in a + b], [p[1] for p in a + b]
        self.span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
        self.layout(max(1.0, min(6.0, SHAPES_SPAN / self.span)))
        self.view.axis_index = self._best_axis()

    # ---- layout
    def _place(self, scale, shift=Vector2()):
        """Build both bodies `scale` times the case's size, their shapes' middle at the band's middle + shift."""
        self.scale = scale
        self.view.font = ScaledFont(getattr(self.view.font, "font", self.view.font), scale)
        self.view.big_font = ScaledFont(getattr(self.view.big_font, "font", self.view.big_font), scale)
        a = [[v * scale for v in p] for p in self.case["a"]]
        b = [[v * scale for v in p] for p in self.case["b"]]
        middle = (centre_of([Vector2(p) for p in a]) + centre_of([Vector2(p) for p in b])) / 2
        top, bottom = self.band()
        at = Vector2(SIZE[0] / 2, (top + bottom) / 2) + shift - middle
        self.view.blue = _body(a, at, self.colours[0])
        self.view.orange = _body(b, at, self.colours[1])

    def header(self):
        """The header's lines: the explorer's explanation of the axis on screen, wrapped to the window."""
        return wrapped(ScaledFont(self.font, self.scale), self.view.lines(), SIZE[0] - 40)

    def band(self):
        """(top, bottom) in screen px of the band the drawing must stay in: under the header, over the footer."""
        return HEADER_TOP + HEADER_ROW * len(self.header()) + self.MARGIN, footer_top(len(self.lines())) - self.MARGIN

    def extent(self):
        """(left, top, right, bottom) screen px of everything the case draws for the axis on screen: both
        shapes, both shadows with the overlap label beside them, the lesson's MTV with its label and ghost,
        the student's ghost (when it is within a few spans of the shapes)."""
        view = self.view
        _, _, normal = view.current_axis()
        blue, orange, overlap = view.shadows(normal)
        anchor = view.axis_anchor(normal)
        label = self.view.font.size(f"overlap {overlap:.1f} px")
        room = 14 + 9 + 10 + max(label)   # the explorer's SHADOW_GAP + SHADOW_WIDTH + 10, and the label
        points = view.blue.world_points() + view.orange.world_points()
        for value in blue + orange:
            points += [view.on_axis(value, normal, anchor, room), view.on_axis(value, normal, anchor, -room)]
        boxes = [(p, (0, 0)) for p in points]
        hit = view.hit()
        if hit is not None:
            tip = view.orange.pos + hit[0] * hit[1]
            boxes += [(p + hit[0] * hit[1], (0, 0)) for p in view.orange.world_points()]
            boxes.append((tip + hit[0] * (view.orange.radius + 45), view.font.size(f"MTV {hit[1]:.1f} px")))
        for p in self.student_ghost() or ():
            boxes.append((p, (0, 0)))
        return (min(p.x - w / 2 for p, (w, h) in boxes), min(p.y - h / 2 for p, (w, h) in boxes),
                max(p.x + w / 2 for p, (w, h) in boxes), max(p.y + h / 2 for p, (w, h) in boxes))

    def fits(self):
        left, top, right, bottom = self.extent()
        band = self.band()
        return right - left <= SIZE[0] - 2 * self.MARGIN and bottom - top <= band[1] - band[0]

    def layout(self, scale):
        """Shrink the drawing until it fits the band for every axis (the scale stays the same while N steps
        through the axes), then centre it in the band for the axis on screen."""
        index = self.view.axis_index
        while scale > 0.2:
            self._place(scale)
            fits = True
            for k in range(len(self.view.axes())):
                self.view.axis_index = k
                fits = fits and self.fits()
            if fits:
                break
            scale *= 0.9
        self.view.axis_index = index
        self.centre()

    def centre(self):
        """Move the shapes so the drawing for the axis on screen sits in the middle of the band."""
        self._place(self.scale)
        left, top, right, bottom = self.extent()
        band = self.band()
        self._place(self.scale, Vector2(SIZE[0] / 2 - (left + right) / 2, (band[0] + band[1]) / 2 - (top + bottom) / 2))

    def _best_axis(self):
        """The axis of the lesson's answer (the smallest overlap), or the first that shows a gap."""
        hit = self.view.hit()
        axes = self.view.axes()
        for index, (_, _, normal) in enumerate(axes):
            if hit is None and self.view.separates(normal):
                return index
            if hit is not None and abs(abs(normal.dot(hit[0])) - 1) < 1e-9:
                return index
        return 0

    def key(self, key):
        """N / Space: the next candidate axis."""
        if key in (pygame.K_n, pygame.K_SPACE):
            self.view.next_axis()
            return True
        return False

    def answers(self):
        """(the student's answer, the lesson's) as text."""
        def said(hit):
            if hit is None:
                return "apart (None)"
            if "bad" in hit:
                return f"returned {hit['bad']}"
            return f"depth {hit['depth']:.2f} px along {vec(hit['normal'])}"
        return said(self.case.get("got")), said(self.case.get("lesson"))

    def lines(self):
        yours, lesson = self.answers()
        order = " with A and B swapped" if self.case.get("order") == "B, A" else ""
        return [f"failing case {self.number} of {self.count}: '{self.case.get('pair')}'{order}  (blue A, orange B; "
                f"drawn x{self.scale:.2g})",
                f"yours (magenta): {yours}", f"the lesson's (yellow): {lesson}"]

    def student_ghost(self):
        """The student's answer moved onto B: B's corners moved by depth along the normal (screen px), or None
        (no answer to draw, or one more than four spans of the shapes away: drawn as an arrow only)."""
        got = self.case.get("got")
        if got is None or "bad" in got or abs(got["depth"]) > 4 * self.span:
            return None
        move = Vector2(got["normal"]) * got["depth"] * self.scale
        return [p + move for p in self.view.orange.world_points()]

    def draw_scene(self, surface):
        """The explorer's drawing and the student's answer, without the bands (the tests look at it alone)."""
        self.centre()
        self.view.draw(surface)
        got = self.case.get("got")
        if got is not None and "bad" not in got:
            normal, depth = Vector2(got["normal"]), got["depth"] * self.scale
            orange = self.view.orange
            ghost = self.student_ghost()
            if ghost:
                pygame.draw.polygon(surface, STUDENT, ghost, 2)
            length = min(max(abs(depth), 12), 4 * self.span * self.scale)
            arrow(surface, STUDENT, orange.pos, orange.pos + normal * length * (1 if depth >= 0 else -1), 3)

    def draw(self, surface):
        self.draw_scene(surface)
        top = self.band()[0] - self.MARGIN
        pygame.draw.rect(surface, (16, 18, 24), (0, 0, SIZE[0], top))
        status = self.view.status()
        surface.blit(self.big.render(status, True, (235, 80, 80) if status == "OVERLAP" else (90, 210, 120)),
                     (20, 10))
        for row, line in enumerate(self.header()):
            text = ScaledFont(self.font, self.scale).render(line, True, TEXT)
            surface.blit(text, (20, HEADER_TOP + HEADER_ROW * row))
        footer(surface, self.lines(), "N/Space: next axis   [ ]: previous/next case   Tab: the scene   Esc: quit")


# ---------------------------------------------------------------- apply_impulse

class ImpulseCase(Case):
    """One apply_impulse() case: the contact, the impulse, each body's velocity and spin change, both answers."""

    kind = "impulse"
    SCALE = 3.0     # screen px per px of lever arm
    ARROW = 0.6     # screen px per px/s of velocity change

    def changes(self, side):
        """(the student's (Δv, Δω), the lesson's) for body `side` ("a" or "b")."""
        before, after, want = self.case["before"][side], self.case["after"][side], self.case["expected"][side]

        def delta(state):
            return (Vector2(state["vel"]) - Vector2(before["vel"]), state["omega"] - before["omega"])
        return delta(after), delta(want)

    def lines(self):
        out = [f"failing case {self.number} of {self.count}: '{self.case['case']}'"]
        for side in ("a", "b"):
            (dv, dw), (lv, lw) = self.changes(side)
            out.append(f"yours {side.upper()}: dv {vec(dv)} px/s, dw {dw:+.4g} rad/s")
            out.append(f"the lesson's {side.upper()}: dv {vec(lv)} px/s, dw {lw:+.4g} rad/s")
        return out

    def draw(self, surface):
        surface.fill((24, 26, 34))
        font = text_font()
        contact = Vector2(SIZE[0] / 2, 230)
        impulse = Vector2(self.case["impulse"])
        longest = max([d.length() for side in ("a", "b") for d, _ in self.changes(side)] + [1e-9])
        scale = min(self.ARROW, 160 / longest)   # the longest arrow at most 160 px
        fastest = max([abs(w) for side in ("a", "b") for _, w in self.changes(side)] + [1e-12])
        for side, colour in (("a", (70, 130, 235)), ("b", (245, 150, 40))):
            centre = contact - Vector2(self.case["r" + side]) * self.SCALE
            pygame.draw.circle(surface, colour, centre, 10)
            pygame.draw.line(surface, colour, centre, contact, 1)
            surface.blit(font.render(side.upper(), True, colour), centre + Vector2(12, -22))
            (dv, dw), (lv, lw) = self.changes(side)
            arrow(surface, LESSON, centre, centre + lv * scale, 5)
            arrow(surface, STUDENT, centre, centre + dv * scale, 2)
            for spin, colour_, radius in ((lw, LESSON, 30), (dw, STUDENT, 44)):
                spin_arc(surface, colour_, centre, radius, spin, fastest, font)
        pygame.draw.circle(surface, (235, 80, 80), contact, 5)
        if impulse.length() > 0:
            arrow(surface, TEXT, contact, contact + impulse.normalize() * 60, 2)
            label = self.case.get("impulse_label", "impulse P")
            surface.blit(font.render(label, True, TEXT), contact + impulse.normalize() * 66)
        if self.case.get("friction"):
            self.draw_friction(surface, contact, font)
        footer(surface, self.lines(), "arrows: velocity change, arcs: spin change (+ clockwise), each to one scale  "
                "[ ]: case  Tab: scene")

    def draw_friction(self, surface, contact, font):
        """At the contact: B's slip past A (grey) and the friction impulse on B, the lesson's (yellow) and the
        student's (magenta), to one scale (case["friction"]: {"slip", "lesson", "yours"} vectors, from the lab)."""
        friction = self.case["friction"]
        slip = Vector2(friction["slip"])
        grey = (170, 175, 190)
        if slip.length() > 1e-9:
            tip = contact + slip.normalize() * 70
            arrow(surface, grey, contact, tip, 2)
            surface.blit(font.render(f"slip {slip.length():.3g} px/s", True, grey), tip + Vector2(6, 4))
        pushes = [(Vector2(friction[who]), colour, width) for who, colour, width in
                  (("lesson", LESSON, 5), ("yours", STUDENT, 2))]
        largest = max([p.length() for p, _, _ in pushes] + [1e-9])
        for push, colour, width in pushes:
            if push.length() > 1e-9 * largest:
                arrow(surface, colour, contact, contact + push * (90 / largest), width)
        surface.blit(font.render("friction on B", True, LESSON), contact + Vector2(-150, 20))


# ---------------------------------------------------------------- polygon_centroid and polygon_inertia

class PolygonCase(Case):
    """One polygon_centroid() or polygon_inertia() case: the outline (fitted to the window) with the student's
    point and the lesson's (centroid), or both radii of gyration sqrt(I / m) as circles around (0, 0) (inertia)."""

    kind = "polygon"

    def __init__(self, case, number, count, inertia):
        super().__init__(case, number, count)
        self.inertia = inertia   # False: the centroid

    def lines(self):
        got, want = self.case["got"], self.case["want"]
        head = self.head()
        if not self.inertia:
            said = got if isinstance(got, str) else vec(got)
            return [head, f"yours (magenta): centroid {said}", f"the lesson's (yellow): centroid {vec(want)} "
                    f"(grey: the average of the corners {vec(self.case['average'])})"]
        mass = self.case["mass"]
        said = got if isinstance(got, str) else f"{got:.5g} (radius of gyration {math.sqrt(abs(got) / mass):.2f} px)"
        return [head, f"yours (magenta): I = {said}",
                f"the lesson's (yellow): I = {want:.5g} (radius of gyration {math.sqrt(want / mass):.2f} px), "
                f"mass {mass:.3g}"]

    def draw(self, surface):
        surface.fill((24, 26, 34))
        points = self.case["points"]
        got, want = self.case["got"], self.case["want"]
        if not self.inertia:
            extra = [want] + ([got] if not isinstance(got, str) and all(abs(v) < 1e6 for v in got) else [])
        else:
            radii = [math.sqrt(want / self.case["mass"])]
            if not isinstance(got, str) and 0 <= got / self.case["mass"] < 1e12:
                radii.append(math.sqrt(got / self.case["mass"]))
            extra = [(r * sx, r * sy) for r in radii for sx, sy in ((1, 1), (-1, -1))]
        scale, offset = fit(list(points) + extra)
        corners = [Vector2(p) * scale + offset for p in points]
        pygame.draw.polygon(surface, (70, 130, 235), corners)
        pygame.draw.polygon(surface, TEXT, corners, 2)
        if not self.inertia:
            cross(surface, (150, 155, 170), Vector2(self.case["average"]) * scale + offset, 6, 2)
            cross(surface, LESSON, Vector2(want) * scale + offset, 10, 4)
            if not isinstance(got, str):
                cross(surface, STUDENT, Vector2(got) * scale + offset, 8, 2)
        else:
            centre = offset
            pygame.draw.circle(surface, LESSON, centre, max(2, radii[0] * scale), 4)
            if len(radii) > 1:
                pygame.draw.circle(surface, STUDENT, centre, max(2, radii[1] * scale), 2)
        footer(surface, self.lines(), "[ ]: previous/next case   Tab: the scene   Esc: quit")
