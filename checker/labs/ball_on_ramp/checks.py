"""Ball on the Ramp (Lesson 11, Going Further): the checks, their bounds and the hints.

Order of checks (stable), one per lesson step where a step is the student's:
  loads, handout_unchanged, runtime_lines,
  closest_point (step 2), inside_case (step 3), push_out_split (step 4), ball_inertia (step 5),
  contact_on_surface (step 6), friction_rolls (step 7),
  runs, then the four done-criteria: rolls_without_slipping, slides_without_friction,
  knocks_crate_over, pushed_out_of_crate.
Checks are worth 1 point, the four criteria 2 points each.

The function checks compare the student's functions with the lesson's
formulas on the configurations of checker/labs/ball_on_ramp/probes.py and name the first
configuration that differs (and the mistake, when it is a known one). The
scenes (checker/labs/ball_on_ramp/scenes.py) run only when every function check passes,
so a mistake is reported once, under its own step. handout_unchanged and
runtime_lines are the bodies every lab shares (checker/judging/common.py).

Every bound of the criteria comes from the issue (rolling within 2 % and 3 %,
sliding within 1 %, sinking at most 1 px) or was set from what
solutions/ball_on_ramp.py measures in the same scene, noted beside it.
"""
import math

from . import probes, scenes
from checker.judging import criteria, lab_checks
from checker.judging.common import close as _close, same_point as _same_point   # 1e-7 relative and absolute
from checker.judging.criteria import Bound, Criterion
from checker.judging.causes import arguments_hint, consistent_mistake, fitting_mistakes, mistake
from checker.judging.checks import Fail, Hint, Passed, Registry

TITLE = "Ball on the Ramp"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("closest_on_segment",), 3: ("circle_polygon",), 4: ("separate", "lesson_separate"),
                5: ("inertia", "inv_inertia", "Circle", "Body"), 6: ("circle_contact_point", "circle_point"),
                7: ("resolve", "lesson_resolve")}
STEP_ADVICE = {2: "clamp t to [0, 1] on the edge yourself",
               3: "handle the centre inside the polygon yourself",
               4: "split the push-out by inverse mass yourself",
               5: "write ½ m r² yourself",
               6: "put the contact point on the ball's surface yourself",
               7: "write the friction impulse at the contact point yourself"}

# ---------------------------------------------------------------- tolerances of the function checks

# ---------------------------------------------------------------- bounds of the criteria
ROLL_ACCEL = 0.03      # relative to ⅔ g sin θ = 244.74 px/s² (the issue); solution: 244.743, off by 0.0000 %
ROLL_SLIP = 0.02       # |ω r - v| / v (the issue); solution: 2e-15
SLIDE_ACCEL = 0.01     # relative to g sin θ = 367.11 px/s² (the issue); solution: 367.114, off by 0.0000 %
SLIDE_SPIN = 0.05      # rad/s (1 px/s at the rim of a 20 px ball); solution: 3e-14
SINK = 1.0             # px into the ramp, the floor or a crate (the issue); solution: ramp 0.010, knock 0.43 (a crate)
KNOCK_TURN = math.radians(60)   # the crate tips over; solution: 90.3° (it ends on its side)
KNOCK_MOVE = 20.0      # px the crate's centre moves; solution: 72.9
INSIDE_DEPTH = 1.0     # px of overlap left after 0.5 s; solution: 0.41 (the push-out's slop is 0.5)

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "clamp": Hint(2, "clamp t to the segment",
                  "A ball against a polygon: the closest point of an EDGE, not of its line: t = (p - a)·ab / (ab·ab), "
                  "kept within [0, 1] before the point a + ab t."),
    "closest": Hint(2, "the closest point on one edge",
                    "A ball against a polygon: t = (p - a)·ab / (ab·ab) runs from 0 at a to 1 at b; clamp it to "
                    "[0, 1]; the point is a + ab t."),
    "inside": Hint(3, "the center inside: push out the other way",
                   "A ball against a polygon: a ball's center inside leaves by the nearest edge: normal "
                   "-offset / dist (flipped), depth radius + dist."),
    "split": Hint(4, "split the push-out by inverse mass",
                  "Lesson §5, the push-out: each body's share is its 1/m over 1/m_A + 1/m_B, A back along the "
                  "normal, B forward; a static body (1/m = 0) never moves."),
    "inertia": Hint(5, "a solid disc's moment of inertia",
                    "Lesson §4: a solid disc has I = ½ m r², half a ring's m r²: mass near the center is easy to "
                    "spin."),
    "contact": Hint(6, "the contact point on the ball's surface",
                    "Lesson §3: the contact is on the ball's surface, center + normal * radius (the normal points "
                    "out of the ball), where friction has a lever arm."),
    "friction_missing": Hint(7, "friction makes it roll",
                             "Lesson §5: one friction impulse t * jt at the contact, jt = -rel·t / kt, kt with both "
                             "spin terms, clamped to [-mu j, mu j]."),
    "friction_sign": Hint(7, "the sign of the friction impulse",
                          "Lesson §5: friction opposes the slip, jt = -rel·t / kt, and the clamp keeps that sign."),
    "friction_clamp": Hint(7, "Coulomb's clamp on friction",
                           "Lesson §5: keep jt within [-mu j, mu j], j the normal impulse; leave a smaller jt, and "
                           "its sign, alone."),
    "friction_kt": Hint(7, "the spin terms of kt",
                        "Lesson §5: kt is k along t: 1/m_A + 1/m_B + (ra × t)²/I_A + (rb × t)²/I_B, both spin terms."),
    "friction_slip": Hint(7, "the slip along the tangent",
                          "Lesson §5: friction stops the slip, the part of rel along t: jt = -rel·t / kt, not the "
                          "whole relative speed."),
    "friction_centre": Hint(7, "friction acts at the contact point",
                            "Lesson §5: apply t * jt at the contact, with the normal impulse's lever arms ra and rb, "
                            "to a then b."),
    "friction_order": Hint(7, "the order of apply_impulse's arguments",
                           "Lesson §5: apply_impulse(a, b, impulse, ra, rb) takes A first with its lever arm ra: "
                           "the same order as the normal impulse."),
    "handout": lab_checks.handout_hint("the constants, the scene, make_ball, build, the World, the `# lab "
                                       "runtime` lines"),
    "runtime": lab_checks.RUNTIME_HINT,
    "settle": Hint(8, "watch it roll",
                   "The function checks pass, yet the ball misbehaves: press D and watch the contacts while it "
                   "rolls; compare your file with the handout around the steps."),
    "crash": Hint(1, "run the file",
                  "Run the file yourself (python ball_on_ramp.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("ramp", "knock", "inside"), "rolls_without_slipping": ("ramp",),
                  "slides_without_friction": ("ramp",), "knocks_crate_over": ("knock",), "pushed_out_of_crate": ("inside",)}

CHECKS = Registry()


# CPU s of the solution's run of each scene (measured 2026-11-23, one job on this 2-core machine): the
# grader starts the longest first, so a long scene does not start last and run alone.
SCENE_SECONDS = {"knock": 0.8, "ramp": 0.3, "inside": 0.3}


# ---------------------------------------------------------------- helpers

_vec = lab_checks.vec_text   # "(x, y)" for messages, shared by the labs


def _function(sub, functions, probe, function, step):
    return lab_checks.function_data(sub, functions, probe, function, step, HINTS["crash"])


def _bad(got):
    return isinstance(got, dict) and "bad" in got


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, ("closest_on_segment", "circle_polygon", "separate", "disc_inertia",
                                            "contact_point", "resolve", "main"))


# ---------------------------------------------------------------- step 2: the closest point

# the known wrong formulas of step 2, by the name the probe gives their points (probes._closest_reference)
CLOSEST_MISTAKES = {
    "line": ("your point lies on the edge's line beyond the edge: t is not clamped to [0, 1]", "clamp"),
    "unsquared": ("t is divided by |ab|, not by ab·ab = |ab|²", "closest"),
    "undivided": ("t = (p - a)·ab is not divided by ab·ab = |ab|²", "closest"),
    "from_b": ("t is measured from b, (p - b)·ab; the lesson measures from a, (p - a)·ab", "closest"),
}


@CHECKS.check(depends=["loads"])
def closest_point(sub, functions):
    """Step 2: closest_on_segment() gives the point of the edge nearest to p (t clamped to [0, 1])."""
    cases = _function(sub, functions, "closest_on_segment", "closest_on_segment", 2)
    for case in cases:
        got, want = case["got"], case["want"]
        where = f"for {case['case']} (p = {_vec(case['p'])}, edge {_vec(case['a'])} to {_vec(case['b'])})"
        for name, now in (case.get("changed") or {}).items():
            raise Fail(f"closest_on_segment() changed its argument {name} in place: return a new point, a + ab t.\n"
                       f"{where}, {name} went from {_vec(case[name])} to {_vec(now)}.", HINTS["closest"])
        if _same_point(got, want):
            continue
        if _bad(got) and "number" in got:
            t_too = ": that is t; return the point a + ab t" if _close(got["number"], case["t"]) else ""
            raise Fail(f"closest_on_segment() returned the number {got['number']:.4g}{t_too}.\n{where}, expected "
                       f"the point {_vec(want)}.", HINTS["closest"],
                       mistake("closest_returns_t", "closest_on_segment() returns t, not the point a + ab t")
                       if t_too else None)
        if _bad(got):
            placeholder = " (the handout's placeholder: write step 2)" if "inf" in got["bad"] else ""
            raise Fail(f"closest_on_segment() returned {got['bad']}{placeholder}.\n{where}, expected the point "
                       f"{_vec(want)}.", HINTS["closest"])
        named = consistent_mistake(cases, lambda c, name: _same_point(c["got"], c["mistakes"][name]),
                                   [name for name in CLOSEST_MISTAKES if not _same_point(case["mistakes"][name], want)])
        text, hint = CLOSEST_MISTAKES.get(named, ("closest_on_segment() does not give the edge's nearest point",
                                                  "closest"))
        raise Fail(f"{text}.\n{where}, yours is {_vec(got)}; expected {_vec(want)}.", HINTS[hint],
                   mistake(f"closest_{named}", text) if named else None)
    outside = _function(sub, functions, "circle_outside", "circle_polygon", 2)
    for case in outside:
        got, want = case["got"], case["want"]
        if _hit_matches(got, want):
            continue
        raise Fail(f"circle_polygon() with your closest_on_segment() misses a ball outside the polygon.\nfor "
                   f"{case['case']} (center {_vec(case['center'])}, radius {case['radius']:g}): {_show_hit(got)}; "
                   f"expected {_show_hit(want)}.", HINTS["closest"])
    return Passed(f"the closest point matches the lesson in all {len(cases)} edges and {len(outside)} circles "
                  "outside a polygon", value=cases)


def _hit_matches(got, want):
    if want is None:
        return got is None or (not _bad(got) and got["depth"] <= 1e-6)  # exact touching may count as touching
    return (got is not None and not _bad(got) and _same_point(got["normal"], want["normal"])
            and _close(got["depth"], want["depth"]))


def _show_hit(hit):
    if hit is None:
        return "None (apart)"
    if _bad(hit):
        return hit["bad"]
    return f"normal {_vec(hit['normal'])}, depth {hit['depth']:.3f} px"


# ---------------------------------------------------------------- step 3: the inside case

@CHECKS.check(depends=["loads"])
def inside_case(sub, functions):
    """Step 3: circle_polygon() pushes a ball whose center is inside the polygon back out the nearest side."""
    cases = _function(sub, functions, "circle_inside", "circle_polygon", 3)
    for case in cases:
        got, want = case["got"], case["want"]
        if _hit_matches(got, want):
            continue
        where = f"for {case['case']} (center {_vec(case['center'])}, {case['dist']:.2f} px in from the edge)"
        if got is None:
            raise Fail(f"circle_polygon() says apart for a center inside the polygon, the deepest overlap of all.\n"
                       f"{where}: None; expected {_show_hit(want)}.", HINTS["inside"])
        if _bad(got):
            raise Fail(f"circle_polygon() must return (normal, depth) or None.\n{where}: {got['bad']}.",
                       HINTS["inside"])
        flipped = _same_point(got["normal"], case["toward"])
        deep = _close(got["depth"], want["depth"])
        if flipped and deep:
            text = "your normal points from the center towards the nearest edge: flip it, or the push drives " \
                   "the ball through"
            raise Fail(f"{text}.\n{where}: normal {_vec(got['normal'])}; expected {_vec(want['normal'])}.",
                       HINTS["inside"], mistake("inside_not_flipped", text))
        if flipped and _close(got["depth"], case["radius"] - case["dist"]):
            text = "there is no inside case: a center inside gets the outside answer (normal towards the edge, " \
                   "depth radius - dist)"
            raise Fail(f"{text}.\n{where}: {_show_hit(got)}; expected {_show_hit(want)}.", HINTS["inside"],
                       mistake("inside_missing", text))
        if _same_point(got["normal"], want["normal"]):
            shallow = _close(got["depth"], case["radius"] - case["dist"])
            text = "the depth is radius - dist, the outside case's; inside it is radius + dist" if shallow else \
                "the normal is right but not the depth: inside it is radius + dist"
            raise Fail(f"{text}.\n{where}: depth {got['depth']:.3f} px; expected {want['depth']:.3f} px.",
                       HINTS["inside"], mistake("inside_shallow_depth", text) if shallow else None)
        raise Fail(f"circle_polygon() does not push a center inside out of the nearest side.\n{where}: "
                   f"{_show_hit(got)}; expected {_show_hit(want)}.", HINTS["inside"])
    return Passed(f"the inside case matches the lesson in all {len(cases)} circles", value=cases)


# ---------------------------------------------------------------- step 4: the push-out

@CHECKS.check(depends=["loads"])
def push_out_split(sub, functions):
    """Step 4: separate() splits the push-out by inverse mass (a static body never moves)."""
    cases = _function(sub, functions, "separate", "separate", 4)
    for case in cases:
        if case.get("normal_after") is not None:
            text = "separate() changed its argument normal in place: scale a new vector, normal * share"
            raise Fail(f"{text}.\nin '{case['case']}', the normal went from {_vec(case['normal'])} to "
                       f"{_vec(case['normal_after'])}; the World goes on using it.", HINTS["split"],
                       mistake("argument_changed"))
        for body in ("a", "b"):
            got, want, before = case["after"][body], case["want"][body], case["before"][body]
            if _same_point(got, want):
                continue
            letter = body.upper()
            where = f"in '{case['case']}' (push {case['push']:.3f} px, 1/m {case['inv']['a']:.3g} and " \
                    f"{case['inv']['b']:.3g})"
            if _bad(got):
                raise Fail(f"separate() left {letter}'s position {got['bad']}.\n{where}.", HINTS["split"])
            moved = math.dist(got, before)
            should = math.dist(want, before)
            evidence = f"{where}, {letter} moved {moved:.3f} px; expected {should:.3f} px."
            other = "b" if body == "a" else "a"
            total = case["inv"]["a"] + case["inv"]["b"]
            if case["inv"][body] == 0 and moved > 0:
                name, text = "static_moved", f"{letter} is static (1/m = 0) and must never move"
            elif _close(moved, case["push"]) and not _close(should, case["push"]):
                name, text = "push_not_split", "each body got the whole push instead of its share by inverse mass"
            elif _close(moved, case["push"] / 2) and not _close(should, case["push"] / 2):
                name, text = "push_halved", "the push was halved, not split by inverse mass"
            elif total and _close(moved, case["push"] * case["inv"][other] / total):
                name, text = "push_shares_swapped", "the shares are swapped: each body got the other's"
            elif total and not _close(total, 1.0) and _close(moved, case["push"] * case["inv"][body]):
                name, text = "push_missing_total", ("each share is push × 1/m without dividing by the total "
                                                    f"1/m_A + 1/m_B = {total:.3g}")
            elif should and _close(moved, should):
                name, text = "push_wrong_way", "the right distance but the wrong way: A moves back along the " \
                                               "normal, B forward"
            else:
                name, text = None, "separate() does not split the push by inverse mass"
            raise Fail(f"{text}.\n{evidence}", HINTS["split"], mistake(name, text) if name else None)
    return Passed(f"the push-out is split by inverse mass in all {len(cases)} cases", value=cases)


# ---------------------------------------------------------------- steps 5 and 6, declared in probes.py

probes.INERTIA.register(CHECKS, HINTS)
probes.CONTACT.register(CHECKS, HINTS)


# ---------------------------------------------------------------- step 7: friction

# step 7's known wrong forms, by the name the probe gives their outcomes (probes.FRICTION_VARIANTS): the mistake
# (its id, and its sentence: causes.SHARED where Tumbling Crates names the same one) and the hint
FRICTION_TEXT = {
    "none": (mistake("friction_missing"), "friction_missing"),
    "sign": (mistake("friction_sign"), "friction_sign"),
    "unclamped": (mistake("friction_unclamped"), "friction_clamp"),
    "always_full": (mistake("friction_always_full"), "friction_clamp"),
    "bound_mu": (mistake("friction_bound_mu"), "friction_clamp"),
    "clamp_loses_sign": (mistake("friction_clamp_loses_sign"), "friction_clamp"),
    "no_spin_kt": (mistake("kt_no_spin"), "friction_kt"),
    "kt_is_k": (mistake("kt_is_k"), "friction_kt"),
    "kt_no_a_spin": (mistake("kt_missing_a_spin", "kt lacks A's spin term (ra × t)²/I_A: it needs both bodies' "
                                                 "terms"), "friction_kt"),
    "kt_no_b_spin": (mistake("kt_missing_b_spin", "kt lacks B's spin term (rb × t)²/I_B: it needs both bodies' "
                                                 "terms"), "friction_kt"),
    "twice": (mistake("friction_twice"), "friction_missing"),
    "whole_rel": (mistake("friction_whole_rel"), "friction_slip"),
    "at_centre": (mistake("friction_at_centre", "the friction impulse changes no spin (applied at the centres, "
                                                "or the velocities changed without the spins): it cannot turn "
                                                "the ball"), "friction_centre"),
    "bodies_swapped": (mistake("friction_bodies_swapped", "friction is applied with the bodies swapped, "
                                                          "apply_impulse(b, a, t * jt, ra, rb)"), "friction_centre"),
}
# a flipped jt and apply_impulse(b, a, t * jt, rb, ra) give the same velocities: the recorded call tells them apart
ARMS_SWAPPED = (mistake("friction_bodies_arms_swapped", "friction is applied as apply_impulse(b, a, t * jt, rb, ra): "
                                                        "bodies and lever arms swapped, so it pushes along the slip"),
                "friction_order")


def _state_matches(got, want):
    return all(_close(got[k]["omega"], want[k]["omega"]) and all(_close(g, w) for g, w in
                                                                 zip(got[k]["vel"], want[k]["vel"]))
               for k in ("a", "b"))


def _friction_calls(cases):
    """"ba rb,ra" when every case that called apply_impulse twice made its second (the friction) call with B first
    and the lever arms swapped, else "" (probes._calls_recorded)."""
    seconds = [c["calls"][1] for c in cases if len(c.get("calls") or ()) == 2]
    return "ba rb,ra" if seconds and all(call == "ba rb,ra" for call in seconds) else ""


def _describe_state(state, want):
    """The first body whose motion differs, as "B ends with v (x, y) px/s, ω w rad/s; the lesson's ..."."""
    key = next((k for k in ("a", "b") if not _state_matches({"a": state[k], "b": state[k]},
                                                              {"a": want[k], "b": want[k]})), "b")
    return (f"{key.upper()} ends with v {_vec(state[key]['vel'])} px/s, ω {state[key]['omega']:.3f} rad/s; the "
            f"lesson's {_vec(want[key]['vel'])} px/s, {want[key]['omega']:.3f} rad/s")


@CHECKS.check(depends=["loads"])
def friction_rolls(sub, functions):
    """Step 7: resolve()'s friction impulse, jt = -rel·t / kt clamped to ±mu j, acts at the contact and turns the ball."""
    cases = _function(sub, functions, "resolve", "resolve", 7)
    for case in cases:
        for name, now in (case.get("changed") or {}).items():
            text = f"resolve() changed its argument {name} in place: make new vectors (normal.rotate(90), not " \
                   "t = normal then t.rotate_ip(90))"
            raise Fail(f"{text}.\nin '{case['case']}', {name} became {_vec(now)}; the World goes on using it for "
                       "its other contact points.", arguments_hint(7, "resolve"), mistake("argument_changed"))
    for case in cases:
        got, variants = case["got"], case["variants"]
        if _state_matches(got, variants["right"]):
            continue
        fitting = fitting_mistakes(cases, lambda c, key: _state_matches(c["got"], c["variants"][key]),
                                   [key for key in FRICTION_TEXT
                                    if not _state_matches(variants[key], variants["right"])])
        named = fitting[0] if len(fitting) == 1 else None
        found, hint = FRICTION_TEXT.get(named, (None, "friction_missing"))
        if named == "sign" and _friction_calls(cases) == "ba rb,ra":
            found, hint = ARMS_SWAPPED
        where = f"in '{case['case']}' (mu = {case['mu']:.2g})"
        if named == "clamp_loses_sign":
            where += ", where |jt| > mu·j"
        first = found.text if found else "the velocities and spins after resolve() differ from the lesson's"
        raise Fail(f"{first}.\n{where}: {_describe_state(got, variants['right'])}.",
                   HINTS[hint], found)
    return Passed(f"friction matches the lesson in all {len(cases)} contacts", value=cases)


# ---------------------------------------------------------------- the scenes and the lesson's criteria

lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, [
    "loads", "handout_unchanged", "runtime_lines", "closest_point", "inside_case", "push_out_split", "ball_inertia",
    "contact_on_surface", "friction_rolls"], "main() runs each of the checker's three scenes to the end.",
    more=lambda records: {name: run.record for name, run in records.items()})


def _roll(index, expected):
    def measure(records):
        roll = scenes.measure_roll(records["ramp"], index)
        return dict(roll, accel_off=abs(roll["accel"] - expected) / expected)
    return measure


def _inside(records):
    inside = scenes.measure_inside(records["inside"])
    return dict(inside, pushed_through=inside["side"] == "far", not_out=inside["side"] != "near")


LEFT, SANK = "the ball let go on the ramp did not stay on it", "the ball sank into the ramp"
INSIDE = "a ball started with its center inside a crate is not pushed out"
criteria.register(CHECKS, HINTS, (
    Criterion("rolls_without_slipping", "On the 22° ramp (mu 0.6) the ball rolls without slipping, |ω r - v| <= 2 % "
              "of v, at a = ⅔ g sin θ (criterion 1).", _roll(0, scenes.ROLLING), (
                  Bound("left_ramp", 0, LEFT, "settle"),
                  Bound("depth", SINK, SANK, "settle", "px", frame="depth_frame"),
                  Bound("accel_off", ROLL_ACCEL, "the ball does not roll down the ramp at ⅔ g sin θ", "settle"),
                  Bound("slip", ROLL_SLIP, "the ball slips on the ramp instead of rolling", "settle"))),
    Criterion("slides_without_friction", "On a frictionless ramp the ball slides at a = g sin θ (within 1 %) and "
              "does not spin (criterion 2).", _roll(1, scenes.SLIDING), (
                  Bound("left_ramp", 0, LEFT, "settle"),
                  Bound("depth", SINK, SANK, "settle", "px", frame="depth_frame"),
                  Bound("accel_off", SLIDE_ACCEL, "the frictionless ball does not slide at g sin θ", "friction_clamp"),
                  Bound("omega", SLIDE_SPIN, "the frictionless ball spins: with mu = 0 nothing can turn it",
                        "friction_clamp", "rad/s"))),
    Criterion("knocks_crate_over", "The ball rolls off the ramp and knocks a tall crate over, never sinking more "
              "than 1 px into anything (criterion 3).", lambda records: scenes.measure_knock(records["knock"]), (
                  Bound("depth", SINK, "the ball sank into {depth_into}", "settle", "px", frame="depth_frame"),
                  Bound("moved", KNOCK_MOVE, "the ball did not knock the tall crate over", "settle", "px", True),
                  Bound("turned", KNOCK_TURN, "the ball did not knock the tall crate over", "settle", "°", True,
                        180 / math.pi))),
    Criterion("pushed_out_of_crate", "A ball started with its center inside a crate is pushed out of the crate, not "
              "through it (criterion 4).", _inside, (
                  Bound("pushed_through", 0, "a ball with its center inside a crate was pushed through it", "inside"),
                  Bound("depth", INSIDE_DEPTH, INSIDE, "inside", "px"),
                  Bound("not_out", 0, INSIDE, "inside"))),
))
