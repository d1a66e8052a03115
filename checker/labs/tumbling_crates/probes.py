"""Probes of a Tumbling Crates file's own functions, run in the checker's child process: each calls one of the
student's functions on configurations that together exercise every term of the lesson's formulas and records
plain data. The lesson's answers and the known wrong forms' are added in the grader only (`judging`, a
@reference: checker/judging/probe_kit.py), from the inputs as they were before the student's function got them;
checks.py's declared steps compare and name.

    sat            (steps 2, 3) lesson pairs, turned boxes, a pentagon, a hexagon, a deep hit, exact touching, far
                   apart, each also with A and B swapped; beside the lesson's answer, what step 2's known wrong
                   loops (SAT_LOOPS) and step 3's known wrong flips give
    apply_impulse  (step 6) both bodies moving, A static, B static; masses and inertias far from 1, off-centre
                   points, spinning bodies
    resolve        (steps 4, 5) the same kinds of pairs, sliding both ways, the Coulomb clamp active and not,
                   impacts above and below the 30 px/s resting cutoff; resolve() runs with the library's
                   apply_impulse, recording each impulse, so steps 4 and 5 are graded before step 6 is written;
                   and two contacts drawn per run, one with friction clamped, one not

Units: px, s, rad, mass in the lab's units (area / 1000).
"""
import math

from pygame import Vector2

from lesson11.physics2d import Body, box_points, centre_of, cross, edge_normals, relative_velocity  # noqa: F401
from lesson11.physics2d import project
from lesson11.physics2d import apply_impulse as lesson_apply_impulse

from checker.judging.probe_kit import (_plain, drawn_sat_pairs, judging, reference, reference_sat, sat_answer,
                                       sat_pairs, twin)
from checker.judging.probe_kit import changed_vectors, stop_over_bound, with_reference_steps
from checker.judging.probe_kit import axis_overlaps, box, ngon   # noqa: F401 (the checks and the corpora read them here)
from checker.judging.tape import run_rng

REQUIRED = ("sat", "apply_impulse", "resolve", "main")
RESTING_SPEED = 30.0   # px/s, the handout's cutoff below which e = 0


def probe_sat(module, lab_path):
    """The student's sat() on every pair, both orders, beside the lesson's answer and the shorter-way-out one."""
    return _sat_cases(module, module.sat, drawn_sat_pairs(run_rng(module, "sat")))


def probe_sat_step2(module, lab_path):
    """As probe_sat, with the solution's step 3 spliced into the student's sat(): step 2 graded on its own.

    None when the step markers cannot be found (the checks then use probe_sat's cases).
    """
    spliced = with_reference_steps(module, lab_path, "sat", (3,))
    return _sat_cases(module, spliced, drawn_sat_pairs(run_rng(module, "sat"))) if spliced else None


def _sat_cases(module, sat, drawn=()):
    cases = []
    for name, pa, pb in sat_pairs() + list(drawn):
        for order, first, second in (("A, B", pa, pb), ("B, A", pb, pa)):
            got = sat([Vector2(p) for p in first], [Vector2(p) for p in second])
            case = {"pair": name, "order": order,
                    "a": [[p.x, p.y] for p in first], "b": [[p.x, p.y] for p in second],
                    "centre_a": list(centre_of(first)), "centre_b": list(centre_of(second)),
                    "got": sat_answer(got)}
            if judging(module):   # the lesson's answers, in the grader only
                case.update(lesson=_plain(reference_sat(first, second, "lesson")),
                            short=_plain(reference_sat(first, second, "short")),
                            mistakes=_sat_mistakes_reference(first, second),
                            flips=_flip_mistakes_reference(first, second))
            cases.append(case)
    return cases


# ---------------------------------------------------------------- the known wrong sat()s (steps 2 and 3)

def _hand_axes(points, closing=True, unit=True):
    """(-e.y, e.x) of each edge, built by hand as a student might: unit or not, the closing edge or not."""
    count = len(points) if closing else len(points) - 1
    axes = [Vector2(-e.y, e.x) for e in (points[(i + 1) % len(points)] - points[i] for i in range(count))]
    return [axis.normalize() for axis in axes if axis.length_squared() > 0] if unit else axes


def _lesson_overlap(shadow_a, shadow_b):
    return min(shadow_a[1], shadow_b[1]) - max(shadow_a[0], shadow_b[0])


# step 2's known wrong loops: name -> (axes, overlap from A's and B's shadows, on a gap, keep the largest)
SAT_LOOPS = {
    "gap_continue": ("both", _lesson_overlap, "continue", False),
    "gap_break": ("both", _lesson_overlap, "break", False),
    "one_sided": ("both", lambda a, b: a[1] - b[0], "return", False),
    "union": ("both", lambda a, b: max(a[1], b[1]) - min(a[0], b[0]), "return", False),
    "a_twice": ("both", lambda a, b: a[1] - a[0], "return", False),     # min_b, max_b from project(pa, axis)
    "unnormalised": ("unnormalised", _lesson_overlap, "return", False),
    "largest": ("both", _lesson_overlap, "return", True),
    "only_a": ("a", _lesson_overlap, "return", False),
    "only_b": ("b", _lesson_overlap, "return", False),
    "no_closing": ("no_closing", _lesson_overlap, "return", False),
}


def _loop_axes(which, pa, pb):
    if which == "unnormalised":
        return _hand_axes(pa, unit=False) + _hand_axes(pb, unit=False)
    if which == "no_closing":
        return _hand_axes(pa, closing=False) + _hand_axes(pb, closing=False)
    return (edge_normals(pa) if which in ("both", "a") else []) + (edge_normals(pb) if which in ("both", "b") else [])


@reference
def _sat_mistakes_reference(pa, pb):
    """{name: what step 2's known wrong loop (SAT_LOOPS) gives for pa, pb}: None, "raises" (no axis kept, so
    step 3's dot product raises) or {"normal", "depth"} with the axis as the loop kept it (not turned round)."""
    out = {}
    for name, (which, overlap_of, on_gap, largest) in SAT_LOOPS.items():
        best_axis, best_depth, answer = None, 0.0 if largest else math.inf, None
        for axis in _loop_axes(which, pa, pb):
            overlap = overlap_of(project(pa, axis), project(pb, axis))
            if overlap <= 0 and on_gap != "continue":
                if on_gap == "break":
                    break
                answer = "apart"
                break
            if overlap > 0 and (overlap > best_depth if largest else overlap < best_depth):
                best_axis, best_depth = axis, overlap
        if answer == "apart":
            out[name] = None
        else:
            out[name] = "raises" if best_axis is None else {"normal": [best_axis.x, best_axis.y], "depth": best_depth}
    return out


@reference
def _flip_mistakes_reference(pa, pb):
    """{name: the normal step 3's known wrong flip gives after the lesson's step 2}, {} when the pair is apart.

    not_flipped: no test; reversed: turned when (centre_b - centre_a)·n > 0 (the same as (centre_a - centre_b)·n
    < 0); always_flipped: turned without a test; first_vertices: the test made with pb[0] - pa[0].
    """
    overlaps = axis_overlaps(pa, pb)   # (axis, the lesson's overlap, the shorter way out) per edge normal
    if any(overlap <= 0 for _, overlap, _ in overlaps):
        return {}
    best_axis = min(overlaps, key=lambda item: item[1])[0]   # the first of equal overlaps, as `<` keeps
    towards = (centre_of(pb) - centre_of(pa)).dot(best_axis)
    forms = {"not_flipped": best_axis, "reversed": -best_axis if towards > 0 else best_axis,
             "always_flipped": -best_axis,
             "first_vertices": -best_axis if (pb[0] - pa[0]).dot(best_axis) < 0 else best_axis}
    return {name: [axis.x, axis.y] for name, axis in forms.items()}


# ---------------------------------------------------------------- bodies for apply_impulse and resolve

def crate(w, h, pos, mass, angle=0.0, vel=(0, 0), omega=0.0, friction=0.6, restitution=0.2):
    """A box body; mass 0 makes it static."""
    return Body(box_points(w, h), pos, mass, angle=angle, vel=vel, omega=omega, friction=friction,
                restitution=restitution)


def _state(body):
    return {"vel": [body.vel.x, body.vel.y], "omega": body.omega}


# ---------------------------------------------------------------- apply_impulse (step 6)

def impulse_cases():
    """(name, body A, body B, impulse P, ra, rb): the lab's apply_impulse(a, b, P, ra, rb)."""
    return [
        ("both crates moving, a heavy A and a light B",
         crate(80, 50, (0, 0), 6.0, vel=(30, -10), omega=0.7),
         crate(30, 20, (10, -34), 0.35, vel=(-20, 60), omega=-1.2),
         Vector2(120, -340), Vector2(18, -25), Vector2(8, 9)),
        ("a static floor (A) under a spinning crate (B)",
         crate(400, 40, (0, 20), 0),
         crate(60, 40, (10, -20), 2.0, vel=(50, 80), omega=0.9),
         Vector2(40, -260), Vector2(-35, 0), Vector2(-45, 20)),
        ("a spinning crate (A) under a static beam (B)",
         crate(50, 30, (0, 0), 0.5, vel=(10, -90), omega=-0.6),
         crate(300, 30, (20, -30), 0),
         Vector2(-25, -180), Vector2(-20, -15), Vector2(-40, 15)),
        ("both crates moving, a sideways friction impulse",
         crate(44, 64, (0, 0), 0.9, vel=(-15, 25), omega=2.0),
         crate(90, 36, (70, 10), 3.2, vel=(5, -5), omega=-0.4),
         Vector2(-90, 15), Vector2(22, 12), Vector2(-48, 2)),
    ]


def drawn_impulse_cases(rng, count=2):
    """`count` apply_impulse cases drawn for this run: two moving, spinning crates, masses far from 1."""
    def mass():
        return rng.uniform(0.2, 0.6) if rng.random() < 0.5 else rng.uniform(2.5, 9.0)

    def spin():
        return rng.choice((-1, 1)) * rng.uniform(0.3, 2.5)

    def vector(low, high):
        return Vector2(rng.uniform(low, high), 0).rotate(rng.uniform(0, 360))

    cases = []
    for k in range(count):
        a = crate(rng.uniform(30, 90), rng.uniform(20, 60), (0, 0), mass(), vel=vector(5, 120), omega=spin())
        b = crate(rng.uniform(20, 60), rng.uniform(20, 60), vector(30, 60), mass(), vel=vector(5, 120), omega=spin())
        cases.append((f"two moving crates drawn for this run ({k + 1} of {count})", a, b, vector(60, 400),
                      vector(10, 35), vector(10, 35)))
    return cases


def probe_apply_impulse(module, lab_path):
    """The student's apply_impulse() on each case: each body's velocity and spin before, after and expected.

    Expected (the lesson): vA -= P/mA, ωA -= (ra × P)/IA, vB += P/mB, ωB += (rb × P)/IB.
    """
    cases = []
    for name, a, b, impulse, ra, rb in impulse_cases() + drawn_impulse_cases(run_rng(module, "apply_impulse")):
        before = {"a": _state(a), "b": _state(b)}
        inv = {"a": [a.inv_mass, a.inv_inertia], "b": [b.inv_mass, b.inv_inertia]}
        vectors = {"impulse": Vector2(impulse), "ra": Vector2(ra), "rb": Vector2(rb)}   # copies: a change shows
        module.apply_impulse(a, b, vectors["impulse"], vectors["ra"], vectors["rb"])
        case = {"case": name, "impulse": list(impulse), "ra": list(ra), "rb": list(rb), "inv": inv,
                "before": before, "after": {"a": _state(a), "b": _state(b)},
                "changed": changed_vectors(vectors, impulse=impulse, ra=ra, rb=rb)}
        if judging(module):
            case.update(_impulse_reference(before, inv, impulse, ra, rb))
        cases.append(case)
    return cases


@reference
def _impulse_reference(before, inv, impulse, ra, rb):
    """The lesson's apply_impulse on bodies in the `before` state with the `inv` inverse masses and inertias."""
    bodies = {}
    for side in ("a", "b"):
        body = crate(1, 1, (0, 0), 0)
        body.vel, body.omega = Vector2(before[side]["vel"]), before[side]["omega"]
        body.inv_mass, body.inv_inertia = inv[side]
        bodies[side] = body
    lesson_apply_impulse(bodies["a"], bodies["b"], Vector2(impulse), Vector2(ra), Vector2(rb))
    return {"cross": {"a": cross(ra, impulse), "b": cross(rb, impulse)},
            "expected": {side: _state(body) for side, body in bodies.items()}}


# ---------------------------------------------------------------- resolve (steps 4 and 5)

def resolve_cases():
    """(name, body A, body B, unit normal A→B, contact point): each a contact resolve() is called on."""
    up = Vector2(0, -1)
    return [
        ("both crates moving, B sliding right over A, fast impact",
         crate(80, 50, (0, 0), 6.0, vel=(-40, 10), omega=0.5, friction=0.5, restitution=0.3),
         crate(30, 20, (10, -34), 0.35, vel=(260, 190), omega=-1.5, friction=0.8, restitution=0.5),
         up, Vector2(18, -25)),
        ("both crates moving, B sliding left over A, fast impact",
         crate(80, 50, (0, 0), 6.0, vel=(40, 10), omega=-0.5, friction=0.5, restitution=0.3),
         crate(30, 20, (-10, -34), 0.35, vel=(-260, 190), omega=1.5, friction=0.8, restitution=0.5),
         up, Vector2(-18, -25)),
        ("a crate landing slowly on a static floor, barely sliding",
         crate(400, 40, (0, 20), 0, friction=0.6, restitution=0.2),
         crate(60, 40, (12, -20), 5.0, vel=(3, 12), omega=0.05, friction=0.6, restitution=0.2),
         up, Vector2(-16, 0)),
        # it bounces (e = 0.5), so after the normal impulse |rel| is far above the slip |rel · t|: a clamp to
        # mu × either shows as itself
        ("a heavy crate bouncing on a static floor, barely sliding",
         crate(400, 40, (0, 20), 0, friction=0.6, restitution=0.5),
         crate(60, 40, (12, -20), 6.0, vel=(4, 150), omega=0.02, friction=0.6, restitution=0.5),
         up, Vector2(-16, 0)),
        ("a light crate thrown up into a static beam",
         crate(50, 30, (0, 0), 0.3, vel=(70, -140), omega=0.8, friction=0.7, restitution=0.4),
         crate(300, 30, (30, -30), 0, friction=0.7, restitution=0.4),
         up, Vector2(-21, -15)),
        ("a turned crate landing on its corner on a moving plank",
         crate(160, 20, (0, 10), 4.0, vel=(20, -5), omega=0.1, friction=0.6, restitution=0.1),
         crate(60, 40, (5, -36), 1.2, angle=math.radians(30), vel=(-30, 210), omega=0.6, friction=0.6,
               restitution=0.1),
         up, Vector2(-17.5, 0)),
        ("both crates moving, a hard landing with little sliding",
         crate(70, 40, (0, 0), 2.6, vel=(-6, -40), omega=0.2, friction=0.9, restitution=0.0),
         crate(40, 40, (12, -40), 0.45, vel=(9, 150), omega=-0.3, friction=0.9, restitution=0.0),
         up, Vector2(25, -20)),
        ("a crate grazing a static wall on its right, sliding down it",
         crate(50, 50, (0, 0), 0.8, vel=(45, 320), omega=1.1, friction=0.4, restitution=0.25),
         crate(30, 400, (40, 0), 0, friction=0.4, restitution=0.25),
         Vector2(1, 0), Vector2(25, 14)),
    ]


def drawn_resolve_cases(rng, count=2):
    """`count` contacts drawn for this run, friction clamped and not in turn (the first clamped), so a table of
    the fixed contacts' answers with one default for the rest (the unclamped jt, say) is wrong on one of them.

    A crate B lands on a crate A (static one time in four) at a contact on A's top face, all of it turned by a
    drawn angle; |the impulse that stops the slip| is over 1.5 × mu j (clamped) or under 0.6 × mu j (not): no
    contact near the clamp's edge.
    """
    cases = []
    while len(cases) < count:
        clamped = len(cases) % 2 == 0
        turn = rng.uniform(0, 360)
        wa, ha, wb, hb = rng.uniform(60, 160), rng.uniform(20, 50), rng.uniform(24, 70), rng.uniform(20, 60)
        offset = rng.uniform(-0.3, 0.3) * (wa - wb)
        point = Vector2(offset + rng.uniform(-0.4, 0.4) * wb, -ha / 2)
        slip = rng.choice((-1, 1)) * (rng.uniform(150, 400) if clamped else rng.uniform(3, 15))
        spin = 1.0 if clamped else 0.05

        def placed(v):
            return Vector2(v).rotate(turn)

        a = crate(wa, ha, (0, 0), 0 if rng.random() < 0.25 else rng.uniform(1.0, 8.0), angle=math.radians(turn),
                  vel=placed((rng.uniform(-20, 20), rng.uniform(-20, 0))), omega=rng.uniform(-spin, spin),
                  friction=rng.uniform(0.3, 0.9), restitution=rng.uniform(0.0, 0.5))
        if a.mass == 0:
            a.vel, a.omega = Vector2(), 0.0
        b = crate(wb, hb, placed((offset, -(ha + hb) / 2 + 1)), rng.uniform(0.3, 3.0), angle=math.radians(turn),
                  vel=placed((slip, rng.uniform(60, 250))), omega=rng.uniform(-spin, spin),
                  friction=rng.uniform(0.3, 0.9), restitution=rng.uniform(0.0, 0.5))
        ratios = [stop_over_bound(a, b, placed((0, -1)), placed(point), RESTING_SPEED, spin) for spin in (True, False)]
        if None not in ratios and (min(ratios) > 1.5 if clamped else max(ratios) < 0.6):
            cases.append((f"a contact drawn for this run, friction {'clamped' if clamped else 'not clamped'} "
                          f"({len(cases) + 1} of {count})", a, b, placed((0, -1)), placed(point)))
    return cases


@reference
def _k_forms(a, b, ra, rb, n):
    """The effective mass k of the lesson, and the k's of plausible mistakes (to name what is missing)."""
    ima, imb, ia, ib = a.inv_mass, b.inv_mass, a.inv_inertia, b.inv_inertia
    ran, rbn = cross(ra, n), cross(rb, n)
    dan, dbn = ra.dot(n), rb.dot(n)
    return {
        "right": ima + imb + ran * ran * ia + rbn * rbn * ib,
        "no_spin": ima + imb,
        "no_a_spin": ima + imb + rbn * rbn * ib,
        "no_b_spin": ima + imb + ran * ran * ia,
        "not_squared": ima + imb + ran * ia + rbn * ib,
        "inv_mass_in_spin": ima + imb + ran * ran * ima + rbn * rbn * imb,
        "spin_only": ran * ran * ia + rbn * rbn * ib,
        "inertias_swapped": ima + imb + ran * ran * ib + rbn * rbn * ia,
        "subtracted": ima + imb - ran * ran * ia - rbn * rbn * ib,
        "a_subtracted": ima + imb - ran * ran * ia + rbn * rbn * ib,
        "b_subtracted": ima + imb + ran * ran * ia - rbn * rbn * ib,
        "dot_not_cross": ima + imb + dan * dan * ia + dbn * dbn * ib,
        "a_with_b_inertia": ima + imb + ran * ran * ib + rbn * rbn * ib,
        "b_with_a_inertia": ima + imb + ran * ran * ia + rbn * rbn * ia,
        "lever_length": ima + imb + ra.length_squared() * ia + rb.length_squared() * ib,
    }


def probe_resolve(module, lab_path):
    """The student's resolve() on each contact, with every impulse it applies recorded.

    Per case: the closing speed vn (px/s, < 0), e, the lesson's k and the mistakes' k's,
    the normal impulse j the student applied, and for friction: the state after the
    student's normal impulse, the impulse jt that would stop the slip, mu, and the
    friction impulse the student applied. The library's apply_impulse applies each
    impulse, so the student's own apply_impulse (step 6) does not matter here. Every
    reference number is computed from twins of the bodies taken before resolve() runs,
    so a resolve() that changes a body's inertia or friction does not change the lesson's answer.
    """
    cases = []
    resting = float(getattr(module, "RESTING_SPEED", RESTING_SPEED))
    own = module.apply_impulse
    try:
        for name, a, b, normal, point in resolve_cases() + drawn_resolve_cases(run_rng(module, "resolve")):
            calls = []

            def stand_in(a_, b_, impulse, ra_, rb_, calls=calls):
                calls.append({"impulse": Vector2(impulse), "ra": Vector2(ra_), "rb": Vector2(rb_)})
                lesson_apply_impulse(a_, b_, Vector2(impulse), Vector2(ra_), Vector2(rb_))

            module.apply_impulse = stand_in
            given = (twin(a), twin(b))   # the bodies as resolve() gets them
            vectors = {"normal": Vector2(normal), "point": Vector2(point)}   # copies: a change in place shows
            module.resolve(a, b, vectors["normal"], vectors["point"])
            if judging(module):
                cases.append(_resolve_case(name, *given, normal, point, resting, calls))
                cases[-1]["changed"] = changed_vectors(vectors, normal=normal, point=point)
    finally:
        module.apply_impulse = own
    return cases


@reference
def _resolve_case(name, a, b, normal, point, resting, calls):
    """Plain data for one resolve() case (see probe_resolve); a and b: the bodies before resolve() ran."""
    ra, rb = point - a.pos, point - b.pos
    vn = relative_velocity(a, b, ra, rb).dot(normal)
    e = min(a.restitution, b.restitution) if vn < -resting else 0.0
    forms = _k_forms(a, b, ra, rb, normal)
    case = {"case": name, "vn": vn, "e": e, "k": forms, "calls": len(calls),
            "mu": math.sqrt(a.friction * b.friction), "masses": [a.mass, b.mass],
            "j": None, "j_off_normal": 0.0, "friction": None}
    if not calls:
        return case
    first = calls[0]
    case["j"] = first["impulse"].dot(normal)
    case["j_off_normal"] = (first["impulse"] - normal * case["j"]).length()
    # the state after the student's normal impulse, from the bodies as given (not as resolve() left them); the
    # friction impulse is the second call (none: "missing", what it should have been at the contact point)
    a, b = twin(a), twin(b)
    lesson_apply_impulse(a, b, Vector2(first["impulse"]), Vector2(first["ra"]), Vector2(first["rb"]))
    second = calls[1] if len(calls) >= 2 else {"impulse": Vector2(), "ra": ra, "rb": rb}
    rel = relative_velocity(a, b, second["ra"], second["rb"])
    tangent = rel - normal * rel.dot(normal)
    if tangent.length_squared() > 1e-12:
        t = tangent.normalize()
        rat, rbt = cross(second["ra"], t), cross(second["rb"], t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        case["friction"] = {
            "slip": rel.dot(t),                         # px/s along t before friction
            "stop": -rel.dot(t) / kt,                   # the impulse that would stop the slip
            "jt": second["impulse"].dot(t),             # what the student applied along t
            "off_tangent": (second["impulse"] - t * second["impulse"].dot(t)).length(),
            "rel_length": rel.length(), "vn_now": rel.dot(normal),
        }
        if len(calls) < 2:
            case["friction"].update(jt=0.0, missing=True)
    return case


# the spliced functions the probes use: (function, the lab's solution's steps put in it)
SPLICES = (("sat", (3,)),)

# the step functions that answer a question and must leave their arguments as they got them (the grader
# fails one that changes them in place, whatever it returns: checker/lab_checks.function_data)
PURE = ("sat",)

# probe name -> (the lab function it needs, the probe); the spliced probe runs last, so nothing it leaves (a step
# 2 that keeps the spliced sat on a handout class) reaches a graded call of the student's own functions
PROBES = {"sat": ("sat", probe_sat), "apply_impulse": ("apply_impulse", probe_apply_impulse),
          "resolve": ("resolve", probe_resolve), "sat_step2": ("sat", probe_sat_step2)}
