"""Probes of a Ball on the Ramp file's own functions, run inside the checker's child process.

Each probe calls one of the student's functions on configurations chosen so
that together they exercise every term of the lesson's formula, and returns
plain data: the student's answer beside the lesson's on the same inputs
(checker/labs/ball_on_ramp/checks.py compares them and names the first that differs).
The lesson's answers are added in the grader only (`judging`, checker/judging/probe_kit.py),
from the inputs as they were before the student's function got them.

    closest_on_segment  (step 2) points beside an edge, beyond either end, slanted and reversed edges
    circle_outside      (step 2) circle_polygon() on circles outside or touching a polygon (near a
                        face, near a corner, apart), with the solution's step 3 spliced in
    circle_inside       (step 3) circle_polygon() with the center inside (near each kind of edge),
                        run with the lesson's closest_on_segment in place of the student's
    separate            (step 4) two dynamic bodies of different mass, a static A, a static B
    disc_inertia        (step 5) masses and radii far from 1
    contact_point       (step 6) balls touching along several normals, with small and large depths
    resolve             (step 7) a ball slipping on the static ramp (clamped and not), spinning in
                        place, hitting a crate, on a frictionless surface; resolve() runs with a
                        recorder in place of apply_impulse, so each impulse and where it acts is seen

Units: px, s, rad, mass in the lab's units (area / 1000).
"""
import math
import numbers

from pygame import Vector2

from lesson11.physics2d import Body, Circle, box_points, centre_of, cross, inside, relative_velocity
from lesson11.physics2d import apply_impulse as lesson_apply_impulse

from checker.judging.common import answer_number, close, real, same_point, value_text
from checker.judging.declared import Form, Step
from checker.judging.lab_checks import vec_text
from checker.judging.probe_kit import box, changed_vectors, judging, ngon, reference, twin, with_reference_steps
from checker.judging.tape import run_rng

REQUIRED = ("closest_on_segment", "circle_polygon", "separate", "disc_inertia", "contact_point", "resolve", "main")
RESTING_SPEED = 30.0   # px/s, the handout's cutoff below which e = 0
SLOP, PERCENT = 0.5, 0.4   # px, share: the handout's push-out constants
RAMP_ANGLE = 22.0      # degrees


def answer_point(value):
    """A returned point as [x, y], or {"bad": what it is} when it is not a finite 2D point.

    A bare number is no point (Vector2(0.3) would make it (0.3, 0.3)): {"bad": ..., "number": value}.
    """
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        try:
            return {"bad": f"the number {_short(value)}, not a point", "number": real(value)}
        except ValueError:   # an int too large for a float
            return {"bad": f"the number {_short(value)}, not a point"}
    try:
        point = Vector2(value)
    except (TypeError, ValueError):
        return {"bad": _short(value)}
    if not (math.isfinite(point.x) and math.isfinite(point.y)):
        return {"bad": f"a point that is not finite: {_short(value)}"}
    return [point.x, point.y]


def answer_hit(hit):
    """circle_polygon's answer as None, {"normal": [x, y], "depth": d} or {"bad": what is wrong}."""
    if hit is None:
        return None
    try:
        first, second = hit
    except (TypeError, ValueError):
        return {"bad": f"a {type(hit).__name__} ({_short(hit)})"}
    if isinstance(first, (int, float)) and not isinstance(second, (int, float)):
        return {"bad": "(depth, normal)"}
    try:
        normal, depth = Vector2(first), real(second)
    except (TypeError, ValueError):
        return {"bad": f"({_short(first)}, {_short(second)})"}
    if not (math.isfinite(normal.x) and math.isfinite(normal.y) and math.isfinite(depth)):
        return {"bad": f"a normal or depth that is not finite: ({_short(first)}, {depth!r})"}
    return {"normal": [normal.x, normal.y], "depth": depth}


_short = value_text   # repr cut to 60 characters; safe for a 5000-digit int


# ---------------------------------------------------------------- the lesson's formulas

def lesson_closest(p, a, b):
    """The lesson's closest_on_segment: a + ab t, t = clamp((p - a)·ab / ab·ab, 0, 1).

    Also put in the student's place under circle_polygon() (step 3 graded on its own), so it runs
    in the child as a stand-in; as a reference answer it is reference_closest, grader only.
    """
    ab = b - a
    t = max(0.0, min(1.0, (p - a).dot(ab) / ab.dot(ab)))
    return a + ab * t


reference_closest = reference(lesson_closest)


@reference
def reference_circle_polygon(center, radius, points):
    """The lesson's circle_polygon: None, or (normal from the circle into the polygon, depth px)."""
    closest = min((reference_closest(center, points[i], points[(i + 1) % len(points)]) for i in range(len(points))),
                  key=center.distance_squared_to)
    offset = closest - center
    dist = offset.length()
    if dist < 1e-9:
        return (centre_of(points) - center).normalize(), radius
    if inside(center, points):
        return -offset / dist, radius + dist
    if dist >= radius:
        return None
    return offset / dist, radius - dist


def _plain(hit):
    return None if hit is None else {"normal": [hit[0].x, hit[0].y], "depth": hit[1]}


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


def probe_closest(module, lab_path):
    """The student's closest_on_segment(p, a, b) on each case beside the lesson's and the unclamped answer."""
    cases = []
    for name, p, a, b in segment_cases() + drawn_segment_cases(run_rng(module, "closest_on_segment")):
        given = {"p": Vector2(p), "a": Vector2(a), "b": Vector2(b)}   # copies: a change shows, and stays here
        got = module.closest_on_segment(given["p"], given["a"], given["b"])
        changed = {key: list(value) for key, value in given.items() if value != {"p": p, "a": a, "b": b}[key]}
        case = {"case": name, "p": list(p), "a": list(a), "b": list(b), "got": answer_point(got), "changed": changed}
        if judging(module):
            case.update(_closest_reference(p, a, b))
        cases.append(case)
    return cases


@reference
def _closest_reference(p, a, b):
    """The lesson's closest point and, by name, the points of the known wrong formulas (CLOSEST_MISTAKES).

    Also the lesson's t, for a function that returns t instead of the point.
    """
    ab = b - a

    def clamped(t):
        return list(a + ab * max(0.0, min(1.0, t)))
    along = (p - a).dot(ab)
    return {"want": list(reference_closest(p, a, b)), "t": max(0.0, min(1.0, along / ab.dot(ab))),
            "mistakes": {"line": list(a + ab * (along / ab.dot(ab))), "unsquared": clamped(along / ab.length()),
                         "undivided": clamped(along), "from_b": clamped((p - b).dot(ab) / ab.dot(ab))}}


# ---------------------------------------------------------------- steps 2 and 3: circle_polygon

def _ramp():
    return box(420, 24, (230, 380), RAMP_ANGLE)


def outside_cases():
    """(name, center, radius, polygon points): circles outside, touching or apart from a polygon."""
    ramp = _ramp()
    up = Vector2(math.sin(math.radians(RAMP_ANGLE)), -math.cos(math.radians(RAMP_ANGLE)))
    slope = Vector2(math.cos(math.radians(RAMP_ANGLE)), math.sin(math.radians(RAMP_ANGLE)))
    crate = box(60, 40, (600, 540))
    return [
        ("a ball sunk 3 px into the ramp's top face", Vector2(230, 380) + up * (12 + 17), 20, ramp),
        ("a ball overlapping the ramp's lower end corner", Vector2(230, 380) + slope * 222 + up * 14, 20, ramp),
        ("a ball overlapping a crate's top-right corner", Vector2(643, 508), 20, crate),
        ("a ball beside a crate's left side", Vector2(556, 545), 16, crate),
        ("a ball near a pentagon's corner", Vector2(40, 0), 14, ngon(5, 30, (0, 0), 0)),
        ("a ball just apart from a crate's corner", Vector2(645, 505), 20, crate),
        ("a ball far from a turned crate", Vector2(0, 0), 20, box(50, 30, (200, 100), 30)),
        ("a ball above the ramp, 10 px clear", Vector2(230, 380) + up * (12 + 30), 20, ramp),
    ]


def inside_cases():
    """(name, center, radius, polygon points): circles whose center is inside the polygon."""
    ramp = _ramp()
    up = Vector2(math.sin(math.radians(RAMP_ANGLE)), -math.cos(math.radians(RAMP_ANGLE)))
    return [
        ("a ball whose center is 5 px inside the ramp's top face", Vector2(230, 380) + up * 7, 20, ramp),
        ("a ball whose center is inside a crate, near its left side", Vector2(575, 538), 20, box(80, 60, (600, 530))),
        ("a ball whose center is inside a turned crate, near its top", Vector2(4, -10), 12, box(70, 40, (0, 0), 15)),
        ("a ball whose center is inside a triangle", Vector2(3, 8), 10, ngon(3, 40, (0, 0), 12)),
        ("a ball whose center is inside a hexagon, near a corner", Vector2(-20, 2), 15, ngon(6, 30, (0, 0), 0)),
    ]


def _circle_cases(module, function, cases):
    out = []
    for name, center, radius, points in cases:
        got = function(Vector2(center), radius, [Vector2(p) for p in points])
        case = {"case": name, "center": list(center), "radius": radius, "points": [list(p) for p in points],
                "got": answer_hit(got)}
        if judging(module):
            case.update(_circle_reference(center, radius, points))
        out.append(case)
    return out


@reference
def _circle_reference(center, radius, points):
    """The lesson's circle_polygon answer, the distance to the outline and the direction to its closest point."""
    closest = min((reference_closest(center, points[i], points[(i + 1) % len(points)])
                   for i in range(len(points))), key=center.distance_squared_to)
    return {"want": _plain(reference_circle_polygon(center, radius, points)),
            "dist": center.distance_to(closest), "toward": list((closest - center).normalize())}


def probe_circle_outside(module, lab_path):
    """circle_polygon() on the outside cases, with the solution's step 3 spliced in (step 2 graded on its own).

    Falls back to the student's own circle_polygon when the markers cannot be found.
    """
    function = with_reference_steps(module, lab_path, "circle_polygon", (3,)) or \
        module.circle_polygon
    return _circle_cases(module, function, outside_cases())


def probe_circle_inside(module, lab_path):
    """circle_polygon() on the inside cases, with the lesson's closest_on_segment in place of the student's."""
    own = module.closest_on_segment
    module.closest_on_segment = lesson_closest
    try:
        return _circle_cases(module, module.circle_polygon, inside_cases())
    finally:
        module.closest_on_segment = own


# ---------------------------------------------------------------- step 4: separate

def _ball(radius, pos, mass=None, friction=0.6, vel=(0, 0), omega=0.0, restitution=0.2):
    mass = math.pi * radius ** 2 / 1000 if mass is None else mass
    return Body(Circle(radius), pos, mass, vel=vel, omega=omega, friction=friction, restitution=restitution)


def separate_cases():
    """(name, body A, body B, unit normal A→B, depth px)."""
    normal = Vector2(1, -2).normalize()
    return [
        # inverse masses 0.21 and 2.2: their total (2.4) is far from 1, so a missing "/ total" shows plainly
        ("a heavy crate (A) and a light ball (B)", Body(box_points(80, 60), (600, 530), 4.8),
         _ball(12, (583, 538)), Vector2(-1, 0), 25.0),
        ("a static ramp (A) and a ball (B)", Body(box_points(420, 24), (230, 380), 0, angle=math.radians(22)),
         _ball(20, (240, 350)), normal, 3.0),
        ("a ball (A) and a static floor (B)", _ball(15, (300, 546)), Body(box_points(900, 40), (450, 580), 0),
         Vector2(0, 1), 1.7),
        ("a light ball (A) and a heavy ball (B)", _ball(10, (0, 0)), _ball(30, (38, 5)),
         Vector2(38, 5).normalize(), 1.66),
        ("a ball (A) and a crate (B) overlapping less than the slop", _ball(20, (0, 0)),
         Body(box_points(40, 40), (39.7, 0), 1.6), Vector2(1, 0), 0.3),
    ]


def probe_separate(module, lab_path):
    """The student's separate() on each case: both positions before, after and as the lesson moves them."""
    cases = []
    slop = float(getattr(module, "SLOP", SLOP))   # the lab's own constants: a changed one is the handout's business
    percent = float(getattr(module, "PERCENT", PERCENT))
    rng = run_rng(module, "separate")   # and one pair drawn for this run: a crate (mass far from 1) and a ball
    crate_pos = Vector2(rng.uniform(200, 700), rng.uniform(200, 500))
    push_dir = Vector2(1, 0).rotate(rng.uniform(0, 360))
    drawn = [("a crate (A) and a ball (B) drawn for this run",
              Body(box_points(rng.uniform(30, 90), rng.uniform(30, 90)), crate_pos, rng.uniform(2.5, 9.0)),
              _ball(rng.uniform(6, 30), crate_pos + push_dir * 40), push_dir, rng.uniform(2.0, 12.0))]
    for name, a, b, normal, depth in separate_cases() + drawn:
        given = (twin(a), twin(b))   # the bodies as separate() gets them
        normal_given = Vector2(normal)   # a copy: a change to it shows
        module.separate(a, b, normal_given, depth)
        case = {"case": name, "normal": list(normal), "depth": depth,
                "normal_after": None if normal_given == normal else list(normal_given),
                "after": {"a": answer_point(a.pos), "b": answer_point(b.pos)}}
        if judging(module):
            case.update(_separate_reference(*given, normal, depth, slop, percent))
        cases.append(case)
    return cases


@reference
def _separate_reference(a, b, normal, depth, slop, percent):
    """The lesson's push-out of a and b (as given): max(depth - slop, 0) · percent px, split by inverse mass."""
    total = a.inv_mass + b.inv_mass
    push = max(depth - slop, 0.0) * percent
    return {"push": push, "inv": {"a": a.inv_mass, "b": b.inv_mass}, "mass": {"a": a.mass, "b": b.mass},
            "before": {"a": list(a.pos), "b": list(b.pos)},
            "want": {"a": list(a.pos - normal * (push * a.inv_mass / total)),
                     "b": list(b.pos + normal * (push * b.inv_mass / total))}}


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
    down_ramp = Vector2(-math.sin(math.radians(RAMP_ANGLE)), math.cos(math.radians(RAMP_ANGLE)))
    rng = run_rng(module, "contact_point")
    return [{"case": name, "center": list(center), "radius": radius, "normal": list(normal), "depth": depth}
            for name, center, radius, normal, depth in (
        ("a ball resting on the ramp", Vector2(240, 350), 20.0, down_ramp, 0.4),
        ("a ball against a crate on its right", Vector2(575, 538), 20.0, Vector2(1, 0), 3.0),
        ("a small ball touching a wall above it, to the left", Vector2(-30, 12), 8.0, Vector2(-3, -4).normalize(), 0.05),
        ("a big ball sunk deep into the floor", Vector2(400, 520), 45.0, Vector2(0, 1), 5.0),
        ("a ball touching something drawn for this run", Vector2(rng.uniform(50, 800), rng.uniform(50, 550)),
         rng.uniform(6, 45), Vector2(1, 0).rotate(rng.uniform(0, 360)), rng.uniform(0.5, 5.0)))]


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

def resolve_cases():
    """(name, body A, body B, unit normal A→B, contact point): each a contact resolve() is called on.

    The ramp and the floor are A (the world lists static bodies first), so the
    normal points from them into the ball; a ball hitting a crate is A.
    """
    theta = math.radians(RAMP_ANGLE)
    slope = Vector2(math.cos(theta), math.sin(theta))
    up = Vector2(math.sin(theta), -math.cos(theta))
    centre = Vector2(230, 380) + up * (12 + 20)
    touch = centre - up * 20

    def on_ramp(vel, omega, friction=0.6):
        ball = _ball(20, centre, vel=vel, omega=omega, friction=friction)
        return Body(box_points(420, 24), (230, 380), 0, angle=theta), ball

    return [
        ("a ball landing on the ramp, slipping a little",) + on_ramp(slope * 50 - up * 40, 2.3) + (up, touch),
        ("a ball landing on the ramp, sliding fast (friction clamped)",) + on_ramp(slope * 300 - up * 35, 0.0)
        + (up, touch),
        ("a ball spinning backwards as it lands on the ramp",) + on_ramp(slope * 20 - up * 60, -9.0) + (up, touch),
        ("a ball landing on the floor, rolling too fast for its speed",
         Body(box_points(900, 40), (450, 580), 0), _ball(15, (300, 545), vel=(40, 90), omega=6.0),
         Vector2(0, -1), Vector2(300, 560)),
        ("a ball hitting a crate's left side while it spins",
         _ball(20, (575, 530), vel=(250, 30), omega=4.0, restitution=0.3),
         Body(box_points(30, 80), (610, 520), 2.4, vel=(0, 10), omega=0.2, restitution=0.3),
         Vector2(1, 0), Vector2(595, 530)),
        ("a ball on a frictionless ramp (mu = 0)",) + on_ramp(slope * 120 - up * 45, 0.0, friction=0.0)
        + (up, touch),
    ]


FRICTION_VARIANTS = ("right", "none", "sign", "unclamped", "no_spin_kt", "kt_is_k", "at_centre", "always_full",
                     "bodies_swapped", "twice", "bound_mu", "whole_rel", "kt_no_a_spin", "kt_no_b_spin",
                     "clamp_loses_sign")


@reference
def reference_resolve(a, b, normal, point, variant="right", resting=RESTING_SPEED):
    """The handout's resolve() with the lesson's friction ("right") or a plausible mistake in step 7.

    Variants: "none" no friction; "sign" the clamped impulse pushed along the slip; "unclamped"
    no Coulomb clamp; "no_spin_kt" kt without the spin terms; "kt_is_k" the normal's k used as kt;
    "at_centre" the friction impulse applied at the centres (ra = rb = 0); "always_full" friction
    always mu j, against the slip; "bodies_swapped" apply_impulse(b, a, t jt, ra, rb); "twice" the friction
    impulse applied twice; "bound_mu" clamped to ±mu; "whole_rel" -|rel| / kt (the whole relative speed, not
    the slip rel·t); "kt_no_a_spin" / "kt_no_b_spin" kt without A's / B's spin term; "clamp_loses_sign"
    `if abs(jt) > mu * j: jt = mu * j`.
    """
    ra, rb = point - a.pos, point - b.pos
    rel = relative_velocity(a, b, ra, rb)
    vn = rel.dot(normal)
    if vn >= 0:
        return
    ran, rbn = cross(ra, normal), cross(rb, normal)
    k = a.inv_mass + b.inv_mass + ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia
    e = min(a.restitution, b.restitution) if vn < -resting else 0.0
    j = -(1 + e) * vn / k
    lesson_apply_impulse(a, b, normal * j, ra, rb)
    rel = relative_velocity(a, b, ra, rb)
    tangent = rel - normal * rel.dot(normal)
    if tangent.length_squared() <= 1e-12 or variant == "none":
        return
    t = tangent.normalize()
    mu = math.sqrt(a.friction * b.friction)
    rat, rbt = cross(ra, t), cross(rb, t)
    kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
    if variant == "no_spin_kt":
        kt = a.inv_mass + b.inv_mass
    elif variant == "kt_is_k":
        kt = k
    elif variant == "kt_no_a_spin":
        kt = a.inv_mass + b.inv_mass + rbt * rbt * b.inv_inertia
    elif variant == "kt_no_b_spin":
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia
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
        ra, rb = Vector2(), Vector2()
    if variant == "bodies_swapped":
        a, b = b, a
    lesson_apply_impulse(a, b, t * jt, ra, rb)
    if variant == "twice":
        lesson_apply_impulse(a, b, t * jt, ra, rb)


def _outcome(a, b):
    return {"a": {"vel": [a.vel.x, a.vel.y], "omega": a.omega}, "b": {"vel": [b.vel.x, b.vel.y], "omega": b.omega}}


def probe_resolve(module, lab_path):
    """The student's resolve() on each contact: both bodies' velocities and spins after it.

    Beside them: the same after the handout's resolve with the lesson's friction ("right")
    and with each plausible step-7 mistake (FRICTION_VARIANTS), from the same start. Also
    the slip speed and the impulses involved, for the message. The library's apply_impulse
    is the lab's (imported), so only step 7 can differ.
    """
    cases = []
    resting = float(getattr(module, "RESTING_SPEED", RESTING_SPEED))
    for name, a, b, normal, point in resolve_cases():
        given = (twin(a), twin(b))   # the bodies as resolve() gets them
        vectors = {"normal": Vector2(normal), "point": Vector2(point)}   # copies: a change in place shows
        calls = []
        with _calls_recorded(module, a, b, point, calls):
            module.resolve(a, b, vectors["normal"], vectors["point"])
        case = {"case": name, "got": _outcome(a, b), "changed": changed_vectors(vectors, normal=normal, point=point),
                "calls": calls}
        if judging(module):
            case.update(_resolve_reference(*given, normal, point, resting))
        cases.append(case)
    return cases


class _calls_recorded:
    """While resolve() runs, the module's apply_impulse also notes each call's order of bodies and lever arms in
    `calls`: "ab" / "ba" (A first / B first) and "ra,rb" / "rb,ra" / "other". Swapped bodies with swapped lever
    arms give the same velocities as a flipped jt: only the call tells them apart."""

    def __init__(self, module, a, b, point, calls):
        self.module, self.original = module, getattr(module, "apply_impulse", None)
        self.a, self.b, self.calls = a, b, calls
        self.ra, self.rb = point - a.pos, point - b.pos

    def __enter__(self):
        if callable(self.original):
            def recorder(*args, **named):
                given = dict(zip(("a", "b", "impulse", "ra", "rb"), args), **named)
                first, second, r1, r2 = (given.get(key) for key in ("a", "b", "ra", "rb"))
                order = "ab" if first is self.a and second is self.b else \
                    "ba" if first is self.b and second is self.a else "other"
                arms = "ra,rb" if _near(r1, self.ra) and _near(r2, self.rb) else \
                    "rb,ra" if _near(r1, self.rb) and _near(r2, self.ra) else "other"
                self.calls.append(order + " " + arms)
                return self.original(*args, **named)
            self.module.apply_impulse = recorder
        return self

    def __exit__(self, *exc):
        if callable(self.original):
            self.module.apply_impulse = self.original
        return False


def _near(v, w):
    try:
        return abs(v[0] - w[0]) <= 1e-9 and abs(v[1] - w[1]) <= 1e-9
    except (TypeError, IndexError, ValueError):
        return False


@reference
def _resolve_reference(a, b, normal, point, resting):
    """The outcome of the handout's resolve with each friction variant, from a and b as given; mu, ra and rb."""
    variants = {}
    for variant in FRICTION_VARIANTS:
        ca, cb = twin(a), twin(b)
        reference_resolve(ca, cb, Vector2(normal), Vector2(point), variant, resting)
        variants[variant] = _outcome(ca, cb)
    return {"mu": math.sqrt(a.friction * b.friction), "variants": variants,
            "ra": list(point - a.pos), "rb": list(point - b.pos)}


# the spliced functions the probes use: (function, the lab's solution's steps put in it)
SPLICES = (("circle_polygon", (3,)),)

# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("closest_on_segment", "circle_polygon", "disc_inertia", "contact_point")

# probe name -> (the lab function it needs, the probe); the spliced probe (circle_outside) runs last, so nothing it
# leaves (a step 2 that keeps the spliced circle_polygon somewhere) reaches a graded call of the student's own functions
PROBES = {
    "closest_on_segment": ("closest_on_segment", probe_closest),
    "circle_inside": ("circle_polygon", probe_circle_inside),
    "separate": ("separate", probe_separate),
    **INERTIA.probes(),
    **CONTACT.probes(),
    "resolve": ("resolve", probe_resolve),
    "circle_outside": ("circle_polygon", probe_circle_outside),
}
