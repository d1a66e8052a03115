"""The failing cases of a function check, drawn (python -m checker FILE --show).

The data are the probe's, judged on the grading side (checker/judging/probing.py): each case holds the
inputs, the student's answer ("got", recorded in the child) and the lesson's (computed here). Nothing
of the student's code runs in this process.

  SatCase      a pair of shapes, every candidate axis with both shadows (lesson11/explorer.py's drawing),
               the lesson's axis and depth (yellow, the explorer's MTV) and the student's (magenta)
  ImpulseCase  the two bodies around the contact, the impulse, each body's velocity change as arrows
               (the lesson's and the student's) and its spin change as arcs
  PolygonCase  an outline with the student's centroid and the lesson's, or both radii of gyration (inertia)
  ResolveCase  resolve(): the contact, both bodies' velocity and spin changes from j n (step 4), the
               friction impulse against its Coulomb bounds (step 5)
  ToiCase      circle_toi(): both circles' paths, where they are at both times of impact, a bar of the step
  SweptCase    swept_move(): the bullet's path to the impact and both ends of the step

More Shapes' separating_axes, Ball on the Ramp's and Sleeping Crates' function checks are drawn by
checker/replay/show_cases_labs.py.

failing_cases(lab, result, functions, seed) -> [case], each with draw(surface), key(key) and lines().
"""
import math
import re

import pygame
from pygame import Vector2

from lesson11.physics2d import Body, centre_of

TOUCHING = 1e-6     # px: a depth this small for shapes exactly touching counts as apart (the labs' own)
CLOSE = 1e-7        # relative and absolute: the function checks' tolerance
STUDENT = (235, 70, 200)   # the student's answer: magenta (the lesson's stays the explorer's yellow)
LESSON = (250, 220, 80)
TEXT = (230, 230, 230)
SIZE = (900, 600)


def _close(got, want):
    return abs(got - want) <= CLOSE + CLOSE * abs(want)


def _font(size=22):
    from checker.replay.pictures import _font as font
    return font(size)


def _vec(v):
    return f"({v[0] + 0.0:.2f}, {v[1] + 0.0:.2f})"


def _arrow(surface, colour, start, end, width=3):
    from lesson11.explorer import draw_arrow
    draw_arrow(surface, colour, start, end, width)


# ---------------------------------------------------------------- SAT

def sat_wrong(case, check_id):
    """True when the student's sat() answer for this case is not the lesson's (as the check judges it):
    apart / overlapping, the depth (either accepted depth), the axis up to sign; for sat_normal, also a
    normal pointing from B to A or a negative depth."""
    got, want, short = case.get("got"), case.get("lesson"), case.get("short")
    if got is not None and "bad" in got:
        return True
    if want is None:
        return got is not None and abs(got["depth"]) > TOUCHING
    if got is None:
        return True
    matches = [ref for ref in (want, short) if ref and _close(abs(got["depth"]), ref["depth"])]
    if not matches:
        return True
    ref = matches[0]["normal"]
    if abs(abs(got["normal"][0] * ref[0] + got["normal"][1] * ref[1]) - 1) > 1e-6:
        return True
    if check_id == "sat_normal":
        towards_b = ((case["centre_b"][0] - case["centre_a"][0]) * got["normal"][0]
                     + (case["centre_b"][1] - case["centre_a"][1]) * got["normal"][1])
        return got["depth"] < 0 or towards_b < 0
    return False


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
        _font()   # the explorer's fonts need pygame.font ready
        self.explorer = CaseExplorer(explorer.Explorer)
        self.view = self.explorer.view
        self.colours = explorer.BLUE, explorer.ORANGE
        self.font = _font(24)
        self.big = _font(44)
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
        return HEADER_TOP + HEADER_ROW * len(self.header()) + self.MARGIN, _footer_top(len(self.lines())) - self.MARGIN

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
            return f"depth {hit['depth']:.2f} px along {_vec(hit['normal'])}"
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
            _arrow(surface, STUDENT, orange.pos, orange.pos + normal * length * (1 if depth >= 0 else -1), 3)

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
        _footer(surface, self.lines(), "N/Space: next axis   [ ]: previous/next case   Tab: the scene   Esc: quit")


def _footer_top(count):
    """The screen y where the footer's text of `count` lines starts."""
    return SIZE[1] - 30 - 24 * count - 6


def _footer(surface, lines, help_text):
    """The case's text lines at the bottom of the case view, over a dark band."""
    font = _font()
    top = _footer_top(len(lines)) + 6
    pygame.draw.rect(surface, (16, 18, 24), (0, top - 6, SIZE[0], SIZE[1] - top + 6))
    for row, line in enumerate(lines):
        colour = STUDENT if line.startswith("yours") else LESSON if line.startswith("the lesson") else TEXT
        surface.blit(font.render(line, True, colour), (20, top + 24 * row))
    surface.blit(font.render(help_text, True, (160, 165, 180)), (20, SIZE[1] - 26))


# ---------------------------------------------------------------- apply_impulse

def impulse_wrong(case):
    """True when the student's velocities or spins after apply_impulse differ from the lesson's."""
    for side in ("a", "b"):
        after, want = case["after"][side], case["expected"][side]
        if not all(_close(g, w) for g, w in zip(after["vel"], want["vel"])) or \
                not _close(after["omega"], want["omega"]):
            return True
    return False


class ImpulseCase:
    """One apply_impulse() case: the contact, the impulse, each body's velocity and spin change, both answers."""

    kind = "impulse"
    SCALE = 3.0     # screen px per px of lever arm
    ARROW = 0.6     # screen px per px/s of velocity change

    def __init__(self, case, number, count):
        self.case, self.number, self.count = case, number, count

    def key(self, key):
        return False

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
            out.append(f"yours {side.upper()}: dv {_vec(dv)} px/s, dw {dw:+.4g} rad/s")
            out.append(f"the lesson's {side.upper()}: dv {_vec(lv)} px/s, dw {lw:+.4g} rad/s")
        return out

    def draw(self, surface):
        surface.fill((24, 26, 34))
        font = _font()
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
            _arrow(surface, LESSON, centre, centre + lv * scale, 5)
            _arrow(surface, STUDENT, centre, centre + dv * scale, 2)
            for spin, colour_, radius in ((lw, LESSON, 30), (dw, STUDENT, 44)):
                _spin_arc(surface, colour_, centre, radius, spin, fastest, font)
        pygame.draw.circle(surface, (235, 80, 80), contact, 5)
        if impulse.length() > 0:
            _arrow(surface, TEXT, contact, contact + impulse.normalize() * 60, 2)
            label = self.case.get("impulse_label", "impulse P")
            surface.blit(font.render(label, True, TEXT), contact + impulse.normalize() * 66)
        if self.case.get("friction"):
            self.draw_friction(surface, contact, font)
        _footer(surface, self.lines(), "arrows: velocity change, arcs: spin change (+ clockwise), each to one scale  "
                "[ ]: case  Tab: scene")

    def draw_friction(self, surface, contact, font):
        """At the contact: B's slip past A (grey) and the friction impulse on B, the lesson's (yellow) and the
        student's (magenta), to one scale (case["friction"]: vectors, see show_cases_labs.friction_arrows)."""
        friction = self.case["friction"]
        slip = Vector2(friction["slip"])
        grey = (170, 175, 190)
        if slip.length() > 1e-9:
            tip = contact + slip.normalize() * 70
            _arrow(surface, grey, contact, tip, 2)
            surface.blit(font.render(f"slip {slip.length():.3g} px/s", True, grey), tip + Vector2(6, 4))
        pushes = [(Vector2(friction[who]), colour, width) for who, colour, width in
                  (("lesson", LESSON, 5), ("yours", STUDENT, 2))]
        largest = max([p.length() for p, _, _ in pushes] + [1e-9])
        for push, colour, width in pushes:
            if push.length() > 1e-9 * largest:
                _arrow(surface, colour, contact, contact + push * (90 / largest), width)
        surface.blit(font.render("friction on B", True, LESSON), contact + Vector2(-150, 20))


FULL_TURN = 1.75 * math.pi   # the arc of the largest spin change in a case (a ring left open at the top)


def _spin_arc(surface, colour, centre, radius, spin, largest, font=None):
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


# ---------------------------------------------------------------- resolve (steps 4 and 5)

def resolve_wrong(case, check_id):
    """True when the student's resolve() differs from the lesson's on this contact, as the check judges it:
    the normal impulse j (resolve_k) or the friction impulse jt, clamped to [-mu j, mu j] (resolve_friction)."""
    if check_id == "resolve_k":
        return case["j"] is None or not _close(case["j"], -(1 + case["e"]) * case["vn"] / case["k"]["right"])
    friction = case.get("friction")
    if friction is None or case["j"] is None:
        return False
    bound = case["mu"] * case["j"]
    return not _close(friction["jt"], max(-bound, min(bound, friction["stop"])))


class ResolveCase:
    """One resolve() contact: both bodies, the contact point and normal; for step 4 each body's velocity
    change (arrows) and spin change (arcs) from the student's normal impulse j n and the lesson's; for
    step 5 the friction impulse on a bar from -mu j to mu j, with the impulse that stops the slip.
    The bodies come from the probe's fixed contacts (checker/labs/tumbling_crates/probes.py resolve_cases())."""

    kind = "resolve"

    def __init__(self, case, number, count, check_id, geometry):
        self.case, self.number, self.count, self.check_id, self.geometry = case, number, count, check_id, geometry

    def key(self, key):
        return False

    def lesson_j(self):
        return -(1 + self.case["e"]) * self.case["vn"] / self.case["k"]["right"]

    def lines(self):
        head = f"failing case {self.number} of {self.count}: {self.case['case']}"
        j = self.case["j"]
        if self.check_id == "resolve_k":
            return [head, f"yours (magenta): j = {'none applied' if j is None else f'{j:.4g}'}",
                    f"the lesson's (yellow): j = {self.lesson_j():.4g}, k = {self.case['k']['right']:.4g}"]
        friction, bound = self.case["friction"], self.case["mu"] * j
        return [head, f"yours (magenta): jt = {friction['jt']:.4g}",
                f"the lesson's (yellow): jt = {max(-bound, min(bound, friction['stop'])):.4g} (stopping the slip "
                f"takes {friction['stop']:.4g}; mu j = {bound:.4g})"]

    def draw(self, surface):
        surface.fill((24, 26, 34))
        a, b, normal, point = self.geometry
        corners = [p for body in (a, b) for p in body.world_points()]
        scale, offset = _fit([(p.x, p.y) for p in corners], (260, 150, 380, 200))

        def at(p):
            return Vector2(p) * scale + offset
        for body, colour in ((a, (70, 130, 235)), (b, (245, 150, 40))):
            pygame.draw.polygon(surface, colour, [at(p) for p in body.world_points()])
            pygame.draw.polygon(surface, TEXT, [at(p) for p in body.world_points()], 1)
        pygame.draw.circle(surface, (235, 80, 80), at(point), 5)
        _arrow(surface, TEXT, at(point), at(point) + Vector2(normal) * 50, 2)
        if self.check_id == "resolve_k":
            self._draw_changes(surface, at, a, b, Vector2(normal), Vector2(point))
            help_text = "white: the normal A->B at the contact   [ ]: case   Tab: scene   Esc: quit"
        else:
            self._draw_friction_arrows(surface, at, a, b, Vector2(normal), Vector2(point))
            self._draw_friction(surface)
            help_text = "grey: B's slip past A   arrows: friction impulse on each box   [ ]: case   Tab: scene"
        _footer(surface, self.lines(), help_text)

    def tangent(self, a, b, normal, point):
        """The unit tangent t the friction acts along (the direction B slips past A at the contact, after the
        student's normal impulse), computed here from the probe's fixed contact with the lesson's apply_impulse
        (grader-side code, as the probe's reference does), or None."""
        from lesson11.physics2d import apply_impulse, relative_velocity
        from checker.labs.tumbling_crates.probes import twin
        j = self.case.get("j")
        if j is None or not math.isfinite(j):
            return None
        a, b = twin(a), twin(b)
        ra, rb = point - a.pos, point - b.pos
        apply_impulse(a, b, normal * j, ra, rb)
        rel = relative_velocity(a, b, ra, rb)
        tangent = rel - normal * rel.dot(normal)
        return tangent.normalize() if tangent.length_squared() > 1e-12 else None

    def _draw_friction_arrows(self, surface, at, a, b, normal, point):
        """On the boxes: B's slip past A at the contact (grey) and the friction impulse on each box, the
        lesson's (yellow, thick) and the student's (magenta): +jt t on B, -jt t on A, one scale for all."""
        friction = self.case.get("friction")
        t = self.tangent(a, b, normal, point) if friction else None
        if t is None:
            return
        bound = abs(self.case["mu"] * self.case["j"])
        lesson = max(-bound, min(bound, friction["stop"]))
        impulses = [(lesson, LESSON, 5), (friction["jt"], STUDENT, 2)]
        largest = max([abs(jt) for jt, _, _ in impulses if math.isfinite(jt)] + [1e-9])
        contact = at(point)
        font = _font(20)
        slip = t * 70
        _arrow(surface, (170, 175, 190), contact + normal * 14, contact + normal * 14 + slip, 2)
        surface.blit(font.render(f"slip {friction['slip']:.3g} px/s", True, (170, 175, 190)),
                     contact + normal * 14 + slip + Vector2(6, -8))
        for jt, colour, width in impulses:
            if not math.isfinite(jt) or abs(jt) < 1e-12:
                continue
            push = t * (jt / largest * 90)
            _arrow(surface, colour, contact + normal * 34, contact + normal * 34 + push, width)   # on B
            _arrow(surface, colour, contact - normal * 24, contact - normal * 24 - push, width)   # on A

    def _draw_changes(self, surface, at, a, b, normal, point):
        impulses = [(normal * self.lesson_j(), LESSON, 5)]
        if self.case["j"] is not None:
            impulses.append((normal * self.case["j"], STUDENT, 2))
        changes = [(body, sign * impulse * body.inv_mass, sign * (point - body.pos).cross(impulse) * body.inv_inertia,
                    colour, width) for impulse, colour, width in impulses for body, sign in ((a, -1), (b, 1))]
        longest = max([dv.length() for _, dv, _, _, _ in changes] + [1e-9])
        fastest = max([abs(dw) for _, _, dw, _, _ in changes] + [1e-12])
        for body, dv, dw, colour, width in changes:
            _arrow(surface, colour, at(body.pos), at(body.pos) + dv * (120 / longest), width)
            _spin_arc(surface, colour, at(body.pos), 22 if colour == LESSON else 30, dw, fastest)

    def _draw_friction(self, surface):
        friction, bound = self.case["friction"], abs(self.case["mu"] * self.case["j"])
        reach = max(bound, abs(friction["stop"]), abs(friction["jt"]), 1e-9) * 1.1
        bar = pygame.Rect(100, 400, 700, 6)
        x_of = lambda v: bar.centerx + v / reach * bar.width / 2   # noqa: E731
        pygame.draw.rect(surface, (80, 84, 100), bar)
        pygame.draw.rect(surface, (150, 155, 170), (x_of(-bound), bar.top, x_of(bound) - x_of(-bound), bar.height))
        font = _font(20)
        for value, colour, label, rise in ((friction["stop"], TEXT, "stops the slip", 70),
                                           (max(-bound, min(bound, friction["stop"])), LESSON, "the lesson's", 52),
                                           (friction["jt"], STUDENT, "yours", 34)):
            pygame.draw.line(surface, colour, (x_of(value), bar.top - 14), (x_of(value), bar.bottom + 14), 3)
            surface.blit(font.render(label, True, colour), (x_of(value) - 20, bar.top - rise))
        surface.blit(font.render("-mu j", True, TEXT), (x_of(-bound) - 16, bar.bottom + 16))
        surface.blit(font.render("mu j", True, TEXT), (x_of(bound) - 12, bar.bottom + 16))


def _resolve_geometry(name):
    from checker.labs.tumbling_crates import probes
    for case in probes.resolve_cases():
        if case[0] == name:
            return case[1], case[2], Vector2(case[3]), Vector2(case[4])
    return None


# ---------------------------------------------------------------- polygon_centroid and polygon_inertia

def _fit(points, box=(120, 90, 660, 380)):
    """(scale, offset) that fit the outline's points into `box` (left, top, width, height; screen px)."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    width, height = max(max(xs) - min(xs), 1e-9), max(max(ys) - min(ys), 1e-9)
    scale = min(box[2] / width, box[3] / height)
    offset = Vector2(box[0] + box[2] / 2, box[1] + box[3] / 2) - Vector2((max(xs) + min(xs)) / 2,
                                                                         (max(ys) + min(ys)) / 2) * scale
    return scale, offset


def _cross(surface, colour, at, size=8, width=3):
    pygame.draw.line(surface, colour, at - Vector2(size, size), at + Vector2(size, size), width)
    pygame.draw.line(surface, colour, at - Vector2(size, -size), at + Vector2(size, -size), width)


class PolygonCase:
    """One polygon_centroid() or polygon_inertia() case: the outline (fitted to the window) with the student's
    point and the lesson's (centroid), or both radii of gyration sqrt(I / m) as circles around (0, 0) (inertia)."""

    kind = "polygon"

    def __init__(self, case, number, count, what):
        self.case, self.number, self.count, self.what = case, number, count, what

    def key(self, key):
        return False

    def lines(self):
        got, want = self.case["got"], self.case["want"]
        head = f"failing case {self.number} of {self.count}: {self.case['case']}"
        if self.what == "centroid":
            said = got if isinstance(got, str) else _vec(got)
            return [head, f"yours (magenta): centroid {said}", f"the lesson's (yellow): centroid {_vec(want)} "
                    f"(grey: the average of the corners {_vec(self.case['average'])})"]
        mass = self.case["mass"]
        said = got if isinstance(got, str) else f"{got:.5g} (radius of gyration {math.sqrt(abs(got) / mass):.2f} px)"
        return [head, f"yours (magenta): I = {said}",
                f"the lesson's (yellow): I = {want:.5g} (radius of gyration {math.sqrt(want / mass):.2f} px), "
                f"mass {mass:.3g}"]

    def draw(self, surface):
        surface.fill((24, 26, 34))
        points = self.case["points"]
        got, want = self.case["got"], self.case["want"]
        if self.what == "centroid":
            extra = [want] + ([got] if not isinstance(got, str) and all(abs(v) < 1e6 for v in got) else [])
        else:
            radii = [math.sqrt(want / self.case["mass"])]
            if not isinstance(got, str) and 0 <= got / self.case["mass"] < 1e12:
                radii.append(math.sqrt(got / self.case["mass"]))
            extra = [(r * sx, r * sy) for r in radii for sx, sy in ((1, 1), (-1, -1))]
        scale, offset = _fit(list(points) + extra)
        corners = [Vector2(p) * scale + offset for p in points]
        pygame.draw.polygon(surface, (70, 130, 235), corners)
        pygame.draw.polygon(surface, TEXT, corners, 2)
        if self.what == "centroid":
            _cross(surface, (150, 155, 170), Vector2(self.case["average"]) * scale + offset, 6, 2)
            _cross(surface, LESSON, Vector2(want) * scale + offset, 10, 4)
            if not isinstance(got, str):
                _cross(surface, STUDENT, Vector2(got) * scale + offset, 8, 2)
        else:
            centre = offset
            pygame.draw.circle(surface, LESSON, centre, max(2, radii[0] * scale), 4)
            if len(radii) > 1:
                pygame.draw.circle(surface, STUDENT, centre, max(2, radii[1] * scale), 2)
        _footer(surface, self.lines(), "[ ]: previous/next case   Tab: the scene   Esc: quit")


def polygon_wrong(case, what):
    """True when the student's centroid or inertia differs from the lesson's (relative 1e-7 of the outline's size)."""
    got, want = case.get("got"), case.get("want")
    if isinstance(got, str) or got is None:
        return True
    if what == "centroid":
        size = max(abs(v) for p in case["points"] for v in p) or 1.0
        return any(abs(g - w) > CLOSE * size + CLOSE * abs(w) for g, w in zip(got, want))
    return not _close(got, want)


# ---------------------------------------------------------------- Bullets: circle_toi and swept_move

def _time(value):
    """A time answer as text: "None", "12.5 ms", or what was wrong with it."""
    if value is None:
        return "None (no hit)"
    if isinstance(value, dict):
        return f"returned {value.get('bad')}"
    return f"{value * 1000:.4g} ms"


class ToiCase:
    """One circle_toi() case: both circles' paths over the step, where they are at the student's time of
    impact (magenta) and at the lesson's (yellow), and a bar of the step [0, dt] with both times on it.
    The geometry comes from the probe's cases (checker/labs/bullets/probes.py toi_cases(), and drawn_toi_cases()
    redrawn from the grading seed: _toi_geometry), grader-side code; without it only the times are shown."""

    kind = "toi"

    def __init__(self, case, number, count, geometry=None):
        self.case, self.number, self.count, self.geometry = case, number, count, geometry

    def key(self, key):
        return False

    def lines(self):
        return [f"failing case {self.number} of {self.count}: {self.case['case']} (dt = {self.case['dt'] * 1000:.4g} ms)",
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
            scale, offset = _fit([(p.x - pad, p.y - pad) for p in ends] + [(p.x + pad, p.y + pad) for p in ends],
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
        font = _font(20)
        surface.blit(font.render("0", True, TEXT), (bar.left - 4, bar.bottom + 4))
        surface.blit(font.render("dt", True, TEXT), (bar.right - 8, bar.bottom + 4))
        for t, colour in times:
            x = bar.left + max(-0.1, min(1.1, t / dt)) * bar.width
            pygame.draw.line(surface, colour, (x, bar.top - 14), (x, bar.bottom + 14), 3)
        _footer(surface, self.lines(), "circles: where both are at each time   [ ]: case   Tab: scene   Esc: quit")


class SweptCase:
    """One swept_move() case: the bullet's path over the step, the impact (at the lesson's time of impact),
    and where the bullet ends: the student's (magenta) and the lesson's (yellow)."""

    kind = "swept"

    def __init__(self, case, number, count, step):
        self.case, self.number, self.count, self.step = case, number, count, step

    def key(self, key):
        return False

    def path(self):
        """(start, impact or None, lesson's end, student's end) in px, from the probe's data."""
        variants, t = self.case.get("variants") or {}, self.case.get("t")
        want = Vector2(self.case["want"]["bullet"]["pos"])
        got = Vector2(self.case["got"]["bullet"]["pos"])
        if t is None or "stops" not in variants or "old_velocity" not in variants or self.step - t <= 0:
            return None, None, want, got
        impact, through = (Vector2(_bullet_pos(variants[name])) for name in ("stops", "old_velocity"))
        velocity = (through - impact) / (self.step - t)
        return impact - velocity * t, impact, want, got

    def lines(self):
        t = self.case.get("t")
        got, want = self.case["got"]["bullet"], self.case["want"]["bullet"]
        return [f"failing case {self.number} of {self.count}: {self.case['case']}"
                + (f" (impact at t = {t * 1000:.4g} ms of {self.step * 1000:.4g})" if t is not None else ""),
                f"yours (magenta): the bullet ends at {_vec(got['pos'])} moving {_vec(got['vel'])} px/s",
                f"the lesson's (yellow): at {_vec(want['pos'])} moving {_vec(want['vel'])} px/s"]

    def draw(self, surface):
        surface.fill((24, 26, 34))
        start, impact, want, got = self.path()
        points = [p for p in (start, impact, want, got) if p is not None]
        others = [Vector2(o["pos"]) for o in self.case["want"].get("others", ())]
        scale, offset = _fit([(p.x, p.y) for p in points] + [(p.x + 10, p.y + 10) for p in points],
                             (80, 80, 740, 330))

        def at(p):
            return p * scale + offset
        for other in others:   # the other bodies' centres (the wall, a crate) as grey crosses
            _cross(surface, (150, 155, 170), at(other), 8, 2)
        if start is not None:
            pygame.draw.line(surface, (150, 155, 170), at(start), at(impact), 2)
            pygame.draw.circle(surface, (150, 155, 170), at(start), 5, 1)
            pygame.draw.circle(surface, (235, 80, 80), at(impact), 6)
            for end, colour in ((want, LESSON), (got, STUDENT)):
                pygame.draw.line(surface, colour, at(impact), at(end), 2)
        pygame.draw.circle(surface, LESSON, at(want), 9, 3)
        pygame.draw.circle(surface, STUDENT, at(got), 6, 2)
        _footer(surface, self.lines(), "grey: the path to the impact (red)   [ ]: case   Tab: scene   Esc: quit")


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
    return any(not _close(g, w) for a, b in pairs for key in ("pos", "vel") for g, w in zip(a[key], b[key]))


def _toi_geometry(case, seed=None):
    """(p1, v1, r1, p2, v2, r2) of a circle_toi case: a fixed one from the probe's toi_cases(), a drawn one
    redrawn here from the grading seed as the probe drew it (drawn_toi_cases with run_rng's Random), both
    grader-side code; a redrawn case counts only when its dt is the recorded one. None when neither fits."""
    import random
    from checker.labs.bullets import probes
    drawn = probes.drawn_toi_cases(random.Random(f"{seed}:circle_toi")) if seed is not None else []
    for name, p1, v1, r1, p2, v2, r2, dt in probes.toi_cases() + drawn:
        if name == case["case"] and abs(dt - case["dt"]) <= 1e-12 * max(1.0, dt):
            return p1, v1, r1, p2, v2, r2
    return None


# ---------------------------------------------------------------- which cases, per check

SAT_PROBES = {"sat_axes": ("sat_step2", "sat"), "sat_normal": ("sat",)}
IMPULSE_PROBES = {"apply_impulse_spin": "apply_impulse"}
POLYGON_PROBES = {"centroid": ("polygon_centroid", "centroid"), "inertia_sum": ("polygon_inertia", "inertia")}


def _data(functions, name):
    entry = functions.get(name) or {}
    return entry.get("data") if entry.get("ok") else None


def failing_cases(lab, result, functions, seed=None):
    """The failing cases of a failed function check, as drawable cases ([] for other checks or no data).

    seed: the grading run's seed (the probe's drawn inputs; Bullets' drawn circle_toi paths are redrawn from it)."""
    if result.status not in ("fail", "error"):
        return []
    from checker.replay import show_cases_labs
    cases = show_cases_labs.failing_cases(lab, result, functions)
    if cases is not None:
        return cases
    for name in SAT_PROBES.get(result.id, ()):
        data = _data(functions, name)
        if data:
            wrong = [case for case in data if "lesson" in case and sat_wrong(case, result.id)]
            return [SatCase(case, k + 1, len(wrong)) for k, case in enumerate(wrong)]
    if result.id in POLYGON_PROBES:
        name, what = POLYGON_PROBES[result.id]
        data = _data(functions, name) or []
        wrong = [case for case in data if "want" in case and polygon_wrong(case, what)]
        return [PolygonCase(case, k + 1, len(wrong), what) for k, case in enumerate(wrong)]
    if result.id in ("resolve_k", "resolve_friction") and lab.id == "tumbling_crates":
        data = _data(functions, "resolve") or []
        wrong = [case for case in data if resolve_wrong(case, result.id) and _resolve_geometry(case["case"])]
        return [ResolveCase(case, k + 1, len(wrong), result.id, _resolve_geometry(case["case"]))
                for k, case in enumerate(wrong)]
    if result.id == "toi_matches_root":
        wrong = [case for case in _data(functions, "circle_toi") or [] if "want" in case and toi_wrong(case)]
        return [ToiCase(case, k + 1, len(wrong), _toi_geometry(case, seed)) for k, case in enumerate(wrong)]
    if result.id == "swept_move_resolves":
        from checker.labs.bullets import probes
        wrong = [case for case in _data(functions, "swept_move") or [] if "want" in case and swept_wrong(case)]
        return [SweptCase(case, k + 1, len(wrong), probes.STEP) for k, case in enumerate(wrong)]
    if result.id in IMPULSE_PROBES:
        data = _data(functions, IMPULSE_PROBES[result.id]) or []
        wrong = [case for case in data if "expected" in case and impulse_wrong(case)]
        return [ImpulseCase(case, k + 1, len(wrong)) for k, case in enumerate(wrong)]
    return []
