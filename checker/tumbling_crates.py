"""Tumbling Crates (Lesson 11 practice exercise): the checks, their bounds and the hints.

Order of checks (stable): loads, runtime_lines, sat, apply_impulse, resolve,
runs, then the lesson's four done-criteria: corner_tips, ramp_holds,
pile_stable, fast_movers_zero. Function checks are worth 1 point, the four
criteria 2 points each.

Every bound below was set from what solutions/tumbling_crates.py measures in
the same scenario (see checker/crates_scenarios.py for the scenes), with the
measured value noted next to it.
"""
import ast
import math
import re

from . import crates_scenarios as scenes
from .checks import Error, Fail, Hint, Registry

TITLE = "Tumbling Crates"
REQUIRED = ("sat", "apply_impulse", "resolve", "main")
RUNTIME_HOOKS = ("seed", "scene", "frame_budget", "tick", "events", "record")

# ---------------------------------------------------------------- bounds (measured on the solution)
TIPPED_FLAT = math.radians(6)   # rad from flat at the end; solution: 0.4°-0.5°
MIN_TURN = 0.3                  # rad turned while tipping; solution: 0.51-0.56 (the drop angles are 0.5, 0.55)
REST_SPEED = 5.0                # px/s over the last 0.5 s; solution: 0.01
REST_OMEGA = 0.2                # rad/s over the last 0.5 s; solution: 0.0002
PENETRATION = 3.0               # px below the floor's top face; solution: corner 0.50, pile 0.79
PAIR_OVERLAP = 3.0              # px between two crates in the pile; solution: 0.88
# The ramp: physics2d's World moves bodies (x += v dt) before it solves the contacts, so a crate
# resting on a slope creeps g·sin(22°)·dt = 3.06 px/s downhill whatever its friction. The solution
# measures 9.2-10.3 px in 3 s (velocities after the solve stay below 0.5 px/s); with the contacts
# solved before the positions move (as Box2D-Lite does) it measures 1.3 px. Bound: 15 px.
RAMP_SLIDE = 15.0               # px along the slope in 3 s; solution: 9.2-10.3 (integrator creep)
RAMP_SPEED = 5.0                # px/s in the last second; solution: 2.45
PILE_SPEED = 30.0               # px/s in the last second (the lab's fast-mover speed); solution: 16.4
PILE_DRIFT = 10.0               # px a crate's centre may move during the last second; solution: 3.2 (the same
                                # integrator creep as on the ramp; below 1 px with the solve-then-move order)
EXPLODED = 1500.0               # px/s: faster than any fall in these scenes (free fall from the top: ~1100)

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "no_overlap": Hint(2, "sat() never finds an overlap",
                       "Crates fall through the floor because sat() never reports a hit. Project both polygons "
                       "on every edge normal of BOTH shapes, return None only when one axis shows a gap, and "
                       "otherwise return (normal, depth) for the axis with the smallest overlap."),
    "sat_depth": Hint(2, "the SAT loop",
                      "Keep the smallest overlap min(maxA, maxB) - max(minA, minB) over all edge normals of both "
                      "shapes; that axis and overlap are the normal and depth (the minimum translation vector)."),
    "sat_apart": Hint(2, "the SAT loop",
                      "A single axis with a gap means 'not touching': return None as soon as an overlap is <= 0, and "
                      "test the edge normals of both shapes (the diamond's diagonal axis shows the gap)."),
    "normal_flipped": Hint(3, "the normal must point from A to B",
                           "Crates are shot apart (or pulled into each other) because the normal points the wrong "
                           "way about half the time. Flip it when (center_b - center_a) · normal < 0."),
    "k_spin": Hint(4, "the spin terms of the effective mass",
                   "A corner hit should feel lighter: add (ra × n)² / Ia + (rb × n)² / Ib to k, or the impulse "
                   "is too big and corners bounce and crates slide off the ramp."),
    "friction_unclamped": Hint(5, "Coulomb's clamp on friction",
                               "A glancing touch stops a crate dead because the friction impulse is not clamped. "
                               "Cap it so |jt| <= mu * j: jt = max(-mu * j, min(mu * j, jt))."),
    "friction_sign": Hint(5, "the sign of the friction impulse",
                          "Sliding crates speed up and spin up instead of slowing down: a sign in the friction or "
                          "spin update is flipped. jt = -rel·t / kt, and friction goes through the same "
                          "apply_impulse as the normal impulse."),
    "spin_missing": Hint(6, "the two spin updates in apply_impulse",
                         "Crates land but never tip over because apply_impulse changes only the velocities. Add "
                         "a.omega -= cross(ra, impulse) * a.inv_inertia and b.omega += cross(rb, impulse) * b.inv_inertia."),
    "spin_swapped": Hint(6, "the signs of the spin updates",
                         "The spin lines in apply_impulse have swapped signs: A uses -=, B uses +=, exactly like the "
                         "velocity lines. With the wrong signs corners spin the wrong way and crates fly off."),
    "velocity": Hint(6, "apply_impulse",
                     "Equal and opposite: a.vel -= impulse * a.inv_mass and b.vel += impulse * b.inv_mass."),
    "sinking": Hint(7, "the push-out after the impulses",
                    "The pile sinks: impulses stop the approach but nothing removes the overlap that is already "
                    "there. The World's push-out (separate, the second stabiliser in 'Impulses That Spin, and "
                    "Friction') must stay on: do not pass World a separate that does nothing."),
    "settle": Hint(7, "watch them settle",
                   "Crates keep moving where they should rest. Press D and watch the contact points and normals: "
                   "check the spin terms (step 4), the friction clamp (step 5) and the spin updates (step 6)."),
    "runtime": Hint(None, "the lines marked # lab runtime",
                    "Keep the lines marked `# lab runtime` from the handout (lab.seed, lab.scene, lab.frame_budget, "
                    "lab.tick, lab.events, lab.record): they do nothing when you run the file yourself, and the "
                    "checker needs them to run it headless."),
    "print": Hint(7, "the final line",
                  "After the loop, print the line the handout prints: count the dynamic crates whose speed is "
                  "above 30 px/s in the world you simulated, e.g. "
                  "'Simulated 5.5 s with 8 crates; fast movers now: 0'."),
    "crash": Hint(1, "run the file",
                  "Run the file yourself (python tumbling_crates.py) and fix the error at the line shown."),
}

# Function-level diagnoses, most basic first: a criterion that fails takes the first one found.
PRIORITY = ("no_overlap", "sat_apart", "sat_depth", "normal_flipped", "velocity", "spin_swapped", "spin_missing",
            "friction_sign", "friction_unclamped", "k_spin")

CHECKS = Registry()


def recognise(path, source):
    """True if the file is a Tumbling Crates lab: its name or its text says so."""
    name = path.replace("\\", "/").rsplit("/", 1)[-1].lower()
    return "tumbling_crates" in name or "tumbling crates" in source.lower()


def scenarios():
    """The scenario runs this lab needs, by name (settings for lesson11.runtime.configure)."""
    return {name: build() for name, build in scenes.SCENARIOS.items()}


# ---------------------------------------------------------------- helpers

def describe_run_failure(run, lab_name, what):
    """A one-paragraph account of a run that did not finish: crash, exit, timeout, flood or memory."""
    error = run.result.get("error") or {}
    at = f"{lab_name}, line {error['line']}" if error.get("line") else lab_name
    text = f": {error['text']}" if error.get("text") else ""
    if run.status == "timeout" and getattr(run, "cut_short", False):
        return (f"{what} was still running when the time limit for the whole run ({run.total_timeout:g} s) ran "
                "out; grade this file again with a longer --total-timeout.")
    if run.status == "timeout":
        line = _timeout_line(run.timeout_trace, run.lab_path)
        where = f" (it was at {lab_name}, line {line[0]}{': ' + line[1] if line[1] else ''})" if line else ""
        phase = run.result.get("phase")
        if phase == "import":
            return (f"{what} did not finish importing within {run.timeout:.3g} s{where}: is there an endless loop "
                    "outside main()?")
        return (f"{what} was stopped after {run.timeout:.3g} s{where}: the loop never ended. Is "
                "`and lab.frame_budget()` still in the while condition?")
    if run.status == "flood":
        return f"{what} printed more than {run.max_output // 1024} KB of output and was stopped."
    if error.get("kind") == "exit":
        return f"{what} ended the program: {error['message']} at {at}{text}."
    if error.get("kind") == "memory" or (run.returncode or 0) in (-9,) and not error:
        return f"{what} ran out of memory (limit {run.memory_mb} MB) at {at}{text}."
    if error:
        return f"{what} raised {error['message']} at {at}{text}."
    return (f"{what} ended the process unexpectedly (exit code {run.returncode}) before the checker could "
            f"record a result. Last output: {(run.stderr or run.stdout).strip()[-300:] or 'none'}")


def _timeout_line(trace, lab_path):
    """(line, text) of the innermost frame in the lab file from a faulthandler dump, or None."""
    if not trace or not lab_path:
        return None
    found = None
    for match in re.finditer(r'File "([^"]+)", line (\d+)', trace):
        if match.group(1) == lab_path:
            found = int(match.group(2))
            break  # faulthandler lists the most recent call first
    if found is None:
        return None
    try:
        with open(lab_path, encoding="utf-8", errors="replace") as handle:
            lines = handle.read().splitlines()
        return found, lines[found - 1].strip() if 0 < found <= len(lines) else ""
    except OSError:
        return found, ""


def _close(a, b, tol):
    return abs(a - b) <= tol


def _vec_close(a, b, tol):
    return math.hypot(a[0] - b[0], a[1] - b[1]) <= tol


def first_diagnosis(ctx):
    """The most basic function-level diagnosis found by the sat/apply_impulse/resolve checks, or None."""
    for key in PRIORITY:
        if key in ctx.diagnoses:
            return key
    return None


def _fail_with(ctx, rationale, fallback):
    """Fail a criterion, naming the function-level bug if one was found, else `fallback`."""
    key = first_diagnosis(ctx) or fallback
    if key in ("no_overlap", "settle") and "sinking" in ctx.diagnoses and not first_diagnosis(ctx):
        key = "sinking"  # sat() is right (its check passed): crates sank through because nothing pushes them out
    raise Fail(rationale, HINTS[key])


def _escaped(ctx, summary, what):
    """Fail if crates fell through the floor or were flung away; the hint follows what was seen."""
    flung = summary["highest_y"] < -50 or (summary["peak_speed"] > EXPLODED and summary["off_screen"]
                                           and summary["fell_through"] < summary["crates"])
    if flung:
        key = "friction_sign" if summary["tail_omega"] > 20 else "normal_flipped"
        _fail_with(ctx, f"{what}: crates were flung apart (top speed {summary['peak_speed']:.0f} px/s, spin up to "
                   f"{summary['tail_omega']:.0f} rad/s at the end; {summary['off_screen']} of {summary['crates']} "
                   "left the screen).", key)
    if summary["fell_through"]:
        _fail_with(ctx, f"{what}: {summary['fell_through']} of {summary['crates']} crates fell through the floor "
                   f"(top speed {summary['peak_speed']:.0f} px/s).", "no_overlap")
    if summary["off_screen"]:
        _fail_with(ctx, f"{what}: {summary['off_screen']} of {summary['crates']} crates left the screen.", "settle")


def _record(ctx, name):
    run = ctx.scenarios[name]
    record = run.record or {}
    frames = record.get("records") or []
    if not frames:
        raise Fail(f"the '{name}' scene recorded no frames: main() returned before its loop ran, or the loop "
                   "does not call lab.record(...).", HINTS["runtime"])
    if not scenes.finite(frames):
        _fail_with(ctx, f"in the '{name}' scene a crate's position or speed became infinite or NaN.", "settle")
    return record


# ---------------------------------------------------------------- the checks

@CHECKS.check()
def loads(ctx):
    """The file imports without errors and defines sat, apply_impulse, resolve and main."""
    run = ctx.probe
    if run.status != "done":
        raise Error(describe_run_failure(run, ctx.name, "The file"), HINTS["crash"])
    missing = run.result["probe"]["missing"]
    if missing:
        raise Error(f"{ctx.name} defines no function {missing[0]}() (missing: {', '.join(missing)}).",
                    Hint(None, "the handout's functions", "Keep the handout's function names: sat, apply_impulse, "
                         "resolve and main; the checker calls them."))


@CHECKS.check(depends=["loads"])
def runtime_lines(ctx):
    """The lines marked `# lab runtime` are still there (seed, scene, frame_budget, tick, events, record)."""
    try:
        tree = ast.parse(ctx.source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise Error(f"{ctx.name} could not be read as Python source.", HINTS["crash"])
    called = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            func = node.func
            if isinstance(func, ast.Attribute):
                called.add(func.attr)
            elif isinstance(func, ast.Name):
                called.add(func.id)
    missing = [hook for hook in RUNTIME_HOOKS if hook not in called]
    if missing:
        raise Fail("the lab-runtime call" + ("s " if len(missing) > 1 else " ")
                   + ", ".join(f"lab.{m}()" for m in missing) + " " + ("are" if len(missing) > 1 else "is")
                   + " missing, so the checker cannot run the file headless.", HINTS["runtime"])


@CHECKS.check(depends=["loads"])
def sat(ctx):
    """sat() on the lesson's three pairs: 10 px along (1, 0); apart; 5.86 px along (0.71, 0.71)."""
    data = _function(ctx, "sat")
    expected = {"side by side, 10 px overlap": ((1.0, 0.0), 10.0), "diamond near a corner": None,
                "diamond pushed closer": ((math.sqrt(0.5), math.sqrt(0.5)), 20 - 10 * math.sqrt(2))}
    hits = [case["result"] for case in data]
    if all(hit is None for hit in hits):
        ctx.diagnoses.add("no_overlap")
        raise Fail("sat() returned None for every pair, even the two that overlap (10 px and 5.86 px).",
                   HINTS["no_overlap"])
    for case in data:
        want = expected[case["pair"]]
        got = case["result"]
        swapped = case["order"] == "B, A"
        label = f"'{case['pair']}'" + (" with A and B swapped" if swapped else "")
        if want is None:
            if got is not None:
                ctx.diagnoses.add("sat_apart")
                raise Fail(f"sat() says {label} overlaps by {got['depth']:.2f} px, but the shapes are apart "
                           "(only their bounding boxes overlap).", HINTS["sat_apart"])
            continue
        normal, depth = want
        if swapped:
            normal = (-normal[0], -normal[1])
        if got is None:
            ctx.diagnoses.add("no_overlap")
            raise Fail(f"sat() says {label} is apart, but the shapes overlap by {depth:.2f} px.", HINTS["no_overlap"])
        if not _close(got["depth"], depth, 0.05):
            ctx.diagnoses.add("sat_depth")
            raise Fail(f"sat() gives depth {got['depth']:.2f} px for {label}; expected {depth:.2f} px.",
                       HINTS["sat_depth"])
        if _vec_close(got["normal"], (-normal[0], -normal[1]), 0.02):
            ctx.diagnoses.add("normal_flipped")
            raise Fail(f"sat() gives normal ({got['normal'][0]:.2f}, {got['normal'][1]:.2f}) for {label}: it points "
                       f"from B to A; expected ({normal[0]:.2f}, {normal[1]:.2f}).", HINTS["normal_flipped"])
        if not _vec_close(got["normal"], normal, 0.02):
            ctx.diagnoses.add("sat_depth")
            raise Fail(f"sat() gives normal ({got['normal'][0]:.2f}, {got['normal'][1]:.2f}) for {label}; expected "
                       f"({normal[0]:.2f}, {normal[1]:.2f}).", HINTS["sat_depth"])


@CHECKS.check(depends=["loads"])
def apply_impulse(ctx):
    """apply_impulse() on an off-centre hit changes both velocities and both spins with the lesson's signs."""
    data = _function(ctx, "apply_impulse")
    after, want = data["after"], data["expected"]
    for body in ("a", "b"):
        if not _vec_close(after[body]["vel"], want[body]["vel"], 1e-6 + 1e-6 * math.hypot(*want[body]["vel"])):
            ctx.diagnoses.add("velocity")
            raise Fail(f"body {body.upper()}'s velocity after the impulse is ({after[body]['vel'][0]:.1f}, "
                       f"{after[body]['vel'][1]:.1f}) px/s; expected ({want[body]['vel'][0]:.1f}, "
                       f"{want[body]['vel'][1]:.1f}).", HINTS["velocity"])
    got = (after["a"]["omega"], after["b"]["omega"])
    expect = (want["a"]["omega"], want["b"]["omega"])
    if all(abs(g) < 1e-9 for g in got):
        ctx.diagnoses.add("spin_missing")
        raise Fail("an impulse (0, 300) at ra = (25, 18), rb = (-20, -22) left both spins at 0 rad/s; expected "
                   f"ωA = {expect[0]:.2f}, ωB = {expect[1]:.2f} rad/s.", HINTS["spin_missing"])
    wrong = [name for name, g, e in zip("AB", got, expect) if not _close(g, e, 1e-6 + 1e-6 * abs(e))]
    if not wrong:
        return None
    flipped = [name for name, g, e in zip("AB", got, expect) if _close(g, -e, 1e-6 + 1e-6 * abs(e))]
    ctx.diagnoses.add("spin_swapped" if flipped else "spin_missing")
    raise Fail(f"after an off-centre hit ωA = {got[0]:.2f}, ωB = {got[1]:.2f} rad/s; expected ωA = {expect[0]:.2f}, "
               f"ωB = {expect[1]:.2f}" + (f" (the sign of {' and '.join(flipped)} is reversed)." if flipped else "."),
               HINTS["spin_swapped" if flipped else "spin_missing"])


@CHECKS.check(depends=["loads", "apply_impulse"])
def resolve(ctx):
    """resolve() clamps friction (|jt| <= mu j) with the right sign and includes the spin terms in k."""
    data = _function(ctx, "resolve")
    for name in ("glancing", "sliding"):
        # The floor is static and the normal vertical, so the crate's momentum change along x is the
        # friction impulse F and along y the normal impulse j. Coulomb: F opposes the slide, |F| <= mu j.
        case = data[name]
        mass = case["mass"]
        friction = mass * (case["vel_after"][0] - case["vel_before"][0])
        normal = mass * abs(case["vel_after"][1] - case["vel_before"][1])
        slide = case["vel_before"][0]
        if friction > 1e-6:
            ctx.diagnoses.add("friction_sign")
            raise Fail(f"a crate sliding right at {slide:.0f} px/s over the floor was pushed further right by "
                       f"friction (its speed went up by {friction / mass:.1f} px/s): friction must oppose the slide.",
                       HINTS["friction_sign"])
        if abs(friction) > case["mu"] * normal * 1.05 + 1e-6:
            ctx.diagnoses.add("friction_unclamped")
            raise Fail(f"a {'glancing' if name == 'glancing' else 'sliding'} touch ({-case['vn_before']:.0f} px/s into the "
                       f"floor) gave a friction impulse of {abs(friction):.1f}, more than mu·j = "
                       f"{case['mu']:.1f} × {normal:.1f} = {case['mu'] * normal:.1f}; it cut the {slide:.0f} px/s slide "
                       f"to {case['vel_after'][0]:.0f} px/s.", HINTS["friction_unclamped"])
    corner = data["corner"]
    if abs(corner["vn_after"]) > 0.05 * abs(corner["vn_before"]):
        ctx.diagnoses.add("k_spin")
        raise Fail(f"a crate landing on a corner at {abs(corner['vn_before']):.0f} px/s with restitution 0 should "
                   f"stop closing (normal speed 0), but leaves at {corner['vn_after']:.1f} px/s.", HINTS["k_spin"])


def _function(ctx, name):
    entry = ctx.probe.result["probe"]["functions"].get(name)
    if entry is None:
        raise Error(f"{ctx.name} defines no {name}().", HINTS["crash"])
    if not entry["ok"]:
        error = entry["error"]
        at = f"{ctx.name}, line {error['line']}" if error.get("line") else ctx.name
        text = f": {error['text']}" if error.get("text") else ""
        raise Error(f"{name}() raised {error['message']} at {at}{text}.", HINTS["crash"])
    return entry["data"]


@CHECKS.check(depends=["loads", "runtime_lines"])
def runs(ctx):
    """main() runs each of the checker's four scenes to the end without an error."""
    for name in scenes.SCENARIOS:
        run = ctx.scenarios.get(name)
        if run is None:
            raise Error(f"the '{name}' scene was not run (the time limit for the whole run ran out).")
        if run.status != "done":
            raise Error(describe_run_failure(run, ctx.name, f"main() in the '{name}' scene"), HINTS["crash"])
    # Diagnoses visible in the scenes themselves (the push-out is World's, not a student function).
    pile = ctx.scenarios["pile"].record or {}
    if pile.get("records") and scenes.finite(pile["records"]) and not (
            scenes.summary(pile)["off_screen"] or scenes.summary(pile)["fell_through"]):
        measured = scenes.measure_pile(pile)
        if measured["floor_penetration"] > PENETRATION or measured["pair_overlap"] > PAIR_OVERLAP:
            ctx.diagnoses.add("sinking")


@CHECKS.check(depends=["runs"], max_score=2)
def corner_tips(ctx):
    """A crate that lands on a corner tips over onto a flat side and comes to rest (criterion 1)."""
    record = _record(ctx, "corner")
    summary = scenes.summary(record)
    _escaped(ctx, summary, "two crates dropped on a corner did not land")
    for index, crate in enumerate(scenes.measure_corner(record), 1):
        if -crate["floor_gap"] > PENETRATION:
            raise Fail(f"crate {index} landed on its corner but sank {-crate['floor_gap']:.1f} px into the floor "
                       f"(bound {PENETRATION:g} px).", HINTS[first_diagnosis(ctx) or "sinking"])
        if crate["turned"] < MIN_TURN or crate["flat_error"] > TIPPED_FLAT:
            _fail_with(ctx, f"crate {index} landed on a corner but did not tip onto a flat side: it turned "
                       f"{math.degrees(crate['turned']):.0f}° and ended {math.degrees(crate['flat_error']):.0f}° "
                       f"from flat (bound {math.degrees(TIPPED_FLAT):.0f}°).", "spin_missing")
        if crate["rest_speed"] > REST_SPEED or crate["rest_omega"] > REST_OMEGA:
            _fail_with(ctx, f"crate {index} tipped over but is still moving 2.5 s after the drop "
                       f"({crate['rest_speed']:.1f} px/s, {crate['rest_omega']:.2f} rad/s; bounds {REST_SPEED:g} px/s, "
                       f"{REST_OMEGA:g} rad/s).", "settle")


@CHECKS.check(depends=["runs"], max_score=2)
def ramp_holds(ctx):
    """Crates set on the 22° ramp (friction 0.6) stay put (criterion 2)."""
    record = _record(ctx, "ramp")
    summary = scenes.summary(record)
    crates = scenes.measure_ramp(record)
    worst = max(crates, key=lambda c: abs(c["slid"]))
    _escaped(ctx, summary, "three crates set on the ramp did not stay there")
    if abs(worst["slid"]) > RAMP_SLIDE or summary["tail_speed"] > RAMP_SPEED:
        key = "friction_sign" if summary["tail_omega"] > 1.0 else "settle"
        _fail_with(ctx, f"crates set at rest on the 22° ramp did not stay put: one moved {worst['slid']:.0f} px "
                   f"along the slope in 3 s (bound {RAMP_SLIDE:g} px) and the fastest moves "
                   f"{summary['tail_speed']:.0f} px/s at the end (bound {RAMP_SPEED:g}). Friction 0.6 holds a 22° slope.",
                   key)
    return f"the crates moved at most {abs(worst['slid']):.1f} px along the slope in 3 s"


@CHECKS.check(depends=["runs"], max_score=2)
def pile_stable(ctx):
    """A pile of a dozen crates neither sinks into the floor nor jitters apart (criterion 3)."""
    record = _record(ctx, "pile")
    summary = scenes.summary(record)
    _escaped(ctx, summary, "the pile of 12 crates fell apart")
    pile = scenes.measure_pile(record)
    if pile["floor_penetration"] > PENETRATION or pile["pair_overlap"] > PAIR_OVERLAP:
        raise Fail(f"the pile sinks: crates end {max(pile['floor_penetration'], 0):.1f} px into the floor and up to "
                   f"{pile['pair_overlap']:.1f} px into each other (bound {PENETRATION:g} px).",
                   HINTS[first_diagnosis(ctx) or "sinking"])
    if pile["tail_speed"] > PILE_SPEED or pile["drift"] > PILE_DRIFT:
        _fail_with(ctx, f"the pile jitters apart: in its last second a crate moves at {pile['tail_speed']:.0f} px/s "
                   f"(bound {PILE_SPEED:g}) and drifts {pile['drift']:.1f} px (bound {PILE_DRIFT:g}).", "settle")
    return (f"deepest overlap {max(pile['floor_penetration'], pile['pair_overlap'], 0):.2f} px, top speed "
            f"{pile['tail_speed']:.1f} px/s in the last second")


LINE = re.compile(r"Simulated\s+(-?[\d.]+)\s*s\s+with\s+(\d+)\s+crates?;\s*fast movers now:\s*(\d+)")


@CHECKS.check(depends=["runs"], max_score=2)
def fast_movers_zero(ctx):
    """A few seconds after the last drop the program prints `fast movers now: 0`, matching the simulation (criterion 4)."""
    run = ctx.scenarios["own_scene"]
    matches = LINE.findall(run.stdout)
    if not matches:
        raise Fail("when the window closed, the program printed no line like "
                   "'Simulated 5.5 s with 8 crates; fast movers now: 0'.", HINTS["print"])
    seconds, crates, movers = float(matches[-1][0]), int(matches[-1][1]), int(matches[-1][2])
    frames = (run.record or {}).get("records") or []
    if not frames:
        raise Fail(f"the program printed 'fast movers now: {movers}' but the runtime recorded no simulated frames: "
                   "the line must report the crates you simulated.", HINTS["print"])
    last = frames[-1]
    recorded_movers = scenes.fast_movers(last)
    recorded_crates = len(scenes.dynamic(last))
    recorded_seconds = last["frame"] / scenes.FPS
    if movers != recorded_movers or crates != recorded_crates or abs(seconds - recorded_seconds) > 0.15:
        raise Fail(f"the printed line says {seconds:g} s, {crates} crates, {movers} fast movers, but the simulation "
                   f"recorded {recorded_seconds:.1f} s, {recorded_crates} crates and {recorded_movers} faster than "
                   f"{scenes.FAST_MOVER:g} px/s at the end.", HINTS["print"])
    if movers:
        _escaped(ctx, scenes.summary(run.record), f"in the lab's own scene with {len(scenes.DROPS)} dropped crates, "
                 f"the program printed 'fast movers now: {movers}'")
        _fail_with(ctx, f"{scenes.SETTLE_FRAMES / scenes.FPS:g} s after the last of {len(scenes.DROPS)} dropped "
                   f"crates the program printed 'fast movers now: {movers}' (expected 0).", "settle")
