"""The parts of a lab's checks that every lab shares: loading, the handout comparison, the runtime lines.

A lab's module (checker/tumbling_crates.py, checker/more_shapes.py) registers
its own checks, with its own docstrings and hints, and calls these for the
work: each returns what the check passes on, or raises Fail / Error with the
hint it is given.
"""
import ast

from . import handout
from .checks import Error, Fail, Hint
from .common import describe_function_error, describe_run_failure

RUNTIME_HOOKS = ("seed", "scene", "frame_budget", "tick", "events", "record")

RUNTIME_HINT = Hint(None, "the lines marked # lab runtime",
                    "Keep the lines marked `# lab runtime` from the handout (lab.seed, lab.scene, lab.frame_budget, "
                    "lab.tick, lab.events, lab.record): they do nothing when you run the file yourself, and the "
                    "checker needs them to run it headless.")


def number_text(value, digits=2):
    """A number for a message with `digits` decimals; a tiny negative never reads "-0.00"."""
    text = f"{value:.{digits}f}"
    return text[1:] if text.startswith("-") and float(text) == 0 else text


def vec_text(v):
    """A vector (x, y) for a message, two decimals each: "(1.00, 0.00)", never "(1.00, -0.00)"."""
    return f"({number_text(v[0])}, {number_text(v[1])})"


def loaded(sub, crash_hint, names_hint):
    """The probe's {probe name: data} when the file imported and defines every required function.

    Error with crash_hint when the import failed, with names_hint when a function is missing.
    """
    run = sub.probe
    if run.status != "done":
        raise Error(describe_run_failure(run, sub.name, "The file"), crash_hint)
    missing = run.result["probe"]["missing"]
    if missing:
        raise Error(f"{sub.name} defines no function {missing[0]}() (missing: {', '.join(missing)}).", names_hint)
    return run.result["probe"]["functions"]


def handout_unchanged(sub, starter_path, hint):
    """A message when the code outside the step regions is the starter's; Fail (with hint) listing differences.

    With the --allow-edits option a difference is a warning message instead.
    """
    try:
        with open(starter_path, encoding="utf-8") as handle:
            starter = handle.read()
    except OSError as exc:
        raise Error(f"the checker cannot read the handout {starter_path} ({exc.strerror}) to compare with; "
                    "reinstall the lab bundle.")
    try:
        comparison = handout.compare(sub.source, starter, sub.name, "the handout")
    except handout.MarkerError as exc:
        raise Fail(f"{exc}.", hint)
    if comparison.same:   # the check's own title says the rest: only the imports the file adds are news
        return f"added imports: {'; '.join(comparison.added_imports)}" if comparison.added_imports else ""
    listed = "; ".join(comparison.problems[:handout.MAX_PROBLEMS])
    more = len(comparison.problems) - handout.MAX_PROBLEMS
    text = f"code outside the steps differs from the handout: {listed}" + (f"; and {more} more" if more > 0 else "")
    if sub.options.get("allow_edits"):
        return f"warning (allowed by --allow-edits): {text}."
    raise Fail(text + ".", hint)


def runtime_lines(sub, crash_hint, hint=RUNTIME_HINT, hooks=RUNTIME_HOOKS):
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
                   + " missing, so the checker cannot run the file headless.", hint)


def function_data(sub, functions, probe, function, step, crash_hint):
    """The data of one probe of a lab function; Error (under the check for `step`) if it raised or looped."""
    entry = functions.get(probe)
    if entry is None:
        raise Error(f"{sub.name} defines no {function}().", crash_hint)
    if not entry["ok"]:
        hint = Hint(step, f"the error in {function}()", f"Your code in {function}() stopped with the error above; "
                    "fix it at the line shown, then run the checker again.")
        raise Error(describe_function_error(function, entry["error"], sub.name), hint)
    return entry["data"]


def scene_records(sub, names, crash_hint, runtime_hint=RUNTIME_HINT):
    """{scene name: its run} when every named scene ran to the end and recorded frames; Error / Fail otherwise."""
    records = {}
    for name in names:
        run = sub.scenarios.get(name)
        if run is None:
            raise Error(f"the '{name}' scene was not run (the time limit for the whole run ran out).")
        if run.status != "done":
            raise Error(describe_run_failure(run, sub.name, f"main() in the '{name}' scene"), crash_hint)
        frames = (run.record or {}).get("records") or []
        if not frames:
            raise Fail(f"the '{name}' scene recorded no frames: main() returned before its loop ran, or the loop "
                       "does not call lab.record(...).", runtime_hint)
        records[name] = run
    return records
