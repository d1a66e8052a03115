"""Tumbling Crates (Lesson 11 practice exercise): the checks, their bounds and the hints.

Checks, in order: loads, handout_unchanged, runtime_lines; sat_axes (step 2), sat_normal (step 3), resolve_k
(step 4), resolve_friction (step 5), apply_impulse_spin (step 6), each declared (a SharedStep over the probes of
probes.py: the lesson's answer, the known wrong forms); runs, then the four done-criteria, 2 points each:
corner_tips, ramp_holds, pile_stable, fast_movers_zero. resolve is probed with the library's apply_impulse, so
steps 4 and 5 are graded before step 6 is written; the scenes run only when every function check passes, so a
mistake is reported once, under its own step. Every bound was measured on solutions/tumbling_crates.py in the
same scene (lesson11/crate_scenes.py has the scenes and the bounds, each beside its measured value).
"""
import ast
import math
import re

from . import probes
from . import scenes
from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from checker.judging.causes import SHARED, arguments_hint, mistake
from checker.judging.common import close
from lesson11 import records as metrics
from lesson11.crate_scenes import (EXPLODED, GRAVITY, GRAVITY_TOLERANCE, MIN_TURN, PAIR_OVERLAP, PENETRATION,
                                   PILE_DRIFT, PILE_SPEED, RAMP_SLIDE, RAMP_SPEED, REST_OMEGA, REST_SPEED,
                                   TIPPED_FLAT)
from checker.judging.checks import Fail, Hint, Registry
from checker.judging.declared import Form, forms_of
from checker.judging.declared_shared import SharedStep, unchanged_arguments

TITLE = "Tumbling Crates"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("sat",), 3: ("sat",), 4: ("resolve", "lesson_resolve", "effective_mass_inverse"),
                5: ("resolve", "lesson_resolve"), 6: ("apply_impulse",)}
STEP_ADVICE = {2: "write the loop over both shapes' edge normals yourself (project, overlap, keep the smallest)",
               3: "turn the axis round yourself when it points from B to A",
               4: "add the spin terms (ra × n)² / I_A and (rb × n)² / I_B to k yourself",
               5: "clamp jt to [-μ j, μ j] yourself",
               6: "write the two spin lines yourself, like the velocity lines"}

# ---------------------------------------------------------------- tolerances of the function checks
REL = 1e-7      # relative difference allowed against the reference (same inputs, other order of operations)
ABS = 1e-7      # absolute floor of the same (px, px/s, rad/s, impulse units)
TOUCHING = 1e-6  # px: a depth this small for shapes exactly touching counts as "apart"

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "sat_none": Hint(2, "sat() never finds an overlap",
                     "Lesson §2: project both polygons on every edge normal of BOTH shapes; None only when one axis "
                     "shows a gap, else (normal, depth) of the smallest overlap."),
    "sat_depth": Hint(2, "the SAT loop",
                      "Lesson §2: on each axis the overlap is the lower shadow end minus the higher start; keep the "
                      "smallest over both shapes' normals: that axis and depth."),
    "sat_apart": Hint(2, "one gap means apart",
                      "Lesson §2: one axis with a gap means apart: return None as soon as an overlap is <= 0, over "
                      "the edge normals of both shapes."),
    "sat_shape": Hint(2, "what sat() returns",
                      "Lesson §2: sat() returns None when apart, else (normal, depth): a unit Vector2, then the "
                      "overlap in px (the handout's last line)."),
    "normal_flipped": Hint(3, "the normal must point from A to B",
                           "Lesson §3: the kept axis may point either way (each comes from two opposite edges; the "
                           "first wins). Flip it when (B's centre − A's centre) · axis < 0: the axis, not the depth."),
    "k_spin": Hint(4, "the spin terms of the effective mass",
                   "Lesson §5: k = 1/m_A + 1/m_B + (ra × n)²/I_A + (rb × n)²/I_B: a corner hit feels lighter, or "
                   "corner landings kick."),
    "friction_clamp": Hint(5, "Coulomb's clamp on friction",
                           "Lesson §5: keep jt within [-μ j, μ j], j the normal impulse; leave a smaller jt, and "
                           "its sign, alone."),
    "friction_sign": Hint(5, "the sign of the friction impulse",
                          "Lesson §5: friction opposes the slip, jt = -rel·t / kt, and the clamp keeps that sign."),
    "spin_missing": Hint(6, "the two spin updates in apply_impulse",
                         "Lesson §5: each body's spin changes by r × P times its inverse inertia; A uses -=, B uses "
                         "+=, like the velocity lines."),
    "spin_swapped": Hint(6, "the signs of the spin updates",
                         "Lesson §5: A's spin uses -=, B's +=, like the velocity lines; swapped, every touch spins a "
                         "crate faster."),
    "spin_terms": Hint(6, "the two spin updates in apply_impulse",
                       "Lesson §5: each body uses its own lever arm (ra × P for A, rb × P for B) and its own inverse "
                       "inertia; A -=, B +=."),
    "handout": lab_checks.handout_hint("gravity, MAX_CRATES, the scene, the World, the `# lab runtime` lines, the "
                                       "final print"),
    "sinking": Hint(7, "the push-out after the impulses",
                    "The pile sinks: impulses stop the approach but nothing removes the overlap already there; the "
                    "World's push-out (separate) must stay on."),
    "settle": Hint(7, "watch them settle",
                   "The function checks pass, yet crates keep moving: press D and watch the contacts while they "
                   "settle; compare your file with the handout."),
    "runtime": lab_checks.RUNTIME_HINT,
    "print": Hint(7, "the final line",
                  "After the loop print the handout's line: the dynamic crates faster than 30 px/s in the world you "
                  "simulated, e.g. 'Simulated 4.5 s with 8 crates; fast movers now: 0'."),
    "crash": Hint(1, "run the file",
                  "Run the file yourself (python tumbling_crates.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("corner", "ramp", "pile", "own_scene"), "corner_tips": ("corner",), "ramp_holds": ("ramp",),
                  "pile_stable": ("pile",), "fast_movers_zero": ("own_scene",)}

CHECKS = Registry()


# CPU s of the solution's run of each scene (measured 2026-11-23, one job on this 2-core machine): the
# grader starts the longest first, so a long scene does not start last and run alone.
SCENE_SECONDS = {"pile": 4.6, "own_scene": 3.3, "ramp": 1.5, "corner": 0.9}


# ---------------------------------------------------------------- helpers

def _close(got, want):
    return close(got, want, REL, ABS)


_vec = lab_checks.vec_text   # "(x, y)" for messages, shared by the labs


# ---------------------------------------------------------------- loading and the handout

lab_checks.register_common(CHECKS, HINTS, ("sat", "apply_impulse", "resolve", "main"))


# ---------------------------------------------------------------- step 2 and step 3: sat()

def _label(case):
    return f"'{case['pair']}'" + (" with A and B swapped" if case["order"] == "B, A" else "")


def _placeholder_line(source):
    """The line of a bare `return None` left at the top level of sat() before its last return, or None."""
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name == "sat":
            returns = [s for s in node.body if isinstance(s, ast.Return)]
            for statement in returns[:-1]:
                if statement.value is None or (isinstance(statement.value, ast.Constant)
                                               and statement.value.value is None):
                    return statement.lineno
    return None


def _overlaps(case):
    from pygame import Vector2
    pa, pb = [Vector2(p) for p in case["a"]], [Vector2(p) for p in case["b"]]
    return probes.axis_overlaps(pa, pb), len(probes.edge_normals(pa))


def _gap_side(case):
    overlaps, count_a = _overlaps(case)
    return "A's" if any(o <= 0 for _, o, _ in overlaps[:count_a]) else "B's"


def _depth_form(case, depth):
    """The Form of a plausible step-2 loop that gives `depth` for this overlapping pair, or None."""
    overlaps, count_a = _overlaps(case)
    lesson = [o for _, o, _ in overlaps]
    if _close(depth, max(lesson)):
        return Form("sat_largest", "that is the LARGEST overlap: keep the smallest (best_depth starts at math.inf, "
                                   "update when overlap < best_depth)")
    closing = lesson[:count_a - 1] + lesson[count_a:-1]  # every edge but each shape's closing edge
    if closing and _close(depth, min(closing)):
        return Form("sat_closing_edge", "that is the smallest overlap with the closing edge left out: test every "
                                        "edge, the last point back to the first too")
    if _close(depth, min(lesson[:count_a])) or _close(depth, min(lesson[count_a:])):
        which = "A's" if _close(depth, min(lesson[:count_a])) else "B's"
        return Form("sat_one_shape", f"that is the smallest overlap over {which} edge normals only: loop over both "
                                     "shapes' edge normals")
    return None


# step 2's known wrong loops named by their own words (probes.SAT_LOOPS); the others (the largest overlap, one
# shape's normals, the closing edge left out, `break`) keep _depth_form's and the apart message's words
SAT_MISTAKES = {
    "gap_continue": "on an axis with a gap, sat() goes on to the next axis (`continue`) instead of returning None",
    "one_sided": "overlap = max_a - min_b holds only while B lies on A's positive side: the overlap is "
                 "min(max_a, max_b) - max(min_a, min_b)",
    "union": "the overlap is the length of both shadows together; it is the part they share, min(max_a, max_b) - "
             "max(min_a, min_b)",
    "a_twice": "B's shadow is taken from project(pa, axis), A's own: B's is project(pb, axis)",
    "unnormalised": "the axes (-e.y, e.x) are not divided by their length: projections come out |e| times too long",
}


def _same_hit(got, form):
    """Two sat() answers agree: both None, or the same depth and axis up to its sign (step 3, the lesson's in the
    step-2 probe, may have turned it round). "raises" (a probes.SAT_LOOPS loop that keeps no axis) and a malformed
    answer agree with nothing."""
    if got is None or form is None:
        return got is None and form is None
    if "raises" in (got, form) or "bad" in got:
        return False
    return _close(abs(got["depth"]), form["depth"]) and any(
        all(_close(g, sign * f) for g, f in zip(got["normal"], form["normal"])) for sign in (1, -1))


def _sat_fault(case):
    """(what is wrong with sat()'s answer for one pair in step 2, the evidence), (None, None) when nothing is: "gap"
    (a hit where the shapes are apart), "apart" (None where they overlap), "depth", "unit" (the normal's length),
    "axis"."""
    got, want, label = case["got"], case["lesson"], _label(case)
    if want is None:
        if got is None or ("touching" in case["pair"] and abs(got["depth"]) <= TOUCHING):
            return None, None
        return "gap", (f"for {label}, sat() says they overlap by {got['depth']:.2f} px; one of {_gap_side(case)} "
                       "edge normals shows a gap.")
    if got is None:
        return "apart", (f"for {label}, the smallest overlap is {want['depth']:.2f} px along {_vec(want['normal'])}; "
                         "sat() says apart.")
    matches = [ref for ref in (want, case["short"]) if _close(abs(got["depth"]), ref["depth"])]
    if not matches:   # the depth's sign is step 3's business
        deep = " (one shape deep inside the other)" if not _close(want["depth"], case["short"]["depth"]) else ""
        return "depth", (f"for {label}{deep}: depth {abs(got['depth']):.4g} px; the smallest overlap is "
                         f"{want['depth']:.4g} px along {_vec(want['normal'])}.")
    length, ref = math.hypot(*got["normal"]), matches[0]["normal"]
    if abs(length - 1) > 1e-6:
        return "unit", f"for {label}, the normal has length {length:.4g}."
    if abs(abs(got["normal"][0] * ref[0] + got["normal"][1] * ref[1]) - 1) > 1e-6:
        return "axis", (f"for {label}: axis {_vec(got['normal'])}; the smallest overlap is along {_vec(ref)} (or its "
                        "opposite).")
    return None, None


def _sat_screen(cases, sub):
    """Fail first on an answer that is not (normal, depth) or None, and when sat() says apart for every hit."""
    for case in cases:
        if case["got"] is not None and "bad" in case["got"]:
            raise Fail(f"sat() must return (normal, depth) or None.\nfor {_label(case)} it returned "
                       f"{case['got']['bad']}.", HINTS["sat_shape"])
    hits = [case for case in cases if case["lesson"] is not None]
    if all(case["got"] is None for case in hits):
        line = _placeholder_line(sub.source)
        if line:
            text = f"line {line} of {sub.name} is the handout's placeholder `return None`, still there after step 2"
            found = mistake("sat_placeholder", text)
        else:
            text, found = "sat() returned None for every pair, even those that overlap", None
        raise Fail(f"{text}.\nsat() said apart for all {len(hits)} overlapping pairs, e.g. {_label(hits[0])}, "
                   f"{hits[0]['lesson']['depth']:.2f} px deep.", HINTS["sat_none"], found)
    return cases


def _sat_diagnosis(cases, case):
    """A depth right on the wrong axis; a hit where one edge normal shows a gap (a known loop, else the gap)."""
    fault = _sat_fault(case)[0]
    if fault == "axis":
        return Form("sat_axis_apart", "the depth is right but not its axis: keep best_axis and best_depth together")
    if fault == "gap":
        form = SAT_AXES.named(cases, case)
        return Form(form.id, form.text, hint="sat_apart") if form else Form(
            "sat_misses_gap", "sat() says overlap where one edge normal shows a gap", hint="sat_apart",
            line=f"sat() misses a gap: one of {_gap_side(case)} edge normals shows a gap between the shadows")
    return None


SAT_UNNAMED = {"apart": "sat() says apart where the shapes overlap",
               "depth": "sat() does not find the smallest overlap",
               "unit": "sat()'s normal is not a unit vector (edge_normals gives unit axes)"}
# graded on your step 2 with the lesson's step 3 (sat_step2); on sat() as it is when the step markers are broken
SAT_AXES = SharedStep(
    "sat_axes", "Step 2: sat() finds the smallest overlap over both shapes' edge normals (depth and axis), and None "
    "when apart.", 2, "sat", probe_name="sat_step2", fallbacks=("sat",),
    screen=_sat_screen, read=lambda c: c["got"], lesson=lambda c: c["lesson"],
    wrong=forms_of(SAT_MISTAKES, lambda c: c["mistakes"], "sat_"), same=_same_hit,
    accepts=lambda c: _sat_fault(c)[0] is None, diagnose=_sat_diagnosis,
    fallback=lambda cases, c: _depth_form(c, abs(c["got"]["depth"])) if _sat_fault(c)[0] == "depth" else None,
    evidence=lambda c: _sat_fault(c)[1], unnamed=lambda c: SAT_UNNAMED[_sat_fault(c)[0]], hint="sat_depth",
    passed="all {n} pairs give the lesson's depth and axis")
SAT_AXES.register(CHECKS, HINTS)


# step 3's known wrong flips (probes._flip_mistakes_reference), named when one gives every pair's normal
FLIP_MISTAKES = {
    "not_flipped": "the axis is never turned round: every normal points the way edge_normals gave it",
    "reversed": "the flip test is the wrong way round: the axis is turned when it already points from A to B; turn "
                "it when (centre_b - centre_a)·n < 0",
    "always_flipped": "the axis is turned round every time, without the test: turn it only when "
                      "(centre_b - centre_a)·n < 0",
    "first_vertices": "the test uses pb[0] - pa[0], the first corners, instead of centre_of(pb) - centre_of(pa)",
}


def _normal_fault(case):
    """(what is wrong with sat()'s answer for one pair after step 3, the evidence), (None, None) when nothing is:
    "found" (step 3 changed what step 2 found), "part" (more than the direction), "depth" (negated) or "flip" (the
    normal points from B to A)."""
    got, want, before, label = case["answer"], case["lesson"], case["before"], _label(case)
    if (got is None) != (before is None) or (got is not None and "bad" in got):
        said = "apart" if got is None else (f"returns {got['bad']}" if "bad" in got else
                                            f"overlaps by {got['depth']:.2f} px")
        return "found", (f"for {label} sat() says {said}; with step 2 alone it was "
                         f"{'apart' if before is None else 'a hit'}.")
    if got is None or want is None:
        return None, None
    if not _close(abs(got["depth"]), abs(before["depth"])) or \
            abs(abs(got["normal"][0] * before["normal"][0] + got["normal"][1] * before["normal"][1]) - 1) > 1e-6:
        return "part", (f"for {label} step 2 found {abs(before['depth']):.2f} px along {_vec(before['normal'])}; sat() "
                        f"returns {got['depth']:.2f} px along {_vec(got['normal'])}.")
    if got["depth"] < 0:
        return "depth", f"for {label}: depth {got['depth']:.2f} px."
    towards_b = (case["centre_b"][0] - case["centre_a"][0]) * got["normal"][0] + \
                (case["centre_b"][1] - case["centre_a"][1]) * got["normal"][1]
    if towards_b < 0:
        return "flip", (f"for {label} the normal {_vec(got['normal'])} points from B to A; expected "
                        f"{_vec((-got['normal'][0], -got['normal'][1]))}.")
    return None, None


def _normal_screen(cases, sub, step2_cases):
    """No vacuous pass; each pair with sat()'s whole answer (its normal is graded) and what step 2 alone found."""
    if not any(case["got"] is not None and case["lesson"] is not None for case in cases):
        raise Fail(f"sat() found no overlap in any of the {len(cases)} pairs.\nSo the direction of its normal could "
                   "not be graded (nothing was graded).", HINTS["normal_flipped"])
    return [dict(case, answer=case["got"], before=step2["got"]) for case, step2 in zip(cases, step2_cases)]


NORMAL_FAULTS = {
    "found": Form(None, "your step 3 changes what sat() finds; it only turns the normal round"),
    "part": Form("normal_part_flipped", "your step 3 changes more than the normal's direction: turn the whole "
                                        "axis, best_axis = -best_axis"),
    "depth": Form("normal_depth_negated", "sat() gives a negative depth: flip the axis (best_axis = -best_axis), "
                                          "not the depth"),
}


def _same_normal(got, want):
    return (got is None) == (want is None) and (got is None or all(_close(g, w) for g, w in zip(got, want)))


SharedStep(
    "sat_normal", "Step 3: the normal sat() returns points from A to B, with a positive depth.", 3, "sat",
    probe_name="sat", screen=_normal_screen, read=lambda c: c["got"] and c["got"].get("normal"),
    lesson=lambda c: c["lesson"] and c["lesson"]["normal"], wrong=forms_of(FLIP_MISTAKES, lambda c: c["flips"],
                                                                           "normal_"),
    same=_same_normal, accepts=lambda c: _normal_fault(c)[0] is None, diagnose=lambda cases, c: NORMAL_FAULTS.get(
        _normal_fault(c)[0]), evidence=lambda c: _normal_fault(c)[1], unnamed="sat()'s normal points from B to A",
    hint="normal_flipped", passed="the normal points from A to B in all {n} pairs",
).register(CHECKS, HINTS, depends=("loads", "sat_axes"))


# ---------------------------------------------------------------- steps 4 and 5: resolve()

K_MISTAKES = {
    "no_spin": "k has no spin terms",
    "no_a_spin": "k lacks A's spin term (ra × n)² / I_A",
    "no_b_spin": "k lacks B's spin term (rb × n)² / I_B",
    "not_squared": "the spin terms are not squared: (ra × n)² / I_A, not (ra × n) / I_A",
    "inv_mass_in_spin": "the spin terms use inv_mass where inv_inertia belongs",
    "spin_only": "k = replaced the inverse masses instead of adding to them (use k +=)",
    "inertias_swapped": "A's term uses B's inertia and B's uses A's",
    "subtracted": "the spin terms are subtracted; they add to k",
    "a_subtracted": "A's spin term is subtracted; it adds to k",
    "b_subtracted": "B's spin term is subtracted; it adds to k",
    "dot_not_cross": "the spin terms use ra · n (a dot product) where the cross product ra × n belongs",
    "a_with_b_inertia": "A's spin term uses B's inv_inertia; each body's term uses its own",
    "b_with_a_inertia": "B's spin term uses A's inv_inertia; each body's term uses its own",
    "lever_length": "the spin terms use |r|² (as in I = m r²) where (r × n)², the lever arm across the normal, belongs",
}


def _same(got, want):
    return got is not None and want is not None and _close(got, want)


def _push(case):
    """-(1 + e) vn: the normal impulse j times k."""
    return -(1 + case["e"]) * case["vn"]


def _k_evidence(case):
    j = case["j"]
    return (f"in '{case['case']}', your j = {j:.4g}, so your k = {_push(case) / j if j else math.inf:.4g}; expected "
            f"k = {case['k']['right']:.4g} (j = {case['want']:.4g}).")


SharedStep(
    "resolve_k", "Step 4: resolve() applies the normal impulse j = -(1 + e) vn / k with both spin terms in k.", 4,
    "resolve", probe_name="resolve", read=lambda c: c["j"], lesson=lambda c: _push(c) / c["k"]["right"],
    wrong=forms_of(K_MISTAKES, lambda c: {key: _push(c) / k for key, k in c["k"].items() if k}, "k_"), same=_same,
    bad=lambda got: got is None, malformed=lambda c: "resolve() applied no normal impulse where the contact closes."
    f"\nin '{c['case']}', closing at {-c['vn']:.1f} px/s.", evidence=_k_evidence,
    unnamed="the normal impulse's k is not the lesson's", hint="k_spin",
    passed="k and j match the lesson in all {n} contacts").register(CHECKS, HINTS)


def _clamp_form(name, mistake_id, note, hint="friction_clamp"):
    """The wrong clamp `name` of _clamp_forms: a shared mistake (causes.SHARED, Ball on the Ramp's words) with this
    lab's note after its sentence, or the lab's own sentence."""
    shared = mistake_id in SHARED
    return Form(mistake_id, None if shared else note, lambda case: _clamp_forms(case)[name], hint,
                f"{SHARED[mistake_id]} {note}" if shared and note else None)


# the known wrong clamps of step 5 (_clamp_forms): the mistake, its note or sentence, the hint
CLAMP_FORMS = (
    _clamp_form("unclamped", "friction_unclamped", "(min(mu·j, jt) alone clamps nothing: jt <= 0 here)"),
    _clamp_form("vn_signed", "friction_bound_vn_signed", "the clamp uses mu × vn, the closing speed with its sign, "
                "where Coulomb's law uses mu × j"),
    _clamp_form("vn_abs", "friction_bound_vn", "the clamp uses mu × the closing speed |vn| where Coulomb's law uses "
                "mu × j"),
    _clamp_form("slip", "friction_bound_slip", "the clamp uses mu × the slip speed where Coulomb's law uses mu × j"),
    _clamp_form("rel", "friction_bound_rel", "the clamp uses mu × the relative speed |rel| where Coulomb's law uses "
                "mu × j"),
    _clamp_form("k", "friction_bound_k", "the clamp uses mu × k where Coulomb's law uses mu × j"),
    _clamp_form("mu", "friction_bound_mu", ""),
    _clamp_form("half", "friction_bound_half", "the bound is mu·j / 2; Coulomb's law lets |jt| reach mu·j"),
    _clamp_form("always_full", "friction_always_full", ""),
    _clamp_form("clamp_loses_sign", "friction_clamp_loses_sign", ""),
    _clamp_form("sign", "friction_sign", "(a flipped jt, or min(|jt|, mu·j), which loses jt's sign)", "friction_sign"),
)


def _clamp_forms(case):
    """{name: the friction impulse jt a known wrong clamp gives in this case} (CLAMP_FORMS), from the
    case's own j, so a mistake in step 4 does not show here."""
    friction, j, mu, vn = case["friction"], case["j"], case["mu"], case["vn"]
    stop = friction["stop"]

    def clamped(bound):
        return max(-bound, min(bound, stop))
    return {"unclamped": stop, "vn_signed": clamped(mu * vn), "vn_abs": clamped(mu * abs(vn)),
            "slip": clamped(mu * abs(friction["slip"])), "rel": clamped(mu * friction["rel_length"]),
            "k": clamped(mu * case["k"]["right"]), "mu": clamped(mu), "half": clamped(mu * j / 2),
            "always_full": math.copysign(mu * j, stop), "sign": -clamped(mu * j),
            "clamp_loses_sign": mu * j if abs(stop) > mu * j else stop}


def _friction_graded(cases, sub=None):
    """The contacts with a normal impulse and a slip to grade; Fail when none is (nothing graded is no pass)."""
    unchanged_arguments("resolve", "the World goes on using the contact's {name} for its other contact points and "
                        "the push-out", arguments_hint(5, "resolve"))(cases)
    graded = [case for case in cases if case["friction"] is not None and case["j"] is not None]
    if not graded:   # a resolve() that returns before step 4 applies no impulse
        said = "applied no impulse" if all(case["calls"] == 0 for case in cases) else "left no slip to stop"
        raise Fail(f"resolve() {said} in any of the {len(cases)} contacts: nothing was graded.\n"
                   "Write step 4 (the normal impulse) first, then step 5's friction after it.",
                   HINTS["friction_clamp"])
    return graded


def _friction_read(case):
    """The student's jt, or nan when the friction impulse also pushes off the tangent."""
    jt = case["friction"]["jt"]
    return jt if case["friction"]["off_tangent"] <= ABS + REL * abs(jt) else math.nan


def _friction_diagnosis(cases, case):
    """No friction impulse at all; or a clamp that loses the sign, which a flipped jt gives too wherever a case
    tells them apart (every case that decides it binds): the sign's sentence names both."""
    if case["friction"].get("missing"):
        return Form("friction_missing", None)
    fitting = [form for form in CLAMP_FORMS if not _same(case["forms"][form.id], case["want"])
               and all(_same(c["got"], c["forms"][form.id]) for c in cases)]
    return fitting[-1] if [form.id for form in fitting] == ["friction_clamp_loses_sign", "friction_sign"] else None


def _friction_fallback(cases, case):
    """What one case shows when no known clamp is named."""
    stop, jt, bound = case["friction"]["stop"], case["friction"]["jt"], case["mu"] * case["j"]
    active = abs(stop) > abs(bound)
    if jt * stop < 0:
        return Form(None, "friction pushes the slide along instead of against it", hint="friction_sign")
    if active and _close(jt, stop):
        return Form(None, "the friction impulse was not clamped here (no clamp, or a bound above mu·j)")
    if not active and _close(abs(jt), abs(bound)):
        return Form(None, "friction takes its full mu·j where a smaller impulse already stops the slip")
    return Form(None, "the clamp is too tight: |jt| may reach mu·j") if active and abs(jt) < abs(bound) else None


def _clamping(cases):
    return sum(1 for case in cases if abs(case["friction"]["stop"]) > case["mu"] * abs(case["j"]))


def _friction_evidence(case):
    stop, j, mu = case["friction"]["stop"], case["j"], case["mu"]
    where = f"in '{case['case']}'" + (", where |jt| > mu·j" if abs(stop) > abs(mu * j) else "")
    return (f"{where}: the slip needs jt = {stop:.4g}, mu·j = {mu:.2g} × {j:.4g} = {mu * j:.4g}, so jt = "
            f"{case['want']:.4g}; yours {case['friction']['jt']:.4g}.")


SharedStep(
    "resolve_friction", "Step 5: resolve() clamps friction with Coulomb's law, |jt| <= mu j, and leaves smaller jt "
    "alone.", 5, "resolve", probe_name="resolve", screen=_friction_graded, read=_friction_read,
    lesson=lambda c: max(-c["mu"] * c["j"], min(c["mu"] * c["j"], c["friction"]["stop"])),   # with your own j
    wrong=CLAMP_FORMS, same=_same, diagnose=_friction_diagnosis, fallback=_friction_fallback,
    evidence=_friction_evidence, unnamed="the friction impulse is not Coulomb's clamped jt", hint="friction_clamp",
    passed=lambda cases: f"friction matches Coulomb's law in all {len(cases)} contacts ({_clamping(cases)} of them "
    "clamped)").register(CHECKS, HINTS)


# ---------------------------------------------------------------- step 6: apply_impulse()

def _motion(bodies):
    """Both bodies' motion laid flat: [vA.x, vA.y, ωA, vB.x, vB.y, ωB]."""
    return [x for side in "ab" for x in (*bodies[side]["vel"], bodies[side]["omega"])]


def _first_wrong(case):
    """(body "a" or "b", "vel" or "omega", the evidence): the first part of the motion that is not the lesson's."""
    for side in "ab":
        (before, after, want), letter = (case[key][side] for key in ("before", "after", "expected")), side.upper()
        if not all(_close(g, w) for g, w in zip(after["vel"], want["vel"])):
            return side, "vel", (f"in '{case['case']}', {letter} moves at {_vec(after['vel'])} px/s after the "
                                 f"impulse; expected {_vec(want['vel'])}.")
        if not _close(after["omega"], want["omega"]):
            return side, "omega", (f"in '{case['case']}', ω{letter} went from {before['omega']:.4g} to "
                                   f"{after['omega']:.4g} rad/s; expected {want['omega']:.4g} "
                                   f"({want['omega'] - before['omega']:+.4g}).")


def _spin_diagnosis(cases, case):
    """The step-6 mistake one body's motion shows in this case: its velocity changed, or a known wrong spin update."""
    body, part, _ = _first_wrong(case)
    letter, other, sign = body.upper(), "b" if body == "a" else "a", -1 if body == "a" else 1
    if part == "vel":
        return Form(None, f"{letter}'s velocity changed: keep the handout's velocity lines (a.vel -= impulse * "
                          "a.inv_mass, b.vel +=)")
    before, after, want = (case[key][body]["omega"] for key in ("before", "after", "expected"))
    change, inv_mass, inv_inertia = want - before, *case["inv"][body]
    if _close(after, change) and not _close(change, want):
        return Form("spin_assigned", f"{letter}'s spin was set to the change instead of changed by it: use "
                                     f"{body}.omega {'-' if body == 'a' else '+'}=")
    for value, name, text, key in (
            (0.0, "spin_missing", f"{letter}'s spin did not change: its spin update is missing", "spin_missing"),
            (-change, "spin_wrong_way", f"{letter}'s spin changed the wrong way: A uses -=, B uses += (cross(ra, P) "
                                        "= -cross(P, ra))", "spin_swapped"),
            (sign * case["cross"][body] * inv_mass, "spin_inv_mass",
             f"{letter}'s spin update uses inv_mass where inv_inertia belongs", "spin_terms"),
            (sign * case["cross"][other] * inv_inertia, "spin_other_lever",
             f"{letter}'s spin update uses r{other} where r{body} belongs", "spin_terms"),
            (sign * case["cross"][body] * case["inv"][other][1], "spin_other_inertia",
             f"{letter}'s spin update uses {other.upper()}'s inv_inertia", "spin_terms")):
        if _close(after - before, value) and not _close(value, change):
            return Form(name, text, hint=key)
    return Form(None, f"{letter}'s spin change is not -(ra × P)/I_A, +(rb × P)/I_B")


SharedStep(
    "apply_impulse_spin", "Step 6: apply_impulse() changes both spins, A by -(ra × P)/I_A and B by +(rb × P)/I_B.",
    6, "apply_impulse", probe_name="apply_impulse", read=lambda c: _motion(c["after"]),
    lesson=lambda c: _motion(c["expected"]), same=lambda got, want: all(_close(g, w) for g, w in zip(got, want)),
    screen=unchanged_arguments("apply_impulse", "resolve() goes on using its {name} for the friction impulse",
                               arguments_hint(6, "apply_impulse")),
    diagnose=_spin_diagnosis, evidence=lambda c: _first_wrong(c)[2], hint="spin_terms",
    passed="both spins change as the lesson says in all {n} cases").register(CHECKS, HINTS)


# ---------------------------------------------------------------- the scenes and the lesson's criteria

lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, ["loads", "handout_unchanged", "runtime_lines", "sat_normal",
                         "resolve_k", "resolve_friction", "apply_impulse_spin"], "main() runs each of the checker's four "
                         "scenes to the end, with the course's gravity.", "a crate", ("corner", GRAVITY, GRAVITY_TOLERANCE))


def _escapes(record):
    return criteria.escapes(metrics.summary(record), EXPLODED)


def _corner(records):
    record = records["corner"].record
    return [dict(_escapes(record), **crate, sink=-crate["floor_gap"]) for crate in scenes.measure_corner(record)]


def _ramp(records):
    record = records["ramp"].record
    return dict(_escapes(record), slid=max(abs(crate["slid"]) for crate in metrics.measure_ramp(record)),
                tail_speed=metrics.summary(record)["tail_speed"])


def _pile(records):
    return dict(_escapes(records["pile"].record), **metrics.measure_pile(records["pile"].record))


LINE = re.compile(r"Simulated\s+(-?[\d.]+)\s*s\s+with\s+(\d+)\s+crates?;\s*fast movers now:\s*(\d+)")


def _printed(records):
    """The clicked drops, the printed line and whether it matches the run's last frame, the fast movers."""
    run = records["own_scene"]
    out = {"crates_dropped": metrics.drops_added(run.record), "final_line_printed": bool(LINE.findall(run.stdout))}
    if out["final_line_printed"]:
        seconds, crates, movers = LINE.findall(run.stdout)[-1]
        last = run.record["records"][-1]
        out.update(fast_movers_printed=int(movers), printed_line_matches_the_run=(
            int(movers) == metrics.fast_movers(last) and int(crates) == len(metrics.dynamic(last))
            and abs(float(seconds) - last["frame"] / metrics.FPS) <= 0.15))
        out.update(_escapes(run.record) if int(movers) else {"flung": False, "fell_through": 0, "off_screen": 0})
    return out


CRATES, STILL = "crates", "a crate is still moving 2.5 s after the drop"
criteria.register(CHECKS, HINTS, (
    Criterion("corner_tips", "A crate that lands on a corner tips over onto a flat side and comes to rest "
              "(criterion 1).", _corner, criteria.escape_bounds(CRATES, "settle") + (
                  Bound("sink", PENETRATION, "a crate landed on its corner and sank into the floor", "sinking", "px"),
                  Bound("turned", MIN_TURN, "a crate landed on a corner but did not tip over", "settle", "°", True,
                        180 / math.pi),
                  Bound("flat_error", TIPPED_FLAT, "a crate landed on a corner but did not end on a flat side",
                        "settle", "°", scale=180 / math.pi),
                  Bound("rest_speed", REST_SPEED, STILL, "settle", "px/s"),
                  Bound("rest_omega", REST_OMEGA, STILL, "settle", "rad/s"))),
    Criterion("ramp_holds", "Crates set on the 22° ramp (friction 0.6) stay put (criterion 2).", _ramp,
              criteria.escape_bounds(CRATES, "settle") + (
                  Bound("slid", RAMP_SLIDE, "crates at rest on the 22° ramp did not stay put: friction 0.6 holds "
                        "them", "settle", "px"),
                  Bound("tail_speed", RAMP_SPEED, "crates at rest on the 22° ramp did not stay put: friction 0.6 "
                        "holds them", "settle", "px/s"))),
    Criterion("pile_stable", "A pile of a dozen crates neither sinks into the floor nor jitters apart "
              "(criterion 3).", _pile, criteria.escape_bounds(CRATES, "settle") + (
                  Bound("floor_penetration", PENETRATION, "the pile sinks", "sinking", "px"),
                  Bound("pair_overlap", PAIR_OVERLAP, "the pile sinks", "sinking", "px"),
                  Bound("tail_speed", PILE_SPEED, "the pile jitters apart", "settle", "px/s"),
                  Bound("drift", PILE_DRIFT, "the pile jitters apart", "settle", "px"))),
    Criterion("fast_movers_zero", "After four clicked drops the program prints `fast movers now: 0`, matching the "
              "simulation (criterion 4).", _printed, (
                  Bound("crates_dropped", len(scenes.DROPS), "every click must drop a crate (MAX_CRATES is 14)",
                        "handout", least=True),
                  Bound("final_line_printed", 1, "when the window closed, the program printed no final line",
                        "print", least=True),
                  Bound("printed_line_matches_the_run", 1, "the printed line does not match the simulation (a fast "
                        f"mover: over {metrics.FAST_MOVER:g} px/s)", "print", least=True)) + criteria.escape_bounds(CRATES, "settle") + (
                  Bound("fast_movers_printed", 0, "dropped crates do not come to rest", "settle"),)),
))
