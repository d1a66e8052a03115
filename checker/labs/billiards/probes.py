"""Billiards' three steps declared as data (checker/judging/declared.py): each one's cases (some drawn for this
run), the lesson's answer (reference_*, run in the grader only), its known wrong forms and their words. px, s."""
import math

from pygame import Vector2

from checker.judging.declared import Step, close, forms_of, listed, numbers
from checker.judging.probe_kit import reference
from checker.judging.tape import run_rng
from lesson11.physics2d import Body, Circle

REQUIRED = ("circle_circle", "bounce", "cloth_slowing", "main")
G = 980.0   # px/s², the handout's g
same = close(1e-9)   # relative: the same sums in another order agree this well


def declare(check, doc, step, function, key, table, forms, text, must, **parts):
    """A Step in this lab's words: text(case) names the call; `key` is its hint and its forms' id prefix."""
    return Step(check, doc, step, function, same=same, bad=lambda got: isinstance(got, str), hint=key,
                malformed=lambda c: f"{function}() must {must}.\n{text(c)}: {c['got']}.",
                evidence=lambda c: f"{text(c)} gave {listed(c['got'])}; expected {listed(c['want'])}.",
                wrong=forms_of(table, forms, key + "_"), **parts)


def contact_cases(module):
    rng = run_rng(module, "circle_circle")
    angle, ra, rb = rng.uniform(0, 2 * math.pi), rng.uniform(8, 20), rng.uniform(8, 20)
    cases = [  # (what, centre A, radius A, centre B, radius B)
        ("overlapping along x", [100, 100], 14, [120, 100], 14), ("B above A", [200, 200], 14, [200, 180], 14),
        ("slanted, radii 10 and 15", [50, 60], 10, [62, 76], 15), ("B left of A, deep", [400, 100], 14, [390, 100], 20),
        ("apart along x", [0, 0], 14, [40, 0], 14), ("apart diagonally", [0, 0], 10, [30, 30], 10),
        ("coincident centres", [300, 300], 14, [300, 300], 14)]
    for what, k in (("overlapping", rng.uniform(0.3, 0.9)), ("apart", rng.uniform(1.1, 2))):
        cases.append((f"drawn for this run, {what}", [300, 200], ra,
                      [300 + k * (ra + rb) * math.cos(angle), 200 + k * (ra + rb) * math.sin(angle)], rb))
    return [dict(zip(("case", "ca", "ra", "cb", "rb"), case)) for case in cases]


@reference
def reference_contact(case):
    """The lesson's (normal, depth) as [nx, ny, depth], None when apart; normal (1, 0) for coincident centres."""
    offset = Vector2(case["cb"]) - Vector2(case["ca"])
    depth = case["ra"] + case["rb"] - offset.length()
    if depth <= 0:
        return None
    return [*(offset / offset.length() if offset.length() else Vector2(1, 0)), depth]


def contact_forms(case):
    """{form: its answer} where it is not None; at coincident centres every form keeps the fixed normal."""
    offset = Vector2(case["cb"]) - Vector2(case["ca"])
    right, far, radii = reference_contact(case), offset.length(), case["ra"] + case["rb"]
    if right is None:
        return {"inverted": [offset.x / far, offset.y / far, radii - far]}
    n, depth = right[:2], right[2]
    return {"reversed": [-n[0], -n[1], depth] if far else right, "unit": [*offset, depth] if far else right,
            "gap": [*n, -depth], "halved": [*n, depth / 2], "squared": right if far * far < radii else None}


CONTACT = {
    "reversed": "the normal points from B to A: it must run from A's centre to B's",
    "gap": "the depth is |cb - ca| - ra - rb, the gap: the overlap is ra + rb - |cb - ca|",
    "unit": "the normal is cb - ca, not a unit vector: divide it by its length",
    "halved": "the depth is halved: the overlap is the whole ra + rb - |cb - ca|",
    "squared": "|d|² is compared with ra + rb: compare |d| with ra + rb",
    "inverted": "overlapping balls give None and apart ones a contact: the test is the wrong way round"}

CIRCLE_CIRCLE = declare(
    "circle_circle_right", "Step 2: circle_circle() gives None when two balls are apart, else the unit normal from "
    "A to B and the depth ra + rb - |cb - ca|.", 2, "circle_circle", "contact", CONTACT, contact_forms,
    lambda c: f"circle_circle({listed(c['ca'])}, {c['ra']:.4g}, {listed(c['cb'])}, {c['rb']:.4g}) ({c['case']})",
    "return None or (normal, depth)", cases=contact_cases, answer=lambda raw: numbers(raw, 3),
    call=lambda function, c: function(Vector2(c["ca"]), c["ra"], Vector2(c["cb"]), c["rb"]),
    lesson=lambda case: reference_contact(case), passed="all {n} pairs (overlapping, apart, coincident) right",
    unnamed="the contact is not (unit normal A to B, ra + rb - |cb - ca|), None when apart")


def bounce_cases(module):
    rng = run_rng(module, "bounce")
    angle, closing = rng.uniform(0, 2 * math.pi), rng.uniform(50, 600)
    n = [math.cos(angle), math.sin(angle)]
    cases = [  # (what, mA, vA, mB, vB, unit normal A to B, e)
        ("equal balls head-on, e = 1", 1, [400, 0], 1, [0, 0], [1, 0], 1.0),
        ("equal balls head-on, e = 0.95", 1, [400, 0], 1, [-100, 0], [1, 0], 0.95),
        ("B three times heavier", 1, [0, 300], 3, [0, 0], [0, 1], 0.95),
        ("a ball into a cushion (A, static)", 0, [0, 0], 1, [-200, 150], [-1, 0], 0.8),
        ("slanted normal, glancing", 2, [250, 40], 0.5, [-30, 60], [0.6, -0.8], 0.5),
        ("separating", 1, [-100, 0], 1, [100, 0], [1, 0], 0.95),
        ("sliding past each other", 1, [0, 100], 1, [0, -100], [1, 0], 0.95),
        ("drawn for this run", rng.uniform(0.5, 3), [closing * n[0], closing * n[1]], rng.uniform(0.5, 3),
         [rng.uniform(-50, 50), rng.uniform(-50, 50)], n, rng.uniform(0.3, 1))]
    return [dict(zip(("case", "ma", "va", "mb", "vb", "normal", "e"), case)) for case in cases]


def bounce_call(function, c):
    a, b = Body(Circle(14), (0, 0), c["ma"], vel=c["va"]), Body(Circle(14), (28, 0), c["mb"], vel=c["vb"])
    function(a, b, Vector2(c["normal"]), c["e"])
    return a.vel, b.vel


def impulse(case, e=None, k=None, always=False, on_a=-1, on_b=1):
    """[vA, vB] after j = -(1 + e) vn / k (default: the lesson's, only while closing): on_a j n / mA, on_b j n / mB."""
    n, va, vb = Vector2(case["normal"]), Vector2(case["va"]), Vector2(case["vb"])
    ia, ib = [1 / m if m else 0.0 for m in (case["ma"], case["mb"])]
    vn = (vb - va).dot(n)
    j = 0.0 if vn >= 0 and not always else -(1 + (case["e"] if e is None else e)) * vn / (k or ia + ib)
    return [*(va + n * (on_a * j * ia)), *(vb + n * (on_b * j * ib))]


@reference
def reference_bounce(case):
    """The lesson's velocities after the bounce: [vAx, vAy, vBx, vBy] (px/s)."""
    return impulse(case)


def bounce_forms(case):
    return {"separating": impulse(case, always=True), "e_alone": impulse(case, e=case["e"] - 1),
            "no_e": impulse(case, e=0), "masses_summed": impulse(case, k=case["ma"] + case["mb"]),
            "b_only": impulse(case, on_a=0), "same_sign": impulse(case, on_a=1),
            "signs_swapped": impulse(case, on_a=1, on_b=-1)}


BOUNCE = {
    "separating": "the impulse also pushes balls that already separate: none when vn >= 0",
    "e_alone": "j uses e alone: it takes (1 + e), the stop and the bounce back",
    "no_e": "j leaves out e: (1 + e) vn, not vn, or the balls never bounce apart",
    "masses_summed": "j divides by mA + mB: divide by the inverse masses, 1/mA + 1/mB",
    "b_only": "only B gets the impulse: A takes -j n as well",
    "same_sign": "both balls get +j n: A takes -j n",
    "signs_swapped": "A gets +j n and B -j n: the push runs from A to B, so B gets +j n"}

BOUNCE_STEP = declare(
    "bounce_right", "Step 3: bounce() gives B +j n and A -j n, j = -(1 + e) vn / (1/mA + 1/mB), only while the "
    "balls close.", 3, "bounce", "bounce", BOUNCE, bounce_forms,
    lambda c: f"bounce, {c['case']} (mA {c['ma']:.3g}, mB {c['mb']:.3g}, e {c['e']:.3g}): vA, vB",
    "leave both velocities Vector2s", cases=bounce_cases, call=bounce_call, answer=lambda raw: numbers(raw, 4),
    lesson=lambda case: reference_bounce(case), unnamed="the velocities after the bounce are not the lesson's",
    passed="all {n} pairs bounce as the lesson's impulse says")


def cloth_cases(module):
    rng = run_rng(module, "cloth_slowing")
    angle = rng.uniform(0, 2 * math.pi)
    cases = [("fast along x", [300, 0], 0.15, 1 / 60), ("slanted", [120, -160], 0.15, 1 / 60),
             ("slow: it stops", [1, 1], 0.15, 1 / 60), ("at rest", [0, 0], 0.15, 1 / 60),
             ("a slower cloth, a longer frame", [-80, 60], 0.05, 1 / 30),
             ("just faster than one frame's drop", [0, -2.5], 0.15, 1 / 60)]
    for what, speed in (("drawn for this run", rng.uniform(50, 500)), ("drawn for this run, stops", rng.uniform(0, 2))):
        cases.append((what, [speed * math.cos(angle), speed * math.sin(angle)], rng.uniform(0.05, 0.3), 1 / 60))
    return [dict(zip(("case", "vel", "mu", "dt"), case)) for case in cases]


@reference
def reference_cloth(case):
    """The lesson's velocity after the cloth: the speed less mu g dt, never below 0 (px/s)."""
    vel, drop = Vector2(case["vel"]), case["mu"] * G * case["dt"]
    return [0.0, 0.0] if vel.length() <= drop else [*(vel * ((vel.length() - drop) / vel.length()))]


def cloth_forms(case):
    vel, drop = Vector2(case["vel"]), case["mu"] * G * case["dt"]
    return {"reverses": [*(vel - (vel.normalize() * drop if vel.length() else vel))],
            "drag": [*(vel * (1 - case["mu"] * case["dt"]))], "no_dt": reference_cloth(dict(case, dt=1.0)),
            "no_g": reference_cloth(dict(case, mu=case["mu"] / G)),
            "per_axis": [math.copysign(max(abs(x) - drop, 0.0), x) for x in vel]}


CLOTH = {
    "reverses": "a slow ball turns round: stop it at exactly (0, 0) when its speed is below mu g dt",
    "drag": "the drop grows with the speed (a drag): the cloth takes the same mu g dt every frame",
    "no_dt": "the drop leaves out dt: mu g is per second, a frame takes mu g dt",
    "no_g": "the drop leaves out g: it is mu g dt, g = 980 px/s²",
    "per_axis": "x and y are slowed apart: lower the speed along -v, keeping the direction"}

CLOTH_STEP = declare(
    "cloth_slowing_right", "Step 4: cloth_slowing() lowers the speed by mu g dt along -v and stops a slower ball at "
    "exactly (0, 0).", 4, "cloth_slowing", "cloth", CLOTH, cloth_forms,
    lambda c: f"cloth_slowing({listed(c['vel'])}, {c['mu']:.3g}, {c['dt']:.4g}) ({c['case']})", "return a Vector2",
    cases=cloth_cases, call=lambda function, c: function(Vector2(c["vel"]), c["mu"], c["dt"]),
    answer=lambda raw: numbers(raw, 2), lesson=lambda case: reference_cloth(case),
    unnamed="the velocity after the cloth is not the speed less mu g dt, stopping at 0",
    passed="all {n} balls slowed by mu g dt, the slow ones stopped")

STEPS = (CIRCLE_CIRCLE, BOUNCE_STEP, CLOTH_STEP)
PROBES = {**CIRCLE_CIRCLE.probes(), **BOUNCE_STEP.probes(), **CLOTH_STEP.probes()}
