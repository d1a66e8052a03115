"""The parts of a lab's checks that every lab shares: loading, the handout comparison, the runtime lines.

A lab's module (checker/labs/<id>/checks.py) registers its first three checks, the same in every lab, with
one call (register_common: loads, handout_unchanged, runtime_lines), then its own checks, with their
docstrings and hints, which call the helpers here for the work: each returns what the check passes on, or
raises Fail / Error with the hint it is given.
"""
import ast
import math

from checker.reading import handout, source
from lesson11.physics2d.world import CONTACT_RULES, EFFECTS, ORDERS, SOLVERS

from checker.judging.causes import mistake
from checker.judging.checks import Error, Fail, Hint, Mistake
from checker.judging.common import describe_function_error, describe_run_failure

RUNTIME_HOOKS = ("seed", "scene", "frame_budget", "tick", "events", "record")

RUNTIME_HINT = Hint(None, "the lines marked # lab runtime",
                    "Keep the handout's `# lab runtime` lines (lab.seed, scene, frame_budget, tick, events, "
                    "record): they do nothing when you run the file; the checker needs them.")


def handout_hint(rest):
    """The hint of a lab's handout_unchanged, the same words in every lab; `rest`: what stays as handed out."""
    return Hint(None, "keep the handed-out code",
                f"Write only inside the `# --- step N` regions; the rest ({rest}) stays as handed out. Unsure? "
                "Start again from the starter.")


def number_text(value, digits=2):
    """A number for a message with `digits` decimals; a tiny negative never reads "-0.00"."""
    text = f"{value:.{digits}f}"
    return text[1:] if text.startswith("-") and float(text) == 0 else text


def vec_text(v):
    """A vector (x, y) for a message, two decimals each: "(1.00, 0.00)", never "(1.00, -0.00)"."""
    return f"({number_text(v[0])}, {number_text(v[1])})"


def argument_changed(function, name, advice, where, now, user, hint, before=None):
    """The Fail (mistake argument_changed) of a step function that changed its vector argument `name` in place:
    `advice` says what to write instead, `where` names the case, `now` (and `before`, when the record kept it)
    its value after (and before) the call, `user` who goes on using it."""
    change = f"went from {vec_text(before)} to {vec_text(now)}" if before is not None else f"became {vec_text(now)}"
    return Fail(f"{function}() changed its argument {name} in place: {advice}.\n{where}, {name} {change}; {user}.",
                hint, mistake("argument_changed"))


def loaded(sub, crash_hint, names_hint):
    """The probe's {probe name: data} when the file imported and defines every required function.

    Error with crash_hint when the import failed, with names_hint when a function is missing.
    """
    run = sub.probe
    if run.status != "done":
        raise Error(describe_run_failure(run, sub.name, "The file"), crash_hint)
    missing = run.result["probe"]["missing"]
    if missing:
        raise Error(f"{sub.name} defines no function {missing[0]}().\nmissing: {', '.join(missing)}.", names_hint)
    return run.result["probe"]["functions"]


def register_common(registry, hints, names, kind="function names"):
    """Register the checks every lab starts with, 1 point each, in this order: loads, handout_unchanged (after
    loads), runtime_lines (after loads).

    names: the handout's functions (and classes) the checker calls, in the order the student reads them in
    `loads`' description; kind: what its hint calls them ("function names", or "names" when a class is among
    them); hints: the lab's HINTS, whose "crash", "handout" and "runtime" entries these checks give.
    """
    listed = ", ".join(names[:-1]) + " and " + names[-1] if len(names) > 1 else names[0]
    names_hint = Hint(None, "the handout's functions", f"Keep the handout's {kind}: {listed}; the checker calls "
                      "them.")

    def loads(sub):
        return loaded(sub, hints["crash"], names_hint)
    loads.__doc__ = f"The file imports without errors and defines {listed}."

    def handout_unchanged(sub):
        """The code outside the steps is the handout's (formatting and comments aside)."""
        return handout_note(sub, hints["handout"])

    def runtime_lines(sub):
        """The lines marked `# lab runtime` are still there (seed, scene, frame_budget, tick, events, record)."""
        missing_hooks(sub, hints["crash"], hints["runtime"])

    registry.check()(loads)
    registry.check(after=["loads"])(handout_unchanged)
    registry.check(after=["loads"])(runtime_lines)


def handout_note(sub, hint):
    """A message when the code outside the step regions is the starter's (sub.starter); Fail (with hint) listing
    differences.

    With the --allow-edits option a difference is a warning message instead.
    """
    starter_path = sub.starter
    try:
        starter = source.read(starter_path)
    except (OSError, source.SourceError) as exc:
        reason = getattr(exc, "strerror", None) or exc
        raise Error(f"the checker cannot read the handout {starter_path} ({reason}) to compare with; "
                    "reinstall the lab bundle.")
    try:
        comparison = handout.compare(sub.source, starter, sub.name, "the handout")
    except handout.MarkerError as exc:
        raise Fail(f"{exc}.", hint)
    if comparison.same:   # the check's own title says the rest: only added imports and debug prints are news
        notes = ([f"added imports: {'; '.join(comparison.added_imports)}"] if comparison.added_imports else []) + \
            [f"warning: {w}" for w in comparison.warnings]
        return "; ".join(notes)
    listed = "; ".join(comparison.problems[:handout.MAX_PROBLEMS])
    more = len(comparison.problems) - handout.MAX_PROBLEMS
    text = f"code outside the steps differs from the handout: {listed}" + (f"; and {more} more" if more > 0 else "")
    if sub.options.get("allow_edits"):
        return f"warning (allowed by --allow-edits): {text}."
    if getattr(sub, "edits_not_run", None) and len(sub.edits_not_run) == len(comparison.problems):
        return (f"warning: {'; '.join(sub.edits_not_run[:handout.MAX_PROBLEMS])}: a constant no check reads, so "
                "the checker graded your steps with the handout's line there; put it back before you hand in.")
    first = comparison.problems[0]
    others = len(comparison.problems) - 1
    raise Fail(f"code outside the steps differs from the handout.\n{first}" + (f"; and {others} more" if others else "")
               + ".", hint, Mistake("handout_changed", "code outside the steps differs from the handout"))


def missing_hooks(sub, crash_hint, hint=RUNTIME_HINT, hooks=RUNTIME_HOOKS):
    """None when the source calls every lab-runtime hook; Fail (with hint) naming the missing ones."""
    try:
        tree = ast.parse(sub.source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise Error(f"{sub.name} could not be read as Python source.", crash_hint)
    called = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            func = node.func
            if isinstance(func, ast.Attribute):
                called.add(func.attr)
            elif isinstance(func, ast.Name):
                called.add(func.id)
    missing = [hook for hook in hooks if hook not in called]
    if missing:
        raise Fail("the lab-runtime call" + ("s " if len(missing) > 1 else " ")
                   + ", ".join(f"lab.{m}()" for m in missing) + " " + ("are" if len(missing) > 1 else "is")
                   + " missing.\nWithout them the checker cannot run the file headless.", hint,
                   Mistake("runtime_lines_missing", "a line marked # lab runtime is missing"))


def function_data(sub, functions, probe, function, step, crash_hint):
    """The data of one probe of a lab function; Error (under the check for `step`) if it raised or looped.

    Fail first when the step rules flagged the step's code (sub.flags, checker/reading/step_rules.py): a
    step that reaches around the exercise earns nothing, whatever its function returns.
    """
    # a breach in any step of the same function counts: steps 4 and 5 both live in resolve(), so a step 4 that
    # hands resolve() to the library would otherwise let step 5's check pass through it
    steps = set(getattr(sub, "function_steps", {}).get(function, ())) | {step}
    breach = next((b for b in getattr(sub, "flags", ()) or () if b.step == step), None) or \
        next((b for b in getattr(sub, "flags", ()) or () if b.step in steps), None)
    if breach is not None and breach.rule == "outside":
        raise Fail(breach.message, Hint(step, "keep the code around the steps",
                                        "Functions are graded as written inside their steps; code outside that "
                                        "imports the library or the checker, or binds a step's function again, "
                                        "replaces that work: take it out."))
    if breach is not None:
        raise Fail(breach.message, Hint(step, f"write step {step} yourself",
                                        "Inside a step use the handout's names, math and your own functions: no "
                                        "import, no dunder names, nothing through World or a module, not the "
                                        "library's version of the step."))
    entry = functions.get(probe)
    if entry is None:
        raise Error(f"{sub.name} defines no {function}().", crash_hint)
    for constant, (handout, now) in sorted(((entry.get("changed_constants") or {}).get(function) or {}).items()):
        raise Fail(f"{function}() sets the handout's constant {constant} to {now} while it runs (the handout's: "
                   f"{handout}); the checker grades with the handout's constants.",
                   Hint(step, "the handout's constants", f"Read {constant} and the other constants at the top of "
                        "the file as they are: no `global` and no assignment to them inside a step."))
    if not entry["ok"] and entry["error"].get("kind") == "value":   # tape.StudentValue: a body's motion's kind
        raise Error(describe_function_error(function, entry["error"], sub.name),
                    Hint(step, f"what {function}() leaves in a body", "A body's pos and vel are Vector2s, its "
                         "angle and omega finite numbers: change them with the same kind (cross() gives a number, "
                         "impulse * inv_mass a Vector2)."))
    if not entry["ok"]:
        hint = Hint(step, f"the error in {function}()", f"Your code in {function}() stopped with the error above; "
                    "fix it at the line shown, then run the checker again.")
        raise Error(describe_function_error(function, entry["error"], sub.name), hint)
    if function in (entry.get("changed_arguments") or ()):
        raise Fail(f"{function}() changes the arguments it is given in place (a corner, a Vector2 or a list).\n"
                   "Its caller sees its own shapes or vectors change: a + ab * t makes a new vector; a += ... "
                   "changes a.", mistake=mistake("argument_changed"),
                   hint=Hint(step, f"the arguments of {function}()", "A function that answers a question must not "
                        "change what it was asked about: build new vectors and lists, leave the arguments alone."))
    if isinstance(entry["data"], list) and not entry["data"]:   # the grader's probe always has cases: never a pass
        raise Error(f"the checker's probe of {function}() holds no case: nothing was graded.\nThe checker, not your "
                    "file, is at fault: tell your instructor.", crash_hint)
    for changer, fields in sorted((entry.get("changed_fields") or {}).items()):
        raise Fail(f"{changer}() changes the {', '.join(fields)} of a body it is given.\nA step may change a "
                   "body's motion (position, velocity, spin), never its mass, inertia, material or shape.",
                   Hint(step, f"the bodies given to {changer}()", "Use a body's mass, inv_mass, inertia, "
                        "inv_inertia, friction, restitution and shape as they are: they describe the body, "
                        "and every other contact reads them too."))
    return entry["data"]


RIGID_TOLERANCE = 0.01   # px: how far a corner's distance from its body's position may drift between frames


def _finite(value):
    """A number (NaN and infinity included: a lab whose physics blows up records them honestly)."""
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _pair(value):
    return isinstance(value, list) and len(value) == 2 and all(_finite(v) for v in value)


def record_problem(record, settings):
    """Why a scene's record cannot be what lesson11.runtime wrote for these settings, or "".

    The record comes from the child, where the student's code runs, so the parent checks it
    against what it knows: frames numbered in order and within the scene's length, numbers where
    numbers belong, no more bodies than the scene's start plus its scripted clicks, and each body rigid
    (its corners keep their distances from its position from one frame to the next while no
    key is pressed). A record that passes can still be forged (see checker/README.md).
    """
    frames = record.get("records") if isinstance(record, dict) else None
    if not isinstance(frames, list):
        return "the record has no list of frames"
    limit = settings.get("frames", 600)
    script = settings.get("script") or []
    clicks = sorted(item["frame"] for item in script if item.get("type") == "click")
    keys = sorted(item["frame"] for item in script if item.get("type") == "key")
    last, start_count, previous = 0, None, None
    for item in frames:
        number = item.get("frame") if isinstance(item, dict) else None
        if not isinstance(number, int) or isinstance(number, bool) or not last < number <= limit:
            return f"its frames are not numbered in order within the scene's {limit} frames (frame {number!r} " \
                   f"after frame {last})"
        bodies = item.get("bodies")
        if not isinstance(bodies, list) or not all(isinstance(b, dict) for b in bodies):
            return f"frame {number} has no list of bodies"
        for body in bodies:
            points = body.get("points")
            if not (_pair(body.get("pos")) and _pair(body.get("vel")) and _finite(body.get("angle"))
                    and _finite(body.get("omega")) and isinstance(points, list) and all(_pair(p) for p in points)):
                return f"frame {number} holds a body whose position, velocity, angle, spin or corners are not " \
                       "numbers"
        if start_count is None:
            start_count = len(bodies)
        if len(bodies) > start_count + sum(1 for frame in clicks if frame <= number):
            return f"frame {number} has {len(bodies)} bodies, more than the scene's {start_count} and its clicks add"
        if previous is not None and len(previous[1]) == len(bodies) and \
                not any(previous[0] < frame <= number for frame in keys):
            for index, (before, now) in enumerate(zip(previous[1], bodies)):
                if len(before["points"]) != len(now["points"]):
                    continue
                if any(abs(math.dist(p, before["pos"]) - math.dist(q, now["pos"])) > RIGID_TOLERANCE
                       for p, q in zip(before["points"], now["points"])):
                    return f"body {index} changes shape between frames {previous[0]} and {number}"
        previous, last = (number, bodies), number
    return ""


MAX_RECORDED_COUNT = 10_000   # iterations and sub-steps above this are no World a lab runs at 60 fps


def _count(value):
    return isinstance(value, int) and not isinstance(value, bool) and 1 <= value <= MAX_RECORDED_COUNT


# the World's settings a frame's "world" holds (lesson11/panel.py RECORDED): name -> is the value one it can have
WORLD_SETTINGS = {
    "solver": lambda v: isinstance(v, str) and v in SOLVERS,
    "order": lambda v: isinstance(v, str) and v in ORDERS,
    "iterations": _count,
    "substeps": _count,
    "warm_starting": lambda v: isinstance(v, bool),
    "correction": lambda v: isinstance(v, bool),
    "contact_rule": lambda v: isinstance(v, str) and v in CONTACT_RULES,
    "effects": lambda v: isinstance(v, list) and len(v) <= len(EFFECTS)
    and all(isinstance(e, str) and e in EFFECTS for e in v) and len(set(v)) == len(v),
    "step_seconds": lambda v: _finite(v) and 0 < v <= 1,
}


def _shown(value):
    """A value from a record for a message: short, whatever it is (a record may hold a megabyte string)."""
    if isinstance(value, str):
        return repr(value[:30]) + ("..." if len(value) > 30 else "")
    return repr(value) if value is None or isinstance(value, (bool, int, float)) else f"a {type(value).__name__}"


def world_problem(world):
    """Why a frame's "world" (the World's settings, written by the child) cannot be what the runtime wrote, or ""."""
    if not isinstance(world, dict):
        return f"the settings are {_shown(world)}, not a mapping"
    if not world:
        return "the run could not read its World's settings"
    unknown = [name for name in world if name not in WORLD_SETTINGS]
    if unknown:
        return f"unknown setting {_shown(unknown[0])}" if len(world) <= len(WORLD_SETTINGS) else \
            f"{len(world)} settings, more than the {len(WORLD_SETTINGS)} a World has"
    missing = [name for name in WORLD_SETTINGS if name not in world]
    if missing:
        return f"no {missing[0]}"
    bad = next((name for name, valid in WORLD_SETTINGS.items() if not valid(world[name])), None)
    if bad:
        return f"{bad} cannot be {_shown(world[bad])}"
    if world["correction"] != ("correction" in world["effects"]):
        return "correction disagrees with the effects"
    return ""


def world_settings(frames):
    """(the World's settings at each frame, note): {name: value} or None per recorded frame, and "" or why a
    "world" was ignored.

    The runtime writes "world" on the first frame and where the settings change; each holds until the next. The
    child wrote them, so each is checked (world_problem): a bad one is ignored (None until the next good one) and
    named in the note, never trusted and never an error: the settings are shown, not graded.
    """
    settings, current, note = [], None, ""
    for frame in frames:
        if isinstance(frame, dict) and "world" in frame:
            problem = world_problem(frame["world"])
            current = None if problem else dict(frame["world"])
            if problem and not note:
                note = f"the World's settings recorded at frame {_shown(frame.get('frame'))} are ignored: {problem}"
        settings.append(current)
    return settings, note


def scene_records(sub, names, crash_hint, runtime_hint=RUNTIME_HINT):
    """{scene name: its run} when every named scene ran to the end and recorded frames; Error / Fail otherwise.

    `names`: the lab's scenes (a dict name -> settings builder, or just names). A record that
    cannot be what the runtime wrote (record_problem) is an Error naming why.
    """
    records = {}
    for name in names:
        run = sub.scenarios.get(name)
        if run is None:
            raise Error(f"the '{name}' scene was not run.\nThe time limit for the whole run ran out.")
        if run.status != "done":
            raise Error(describe_run_failure(run, sub.name, f"main() in the '{name}' scene"), crash_hint)
        frames = (run.record or {}).get("records") or []
        if not frames:
            raise Fail(f"the '{name}' scene recorded no frames.\nmain() returned before its loop ran, or the loop "
                       "does not call lab.record(...).", runtime_hint)
        build = names.get(name) if isinstance(names, dict) else None
        problem = record_problem(run.record, build() if callable(build) else {})
        if problem:
            raise Error(f"the '{name}' scene's record cannot be what the lab runtime wrote; it is not graded.\n"
                        f"{problem}.", runtime_hint)
        records[name] = run
    return records


def register_runs(registry, hints, scenarios, after, doc, what="a body", gravity=None, more=None, hint="settle"):
    """Register the lab's `runs` check (described by `doc`, after the checks in `after`): main() runs each scene of
    `scenarios` to its end (scene_records) with finite positions and speeds ("<what>'s position ..."); given
    gravity = (scene, g, relative tolerance), its bodies fall with g px/s²; more(records) may fail it further.
    It hands on {scene name: its run}, or what `more` returns when that is not None."""
    from lesson11 import records as measured   # the runtime's record format (a leaf module)

    def runs(sub):
        records = scene_records(sub, scenarios, hints["crash"], hints["runtime"])
        for name, run in records.items():
            if not measured.finite(run.record["records"]):
                raise Fail(f"{what}'s position or speed became infinite or NaN.\nin the '{name}' scene.",
                           hints[hint])
        if gravity is not None:
            scene, g, tolerance = gravity
            fall = measured.free_fall(records[scene].record)
            if fall is not None and abs(fall - g) > tolerance * g:
                raise Fail(f"bodies do not fall with the course's gravity, {g:g} px/s².\nin the '{scene}' scene "
                           f"they fall with {fall:.1f} px/s².", hints["handout"])
        handed = more(records) if more is not None else None
        return records if handed is None else handed
    runs.__doc__ = doc
    registry.check(after=list(after), needs_scenarios=True)(runs)
