"""Bullets' probes, run in the checker's child; the lesson's answers are added in the grader only (@reference).

Steps 2-5 are declared (checker/judging/declared.py), each run with the lesson's code in place of the steps it
calls, so a mistake is graded once, under its own step:
    circle_toi      (step 2) against the geometric answer (closest approach, then back along the path)
    bounding_radius (step 3) boxes, turned boxes, a triangle and a pentagon around their centres
    time_of_impact  (step 4) crates hit, missed, grazed, reached from inside; its exact swept tests counted
    swept_move      (step 5) one swept move against a wall, a crate and nothing
    shots, crate_hit (criteria 1, 2 and 4) the lab's own BulletWorld: >= 100 shots at 3000-12000 px/s with CCD,
                    shots at 12000 px/s with sub-steps x8, a bullet into a free crate
Units: px, s, mass in the lab's units (area / 1000).
"""
import math
import threading

from pygame import Vector2

from lesson11.physics2d import Body, Circle, box_points, circle_polygon_toi

from checker.judging.common import answer_number, close, real, same_point, value_text
from checker.judging.declared import Form, Step
from checker.judging.lab_checks import vec_text
from checker.judging.probe_kit import box, judging, ngon, reference, twin
from checker.judging.tape import clock, run_rng

REQUIRED = ("circle_toi", "bounding_radius", "time_of_impact", "swept_move", "apply_mode", "make_wall", "make_bullet",
            "BulletWorld", "main")
STEP = 1 / 120                          # s
SHOT_SPEEDS = (3000, 4500, 6000, 7500, 9000, 10500, 12000)   # px/s, with CCD
SHOTS_PER_SPEED = 16                    # 7 x 16 = 112 shots, start offsets spread over one step's travel
SUBSTEP_SHOTS = 32                      # shots at 12000 px/s with sub-steps x8
FAST = 12000.0                          # px/s
TOI_TOLERANCE = 1e-9                    # s (the issue); solution: at most 5e-16 s off the geometric answer


def answer_time(value):
    """A returned time (or radius) as a float, None, or {"bad": what it is}."""
    return answer_number(value, none=True, finite=True)


_short = value_text   # repr cut to 60 characters; safe for a 5000-digit int


# ---------------------------------------------------------------- step 2: circle_toi

@reference
def analytic_toi(p1, v1, r1, p2, v2, r2, dt):
    """The first touching time by geometry: closest approach of the relative path, then back by the chord.

    Independent of the quadratic: s* = -dp·dv / |dv|² is when the centres are
    closest, h² = |dp|² - (dp·dv)²/|dv|² the squared closest distance; the
    circles touch sqrt(R² - h²) / |dv| before s*.
    """
    dp, dv = p2 - p1, v2 - v1
    reach = r1 + r2
    if dp.length() <= reach:
        return 0.0
    speed = dv.length()
    if speed == 0:
        return None
    along = -dp.dot(dv) / speed              # px travelled until closest approach
    miss_sq = dp.length_squared() - along * along
    if miss_sq > reach * reach:
        return None
    t = (along - math.sqrt(max(reach * reach - miss_sq, 0.0))) / speed
    return t if 0 <= t <= dt else None


def toi_cases():
    """(name, p1, v1, r1, p2, v2, r2, dt) in px, px/s, s."""
    return [
        ("head-on: a bullet at 3000 px/s towards a still circle 60 px away", Vector2(0, 0), Vector2(3000, 0), 2.0,
         Vector2(60, 0), Vector2(0, 0), 5.0, 1 / 30),
        ("head-on, both moving towards each other", Vector2(10, 20), Vector2(0, 400), 6.0,
         Vector2(10, 220), Vector2(0, -200), 14.0, 1.0),
        ("glancing: the path passes 9 px from the centre, radii adding to 12", Vector2(0, 0), Vector2(500, 0), 4.0,
         Vector2(100, 9), Vector2(0, 0), 8.0, 1.0),
        ("a slanted path towards a moving circle", Vector2(-30, 40), Vector2(250, -120), 3.0,
         Vector2(120, -20), Vector2(-40, 10), 10.0, 1.0),
        ("already touching (overlapping by 1 px)", Vector2(0, 0), Vector2(100, 0), 5.0,
         Vector2(9, 0), Vector2(0, 0), 5.0, 0.1),
        ("moving apart", Vector2(0, 0), Vector2(-300, 0), 5.0, Vector2(40, 0), Vector2(0, 0), 5.0, 1.0),
        ("moving apart at a slant, paths crossing behind", Vector2(0, 0), Vector2(-200, -150), 3.0,
         Vector2(30, 10), Vector2(50, 0), 4.0, 1.0),
        ("parallel paths at the same velocity", Vector2(0, 0), Vector2(800, 0), 5.0,
         Vector2(0, 30), Vector2(800, 0), 5.0, 1.0),
        ("parallel paths 20 px apart, radii adding to 10", Vector2(0, 0), Vector2(600, 0), 5.0,
         Vector2(100, 20), Vector2(0, 0), 5.0, 1.0),
        ("missing: the path passes 15 px from the centre, radii adding to 12", Vector2(0, 0), Vector2(0, 700), 4.0,
         Vector2(15, 200), Vector2(0, 0), 8.0, 1.0),
        ("head-on but too far away for this step", Vector2(0, 0), Vector2(1200, 0), 3.0,
         Vector2(200, 0), Vector2(0, 0), 2.0, 1 / 120),
        # told-apart case (issue 40): a hit within 1/120 s, so a bound fixed at 1/120 s keeps it, while b without
        # its 2 finds a (wrong) root only this close (|dp| < 1.15 (r1 + r2))
        ("head-on, 1 px from touching", Vector2(0, 0), Vector2(300, 0), 4.0, Vector2(11, 0), Vector2(0, 0), 6.0,
         1 / 120),
    ]


def drawn_toi_cases(rng, count=3):
    """`count` cases drawn for this run: a circle heading for another, hitting within the step and passing by in
    turn (the first hits), so a table of the fixed cases' answers with one default for the rest (None, say) is
    wrong on one of them. A hit passes at most 0.7 (r1 + r2) from the centre, a miss at least 1.3 (r1 + r2)."""
    cases = []
    for k in range(count):
        hit = k % 2 == 0
        r1, r2 = rng.uniform(2, 8), rng.uniform(5, 20)
        p1 = Vector2(rng.uniform(-50, 50), rng.uniform(-50, 50))
        direction = Vector2(1, 0).rotate(rng.uniform(0, 360))
        gap = rng.uniform(20, 150)                 # px between the surfaces along the path
        aim = (rng.uniform(0, 0.7) if hit else rng.uniform(1.3, 2.0)) * (r1 + r2)   # miss distance: hit or pass
        p2 = p1 + direction * (gap + r1 + r2) + direction.rotate(90) * aim
        speed = rng.uniform(300, 3000)
        dt = (gap + r1 + r2) / speed * rng.uniform(1.3, 3.0)
        cases.append((f"a path drawn for this run, {'hitting' if hit else 'passing by'} ({k + 1} of {count})", p1,
                      direction * speed, r1, p2,
                       Vector2(), r2, dt))
    return cases


def _toi_cases(module):
    """toi_cases() and drawn_toi_cases() as dicts (points and velocities as [x, y])."""
    keys = ("case", "p1", "v1", "r1", "p2", "v2", "r2", "dt")
    return [{key: list(value) if isinstance(value, Vector2) else value for key, value in zip(keys, case)}
            for case in toi_cases() + drawn_toi_cases(run_rng(module, "circle_toi"))]


def _toi_args(c):
    """circle_toi's arguments for case c."""
    return (Vector2(c["p1"]), Vector2(c["v1"]), c["r1"], Vector2(c["p2"]), Vector2(c["v2"]), c["r2"], c["dt"])


@reference
def _quadratic(c):
    """The quadratic's a, b, c for case c (dp = p2 - p1, dv = v2 - v1)."""
    p1, v1, r1, p2, v2, r2, dt = _toi_args(c)
    dp, dv = p2 - p1, v2 - v1
    return dv.dot(dv), 2 * dp.dot(dv), dp.dot(dp) - (r1 + r2) ** 2


@reference
def _later_root(c):
    """The quadratic's later root (s), when the circles stop touching, or None."""
    a, b, c0 = _quadratic(c)
    disc = b * b - 4 * a * c0
    return (-b + math.sqrt(disc)) / (2 * a) if a > 0 and disc >= 0 else None


def _toi_form(name, text, root, hint=None):
    """A known wrong root: _toi_with on the quadratic as root(a, b, c, dt) changes it."""
    return Form(f"toi_{name}", text, lambda c: _toi_with(*root(*_quadratic(c), c["dt"])), hint)


def _toi_ok(got, want):
    return got is None if want is None else isinstance(got, float) and abs(got - want) <= TOI_TOLERANCE


def _toi_diagnosis(cases, c):
    """What this case shows by itself (touching, the later root, a time in the past or after dt), else a wrong
    root the cases tell apart, else no contact found where there is one."""
    got, want = c["got"], c["want"]
    if want == 0.0 and c["c"] <= 0:
        return Form("toi_touching_missed", "the circles already overlap, so the impact is now: return 0.0",
                    hint="toi_touching")
    if got is not None and c["later"] is not None and abs(got - c["later"]) <= TOI_TOLERANCE:
        return Form("toi_later_root", "that is the later root, when the circles stop touching", hint="toi_later")
    if want is None and got is not None:
        if got < 0:
            return Form("toi_negative_time", "a negative time is in the past: the circles are moving apart",
                        hint="toi_apart")
        if got > c["dt"]:
            return Form("toi_after_dt", "the time is later than this step's dt", hint="toi_apart",
                        line=f"the time is later than this step's dt = {c['dt']:.4g} s")
        return Form(None, TOI.unnamed, hint="toi_apart")
    named = TOI.named(cases, c)
    if named is None and want is not None and got is None:
        return Form(None, "the circles do touch within the step, but circle_toi() found no contact")
    return named


TOI = Step(
    "toi_matches_root", "Step 2: circle_toi() equals the analytic first-contact time within 1e-9 s (head-on, "
    "glancing, already touching, moving apart, parallel paths, missing), the lab's done-criterion 3.", 2,
    "circle_toi", _toi_cases, lambda circle_toi, c: answer_time(circle_toi(*_toi_args(c))),
    lambda c: analytic_toi(*_toi_args(c)), hint="toi", same=_toi_ok, bad=lambda got: isinstance(got, dict),
    kind="a time in seconds or None", diagnose=_toi_diagnosis, unnamed="circle_toi() does not give the first-contact time",
    label=lambda c: f"circle_toi() for {c['case']} (dt = {c['dt']:.4g} s)",
    show=lambda t: "None (no contact)" if t is None else f"{t:.9g} s",
    extra={"later": _later_root, "c": lambda c: _quadratic(c)[2]},
    wrong=(_toi_form("no_two", "the root is divided by a, not 2a: (-b - √disc) / a is twice the first-contact time",
                     lambda a, b, c, dt: (a, b, c, dt, 1.0)),
           _toi_form("four", "the root is divided by 4a, not 2a: half the first-contact time",
                     lambda a, b, c, dt: (a, b, c, dt, 4.0)),
           _toi_form("a_unsquared", "a = |dv|, not dv·dv = |dv|²", lambda a, b, c, dt: (math.sqrt(a), b, c, dt, 2.0)),
           _toi_form("b_sign", "b = -2 dp·dv (as dp = p1 - p2 or dv = v1 - v2 give): time runs backwards; with dp = "
                     "p2 - p1 and dv = v2 - v1, b = 2 dp·dv", lambda a, b, c, dt: (a, -b, c, dt, 2.0)),
           _toi_form("b_no_two", "b = dp·dv without its factor 2: b = 2 dp·dv", lambda a, b, c, dt: (a, b / 2, c, dt, 2.0)),
           _toi_form("fixed_dt", "t is kept only up to 1/120 s, not up to the dt you are given",
                     lambda a, b, c, dt: (a, b, c, 1 / 120, 2.0), hint="toi_apart")))


def toi_root(a, b, c, dt, under=2.0):
    """circle_toi from its quadratic (s): 0.0 when the circles already overlap (c <= 0), None when a == 0, the
    discriminant is negative or t is outside [0, dt], else t = (-b - √disc) / (under · a); the lesson's: under 2."""
    if c <= 0:
        return 0.0
    disc = b * b - 4 * a * c
    if a == 0 or disc < 0:
        return None
    t = (-b - math.sqrt(disc)) / (under * a)
    return t if 0 <= t <= dt else None


_toi_with = reference(toi_root)   # a known wrong root (_toi_form), in the grader only


def lesson_circle_toi(p1, v1, r1, p2, v2, r2, dt):
    """The lesson's circle_toi (the quadratic's earlier root); a stand-in under time_of_impact()."""
    dp, dv = p2 - p1, v2 - v1
    return toi_root(dv.dot(dv), 2 * dp.dot(dv), dp.dot(dp) - (r1 + r2) ** 2, dt)


reference_circle_toi = reference(lesson_circle_toi)


# ---------------------------------------------------------------- step 3: bounding_radius

def lesson_bounding_radius(points, centre):
    """The lesson's bounding_radius: the farthest corner's distance (px); a stand-in under time_of_impact()."""
    return max(centre.distance_to(p) for p in points)


reference_bounding_radius = reference(lesson_bounding_radius)


def bounding_cases():
    """(name, points, centre)."""
    return [
        ("a 40 x 40 crate", box(40, 40, (380, 540)), Vector2(380, 540)),
        ("a 36 x 100 crate", box(36, 100, (540, 510)), Vector2(540, 510)),
        ("a 50 x 70 crate turned 30°", box(50, 70, (0, 0), 30), Vector2(0, 0)),
        ("a triangle around its circumcentre", ngon(3, 25, (10, -5), 12), Vector2(10, -5)),
        ("an uneven pentagon around its middle", [Vector2(0, 0), Vector2(60, 0), Vector2(70, 30), Vector2(30, 50),
                                                  Vector2(-10, 30)], Vector2(30, 22)),
    ]


def _bounding_cases(module):
    """The fixed outlines and one crate drawn for this run, as dicts."""
    rng = run_rng(module, "bounding_radius")
    centre = Vector2(rng.uniform(100, 700), rng.uniform(100, 500))
    drawn = [("a crate drawn for this run", box(rng.uniform(20, 90), rng.uniform(20, 90), centre, rng.uniform(0, 90)),
              centre)]
    return [{"case": name, "points": [list(p) for p in points], "centre": list(centre)}
            for name, points, centre in bounding_cases() + drawn]


def _distances(c):
    return [Vector2(c["centre"]).distance_to(p) for p in c["points"]]


def _bounding_form(name, text, answer):
    return Form(f"bounding_{name}", text, answer)


def _sticks_out(c):
    """The first line when no wrong radius is named: corners stick out of a radius short of the farthest one."""
    if isinstance(c["got"], float) and c["got"] < c["want"]:
        return "corners stick out of your circle, so bullets aimed at them are skipped"
    return "bounding_radius() is not the farthest corner's distance from the centre"


BOUNDING = Step(
    "bounding_circle", "Step 3: bounding_radius() is the distance from the centre to the farthest point of the "
    "outline.", 3, "bounding_radius", _bounding_cases,
    lambda radius, c: answer_time(radius([Vector2(p) for p in c["points"]], Vector2(c["centre"]))),
    lambda c: reference_bounding_radius([Vector2(p) for p in c["points"]], Vector2(c["centre"])), hint="bounding",
    same=lambda got, want: isinstance(got, float) and close(got, want), unnamed=_sticks_out,
    label=lambda c: f"bounding_radius() for {c['case']}", show=lambda r: "None" if r is None else f"{r:.6g} px",
    wrong=(_bounding_form("squared", "the radius is the squared distance: take its square root",
                          lambda c: max(d * d for d in _distances(c))),
           _bounding_form("from_origin", "the radius is the farthest corner's distance from (0, 0); measure from "
                          "the centre, centre.distance_to(p)", lambda c: max(Vector2(p).length() for p in c["points"])),
           _bounding_form("half_side", "the radius is the largest |x| or |y| offset (half a side), not a distance: a "
                          "corner is farther", lambda c: max(abs(p[k] - c["centre"][k]) for p in c["points"]
                                                             for k in (0, 1))),
           _bounding_form("half_width", "the radius is the largest |x - centre.x| (half the width), not a distance: "
                          "a corner is farther", lambda c: max(abs(p[0] - c["centre"][0]) for p in c["points"])),
           _bounding_form("nearest", "the radius is the nearest corner's distance; the circle must reach the "
                          "farthest (max, not min)", lambda c: min(_distances(c))),
           _bounding_form("average", "the radius is the average distance to the corners; the circle must reach the "
                          "farthest (max)", lambda c: sum(_distances(c)) / len(c["points"]))))



# ---------------------------------------------------------------- step 4: time_of_impact, the broad test

def _bullet(pos, vel, radius=3.0, mass=0.05):
    return Body(Circle(radius), pos, mass, vel=vel, bullet=True)


def _crate(w, h, pos, angle=0.0, mass=None):
    return Body(box_points(w, h), pos, w * h / 1000 if mass is None else mass, angle=math.radians(angle))


def impact_cases(module=None):
    """{"case", "bullet", "other", "dt", "needs_exact": does the bullet reach the bounding circle this step?}."""
    cases = [
        ("a bullet at 12000 px/s hitting a 40 x 40 crate head-on", _bullet((300, 540), (12000, 0)),
         _crate(40, 40, (380, 540)), True),
        ("a bullet at 6000 px/s hitting a turned crate's corner", _bullet((330, 486), (6000, 0)),
         _crate(50, 70, (380, 520), 30), True),
        ("a bullet flying far above a crate", _bullet((300, 300), (12000, 0)), _crate(40, 40, (380, 540)), False),
        ("a bullet too slow to reach a crate this step", _bullet((100, 540), (3000, 0)),
         _crate(40, 40, (380, 540)), False),
        ("a bullet already inside a tall crate's bounding circle, 1 px from its side",
         _bullet((518, 470), (4000, 0)), _crate(36, 100, (540, 510)), True),
        ("a bullet crossing a tall crate's bounding circle 2 px above the crate",
         _bullet((500, 455), (4000, 0)), _crate(36, 100, (540, 510)), True),
        # its centre passes 29.5 px from the centre, 1.2 px outside the 28.3 px bounding circle: only the
        # bullet's own 3 px radius reaches the corner (a broad test without it lets the bullet tunnel)
        ("a bullet at 12000 px/s grazing the top corner of a 40 x 40 crate turned 45°",
         _bullet((300, 540 - 29.5), (12000, 0)), _crate(40, 40, (380, 540), 45), True),
    ]
    drawn = drawn_impact_cases(run_rng(module, "time_of_impact")) if module is not None else []
    return [{"case": name, "bullet": bullet, "other": other, "dt": STEP, "needs_exact": reaches}
            for name, bullet, other, reaches in cases + drawn]


def drawn_impact_cases(rng):
    """Two cases drawn for this run: a bullet that hits a crate this step and one that cannot reach its bounding
    circle (passing beside it, or too slow), so a table of the fixed cases' answers with one default for the rest
    (the exact test, say) is wrong on one of them. The hit comes before 0.8 of the step; the miss keeps 10 px
    clear of the bounding circle."""
    def crate_at():
        w, h = rng.uniform(24, 90), rng.uniform(24, 90)
        return _crate(w, h, (rng.uniform(300, 600), rng.uniform(200, 500)), rng.uniform(0, 90)), math.hypot(w, h) / 2

    cases = []
    while not cases:   # the hit: aimed near the centre from 8-70 % of a step's travel away from the surface
        other, reach = crate_at()
        direction, speed = Vector2(1, 0).rotate(rng.uniform(0, 360)), rng.uniform(3000, 12000)
        start = other.pos - direction * (reach + 3 + rng.uniform(0.08, 0.7) * speed * STEP)
        bullet = _bullet(start + direction.rotate(90) * rng.uniform(-6, 6), direction * speed)
        hit = circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius, other.world_points(), STEP)
        if hit is not None and hit[0] <= 0.8 * STEP:
            cases.append(("a bullet drawn for this run hitting a crate (1 of 2)", bullet, other, True))
    other, reach = crate_at()
    direction, speed = Vector2(1, 0).rotate(rng.uniform(0, 360)), rng.uniform(3000, 12000)
    if rng.random() < 0.5:   # beside the crate: its path 10-60 px clear of the bounding circle
        side = direction.rotate(90) * (reach + 3 + rng.uniform(10, 60))
        start, how = other.pos + side - direction * rng.uniform(0, speed * STEP), "passing beside"
    else:   # towards the crate, 10-60 px short of the bounding circle at the step's end
        start, how = other.pos - direction * (reach + 3 + speed * STEP + rng.uniform(10, 60)), "too slow to reach"
    cases.append((f"a bullet drawn for this run {how} a crate (2 of 2)", _bullet(start, direction * speed), other,
                  False))
    return cases


def _plain_hit(hit):
    if hit is None:
        return None
    try:
        t, normal = hit
        return {"t": real(t), "normal": [float(Vector2(normal).x), float(Vector2(normal).y)]}
    except (TypeError, ValueError):
        return {"bad": _short(hit)}


_EXACT = threading.local()   # .tests: the exact swept tests of the call being probed, per thread (files are
# judged in parallel threads)


def _exact_counted(*args):
    """The library's exact swept test in the handout's place, counted: the broad test must skip it."""
    _EXACT.tests += 1
    return circle_polygon_toi(*args)


def _impact(time_of_impact, c):
    """The student's hit (bodies given as twins of the case's) and how many exact swept tests it ran."""
    _EXACT.tests = 0
    hit = _plain_hit(time_of_impact(twin(c["bullet"]), twin(c["other"]), c["dt"]))
    return {"hit": hit, "exact_tests": _EXACT.tests}


@reference
def reference_impact(c, broad=None):
    """{"hit", "exact_tests"} of the lesson's time_of_impact(): the exact swept test, where any number of exact
    tests (None) is right if the bullet reaches the bounding circle, else none; with broad = (the bullet's radius
    counts, skips(t)), one known wrong broad test (BROAD) with the lesson's circle_toi and bounding_radius first."""
    bullet, other, dt = c["bullet"], c["other"], c["dt"]
    if broad is not None:
        t = reference_circle_toi(bullet.pos, bullet.vel, bullet.radius if broad[0] else 0.0, other.pos, Vector2(),
                                 reference_bounding_radius(other.world_points(), other.pos), dt)
        if broad[1](t):
            return {"hit": None, "exact_tests": 0}
    hit = _plain_hit(circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius, other.world_points(), dt))
    return {"hit": hit, "exact_tests": 1 if broad else None if c["needs_exact"] else 0}


BROAD = {   # step 4's known wrong broad tests: name -> (sentence, the bullet's radius counts, when it returns None)
    "zero_is_falsy": ("the broad test counts t = 0.0 as no contact (`if not t`): return None only when circle_toi() "
                      "gives None", True, lambda t: not t),
    "inverted": ("the broad test is the wrong way round: it returns None when circle_toi() DOES reach the bounding "
                 "circle", True, lambda t: t is not None),
    "point_bullet": ("the broad test treats the bullet as a point (radius 0): give circle_toi() bullet.radius", False,
                     lambda t: t is None),
}


def same_hit(got, want):
    """Both None, or the same time (1e-7) and normal."""
    if want is None:
        return got is None
    return isinstance(got, dict) and "t" in got and close(got["t"], want["t"]) and same_point(got["normal"],
                                                                                             want["normal"])


def hit_text(hit):
    if hit is None:
        return "None (no hit)"
    return hit["bad"] if "bad" in hit else f"t = {hit['t']:.6g} s, normal {vec_text(hit['normal'])}"


def _broad_evidence(c):
    got, want = c["got"], c["want"]
    if same_hit(got["hit"], want["hit"]):
        return f"for {c['case']}, the answer is right but the exact swept test ran {got['exact_tests']} time(s)."
    return f"for {c['case']}, time_of_impact() returned {hit_text(got['hit'])}; expected {hit_text(want['hit'])}."


def _gave_up(c):
    """The first line when no wrong broad test is named."""
    if c["want"]["hit"] is not None and c["got"]["hit"] is None and c["got"]["exact_tests"] == 0:
        return "the broad test gave up on a crate the bullet does hit"
    return "time_of_impact() does not find the lesson's hit"


BROAD_MISSING = Form("broad_missing", "the broad test should have returned None first: the bullet cannot reach "
                     "the bounding circle", hint="broad_missing")

BROAD_TEST = Step(
    "broad_test", "Step 4: time_of_impact() skips a crate whose bounding circle the bullet cannot reach, and finds "
    "every hit.", 4, "time_of_impact", impact_cases, _impact, reference_impact, hint="broad",
    same=lambda got, want: same_hit(got["hit"], want["hit"]) and want["exact_tests"] in (None, got["exact_tests"]),
    stand_ins=lambda module: {"circle_toi": lesson_circle_toi, "bounding_radius": lesson_bounding_radius,
                              "circle_polygon_toi": _exact_counted},
    diagnose=lambda cases, c: BROAD_MISSING if same_hit(c["got"]["hit"], c["want"]["hit"]) else None,
    evidence=_broad_evidence, unnamed=_gave_up,
    passed="the broad test skips the crates out of reach and keeps every hit in all {n} cases",
    wrong=tuple(Form(f"broad_{name}", text, lambda c, broad=(radius, skips): reference_impact(c, broad))
                for name, (text, radius, skips) in BROAD.items()))


# ---------------------------------------------------------------- step 5: swept_move

def lesson_time_of_impact(bullet, other, dt):
    """The lesson's time_of_impact (no broad test); a stand-in under swept_move()."""
    if other.shape.kind == "circle":
        t = lesson_circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(), other.radius, dt)
        return None if t is None else (t, (other.pos - bullet.pos - bullet.vel * t).normalize())
    return circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius, other.world_points(), dt)


def swept_cases(module):
    """{"case", "make": a function making a fresh (world, bullet)} for one swept move of 1/120 s each."""
    wall_x = float(getattr(module, "WALL_X", 640.0))

    def maker(other, pos, vel, effects=("ccd", "restitution"), at=(380, 300)):
        def make():   # the bullet against the lab's wall, a free 40 x 40 crate (at `at`) or nothing
            bullet = _bullet(pos, vel)
            first = [] if other is None else [module.make_wall() if other == "wall" else _crate(40, 40, at)]
            return module.BulletWorld(first + [bullet], effects=set(effects), substeps=1), bullet
        return make

    # drawn for this run, each kind of swept move: a bullet hitting a free crate (from 30 px plus 10-70 % of a
    # step's travel before its centre, off-centre and at a slant, up to 8 px and 20°), and one with nothing in its way
    rng = run_rng(module, "swept_move")
    speed, turn, off = rng.uniform(4000, 12000), rng.uniform(-20, 20), rng.uniform(-8, 8)
    crate_at = Vector2(rng.uniform(300, 600), rng.uniform(150, 450))
    heading = Vector2(1, 0).rotate(turn)
    start = crate_at + heading.rotate(90) * off - heading * (30 + rng.uniform(0.1, 0.7) * speed * STEP)
    drawn = (("a bullet drawn for this run striking a free crate (1 of 2)", "crate", tuple(start),
              tuple(heading * speed), ("ccd", "restitution", "friction", "rotation"), tuple(crate_at)),
             ("a bullet drawn for this run with nothing in its way (2 of 2)", None,
              (rng.uniform(50, 700), rng.uniform(50, 500)), tuple(Vector2(rng.uniform(3000, 12000), 0).rotate(
                  rng.uniform(0, 360))), ("ccd",)))
    return [{"case": name, "make": maker(*how)} for name, *how in (
        ("a bullet at 12000 px/s hitting the wall 60 px ahead", "wall", (wall_x - 60, 240.0), (12000.0, 0.0)),
        ("a bullet at 9000 px/s hitting the wall at a slant", "wall", (wall_x - 60, 200.0), (9000.0, 3000.0)),
        ("a bullet at 9000 px/s hitting a free crate head-on", "crate", (300, 300), (9000, 0)),
        # off-centre and at a slant, with friction and spin: the contact point's lever arm counts
        ("a bullet at 9000 px/s striking a free crate 10 px off-centre at a slant (friction, spin)", "crate",
         (300, 290), (9000, 3000), ("ccd", "restitution", "friction", "rotation")),
        ("a bullet with nothing in its way", None, (100, 100), (5000, 700), ("ccd",))) + drawn]


def _state(body):
    return {"pos": [body.pos.x, body.pos.y], "vel": [body.vel.x, body.vel.y], "omega": body.omega}


def _outcome(world, bullet):
    return {"bullet": _state(bullet), "others": [_state(b) for b in world.bodies if b is not bullet]}


def _swept(swept_move, c):
    """The outcome of one swept_move() of 1/120 s in a fresh world of the case's."""
    world, bullet = c["make"]()
    swept_move(world, bullet, STEP)
    return _outcome(world, bullet)


@reference
def first_hit(world, bullet):
    """(t, normal, other) of the bullet's first impact this step by the lesson's time_of_impact, or None."""
    return min((h + (o,) for o in world.bodies if o is not bullet
                for h in [lesson_time_of_impact(bullet, o, STEP)] if h is not None),
               key=lambda h: h[0], default=None)


@reference
def reference_swept(c, name=None):
    """The outcome of one lesson's swept move in a fresh world from c["make"](), or with the usual mistake `name`
    (SWEPT; without a hit every mistake moves the bullet as the lesson does)."""
    world, bullet = c["make"]()
    hit = first_hit(world, bullet)
    if hit is None:
        bullet.pos += bullet.vel * STEP
        return _outcome(world, bullet)
    t, normal, other = hit
    start, velocity = Vector2(bullet.pos), Vector2(bullet.vel)
    bullet.pos += velocity * {"resolve_first": 0.0, "move_then_resolve": STEP}.get(name, t)   # to the impact
    if name != "no_impulse":   # the contact on the bullet's surface towards the other body
        side = -1 if name == "far_side" else 0 if name == "at_centre" else 1
        world.resolve(bullet, other, normal, bullet.pos + normal * (side * bullet.radius))
    if name == "old_velocity":
        bullet.pos = start + velocity * STEP
    elif name in ("whole_step", "resolve_first"):
        bullet.pos += bullet.vel * STEP
    elif name not in ("stops", "move_then_resolve"):
        bullet.pos += bullet.vel * (STEP - t)   # the rest of the step with the new velocity
    return _outcome(world, bullet)


SWEPT = {   # the usual step-5 mistakes (issue 40 added at_centre and move_then_resolve)
    "stops": "the bullet stopped at the impact: the rest of the step (dt - t) was not spent",
    "old_velocity": "the bullet was resolved at the impact but spent the step with its velocity from before the hit "
                    "(it went on through)",
    "no_impulse": "nothing changed at the impact: resolve() was not called there, or was given the normal "
                  "reversed (-normal) and saw the bodies moving apart",
    "whole_step": "after the impact the bullet moved a whole dt more instead of the rest, dt - t",
    "far_side": "the impulse was applied on the far side of the bullet; the contact is on its surface towards "
                "the crate, bullet.pos + normal * radius",
    "resolve_first": "the hit was resolved where the bullet starts the step, then it moved the whole dt: it turned "
                     "back before it reached the impact",
    "at_centre": "the hit was resolved at the bullet's centre; the contact is on its surface, bullet.pos + "
                 "normal * radius",
    "move_then_resolve": "the bullet moved the whole step, then resolved: move it to the impact first, resolve "
                         "there, then spend dt - t",
}


def same_outcome(got, want):
    """The bullet's position and velocity and every other body's position, velocity and spin agree."""
    return same_point(got["bullet"]["pos"], want["bullet"]["pos"]) and \
        same_point(got["bullet"]["vel"], want["bullet"]["vel"]) and len(got["others"]) == len(want["others"]) and \
        all(same_point(g["vel"], w["vel"]) and same_point(g["pos"], w["pos"]) and close(g["omega"], w["omega"])
            for g, w in zip(got["others"], want["others"]))


def _swept_evidence(c):
    """A crate's spin when the bullet ends where the lesson's does, else the bullet's velocity, else its place."""
    got, want = c["got"], c["want"]
    where = f"in '{c['case']}'" + (f" (impact at {c['t'] * 1000:.3f} ms)" if c["t"] is not None else "")
    spins = [(g["omega"], w["omega"]) for g, w in zip(got["others"], want["others"]) if not close(g["omega"],
                                                                                                w["omega"])]
    if spins and same_point(got["bullet"]["pos"], want["bullet"]["pos"]):
        return f"{where}, the crate spins at {spins[0][0]:.3f} rad/s; expected {spins[0][1]:.3f}."
    if not same_point(got["bullet"]["vel"], want["bullet"]["vel"]):   # the velocity says most: show it
        return f"{where}, the bullet leaves at {vec_text(got['bullet']['vel'])} px/s; expected " \
               f"{vec_text(want['bullet']['vel'])}."
    return f"{where}, the bullet ends at {vec_text(got['bullet']['pos'])}; expected {vec_text(want['bullet']['pos'])}."


SWEPT_MOVE = Step(
    "swept_move_resolves", "Step 5: swept_move() moves a bullet to its time of impact, resolves there and spends the "
    "rest of the step.", 5, "swept_move", swept_cases, _swept, reference_swept, hint="swept", same=same_outcome,
    stand_ins=lambda module: {"time_of_impact": lesson_time_of_impact}, evidence=_swept_evidence,
    extra={"t": lambda c: (first_hit(*c["make"]()) or (None,))[0]},
    unnamed="after swept_move() the bullet or the crate is not where the lesson's is",
    passed="the swept move matches the lesson in all {n} cases",
    wrong=tuple(Form(f"swept_{name}", text, lambda c, name=name: reference_swept(c, name))
                for name, text in SWEPT.items()))


# ---------------------------------------------------------------- criteria 1 and 2: the shots

def shoot(module, mode, speed, shots, phase=0.5):
    """`shots` bullets fired one at a time at the lab's wall in its BulletWorld set to `mode`: (tunnelled, physics
    seconds spent). Each starts 1 px plus 1 + (k + phase)/shots steps' travel short of the wall, at its mid-height,
    along +x, with no gravity (nothing takes a shot over the 400 px wall); it tunnels if its centre ends past the
    wall's."""
    wall_x = float(module.WALL_X)
    half = float(module.WALL_WIDTH) / 2
    radius = float(module.BULLET_RADIUS)
    travel = speed * STEP
    steps = 3 + math.ceil((2 * radius + 2 * half + 2) / travel)
    tunnelled, spent = 0, 0.0
    for k in range(shots):
        start_x = wall_x - half - radius - 1 - travel * (1 + (k + phase) / shots)
        wall = module.make_wall()
        bullet = module.make_bullet((start_x, (wall.pos.y)), (speed, 0))
        world = module.BulletWorld([wall, bullet], effects={"restitution", "correction"})
        module.apply_mode(world, mode)
        begin = clock(module)
        for _ in range(steps):
            world.step()
        spent += clock(module) - begin
        tunnelled += bullet.pos.x > wall_x
    return tunnelled, spent


def probe_shots(module, lab_path):
    """Criterion 1: the shots tunnelled with CCD at each speed; criterion 2: those with sub-steps x8 at 12000 px/s."""
    # the CCD shots' starts lie at a drawn place in their slots of a step's travel; the x8 shots' stay mid-slot, where
    # the lesson's sub-steps are known to let some through (a drawn place might put every start outside that window)
    phase = run_rng(module, "shots").uniform(0.05, 0.95)
    ccd = {str(speed): shoot(module, "ccd", speed, SHOTS_PER_SPEED, phase)[0] for speed in SHOT_SPEEDS}
    return {"ccd": ccd, "per_speed": SHOTS_PER_SPEED, "x8": shoot(module, "x8", FAST, SUBSTEP_SHOTS)[0]}


# ---------------------------------------------------------------- criterion 4: momentum into a crate

def probe_crate_hit(module, lab_path):
    """A bullet at 7000-11000 px/s (drawn per run) hits a free 40 x 40 crate (mass 1.6) through its centre from 50-80
    px before its face (drawn), with CCD, no gravity, for 3 steps of 1/120 s; with e = 0.2 (both bodies' default)
    the lesson's crate leaves at (1 + e) m v / (m + M)."""
    rng = run_rng(module, "crate_hit")
    speed, y = rng.uniform(7000, 11000), rng.uniform(200, 400)
    bullet = module.make_bullet((360 - rng.uniform(50, 80), y), (speed, 0))
    crate = _crate(40, 40, (380, y))
    given = (twin(bullet), twin(crate))   # the masses and restitutions as the world got them
    world = module.BulletWorld([crate, bullet], effects={"ccd", "restitution"})
    module.apply_mode(world, "ccd")
    for _ in range(3):
        world.step()
    out = {"got": [crate.vel.x * given[1].mass, crate.vel.y * given[1].mass], "bullet_x": bullet.pos.x,
           "crate_x": crate.pos.x}
    if judging(module):
        out.update(_crate_hit_reference(*given, speed))
    return out


@reference
def _crate_hit_reference(bullet, crate, v):
    """The crate's momentum after a central hit, M (1 + e) m v / (m + M), the bullet's m v and e."""
    m, mass = bullet.mass, crate.mass
    e = min(bullet.restitution, crate.restitution)
    return {"want": mass * (1 + e) * m * v / (m + mass), "bullet_momentum": m * v, "e": e}


# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("circle_toi", "bounding_radius", "time_of_impact")

# probe name -> (the lab function it needs, the probe)
STEPS = (TOI, BOUNDING, BROAD_TEST, SWEPT_MOVE)
PROBES = {**TOI.probes(), **BOUNDING.probes(), **BROAD_TEST.probes(), **SWEPT_MOVE.probes(),
          "shots": ("swept_move", probe_shots), "crate_hit": ("swept_move", probe_crate_hit)}
