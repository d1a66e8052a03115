"""The Billiards steps declared as data (checker/judging/declared.py): cases, the lesson's answer, wrong forms.

    circle_circle (step 2)  pairs overlapping along the axes and slanted, apart, with coincident centres
    bounce        (step 3)  closing, separating and sliding pairs, unequal masses, a ball into a cushion
    cloth_slowing (step 4)  fast and slow balls, one at rest, other cloths and frame times
Each also has cases drawn for this run. The lesson's answers (reference_*) and the wrong forms' run in the
grader only. Units: px, s. G is the handout's g (980 px/s²).
"""
import math

from pygame import Vector2

from checker.judging.common import real, value_text
from checker.judging.declared import Step, forms_of
from checker.judging.probe_kit import reference
from checker.judging.tape import run_rng
from lesson11.physics2d import Body, Circle

REQUIRED = ("circle_circle", "bounce", "cloth_slowing", "main")
G = 980.0
CLOSE = 1e-9   # relative: the same sums in another order agree this well


def plain(raw, size):
    """A step's answer as a list of `size` floats (None stays None), or its text when it is not one."""
    try:
        return None if raw is None else [real(x) for x in raw][:size] if len(raw) == size else value_text(raw)
    except (TypeError, ValueError):
        return value_text(raw)


def same(got, want):
    return got == want or (isinstance(got, list) and isinstance(want, list) and len(got) == len(want)
                           and all(abs(g - w) <= CLOSE * max(1.0, abs(w)) for g, w in zip(got, want)))


def shown(value):
    """An answer in a message: None, its text, or its numbers two decimals each."""
    if not isinstance(value, list):
        return str(value)
    return "(" + ", ".join(f"{x:.2f}".replace("-0.00", "0.00") for x in value) + ")"


# ---------------------------------------------------------------- step 2: circle_circle

def contact_cases(module):
    rng = run_rng(module, "circle_circle")
    angle, ra, rb = rng.uniform(0, 2 * math.pi), rng.uniform(8, 20), rng.uniform(8, 20)
    cases = [("overlapping along x", (100, 100), 14, (120, 100), 14), ("B above A", (200, 200), 14, (200, 180), 14),
             ("slanted, radii 10 and 15", (50, 60), 10, (62, 76), 15),
             ("B left of A, deep", (400, 100), 14, (390, 100), 20), ("apart along x", (0, 0), 14, (40, 0), 14),
             ("apart diagonally", (0, 0), 10, (30, 30), 10), ("coincident centres", (300, 300), 14, (300, 300), 14)]
    for what, share in (("overlapping", rng.uniform(0.3, 0.9)), ("apart", rng.uniform(1.1, 2))):
        cb = (300 + share * (ra + rb) * math.cos(angle), 200 + share * (ra + rb) * math.sin(angle))
        cases.append((f"drawn for this run, {what}", (300, 200), ra, cb, rb))
    return [{"case": what, "ca": list(ca), "ra": ra, "cb": list(cb), "rb": rb} for what, ca, ra, cb, rb in cases]


@reference
def reference_contact(case):
    """The lesson's (normal, depth) as [nx, ny, depth], None when apart; normal (1, 0) for coincident centres."""
    offset = Vector2(case["cb"]) - Vector2(case["ca"])
    depth = case["ra"] + case["rb"] - offset.length()
    if depth <= 0:
        return None
    normal = offset / offset.length() if offset.length() else Vector2(1, 0)
    return [normal.x, normal.y, depth]


def contact_forms(case):
    """{form: its answer} where it differs from None (checks: CONTACT)."""
    offset = Vector2(case["cb"]) - Vector2(case["ca"])
    right, far, radii = reference_contact(case), offset.length(), case["ra"] + case["rb"]
    if right is None:
        return {"inverted": [offset.x / far, offset.y / far, radii - far]}
    n, depth = right[:2], right[2]
    if not far:   # coincident centres: every form keeps the lesson's fixed normal
        return {"reversed": right, "unit": right, "gap": [*n, -depth], "halved": [*n, depth / 2], "squared": right}
    return {"reversed": [-n[0], -n[1], depth], "gap": [*n, -depth], "unit": [offset.x, offset.y, depth],
            "halved": [*n, depth / 2], "squared": right if far * far < radii else None}


CONTACT = {
    "reversed": "the normal points from B to A: it must run from A's centre to B's",
    "gap": "the depth is |cb - ca| - ra - rb, the gap: the overlap is ra + rb - |cb - ca|",
    "unit": "the normal is cb - ca, not a unit vector: divide it by its length",
    "halved": "the depth is halved: the overlap is the whole ra + rb - |cb - ca|",
    "squared": "|d|² is compared with ra + rb: compare |d| with ra + rb",
    "inverted": "overlapping balls give None and apart ones a contact: the test is the wrong way round",
}


def _pair(raw):
    """(normal, depth) as a flat triple; anything else as it came."""
    try:
        return (*raw[0], raw[1]) if len(raw) == 2 and len(raw[0]) == 2 else raw
    except TypeError:
        return raw


def _contact_text(c):
    return f"circle_circle({shown(c['ca'])}, {c['ra']:.4g}, {shown(c['cb'])}, {c['rb']:.4g}) ({c['case']})"


CIRCLE_CIRCLE = Step(
    "circle_circle_right", "Step 2: circle_circle() gives None when two balls are apart, else the unit normal from "
    "A to B and the depth ra + rb - |cb - ca|.", 2, "circle_circle", cases=contact_cases,
    call=lambda function, c: function(Vector2(c["ca"]), c["ra"], Vector2(c["cb"]), c["rb"]),
    answer=lambda raw: plain(_pair(raw), 3), lesson=lambda case: reference_contact(case), same=same,
    bad=lambda got: isinstance(got, str), malformed=lambda c: "circle_circle() must return None or (normal, "
    f"depth).\n{_contact_text(c)} returned {c['got']}.",
    evidence=lambda c: f"{_contact_text(c)} gave {shown(c['got'])}; expected {shown(c['want'])}.",
    unnamed="the contact is not (unit normal A to B, ra + rb - |cb - ca|), None when apart", hint="contact",
    passed="all {n} pairs (overlapping, apart, coincident) right", wrong=forms_of(CONTACT, contact_forms, "contact_"))


# ---------------------------------------------------------------- step 3: bounce

def bounce_cases(module):
    rng = run_rng(module, "bounce")
    angle = rng.uniform(0, 2 * math.pi)
    n = (math.cos(angle), math.sin(angle))
    closing = rng.uniform(50, 600)
    cases = [("equal balls head-on, e = 1", 1, (400, 0), 1, (0, 0), (1, 0), 1.0),
             ("equal balls head-on, e = 0.95", 1, (400, 0), 1, (-100, 0), (1, 0), 0.95),
             ("B three times heavier", 1, (0, 300), 3, (0, 0), (0, 1), 0.95),
             ("a ball into a cushion (A, static)", 0, (0, 0), 1, (-200, 150), (-1, 0), 0.8),
             ("slanted normal, glancing", 2, (250, 40), 0.5, (-30, 60), (0.6, -0.8), 0.5),
             ("separating", 1, (-100, 0), 1, (100, 0), (1, 0), 0.95),
             ("sliding past each other", 1, (0, 100), 1, (0, -100), (1, 0), 0.95),
             ("drawn for this run", rng.uniform(0.5, 3), (closing * n[0], closing * n[1]), rng.uniform(0.5, 3),
              (rng.uniform(-50, 50), rng.uniform(-50, 50)), n, rng.uniform(0.3, 1))]
    return [{"case": what, "ma": ma, "va": list(va), "mb": mb, "vb": list(vb), "normal": list(n), "e": e}
            for what, ma, va, mb, vb, n, e in cases]


def bounce_call(function, c):
    a, b = Body(Circle(14), (0, 0), c["ma"], vel=c["va"]), Body(Circle(14), (28, 0), c["mb"], vel=c["vb"])
    function(a, b, Vector2(c["normal"]), c["e"])
    return a.vel, b.vel


def impulse(case, e=None, k=None, always=False):
    """[vA, vB] after the impulse j = -(1 + e) vn / k along n (default: the lesson's e and k), as 4 floats."""
    n, va, vb = Vector2(case["normal"]), Vector2(case["va"]), Vector2(case["vb"])
    ia, ib = [1 / m if m else 0.0 for m in (case["ma"], case["mb"])]
    vn = (vb - va).dot(n)
    if vn >= 0 and not always:
        return [*va, *vb], n, 0.0, ia, ib
    j = -(1 + (case["e"] if e is None else e)) * vn / (ia + ib if k is None else k)
    return [*(va - n * (j * ia)), *(vb + n * (j * ib))], n, j, ia, ib


@reference
def reference_bounce(case):
    """The lesson's velocities after the bounce: [vAx, vAy, vBx, vBy] (px/s)."""
    return impulse(case)[0]


def bounce_forms(case):
    """{form: [vA, vB] it gives} (checks: BOUNCE)."""
    _, n, j, ia, ib = impulse(case)
    va, vb = Vector2(case["va"]), Vector2(case["vb"])
    return {"separating": impulse(case, always=True)[0], "e_alone": impulse(case, e=case["e"] - 1)[0],
            "no_e": impulse(case, e=0)[0], "masses_summed": impulse(case, k=case["ma"] + case["mb"])[0],
            "b_only": [*va, *(vb + n * (j * ib))], "same_sign": [*(va + n * (j * ia)), *(vb + n * (j * ib))],
            "signs_swapped": [*(va + n * (j * ia)), *(vb - n * (j * ib))]}


BOUNCE = {
    "separating": "the impulse also pushes balls that already separate: none when vn >= 0",
    "e_alone": "j uses e alone: it takes (1 + e), the stop and the bounce back",
    "no_e": "j leaves out e: (1 + e) vn, not vn, or the balls never bounce apart",
    "masses_summed": "j divides by mA + mB: divide by the inverse masses, 1/mA + 1/mB",
    "b_only": "only B gets the impulse: A takes -j n as well",
    "same_sign": "both balls get +j n: A takes -j n",
    "signs_swapped": "A gets +j n and B -j n: the push runs from A to B, so B gets +j n",
}

BOUNCE_STEP = Step(
    "bounce_right", "Step 3: bounce() gives B +j n and A -j n, j = -(1 + e) vn / (1/mA + 1/mB), only while the "
    "balls close.", 3, "bounce", cases=bounce_cases, call=bounce_call,
    answer=lambda raw: plain([*raw[0], *raw[1]] if _vectors(raw) else raw, 4),
    lesson=lambda case: reference_bounce(case), same=same, bad=lambda got: isinstance(got, str),
    malformed=lambda c: f"bounce() must leave both velocities Vector2s.\nafter {_bounce_text(c)} they were "
                        f"{c['got']}.",
    evidence=lambda c: f"{_bounce_text(c)}: vA, vB {shown(c['got'])}; expected {shown(c['want'])}.",
    unnamed="the velocities after the bounce are not the lesson's", hint="bounce",
    passed="all {n} pairs bounce as the lesson's impulse says", wrong=forms_of(BOUNCE, bounce_forms, "bounce_"))


def _vectors(raw):
    return all(isinstance(v, Vector2) for v in raw)


def _bounce_text(c):
    return f"bounce, {c['case']} (mA {c['ma']:.3g}, mB {c['mb']:.3g}, e {c['e']:.3g})"


# ---------------------------------------------------------------- step 4: cloth_slowing

def cloth_cases(module):
    rng = run_rng(module, "cloth_slowing")
    angle = rng.uniform(0, 2 * math.pi)
    cases = [("fast along x", (300, 0), 0.15, 1 / 60), ("slanted", (120, -160), 0.15, 1 / 60),
             ("slow: it stops", (1, 1), 0.15, 1 / 60), ("at rest", (0, 0), 0.15, 1 / 60),
             ("a slower cloth, a longer frame", (-80, 60), 0.05, 1 / 30), ("just faster than one frame's drop",
                                                                        (0, -2.5), 0.15, 1 / 60)]
    for what, speed in (("drawn for this run", rng.uniform(50, 500)), ("drawn for this run, stops", rng.uniform(0, 2))):
        cases.append((what, (speed * math.cos(angle), speed * math.sin(angle)), rng.uniform(0.05, 0.3), 1 / 60))
    return [{"case": what, "vel": list(vel), "mu": mu, "dt": dt} for what, vel, mu, dt in cases]


def slowed(vel, drop):
    vel = Vector2(vel)
    return [0.0, 0.0] if vel.length() <= drop else [*(vel * ((vel.length() - drop) / vel.length()))]


@reference
def reference_cloth(case):
    """The lesson's velocity after the cloth: the speed less mu g dt, never below 0 (px/s)."""
    return slowed(case["vel"], case["mu"] * G * case["dt"])


def cloth_forms(case):
    """{form: the velocity it gives} (checks: CLOTH)."""
    vel, drop = Vector2(case["vel"]), case["mu"] * G * case["dt"]
    along = vel.normalize() * drop if vel.length() else Vector2()
    each = [math.copysign(max(abs(x) - drop, 0.0), x) for x in vel]
    return {"reverses": [*(vel - along)], "drag": [*(vel * (1 - case["mu"] * case["dt"]))],
            "no_dt": slowed(vel, case["mu"] * G), "no_g": slowed(vel, case["mu"] * case["dt"]), "per_axis": each}


CLOTH = {
    "reverses": "a slow ball turns round: stop it at exactly (0, 0) when its speed is below mu g dt",
    "drag": "the drop grows with the speed (a drag): the cloth takes the same mu g dt every frame",
    "no_dt": "the drop leaves out dt: mu g is per second, a frame takes mu g dt",
    "no_g": "the drop leaves out g: it is mu g dt, g = 980 px/s²",
    "per_axis": "x and y are slowed apart: lower the speed along -v, keeping the direction",
}

CLOTH_STEP = Step(
    "cloth_slowing_right", "Step 4: cloth_slowing() lowers the speed by mu g dt along -v and stops a slower ball at "
    "exactly (0, 0).", 4, "cloth_slowing", cases=cloth_cases,
    call=lambda function, c: function(Vector2(c["vel"]), c["mu"], c["dt"]), answer=lambda raw: plain(raw, 2),
    lesson=lambda case: reference_cloth(case), same=same, bad=lambda got: isinstance(got, str),
    malformed=lambda c: f"cloth_slowing() must return a Vector2.\n{_cloth_text(c)} returned {c['got']}.",
    evidence=lambda c: f"{_cloth_text(c)} gave {shown(c['got'])}; expected {shown(c['want'])}.",
    unnamed="the velocity after the cloth is not the speed less mu g dt, stopping at 0", hint="cloth",
    passed="all {n} balls slowed by mu g dt, the slow ones stopped", wrong=forms_of(CLOTH, cloth_forms, "cloth_"))


def _cloth_text(c):
    return f"cloth_slowing({shown(c['vel'])}, {c['mu']:.3g}, {c['dt']:.4g}) ({c['case']})"


STEPS = (CIRCLE_CIRCLE, BOUNCE_STEP, CLOTH_STEP)
PROBES = {**CIRCLE_CIRCLE.probes(), **BOUNCE_STEP.probes(), **CLOTH_STEP.probes()}
PURE = ("circle_circle",)
