"""What --show and --pictures draw for Tumbling Crates' checks (checker/labs/__init__.py says how it is found).

SERIES: the quantity each behaviour check is plotted by. CASES: the failing cases of its function checks,
from the probe's judged data: sat() as the SAT explorer draws it (show_cases.SatCase), apply_impulse()
(show_cases.ImpulseCase), and resolve() (ResolveCase below: the bodies come from the probe's fixed contacts).
"""
import math
import random

import pygame
from pygame import Vector2

from lesson11 import records
from lesson11.crate_scenes import PENETRATION, RAMP_SLIDE

from checker.replay.show_cases import ImpulseCase, SatCase
from checker.replay.show_kit import (LESSON, STUDENT, TEXT, Case, arrow, close, data, fit, footer, numbered,
                                     spin_arc, text_font)
from checker.replay.show_series import FASTEST, Moved, Quantity, sink_depth
from . import probes


def fast_count(frame):
    """How many dynamic bodies move faster than the lab's fast-mover threshold (30 px/s)."""
    return float(records.fast_movers(frame))


SERIES = {
    "runs": FASTEST,
    "corner_tips": Quantity("deepest into the floor (px)", sink_depth, PENETRATION),
    "ramp_holds": Quantity("moved since the start (px)", Moved, RAMP_SLIDE),
    "pile_stable": Quantity("deepest into the floor (px)", sink_depth, PENETRATION),
    "fast_movers_zero": Quantity("fast movers (> 30 px/s)", fast_count, 0.0, at_end=True),
}

TOUCHING = 1e-6     # px: a depth this small for shapes exactly touching counts as apart (the checks' own)


# ---------------------------------------------------------------- sat() (steps 2 and 3)

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
    matches = [ref for ref in (want, short) if ref and close(abs(got["depth"]), ref["depth"])]
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


# ---------------------------------------------------------------- apply_impulse() (step 6)

def impulse_wrong(case):
    """True when the student's velocities or spins after apply_impulse differ from the lesson's."""
    for side in ("a", "b"):
        after, want = case["after"][side], case["expected"][side]
        if not all(close(g, w) for g, w in zip(after["vel"], want["vel"])) or \
                not close(after["omega"], want["omega"]):
            return True
    return False


# ---------------------------------------------------------------- resolve() (steps 4 and 5)

def resolve_wrong(case, check_id):
    """True when the student's resolve() differs from the lesson's on this contact, as the check judges it:
    the normal impulse j (resolve_k) or the friction impulse jt, clamped to [-mu j, mu j] (resolve_friction)."""
    if check_id == "resolve_k":
        return case["j"] is None or not close(case["j"], -(1 + case["e"]) * case["vn"] / case["k"]["right"])
    friction = case.get("friction")
    if friction is None or case["j"] is None:
        return False
    bound = case["mu"] * case["j"]
    return not close(friction["jt"], max(-bound, min(bound, friction["stop"])))


class ResolveCase(Case):
    """One resolve() contact: both bodies, the contact point and normal; for step 4 each body's velocity
    change (arrows) and spin change (arcs) from the student's normal impulse j n and the lesson's; for
    step 5 the friction impulse on a bar from -mu j to mu j, with the impulse that stops the slip.
    The bodies come from the probe's contacts (probes.py resolve_cases(), drawn_resolve_cases())."""

    kind = "resolve"

    def __init__(self, case, number, count, check_id, geometry):
        super().__init__(case, number, count)
        self.check_id, self.geometry = check_id, geometry

    def lesson_j(self):
        return -(1 + self.case["e"]) * self.case["vn"] / self.case["k"]["right"]

    def lines(self):
        head = self.head()
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
        scale, offset = fit([(p.x, p.y) for p in corners], (260, 150, 380, 200))

        def at(p):
            return Vector2(p) * scale + offset
        for body, colour in ((a, (70, 130, 235)), (b, (245, 150, 40))):
            pygame.draw.polygon(surface, colour, [at(p) for p in body.world_points()])
            pygame.draw.polygon(surface, TEXT, [at(p) for p in body.world_points()], 1)
        pygame.draw.circle(surface, (235, 80, 80), at(point), 5)
        arrow(surface, TEXT, at(point), at(point) + Vector2(normal) * 50, 2)
        if self.check_id == "resolve_k":
            self._draw_changes(surface, at, a, b, Vector2(normal), Vector2(point))
            help_text = "white: the normal A->B at the contact   [ ]: case   Tab: scene   Esc: quit"
        else:
            self._draw_friction_arrows(surface, at, a, b, Vector2(normal), Vector2(point))
            self._draw_friction(surface)
            help_text = "grey: B's slip past A   arrows: friction impulse on each box   [ ]: case   Tab: scene"
        footer(surface, self.lines(), help_text)

    def tangent(self, a, b, normal, point):
        """The unit tangent t the friction acts along (the direction B slips past A at the contact, after the
        student's normal impulse), computed here from the probe's fixed contact with the lesson's apply_impulse
        (grader-side code, as the probe's reference does), or None."""
        from lesson11.physics2d import apply_impulse, relative_velocity
        j = self.case.get("j")
        if j is None or not math.isfinite(j):
            return None
        a, b = probes.twin(a), probes.twin(b)
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
        font = text_font(20)
        slip = t * 70
        arrow(surface, (170, 175, 190), contact + normal * 14, contact + normal * 14 + slip, 2)
        surface.blit(font.render(f"slip {friction['slip']:.3g} px/s", True, (170, 175, 190)),
                     contact + normal * 14 + slip + Vector2(6, -8))
        for jt, colour, width in impulses:
            if not math.isfinite(jt) or abs(jt) < 1e-12:
                continue
            push = t * (jt / largest * 90)
            arrow(surface, colour, contact + normal * 34, contact + normal * 34 + push, width)   # on B
            arrow(surface, colour, contact - normal * 24, contact - normal * 24 - push, width)   # on A

    def _draw_changes(self, surface, at, a, b, normal, point):
        impulses = [(normal * self.lesson_j(), LESSON, 5)]
        if self.case["j"] is not None:
            impulses.append((normal * self.case["j"], STUDENT, 2))
        changes = [(body, sign * impulse * body.inv_mass, sign * (point - body.pos).cross(impulse) * body.inv_inertia,
                    colour, width) for impulse, colour, width in impulses for body, sign in ((a, -1), (b, 1))]
        longest = max([dv.length() for _, dv, _, _, _ in changes] + [1e-9])
        fastest = max([abs(dw) for _, _, dw, _, _ in changes] + [1e-12])
        for body, dv, dw, colour, width in changes:
            arrow(surface, colour, at(body.pos), at(body.pos) + dv * (120 / longest), width)
            spin_arc(surface, colour, at(body.pos), 22 if colour == LESSON else 30, dw, fastest)

    def _draw_friction(self, surface):
        friction, bound = self.case["friction"], abs(self.case["mu"] * self.case["j"])
        reach = max(bound, abs(friction["stop"]), abs(friction["jt"]), 1e-9) * 1.1
        bar = pygame.Rect(100, 400, 700, 6)
        x_of = lambda v: bar.centerx + v / reach * bar.width / 2   # noqa: E731
        pygame.draw.rect(surface, (80, 84, 100), bar)
        pygame.draw.rect(surface, (150, 155, 170), (x_of(-bound), bar.top, x_of(bound) - x_of(-bound), bar.height))
        font = text_font(20)
        for value, colour, label, rise in ((friction["stop"], TEXT, "stops the slip", 70),
                                           (max(-bound, min(bound, friction["stop"])), LESSON, "the lesson's", 52),
                                           (friction["jt"], STUDENT, "yours", 34)):
            pygame.draw.line(surface, colour, (x_of(value), bar.top - 14), (x_of(value), bar.bottom + 14), 3)
            surface.blit(font.render(label, True, colour), (x_of(value) - 20, bar.top - rise))
        surface.blit(font.render("-mu j", True, TEXT), (x_of(-bound) - 16, bar.bottom + 16))
        surface.blit(font.render("mu j", True, TEXT), (x_of(bound) - 12, bar.bottom + 16))


def _resolve_geometry(name, seed=None):
    """(A, B, normal, point) of a resolve() case: a fixed one from probes.resolve_cases(), a drawn one redrawn from
    the grading seed as the probe drew it (drawn_resolve_cases with run_rng's Random); None when neither fits."""
    drawn = probes.drawn_resolve_cases(random.Random(f"{seed}:resolve")) if seed is not None else []
    for case in probes.resolve_cases() + drawn:
        if case[0] == name:
            return case[1], case[2], Vector2(case[3]), Vector2(case[4])
    return None


# ---------------------------------------------------------------- which cases, per check

def sat_cases(check_id, names):
    """The failing sat() cases of a check, from the first of the probes `names` that holds data."""
    def cases(functions, seed):
        for name in names:
            found = data(functions, name)
            if found:
                return numbered(SatCase, [case for case in found if "lesson" in case and sat_wrong(case, check_id)])
        return []
    return cases


def impulse_cases(functions, seed):
    return numbered(ImpulseCase, [case for case in data(functions, "apply_impulse") or []
                                  if "expected" in case and impulse_wrong(case)])


def resolve_cases(check_id):
    def cases(functions, seed):
        wrong = [case for case in data(functions, "resolve") or []
                 if resolve_wrong(case, check_id) and _resolve_geometry(case["case"], seed)]
        return [ResolveCase(case, k + 1, len(wrong), check_id, _resolve_geometry(case["case"], seed))
                for k, case in enumerate(wrong)]
    return cases


CASES = {
    "sat_axes": sat_cases("sat_axes", ("sat_step2", "sat")),
    "sat_normal": sat_cases("sat_normal", ("sat",)),
    "resolve_k": resolve_cases("resolve_k"),
    "resolve_friction": resolve_cases("resolve_friction"),
    "apply_impulse_spin": impulse_cases,
}
