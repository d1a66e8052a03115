"""Ball on the Ramp's function steps, declared as data (checker/judging/declared.py, declared_acts.py).

Each step's cases exercise every term of the lesson's formula; the probes run in the checker's child and record
only the student's answers; the lesson's answers and those of the known wrong forms are computed in the grader
(`@reference`), from the inputs as they were before the student's function got them:
    closest_on_segment  (step 2) points beside an edge, beyond either end, slanted and reversed edges
    circle_outside      (step 2) circle_polygon() on circles outside or touching a polygon, with the
                        solution's step 3 spliced in
    circle_inside       (step 3) the center inside, with the lesson's closest_on_segment in the student's place
    separate            (step 4) two dynamic bodies of different mass, a static A, a static B
    disc_inertia        (step 5) masses and radii far from 1
    contact_point       (step 6) balls touching along several normals, with small and large depths
    resolve             (step 7) a ball slipping on the ramp (clamped and not), spinning, hitting a crate, on a
                        frictionless surface; each apply_impulse call's order of bodies and lever arms is noted
Units: px, s, rad, mass in the lab's units (area / 1000).
"""
import math

from pygame import Vector2

from lesson11.physics2d import apply_impulse as lesson_apply_impulse, circle_polygon as lesson_circle_polygon
from lesson11.physics2d import closest_on_segment as lesson_closest, effective_mass_inverse, relative_velocity

from checker.judging.causes import arguments_hint
from checker.judging.common import answer_number, answer_point, close, same_point
from checker.judging.declared import Form, Step
from checker.judging.declared_acts import (Acting, body_of, described, fields, first_differing, motion_difference,
                                           motions, roles, rows, same_motion)
from checker.judging.declared_hits import hit_difference, same_hit
from checker.judging.lab_checks import vec_text
from checker.judging.probe_kit import _plain, box, ngon, random_shape, reference, sat_answer, stop_over_bound
from checker.judging.probe_kit import with_reference_steps
from checker.judging.tape import run_rng

REQUIRED = ("closest_on_segment", "circle_polygon", "separate", "disc_inertia", "contact_point", "resolve", "main")
RESTING_SPEED = 30.0   # px/s, the handout's cutoff below which e = 0
SLOP, PERCENT = 0.5, 0.4   # px, share: the handout's push-out constants
RAMP_ANGLE = 22.0      # degrees


# ---------------------------------------------------------------- the lesson's formulas and the ramp

# the lesson's closest_on_segment also stands in for the student's under circle_polygon() (step 3 graded on its own),
# so it runs in the child; as a reference answer it is reference_closest, grader only
reference_closest = reference(lesson_closest)
reference_circle_polygon = reference(lesson_circle_polygon)   # None, or (normal into the polygon, depth px)

UP = Vector2(math.sin(math.radians(RAMP_ANGLE)), -math.cos(math.radians(RAMP_ANGLE)))   # the ramp's top face normal
SLOPE = Vector2(math.cos(math.radians(RAMP_ANGLE)), math.sin(math.radians(RAMP_ANGLE)))   # down the ramp
RAMP = box(420, 24, (230, 380), RAMP_ANGLE)   # its corners
CIRCLE = ("case", "center", "radius", "points")   # circle_polygon()'s cases


# ---------------------------------------------------------------- step 2: closest_on_segment

def segment_cases():
    """(name, p, a, b) in px."""
    slant_a, slant_b = Vector2(10, 20), Vector2(130, 70)
    return [
        ("a point above the middle of a flat edge", Vector2(30, -20), Vector2(0, 0), Vector2(100, 0)),
        ("a point beyond the edge's end b", Vector2(130, 15), Vector2(0, 0), Vector2(100, 0)),
        ("a point before the edge's start a", Vector2(-40, -10), Vector2(0, 0), Vector2(100, 0)),
        ("a point beside a slanted edge", Vector2(60, 20), slant_a, slant_b),
        ("a point beyond the end of a slanted edge", Vector2(170, 60), slant_a, slant_b),
        ("a point beside the same edge walked the other way", Vector2(60, 20), slant_b, slant_a),
        ("a point before the start of a short steep edge", Vector2(-3, -30), Vector2(2, -12), Vector2(6, 14)),
        ("a point beside a short steep edge", Vector2(-9, 4), Vector2(2, -12), Vector2(6, 14)),
        # |ab| = 0.5 px: t, t·|ab| and t·|ab|² (0.6, 0.3, 0.15) all fall inside [0, 1], so dividing by |ab|
        # or by nothing shows as itself (on long edges both clamp to an end alike)
        ("a point beside a half-pixel edge", Vector2(10.18, 10.24) + Vector2(-4, 3), Vector2(10, 10),
         Vector2(10.3, 10.4)),
    ]


def drawn_segment_cases(rng, count=3):
    """`count` cases drawn for this run: an edge 30-150 px long and a point off it, before, beside or beyond."""
    cases = []
    for k in range(count):
        a = Vector2(rng.uniform(-100, 100), rng.uniform(-100, 100))
        b = a + Vector2(rng.uniform(30, 150), 0).rotate(rng.uniform(0, 360))
        t = rng.choice((rng.uniform(-0.8, -0.2), rng.uniform(0.15, 0.85), rng.uniform(1.2, 1.8)))
        side = (b - a).normalize().rotate(90) * rng.choice((-1, 1)) * rng.uniform(8, 60)
        cases.append((f"a point near an edge drawn for this run ({k + 1} of {count})", a + (b - a) * t + side, a, b))
    return cases


@reference
def _along(case, start="a"):
    """(p - start)·ab of the case's p and edge ab, measured from a (the lesson) or from b."""
    a, b = Vector2(case["a"]), Vector2(case["b"])
    return (Vector2(case["p"]) - Vector2(case[start])).dot(b - a)


def _ab2(case):
    """ab·ab, the case's edge's length squared."""
    return (Vector2(case["b"]) - Vector2(case["a"])).length_squared()


def _on_edge(case, t, clamp=True):
    """The point a + ab t of the case's edge, t clamped to [0, 1] (or not)."""
    a, b = Vector2(case["a"]), Vector2(case["b"])
    return list(a + (b - a) * (max(0.0, min(1.0, t)) if clamp else t))


def _closest_form(name, text, t, hint="closest", clamp=True):
    """A known wrong closest point: a + ab t(case, ab), t clamped unless `clamp` is False."""
    return Form(f"closest_{name}", text, lambda c: _on_edge(c, t(c, Vector2(c["b"]) - Vector2(c["a"])), clamp), hint)


def _closest_returned(cases, case):
    """A number or no point at all, read from this case: t itself is a named mistake."""
    got = case["got"]
    if not isinstance(got, dict):
        return None
    if "number" in got and close(got["number"], case["t"]):
        return Form("closest_returns_t", "closest_on_segment() returns t, not the point a + ab t",
                    line=f"closest_on_segment() returned the number {got['number']:.4g}: that is t; return the point "
                         "a + ab t")
    what = f"the number {got['number']:.4g}" if "number" in got else got["bad"]
    placeholder = " (the handout's placeholder: write step 2)" if "inf" in got["bad"] else ""
    return Form(None, f"closest_on_segment() returned {what}{placeholder}")


def _lesson_hit(c):
    """The lesson's circle_polygon() answer for a case, as plain data."""
    return _plain(reference_circle_polygon(Vector2(c["center"]), c["radius"], [Vector2(p) for p in c["points"]]))


def _where(c):
    return f"for {c['case']} (p = {vec_text(c['p'])}, edge {vec_text(c['a'])} to {vec_text(c['b'])})"


CLOSEST_OUTSIDE = Acting(
    "closest_point", "", 2, "circle_polygon",
    lambda module: rows(CIRCLE, outside_cases() + drawn_circle_cases(run_rng(module, "circle_outside"), inside=False)),
    lambda circle_polygon, g: circle_polygon(g["center"], g["radius"], g["points"]),
    _lesson_hit,
    given=lambda c: {"center": Vector2(c["center"]), "radius": c["radius"],
                     "points": [Vector2(p) for p in c["points"]]},
    function_of=lambda module, lab_path: with_reference_steps(module, lab_path, "circle_polygon", (3,)) or
    module.circle_polygon, probe_name="circle_outside", answer=sat_answer,
    same=same_hit,
    hint="closest", unnamed="circle_polygon() with your closest_on_segment() misses a ball outside the polygon",
    evidence=lambda c: f"for {c['case']} (center {vec_text(c['center'])}, radius {c['radius']:g}): "
                       f"{hit_difference(c['got'], c['want'])}.")

CLOSEST = Acting(
    "closest_point", "Step 2: closest_on_segment() gives the point of the edge nearest to p (t clamped to [0, 1]).",
    2, "closest_on_segment", lambda module: rows(
        ("case", "p", "a", "b"), segment_cases() + drawn_segment_cases(run_rng(module, "closest_on_segment"))),
    lambda closest_on_segment, g: closest_on_segment(g["p"], g["a"], g["b"]),
    lambda c: _on_edge(c, _along(c) / _ab2(c)), given=lambda c: {k: Vector2(c[k]) for k in ("p", "a", "b")},
    kept=("p", "a", "b"), advice="return a new point, a + ab t", answer=answer_point, same=same_point,
    hint="closest", extra={"t": lambda c: max(0.0, min(1.0, _along(c) / _ab2(c)))}, diagnose=_closest_returned,
    unnamed="closest_on_segment() does not give the edge's nearest point",
    evidence=lambda c: f"{_where(c)}, expected the point {vec_text(c['want'])}." if isinstance(c["got"], dict) else
    f"{_where(c)}, yours is {vec_text(c['got'])}; expected {vec_text(c['want'])}.",
    wrong=(_closest_form("line", "your point lies on the edge's line beyond the edge: t is not clamped to [0, 1]",
                         lambda c, ab: _along(c) / ab.dot(ab), "clamp", clamp=False),
           _closest_form("unsquared", "t is divided by |ab|, not by ab·ab = |ab|²",
                         lambda c, ab: _along(c) / ab.length()),
           _closest_form("undivided", "t = (p - a)·ab is not divided by ab·ab = |ab|²", lambda c, ab: _along(c)),
           _closest_form("from_b", "t is measured from b, (p - b)·ab; the lesson measures from a, (p - a)·ab",
                         lambda c, ab: _along(c, "b") / ab.dot(ab))),
    also=(CLOSEST_OUTSIDE,), joint=lambda lists: f"the closest point matches the lesson in all {len(lists[0])} edges "
                                                 f"and {len(lists[1])} circles outside a polygon")


# ---------------------------------------------------------------- steps 2 and 3: circle_polygon

def outside_cases():
    """(name, center, radius, polygon points): circles outside, touching or apart from a polygon."""
    crate = box(60, 40, (600, 540))
    return [
        ("a ball sunk 3 px into the ramp's top face", Vector2(230, 380) + UP * (12 + 17), 20, RAMP),
        ("a ball overlapping the ramp's lower end corner", Vector2(230, 380) + SLOPE * 222 + UP * 14, 20, RAMP),
        ("a ball overlapping a crate's top-right corner", Vector2(643, 508), 20, crate),
        ("a ball beside a crate's left side", Vector2(556, 545), 16, crate),
        ("a ball near a pentagon's corner", Vector2(40, 0), 14, ngon(5, 30, (0, 0), 0)),
        ("a ball just apart from a crate's corner", Vector2(645, 505), 20, crate),
        ("a ball far from a turned crate", Vector2(0, 0), 20, box(50, 30, (200, 100), 30)),
        ("a ball above the ramp, 10 px clear", Vector2(230, 380) + UP * (12 + 30), 20, RAMP),
    ]


def inside_cases():
    """(name, center, radius, polygon points): circles whose center is inside the polygon."""
    return [
        ("a ball whose center is 5 px inside the ramp's top face", Vector2(230, 380) + UP * 7, 20, RAMP),
        ("a ball whose center is inside a crate, near its left side", Vector2(575, 538), 20, box(80, 60, (600, 530))),
        ("a ball whose center is inside a turned crate, near its top", Vector2(4, -10), 12, box(70, 40, (0, 0), 15)),
        ("a ball whose center is inside a triangle", Vector2(3, 8), 10, ngon(3, 40, (0, 0), 12)),
        ("a ball whose center is inside a hexagon, near a corner", Vector2(-20, 2), 15, ngon(6, 30, (0, 0), 0)),
    ]


def _segment_distance(p, a, b):
    """px from p to the segment ab."""
    ab = b - a
    t = max(0.0, min(1.0, (p - a).dot(ab) / ab.dot(ab)))
    return p.distance_to(a + ab * t)


def drawn_circle_cases(rng, inside):
    """Circles drawn for this run beside a drawn box or polygon (probe_kit.random_shape), each at one edge: with
    inside=False one sunk 2-8 px into it and one 3-15 px clear of it (each kind of answer: so a table of the fixed
    cases with one default for the rest, None say, is wrong on one of them); with inside=True one whose center is
    3 px or more inside. Every other edge is at least 3 px farther than that edge: one right answer."""
    kinds = ("inside",) if inside else ("sunk", "clear")
    cases = []
    while len(cases) < len(kinds):
        kind = kinds[len(cases)]
        points = random_shape(rng, (rng.uniform(-100, 100), rng.uniform(-100, 100)))
        k = rng.randrange(len(points))
        a, b = points[k], points[(k + 1) % len(points)]
        middle = sum(points, Vector2()) / len(points)
        edge = a + (b - a) * rng.uniform(0.25, 0.75)
        out = Vector2(-(b - a).y, (b - a).x).normalize()
        out = out if out.dot(edge - middle) > 0 else -out
        radius = rng.uniform(8, 25)
        offset = {"sunk": radius - rng.uniform(2, 8), "clear": radius + rng.uniform(3, 15),
                  "inside": -rng.uniform(3, 12)}[kind]
        center = edge + out * offset
        near = abs(offset)
        others = [_segment_distance(center, points[i], points[(i + 1) % len(points)]) if kind != "inside" else
                  abs((center - points[i]).dot(Vector2(-(points[(i + 1) % len(points)] - points[i]).y,
                                                       (points[(i + 1) % len(points)] - points[i]).x).normalize()))
                  for i in range(len(points)) if i != k]
        if all(d >= near + 3 for d in others):
            what = {"sunk": "sunk into", "clear": "clear of", "inside": "with its center inside"}[kind]
            cases.append((f"a ball drawn for this run {what} a shape ({len(cases) + 1} of {len(kinds)})", center,
                          radius, points))
    return cases


def _inside_mistake(cases, case):
    """The inside case's mistake, read from this case: which of the normal and the depth are the outside case's."""
    got, want = case["got"], case["want"]
    if got is None:
        return Form(None, "circle_polygon() says apart for a center inside the polygon, the deepest overlap of all")
    if "bad" in got:
        return Form(None, "circle_polygon() must return (normal, depth) or None")
    flipped = same_point(got["normal"], case["toward"])
    outside_depth = close(got["depth"], case["radius"] - case["dist"])
    if flipped and close(got["depth"], want["depth"]):
        return Form("inside_not_flipped", "your normal points from the center towards the nearest edge: flip it, or "
                                          "the push drives the ball through")
    if flipped and outside_depth:
        return Form("inside_missing", "there is no inside case: a center inside gets the outside answer (normal "
                                      "towards the edge, depth radius - dist)")
    if same_point(got["normal"], want["normal"]):
        return Form("inside_shallow_depth", "the depth is radius - dist, the outside case's; inside it is radius + "
                                            "dist") if outside_depth else \
            Form(None, "the normal is right but not the depth: inside it is radius + dist")
    return None


INSIDE = Acting(
    "inside_case", "Step 3: circle_polygon() pushes a ball whose center is inside the polygon back out the nearest "
    "side.", 3, "circle_polygon",
    lambda module: rows(CIRCLE, inside_cases() + drawn_circle_cases(run_rng(module, "circle_inside"), inside=True)),
    CLOSEST_OUTSIDE.call, _lesson_hit, given=CLOSEST_OUTSIDE.given, probe_name="circle_inside",
    stand_ins=lambda module: {"closest_on_segment": lesson_closest}, answer=sat_answer, same=same_hit,
    hint="inside", diagnose=_inside_mistake, passed="the inside case matches the lesson in all {n} circles",
    # a center inside: the lesson's normal points away from the nearest edge, its depth is radius + dist
    extra={"toward": lambda c: [-x for x in _lesson_hit(c)["normal"]],
           "dist": lambda c: _lesson_hit(c)["depth"] - c["radius"]},
    unnamed="circle_polygon() does not push a center inside out of the nearest side",
    evidence=lambda c: f"for {c['case']} (center {vec_text(c['center'])}, {c['dist']:.2f} px in from the edge): "
                       f"{hit_difference(c['got'], c['want'])}.")


# ---------------------------------------------------------------- step 4: separate

def ball(radius, pos, **more):
    """A ball's plain description (declared_acts.body_of): its mass is the lab's, its area / 1000."""
    return described(r=radius, pos=pos, mass=math.pi * radius ** 2 / 1000, **more)


def crate(w, h, pos, mass, **more):
    return described(w=w, h=h, pos=pos, mass=mass, **more)


def separate_cases(module):
    """{case, a, b: the bodies' descriptions, normal: unit A→B, depth px}, one pair drawn for this run, and the
    lab's own push-out constants (a changed one is the handout's business)."""
    normal = Vector2(1, -2).normalize()
    rng = run_rng(module, "separate")   # the drawn pair: a crate (mass far from 1) and a ball
    crate_pos = Vector2(rng.uniform(200, 700), rng.uniform(200, 500))
    push_dir = Vector2(1, 0).rotate(rng.uniform(0, 360))
    drawn = crate(rng.uniform(30, 90), rng.uniform(30, 90), crate_pos, rng.uniform(2.5, 9.0))
    slop, percent = float(getattr(module, "SLOP", SLOP)), float(getattr(module, "PERCENT", PERCENT))
    return [{"case": name, "a": a, "b": b, "normal": list(n), "depth": depth, "slop": slop, "percent": percent}
            for name, a, b, n, depth in (
        # inverse masses 0.21 and 2.2: their total (2.4) is far from 1, so a missing "/ total" shows plainly
        ("a heavy crate (A) and a light ball (B)", crate(80, 60, (600, 530), 4.8), ball(12, (583, 538)),
         Vector2(-1, 0), 25.0),
        ("a static ramp (A) and a ball (B)", crate(420, 24, (230, 380), 0, angle=math.radians(22)),
         ball(20, (240, 350)), normal, 3.0),
        ("a ball (A) and a static floor (B)", ball(15, (300, 546)), crate(900, 40, (450, 580), 0), Vector2(0, 1), 1.7),
        ("a light ball (A) and a heavy ball (B)", ball(10, (0, 0)), ball(30, (38, 5)), Vector2(38, 5).normalize(),
         1.66),
        ("a ball (A) and a crate (B) overlapping less than the slop", ball(20, (0, 0)), crate(40, 40, (39.7, 0), 1.6),
         Vector2(1, 0), 0.3),
        ("a crate (A) and a ball (B) drawn for this run", drawn, ball(rng.uniform(6, 30), crate_pos + push_dir * 40),
         push_dir, rng.uniform(2.0, 12.0)))]


@reference
def _push(c):
    """The lesson's push-out, max(depth - slop, 0) · percent px, and the two bodies' inverse masses."""
    return max(c["depth"] - c["slop"], 0.0) * c["percent"], {k: body_of(c[k]).inv_mass for k in ("a", "b")}


def _pushed(c):
    """Both positions after the lesson's push-out: A back along the normal, B forward, by inverse mass."""
    push, inv = _push(c)
    return {k: list(Vector2(c[k]["pos"]) + Vector2(c["normal"]) * (sign * push * inv[k] / (inv["a"] + inv["b"])))
            for k, sign in (("a", -1), ("b", 1))}


def _moved(c, k, where="got"):
    return math.dist(c[where][k], c[k]["pos"])


def _split_mistake(cases, case):
    """The push-out's mistake, read from the first body that moved wrong: how far it moved."""
    k = first_differing(case["got"], case["want"], "ab", same_point)
    other, push, inv, total = "ba"["ab".index(k)], case["push"], case["inv"], case["inv"]["a"] + case["inv"]["b"]
    moved, should = _moved(case, k), _moved(case, k, "want")
    if inv[k] == 0 and moved > 0:
        return Form("static_moved", f"{k.upper()} is static (1/m = 0) and must never move")
    if close(moved, push) and not close(should, push):
        return Form("push_not_split", "each body got the whole push instead of its share by inverse mass")
    if close(moved, push / 2) and not close(should, push / 2):
        return Form("push_halved", "the push was halved, not split by inverse mass")
    if total and close(moved, push * inv[other] / total):
        return Form("push_shares_swapped", "the shares are swapped: each body got the other's")
    if total and not close(total, 1.0) and close(moved, push * inv[k]):
        return Form("push_missing_total", f"each share is push × 1/m without dividing by the total 1/m_A + 1/m_B = "
                                          f"{total:.3g}")
    if should and close(moved, should):
        return Form("push_wrong_way", "the right distance but the wrong way: A moves back along the normal, B forward")
    return None


def _split_where(c):
    return f"in '{c['case']}' (push {c['push']:.3f} px, 1/m {c['inv']['a']:.3g} and {c['inv']['b']:.3g})"


def _split_evidence(c):
    k = first_differing(c["got"], c["want"], "ab", same_point)
    return f"{_split_where(c)}, {k.upper()} moved {_moved(c, k):.3f} px; expected {_moved(c, k, 'want'):.3f} px."


SEPARATE = Acting(
    "push_out_split", "Step 4: separate() splits the push-out by inverse mass (a static body never moves).", 4,
    "separate", separate_cases, lambda separate, g: separate(g["a"], g["b"], g["normal"], g["depth"]), _pushed,
    given=lambda c: {"a": body_of(c["a"]), "b": body_of(c["b"]), "normal": Vector2(c["normal"]), "depth": c["depth"]},
    outcome=lambda g, raw: {k: answer_point(g[k].pos) for k in ("a", "b")}, kept=("normal",),
    advice="scale a new vector, normal * share", user="the World goes on using it", hint="split",
    label=lambda c: f"in '{c['case']}'",
    same=fields(same_point, "ab"), bad=lambda got: any("bad" in got[k] for k in "ab" if isinstance(got[k], dict)),
    malformed=lambda c: next(f"separate() left {k.upper()}'s position {c['got'][k]['bad']}.\n{_split_where(c)}."
                            for k in "ab" if isinstance(c["got"][k], dict)),
    diagnose=_split_mistake, evidence=_split_evidence, unnamed="separate() does not split the push by inverse mass",
    passed="the push-out is split by inverse mass in all {n} cases",
    extra={"push": lambda c: _push(c)[0], "inv": lambda c: _push(c)[1],
           "before": lambda c: {k: c[k]["pos"] for k in ("a", "b")}})


# ---------------------------------------------------------------- step 5: disc_inertia

def inertia_cases(module):
    """Masses and radii far from 1, and one ball drawn for this run."""
    rng = run_rng(module, "disc_inertia")
    return [{"mass": mass, "radius": radius} for mass, radius in ((math.pi * 400 / 1000, 20), (2.0, 12.0), (0.35, 37.5),
            (12.5, 3.0), (rng.uniform(2.5, 9.0), rng.uniform(5.0, 40.0)))]


@reference
def reference_disc_inertia(mass, radius):
    """The lesson's I = ½ m r² (mass·px²)."""
    return 0.5 * mass * radius ** 2


def _inertia_form(name, text, answer):
    return Form(name, f"yours is {text}; a solid disc has ½ m r²", lambda c: answer(c["mass"], c["radius"]))


INERTIA = Step(
    "ball_inertia", "Step 5: disc_inertia() gives a solid disc's moment of inertia, I = ½ m r².", 5, "disc_inertia",
    inertia_cases, lambda disc_inertia, c: disc_inertia(c["mass"], c["radius"]),
    lambda c: reference_disc_inertia(c["mass"], c["radius"]), answer=answer_number, hint="inertia",
    same=lambda got, want: not isinstance(got, dict) and close(got, want), bad=lambda got: isinstance(got, dict),
    label=lambda c: f"disc_inertia({c['mass']:.4g}, {c['radius']:g})", show=lambda v: f"the number {v:.4g}",
    kind="a number", unnamed="disc_inertia() is not ½ m r²",
    wrong=(_inertia_form("disc_ring", "m r², a thin ring's (all the mass at the rim)", lambda m, r: m * r ** 2),
           _inertia_form("disc_sphere", "2/5 m r², a solid sphere's", lambda m, r: 0.4 * m * r ** 2),
           _inertia_form("disc_rod", "m r² / 12, a thin rod's", lambda m, r: m * r ** 2 / 12),
           _inertia_form("disc_quarter", "m r² / 4", lambda m, r: m * r ** 2 / 4),
           _inertia_form("disc_radius_unsquared", "½ m r: the radius is not squared", lambda m, r: 0.5 * m * r),
           _inertia_form("disc_no_mass", "½ r²: the mass is left out", lambda m, r: 0.5 * r ** 2)))


# ---------------------------------------------------------------- step 6: contact_point

def contact_cases(module):
    """(name, center, radius, unit normal out of the ball, depth px), and one contact drawn for this run."""
    rng = run_rng(module, "contact_point")
    return rows(("case", "center", "radius", "normal", "depth"), (
        ("a ball resting on the ramp", Vector2(240, 350), 20.0, -UP, 0.4),
        ("a ball against a crate on its right", Vector2(575, 538), 20.0, Vector2(1, 0), 3.0),
        ("a small ball touching a wall above it, to the left", Vector2(-30, 12), 8.0, Vector2(-3, -4).normalize(), 0.05),
        ("a big ball sunk deep into the floor", Vector2(400, 520), 45.0, Vector2(0, 1), 5.0),
        ("a ball touching something drawn for this run", Vector2(rng.uniform(50, 800), rng.uniform(50, 550)),
         rng.uniform(6, 45), Vector2(1, 0).rotate(rng.uniform(0, 360)), rng.uniform(0.5, 5.0))))


@reference
def reference_contact(center, radius, normal, depth):
    """The lesson's contact point, center + normal · radius: on the ball's surface."""
    return list(Vector2(center) + Vector2(normal) * radius)


def _contact_form(name, text, at):
    """A known wrong contact point: center + normal * at(radius, depth)."""
    return Form(name, text, lambda c: list(Vector2(c["center"]) + Vector2(c["normal"]) * at(c["radius"], c["depth"])))


CONTACT = Step(
    "contact_on_surface", "Step 6: contact_point() puts the contact on the ball's surface, center + normal * radius.",
    6, "contact_point", contact_cases,
    lambda contact_point, c: answer_point(contact_point(Vector2(c["center"]), c["radius"], Vector2(c["normal"]),
                                                        c["depth"])),
    lambda c: reference_contact(c["center"], c["radius"], c["normal"], c["depth"]), hint="contact",
    same=same_point, bad=lambda got: isinstance(got, dict), kind="a point", show=vec_text,
    label=lambda c: f"for {c['case']} (center {vec_text(c['center'])}, radius {c['radius']:g}, normal "
                    f"{vec_text(c['normal'])}, depth {c['depth']:g})",
    unnamed="contact_point() is not on the ball's surface, center + normal * radius",
    wrong=(_contact_form("contact_halfway", "your point is halfway into the overlap, radius - depth / 2 from the "
                         "center; the step asks for the ball's surface", lambda r, d: r - d / 2),
           _contact_form("contact_at_centre", "your point is the ball's center, where friction cannot turn it",
                         lambda r, d: 0.0),
           _contact_form("contact_far_side", "your point is on the far side of the ball: the normal points out of "
                         "the ball, into the other body", lambda r, d: -r),
           _contact_form("contact_depth", "your point is center + normal * depth; the surface is radius px out",
                         lambda r, d: d)))


# ---------------------------------------------------------------- step 7: friction in resolve

def on_ramp(vel, omega, friction=0.6):
    """(the ramp, a 20 px ball resting on its top face with this motion, the normal, the contact point)."""
    centre = Vector2(230, 380) + UP * (12 + 20)
    return (crate(420, 24, (230, 380), 0, angle=math.radians(RAMP_ANGLE)),
            ball(20, centre, vel=vel, omega=omega, friction=friction), UP, centre - UP * 20)


def resolve_cases(module):
    """{case, a, b: the bodies' descriptions, normal: unit A→B, point: the contact, resting: the handout's cutoff}:
    each a contact resolve() is called on. The ramp and the floor are A (the world lists static bodies first), so
    the normal points from them into the ball; a ball hitting a crate is A."""
    resting = float(getattr(module, "RESTING_SPEED", RESTING_SPEED))
    return [{"case": name, "a": a, "b": b, "normal": list(normal), "point": list(point),
             "resting": resting} for name, (a, b, normal, point) in (
        ("a ball landing on the ramp, slipping a little", on_ramp(SLOPE * 50 - UP * 40, 2.3)),
        ("a ball landing on the ramp, sliding fast (friction clamped)", on_ramp(SLOPE * 300 - UP * 35, 0.0)),
        ("a ball spinning backwards as it lands on the ramp", on_ramp(SLOPE * 20 - UP * 60, -9.0)),
        ("a ball landing on the floor, rolling too fast for its speed",
         (crate(900, 40, (450, 580), 0), ball(15, (300, 545), vel=(40, 90), omega=6.0), Vector2(0, -1),
          Vector2(300, 560))),
        ("a ball hitting a crate's left side while it spins",
         (ball(20, (575, 530), vel=(250, 30), omega=4.0, restitution=0.3),
          crate(30, 80, (610, 520), 2.4, vel=(0, 10), omega=0.2, restitution=0.3), Vector2(1, 0), Vector2(595, 530))),
        ("a ball on a frictionless ramp (mu = 0)", on_ramp(SLOPE * 120 - UP * 45, 0.0, friction=0.0)))
        + drawn_contacts(run_rng(module, "resolve"), resting)]


def drawn_contacts(rng, resting=RESTING_SPEED):
    """Two balls landing on the ramp, drawn for this run: one sliding fast (friction clamped), one slipping a little
    (not clamped), so a table of the fixed contacts' answers with one default for the rest (no clamp, say) is
    wrong on one of them. |the impulse that stops the slip| is over 1.5 mu j or under 0.6 mu j: clear of the
    clamp's edge."""
    contacts = []
    while len(contacts) < 2:
        clamped = not contacts
        slide = rng.uniform(150, 400) if clamped else rng.uniform(-60, 60)
        contact = on_ramp(SLOPE * slide - UP * rng.uniform(35, 90), rng.uniform(-3, 3), rng.uniform(0.3, 0.9))
        ratio = stop_over_bound(body_of(contact[0]), body_of(contact[1]), contact[2], contact[3], resting)
        if ratio is not None and (ratio > 1.5 if clamped else ratio < 0.6):
            contacts.append((f"a ball drawn for this run landing on the ramp, friction "
                             f"{'clamped' if clamped else 'not clamped'} ({len(contacts) + 1} of 2)", contact))
    return tuple(contacts)


@reference
def reference_resolve(a, b, normal, point, variant="right", resting=RESTING_SPEED):
    """The handout's resolve() with the lesson's friction ("right") or one plausible mistake in step 7: each
    variant of FRICTION_FORMS changes one thing (its mistake id says which); "clamp_loses_sign" is
    `if abs(jt) > mu * j: jt = mu * j`, "whole_rel" -|rel| / kt.
    """
    ra, rb = point - a.pos, point - b.pos
    rel = relative_velocity(a, b, ra, rb)
    vn = rel.dot(normal)
    if vn >= 0:
        return
    k = effective_mass_inverse(a, b, ra, rb, normal)
    e = min(a.restitution, b.restitution) if vn < -resting else 0.0
    j = -(1 + e) * vn / k
    lesson_apply_impulse(a, b, normal * j, ra, rb)
    rel = relative_velocity(a, b, ra, rb)
    tangent = rel - normal * rel.dot(normal)
    if tangent.length_squared() <= 1e-12 or variant == "none":
        return
    t, mu, zero = tangent.normalize(), math.sqrt(a.friction * b.friction), Vector2()
    # kt with both spin terms, or without one or both (a zero lever arm drops its body's term), or k itself
    arms = {"no_spin_kt": (zero, zero), "kt_no_a_spin": (zero, rb), "kt_no_b_spin": (ra, zero)}.get(variant, (ra, rb))
    kt = k if variant == "kt_is_k" else effective_mass_inverse(a, b, *arms, t)
    jt = -(rel.length() if variant == "whole_rel" else rel.dot(t)) / kt
    if variant == "always_full":
        jt = math.copysign(mu * j, jt)
    elif variant == "bound_mu":
        jt = max(-mu, min(mu, jt))
    elif variant == "clamp_loses_sign":
        jt = mu * j if abs(jt) > mu * j else jt
    elif variant != "unclamped":
        jt = max(-mu * j, min(mu * j, jt))
    if variant == "sign":
        jt = -jt
    if variant == "at_centre":
        ra, rb = zero, zero
    if variant == "bodies_swapped":
        a, b = b, a
    for _ in range(2 if variant == "twice" else 1):
        lesson_apply_impulse(a, b, t * jt, ra, rb)



@reference
def _resolved(c, variant="right"):
    """Both bodies' velocity and spin after the handout's resolve with the `variant` friction, from the case."""
    a, b = body_of(c["a"]), body_of(c["b"])
    reference_resolve(a, b, Vector2(c["normal"]), Vector2(c["point"]), variant, c["resting"])
    return motions(a=a, b=b)


# step 7's known wrong forms: (reference_resolve's variant, the mistake's id, the hint) and the lab's own sentences
# (the others are causes.SHARED's, where Tumbling Crates names the same mistake)
FRICTION_TEXTS = {
    "kt_missing_a_spin": "kt lacks A's spin term (ra × t)²/I_A: it needs both bodies' terms",
    "kt_missing_b_spin": "kt lacks B's spin term (rb × t)²/I_B: it needs both bodies' terms",
    "friction_at_centre": "the friction impulse changes no spin (applied at the centres, or the velocities changed "
                          "without the spins): it cannot turn the ball",
    "friction_bodies_swapped": "friction is applied with the bodies swapped, apply_impulse(b, a, t * jt, ra, rb)"}
FRICTION_FORMS = tuple(Form(name, FRICTION_TEXTS.get(name), lambda c, variant=variant: _resolved(c, variant), hint)
                       for variant, name, hint in (
    ("none", "friction_missing", "friction_missing"), ("sign", "friction_sign", "friction_sign"),
    ("unclamped", "friction_unclamped", "friction_clamp"), ("always_full", "friction_always_full", "friction_clamp"),
    ("bound_mu", "friction_bound_mu", "friction_clamp"),
    ("clamp_loses_sign", "friction_clamp_loses_sign", "friction_clamp"), ("no_spin_kt", "kt_no_spin", "friction_kt"),
    ("kt_is_k", "kt_is_k", "friction_kt"), ("kt_no_a_spin", "kt_missing_a_spin", "friction_kt"),
    ("kt_no_b_spin", "kt_missing_b_spin", "friction_kt"), ("twice", "friction_twice", "friction_missing"),
    ("whole_rel", "friction_whole_rel", "friction_slip"), ("at_centre", "friction_at_centre", "friction_centre"),
    ("bodies_swapped", "friction_bodies_swapped", "friction_centre")))
# a flipped jt and apply_impulse(b, a, t * jt, rb, ra) give the same velocities: the noted calls tell them apart
ARMS_SWAPPED = Form("friction_bodies_arms_swapped", "friction is applied as apply_impulse(b, a, t * jt, rb, ra): "
                    "bodies and lever arms swapped, so it pushes along the slip", hint="friction_order")


def _arms_swapped(cases, case):
    """ARMS_SWAPPED when the flipped jt is named and every second (friction) apply_impulse call was (b, a, rb, ra)."""
    seconds = [c["calls"][1] for c in cases if len(c["calls"]) == 2]
    if seconds and all(call == "b a rb ra" for call in seconds) and FRICTION.named(cases, case) is FRICTION_FORMS[1]:
        return ARMS_SWAPPED
    return None


FRICTION = Acting(
    "friction_rolls", "Step 7: resolve()'s friction impulse, jt = -rel·t / kt clamped to ±mu j, acts at the contact "
    "and turns the ball.", 7, "resolve", resolve_cases,
    lambda resolve, g: resolve(g["a"], g["b"], g["normal"], g["point"]), _resolved,
    given=lambda c: dict({k: body_of(c[k]) for k in "ab"}, normal=Vector2(c["normal"]), point=Vector2(c["point"]),
                         ra=Vector2(c["point"]) - Vector2(c["a"]["pos"]),
                         rb=Vector2(c["point"]) - Vector2(c["b"]["pos"])),
    outcome=lambda g, raw: motions(a=g["a"], b=g["b"]), kept=("normal", "point"), label=lambda c: f"in '{c['case']}'",
    advice="make new vectors (normal.rotate(90), not t = normal then t.rotate_ip(90))",
    user="the World goes on using it for its other contact points",
    changed_hint=arguments_hint(7, "resolve"), same=fields(same_motion, "ab"),
    hooks={"apply_impulse": lambda g, args, named: roles(g, ("a", "b", "impulse", "ra", "rb"), args, named,
                                                          ("a", "b", "ra", "rb"))},
    hint="friction_missing", wrong=FRICTION_FORMS, diagnose=_arms_swapped,
    evidence=lambda c: f"in '{c['case']}' (mu = {c['mu']:.2g}): {motion_difference(c['got'], c['want'], 'ab')}.",
    unnamed="the velocities and spins after resolve() differ from the lesson's",
    passed="friction matches the lesson in all {n} contacts",
    extra={"mu": lambda c: math.sqrt(body_of(c["a"]).friction * body_of(c["b"]).friction),
           "ra": lambda c: list(Vector2(c["point"]) - Vector2(c["a"]["pos"])),
           "rb": lambda c: list(Vector2(c["point"]) - Vector2(c["b"]["pos"]))})


# the spliced functions the probes use: (function, the lab's solution's steps put in it)
SPLICES = (("circle_polygon", (3,)),)

# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("closest_on_segment", "circle_polygon", "disc_inertia", "contact_point")

# probe name -> (the lab function it needs, the probe); the spliced probe (circle_outside) runs last, so nothing it
# leaves (a step 2 that keeps the spliced circle_polygon somewhere) reaches a graded call of the student's own functions
PROBES = {**CLOSEST.probes(), **INSIDE.probes(), **SEPARATE.probes(), **INERTIA.probes(), **CONTACT.probes(),
          **FRICTION.probes(), **CLOSEST_OUTSIDE.probes()}
