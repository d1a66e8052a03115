"""Probes of a Bullets file's own functions, run inside the checker's child process.

Each probe calls the student's functions and returns plain data: the
student's answer beside the analytic one (checker/labs/bullets/checks.py compares them
and names the first case that differs). The analytic answers are added in the grader
only (`judging`, checker/judging/probe_kit.py); the lesson's functions that stand in for the
student's other steps (lesson_circle_toi, ...) run in the child too, as the student's code calls them.

    circle_toi      (step 2) head-on, glancing, both moving, already touching, moving apart,
                    parallel paths, missing, too far for this step; the analytic answer is the
                    geometric one (closest approach, then back along the path), not the quadratic
    bounding_radius (step 3) boxes, turned boxes and a triangle around their centres
    time_of_impact  (step 4) crates hit, missed, grazed at a corner, a bullet already inside the
                    bounding circle; the lesson's circle_toi and bounding_radius stand in for the
                    student's, and the exact swept test is counted (the broad test must skip it);
                    beside the answer, what each known wrong broad test gives (BROAD_MISTAKES)
    swept_move      (step 5) one swept move against a wall, a crate and nothing, with the
                    lesson's time_of_impact standing in for the student's
    shots           (criteria 1 and 2) the lab's own BulletWorld with its wall: >= 100 shots
                    at 3000-12000 px/s with CCD, and shots at 12000 px/s with sub-steps x8
    crate_hit       (criterion 4) a bullet hits a free crate with CCD: the crate's momentum

Units: px, s, mass in the lab's units (area / 1000).
"""
import math

from pygame import Vector2

from lesson11.physics2d import Body, Circle, box_points, circle_polygon_toi

from checker.judging.common import close, real, value_text
from checker.judging.declared import Form, Step
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
    """A returned time as a float, None, or {"bad": what it is}."""
    if value is None:
        return None
    if isinstance(value, bool):
        return {"bad": repr(value)}
    try:
        t = real(value)
    except (TypeError, ValueError):
        return {"bad": _short(value)}
    return t if math.isfinite(t) else {"bad": f"a number that is not finite: {t!r}"}


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
    """`count` cases drawn for this run: a circle heading for another, hitting within the step or passing by."""
    cases = []
    for k in range(count):
        r1, r2 = rng.uniform(2, 8), rng.uniform(5, 20)
        p1 = Vector2(rng.uniform(-50, 50), rng.uniform(-50, 50))
        direction = Vector2(1, 0).rotate(rng.uniform(0, 360))
        gap = rng.uniform(20, 150)                 # px between the surfaces along the path
        aim = rng.choice((rng.uniform(0, 0.7), rng.uniform(1.3, 2.0))) * (r1 + r2)   # miss distance: hit or pass
        p2 = p1 + direction * (gap + r1 + r2) + direction.rotate(90) * aim
        speed = rng.uniform(300, 3000)
        dt = (gap + r1 + r2) / speed * rng.uniform(1.3, 3.0)
        cases.append((f"a path drawn for this run ({k + 1} of {count})", p1, direction * speed, r1, p2,
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


@reference
def _toi_with(a, b, c, dt, under):
    """The lesson's circle_toi with a known wrong root, (-b - √disc) / (under · a), and the lesson's filters (s)."""
    if c <= 0:
        return 0.0
    disc = b * b - 4 * a * c
    if a == 0 or disc < 0:
        return None
    t = (-b - math.sqrt(disc)) / (under * a)
    return t if 0 <= t <= dt else None


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


def _sticks_out(cases, c):
    """A named wrong radius, else "corners stick out" for a radius short of the farthest corner."""
    named = BOUNDING.named(cases, c)
    if named is None and isinstance(c["got"], float) and c["got"] < c["want"]:
        return Form(None, "corners stick out of your circle, so bullets aimed at them are skipped")
    return named


BOUNDING = Step(
    "bounding_circle", "Step 3: bounding_radius() is the distance from the centre to the farthest point of the "
    "outline.", 3, "bounding_radius", _bounding_cases,
    lambda radius, c: answer_time(radius([Vector2(p) for p in c["points"]], Vector2(c["centre"]))),
    lambda c: reference_bounding_radius([Vector2(p) for p in c["points"]], Vector2(c["centre"])), hint="bounding",
    same=lambda got, want: isinstance(got, float) and close(got, want), diagnose=_sticks_out,
    label=lambda c: f"bounding_radius() for {c['case']}", show=lambda r: "None" if r is None else f"{r:.6g} px",
    unnamed="bounding_radius() is not the farthest corner's distance from the centre",
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


# ---------------------------------------------------------------- step 4: time_of_impact

def lesson_circle_toi(p1, v1, r1, p2, v2, r2, dt):
    """The lesson's circle_toi (the quadratic's earlier root); a stand-in under time_of_impact()."""
    dp, dv = p2 - p1, v2 - v1
    c = dp.dot(dp) - (r1 + r2) ** 2
    if c <= 0:
        return 0.0
    a, b = dv.dot(dv), 2 * dp.dot(dv)
    disc = b * b - 4 * a * c
    if a == 0 or disc < 0:
        return None
    t = (-b - math.sqrt(disc)) / (2 * a)
    return t if 0 <= t <= dt else None


reference_circle_toi = reference(lesson_circle_toi)


def _bullet(pos, vel, radius=3.0, mass=0.05):
    return Body(Circle(radius), pos, mass, vel=vel, bullet=True)


def _crate(w, h, pos, angle=0.0, mass=None):
    return Body(box_points(w, h), pos, w * h / 1000 if mass is None else mass, angle=math.radians(angle))


def impact_cases():
    """(name, bullet, other body, dt, does the bullet reach the bounding circle this step?)."""
    return [
        ("a bullet at 12000 px/s hitting a 40 x 40 crate head-on", _bullet((300, 540), (12000, 0)),
         _crate(40, 40, (380, 540)), STEP, True),
        ("a bullet at 6000 px/s hitting a turned crate's corner", _bullet((330, 486), (6000, 0)),
         _crate(50, 70, (380, 520), 30), STEP, True),
        ("a bullet flying far above a crate", _bullet((300, 300), (12000, 0)), _crate(40, 40, (380, 540)), STEP, False),
        ("a bullet too slow to reach a crate this step", _bullet((100, 540), (3000, 0)),
         _crate(40, 40, (380, 540)), STEP, False),
        ("a bullet already inside a tall crate's bounding circle, 1 px from its side",
         _bullet((518, 470), (4000, 0)), _crate(36, 100, (540, 510)), STEP, True),
        ("a bullet crossing a tall crate's bounding circle 2 px above the crate",
         _bullet((500, 455), (4000, 0)), _crate(36, 100, (540, 510)), STEP, True),
        # its centre passes 29.5 px from the centre, 1.2 px outside the 28.3 px bounding circle: only the
        # bullet's own 3 px radius reaches the corner (a broad test without it lets the bullet tunnel)
        ("a bullet at 12000 px/s grazing the top corner of a 40 x 40 crate turned 45°",
         _bullet((300, 540 - 29.5), (12000, 0)), _crate(40, 40, (380, 540), 45), STEP, True),
    ]


def _plain_hit(hit):
    if hit is None:
        return None
    try:
        t, normal = hit
        return {"t": real(t), "normal": [float(Vector2(normal).x), float(Vector2(normal).y)]}
    except (TypeError, ValueError):
        return {"bad": _short(hit)}


def probe_impact(module, lab_path):
    """time_of_impact() with the lesson's circle_toi and bounding_radius; counts the exact swept tests."""
    own = module.circle_toi, module.bounding_radius, getattr(module, "circle_polygon_toi", None)
    calls = [0]

    def counted(*args):
        calls[0] += 1
        return circle_polygon_toi(*args)

    module.circle_toi, module.bounding_radius = lesson_circle_toi, lesson_bounding_radius
    module.circle_polygon_toi = counted
    try:
        cases = []
        for name, bullet, other, dt, exact in impact_cases():
            calls[0] = 0
            given = (twin(bullet), twin(other))   # the bodies as time_of_impact() gets them
            got = module.time_of_impact(bullet, other, dt)
            cases.append({"case": name, "got": _plain_hit(got), "exact_tests": calls[0], "needs_exact": exact})
            if judging(module):
                cases[-1]["want"] = _plain_hit(reference_impact(*given, dt))
                cases[-1]["forms"] = _broad_forms_reference(*given, dt)
        return cases
    finally:
        module.circle_toi, module.bounding_radius = own[0], own[1]
        if own[2] is not None:
            module.circle_polygon_toi = own[2]


# step 4's known wrong broad tests: name -> (the bullet's radius in the broad test, when it returns None)
BROAD_MISTAKES = {
    "zero_is_falsy": (True, lambda t: not t),           # `if not circle_toi(...)`: 0.0 (inside) counts as a miss
    "inverted": (True, lambda t: t is not None),        # returns None when the bounding circle IS reached
    "point_bullet": (False, lambda t: t is None),       # the bullet as a point, radius 0
}


@reference
def _broad_forms_reference(bullet, other, dt):
    """{name: {"hit": the answer, "exact_tests": 0 or 1}} of time_of_impact() with each known wrong broad test
    (BROAD_MISTAKES), the lesson's circle_toi, bounding_radius and exact swept test around it."""
    points = other.world_points()
    forms = {}
    for name, (with_radius, skips) in BROAD_MISTAKES.items():
        t = reference_circle_toi(bullet.pos, bullet.vel, bullet.radius if with_radius else 0.0, other.pos, Vector2(),
                                 reference_bounding_radius(points, other.pos), dt)
        forms[name] = ({"hit": None, "exact_tests": 0} if skips(t) else
                       {"hit": _plain_hit(reference_impact(bullet, other, dt)), "exact_tests": 1})
    return forms


# ---------------------------------------------------------------- step 5: swept_move

@reference
def reference_impact(bullet, other, dt):
    """The exact swept test of a bullet against a polygon: (t, normal) or None."""
    return circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius, other.world_points(), dt)


def lesson_time_of_impact(bullet, other, dt):
    """The lesson's time_of_impact (no broad test); a stand-in under swept_move()."""
    if other.shape.kind == "circle":
        t = lesson_circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(), other.radius, dt)
        return None if t is None else (t, (other.pos - bullet.pos - bullet.vel * t).normalize())
    return circle_polygon_toi(bullet.pos, bullet.vel, bullet.radius, other.world_points(), dt)


@reference
def reference_swept_move(world, bullet, dt):
    first = None
    for other in world.bodies:
        if other is bullet:
            continue
        hit = lesson_time_of_impact(bullet, other, dt)
        if hit is not None and (first is None or hit[0] < first[0]):
            first = (hit[0], hit[1], other)
    if first is None:
        bullet.pos += bullet.vel * dt
        return
    t, normal, other = first
    bullet.pos += bullet.vel * t
    world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
    bullet.pos += bullet.vel * (dt - t)


def swept_cases(module):
    """(name, a function making (world, bullet)) for one swept move of 1/120 s each."""
    wall_x = float(getattr(module, "WALL_X", 640.0))

    def wall_world(speed, y=240.0, vy=0.0):
        def make():
            wall = module.make_wall()
            bullet = _bullet((wall_x - 60, y), (speed, vy))
            return module.BulletWorld([wall, bullet], effects={"ccd", "restitution"}, substeps=1), bullet
        return make

    def crate_world():
        crate = _crate(40, 40, (380, 300))
        bullet = _bullet((300, 300), (9000, 0))
        return module.BulletWorld([crate, bullet], effects={"ccd", "restitution"}, substeps=1), bullet

    def slanted():   # off-centre and at a slant, with friction and spin: the contact point's lever arm counts
        crate = _crate(40, 40, (380, 300))
        bullet = _bullet((300, 290), (9000, 3000))
        return module.BulletWorld([crate, bullet], effects={"ccd", "restitution", "friction", "rotation"},
                                  substeps=1), bullet

    def nothing():
        bullet = _bullet((100, 100), (5000, 700))
        return module.BulletWorld([bullet], effects={"ccd"}, substeps=1), bullet

    return [("a bullet at 12000 px/s hitting the wall 60 px ahead", wall_world(12000.0)),
            ("a bullet at 9000 px/s hitting the wall at a slant", wall_world(9000.0, 200.0, 3000.0)),
            ("a bullet at 9000 px/s hitting a free crate head-on", crate_world),
            ("a bullet at 9000 px/s striking a free crate 10 px off-centre at a slant (friction, spin)", slanted),
            ("a bullet with nothing in its way", nothing)]


def _state(body):
    return {"pos": [body.pos.x, body.pos.y], "vel": [body.vel.x, body.vel.y], "omega": body.omega}


@reference
def first_hit(world, bullet):
    """(t, normal, other) of the bullet's first impact this step by the lesson's time_of_impact, or None."""
    return min((h + (o,) for o in world.bodies if o is not bullet
                for h in [lesson_time_of_impact(bullet, o, STEP)] if h is not None),
               key=lambda h: h[0], default=None)


def probe_swept(module, lab_path):
    """One swept_move() of 1/120 s per case with the lesson's time_of_impact, beside the lesson's swept move.

    Also the outcome of each usual mistake (SWEPT_MISTAKES), for the message.
    """
    own = module.time_of_impact
    module.time_of_impact = lesson_time_of_impact
    try:
        cases = []
        for name, make in swept_cases(module):
            world, bullet = make()
            module.swept_move(world, bullet, STEP)
            others = [_state(b) for b in world.bodies if b is not bullet]
            cases.append({"case": name, "got": {"bullet": _state(bullet), "others": others}})
            if judging(module):
                cases[-1].update(_swept_reference(make))
        return cases
    finally:
        module.time_of_impact = own


@reference
def _swept_reference(make):
    """The lesson's swept move in a fresh world from make(), and the outcome of each usual mistake (SWEPT_MISTAKES).

    An outcome is {"bullet": state, "others": [state, ...]}: a mistake is named only when the whole
    outcome is its own, so two mistakes that leave the bullet at the same place are told apart by
    its velocity or the crate's.
    """
    world, bullet = make()
    reference_swept_move(world, bullet, STEP)
    want = _outcome(world, bullet)
    world, bullet = make()
    hit = first_hit(world, bullet)
    if hit is None:
        return {"want": want, "variants": {}, "t": None}
    return {"want": want, "t": hit[0], "variants": {name: _swept_mistake(make, name) for name in SWEPT_MISTAKES}}


def _outcome(world, bullet):
    return {"bullet": _state(bullet), "others": [_state(b) for b in world.bodies if b is not bullet]}


# the usual step-5 mistakes: "stops" (the rest of the step not spent), "old_velocity" (the rest spent with the
# velocity from before the hit), "whole_step" (a whole dt after the impact), "no_impulse" (nothing changes at the
# impact: no resolve(), or one given the normal reversed, which sees the bodies separating), "far_side" (the
# contact point on the bullet's far side, pos - normal r), "resolve_first" (resolved where the step starts, at
# pos + normal r there, then moved the whole dt with the new velocity)
SWEPT_MISTAKES = ("stops", "old_velocity", "whole_step", "no_impulse", "far_side", "resolve_first", "at_centre",
                  "move_then_resolve")   # issue 40: the contact at the bullet's centre; the whole dt, then resolve


@reference
def _swept_mistake(make, name):
    """The outcome of one step of the swept move with the mistake `name`, in a fresh world from make()."""
    world, bullet = make()
    t, normal, other = first_hit(world, bullet)
    if name == "resolve_first":
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        bullet.pos += bullet.vel * STEP
        return _outcome(world, bullet)
    if name == "move_then_resolve":
        bullet.pos += bullet.vel * STEP
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        return _outcome(world, bullet)
    start, velocity = Vector2(bullet.pos), Vector2(bullet.vel)
    bullet.pos += velocity * t
    if name != "no_impulse":
        side = -1 if name == "far_side" else 0 if name == "at_centre" else 1
        world.resolve(bullet, other, normal, bullet.pos + normal * (side * bullet.radius))
    if name == "old_velocity":
        bullet.pos = start + velocity * STEP
    elif name == "whole_step":
        bullet.pos += bullet.vel * STEP
    elif name != "stops":
        bullet.pos += bullet.vel * (STEP - t)
    return _outcome(world, bullet)


# ---------------------------------------------------------------- criteria 1 and 2: the shots

def shoot(module, mode, speed, shots):
    """`shots` bullets fired one at a time at the lab's wall in its BulletWorld set to `mode`.

    Each starts 1 px plus 1 + k/shots steps' travel short of touching the wall,
    at the wall's mid-height, flying along +x, with no gravity (the wall is
    400 px tall: gravity cannot take a shot over it in 3 steps). A shot
    tunnels when the bullet's centre ends past the wall's centre line.
    Returns (tunnelled, physics seconds spent).
    """
    wall_x = float(module.WALL_X)
    half = float(module.WALL_WIDTH) / 2
    radius = float(module.BULLET_RADIUS)
    travel = speed * STEP
    steps = 3 + math.ceil((2 * radius + 2 * half + 2) / travel)
    tunnelled, spent = 0, 0.0
    for k in range(shots):
        start_x = wall_x - half - radius - 1 - travel * (1 + (k + 0.5) / shots)
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
    """Criterion 1: shots with CCD at every speed; criterion 2: shots at 12000 px/s with sub-steps x8 (and x1)."""
    ccd = {}
    cost = {}
    for speed in SHOT_SPEEDS:
        ccd[str(speed)], cost[f"ccd {speed}"] = shoot(module, "ccd", speed, SHOTS_PER_SPEED)
    x8, cost["x8"] = shoot(module, "x8", FAST, SUBSTEP_SHOTS)
    return {"ccd": ccd, "per_speed": SHOTS_PER_SPEED, "x8": x8, "x8_shots": SUBSTEP_SHOTS,
            "ccd_seconds": sum(v for k, v in cost.items() if k.startswith("ccd")), "x8_seconds": cost["x8"],
            "wall": float(module.WALL_WIDTH), "radius": float(module.BULLET_RADIUS)}


# ---------------------------------------------------------------- criterion 4: momentum into a crate

def probe_crate_hit(module, lab_path):
    """A bullet at 9000 px/s hits a free 40 x 40 crate (mass 1.6) through its centre, with CCD, no gravity.

    The lesson's answer for a central impact with restitution e = 0.2 (both
    bodies' default): the crate leaves at (1 + e) m v / (m + M), so its momentum
    is M (1 + e) m v / (m + M). The world runs 3 steps of 1/120 s.
    """
    bullet = module.make_bullet((300, 300), (9000, 0))
    crate = _crate(40, 40, (380, 300))
    given = (twin(bullet), twin(crate))   # the masses and restitutions as the world got them
    world = module.BulletWorld([crate, bullet], effects={"ccd", "restitution"})
    module.apply_mode(world, "ccd")
    for _ in range(3):
        world.step()
    out = {"got": [crate.vel.x * given[1].mass, crate.vel.y * given[1].mass], "bullet_x": bullet.pos.x,
           "crate_x": crate.pos.x}
    if judging(module):
        out.update(_crate_hit_reference(*given, 9000.0))
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
PROBES = {
    **TOI.probes(),
    **BOUNDING.probes(),
    "time_of_impact": ("time_of_impact", probe_impact),
    "swept_move": ("swept_move", probe_swept),
    "shots": ("swept_move", probe_shots),
    "crate_hit": ("swept_move", probe_crate_hit),
}
