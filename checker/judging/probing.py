"""The grading parent's half of a probe: what the child is told, and the replay that judges its tape.

Before the probe run the parent works out, from the lab's starter and solution
(files the child never opens): which functions are the student's step
functions (those holding a step region in the starter), the spliced sources
some probes use (the student's function with the solution's other step in it,
checker/labs/tumbling_crates/probes.py `with_reference_steps`), and a fresh random seed for
the inputs the probes draw per run. After the run, `judge` replays the child's
tapes (checker/judging/tape.py) through the same probes, with the starter as the
module, and returns what the lab's checks read: {"missing": [...],
"functions": {probe name: {"ok": True, "data": ...} or {"ok": False, "error": ...}}}.
"""
import ast
import importlib
import secrets

from checker.judging import budget, tape
from checker.reading import source as source_text
from checker.judging.common import value_text
from checker.reading.handout import MarkerError, step_regions

_STARTERS = {}   # starter path -> (its compiled code, its step functions)
_CONSTANTS = {}  # starter path -> its constants (handout_constants)
MAX_TAPE = 200_000   # entries on one probe's tape the grader replays at most (the solutions' longest: about 2000)


def regions_by_function(source):
    """{name: [its steps]} of the top-level functions of `source` that hold a step region.

    A region of comments only (a starter's TODO) may lie after the function's last statement, so a
    function reaches to the next top-level statement.
    """
    lines = source_text.lines(source)
    regions = step_regions(lines)
    body = ast.parse(source).body
    out = {}
    for index, node in enumerate(body):
        end = body[index + 1].lineno - 1 if index + 1 < len(body) else len(lines)
        if isinstance(node, ast.FunctionDef):
            steps = sorted(step for step, (start, _, _) in regions.items() if node.lineno <= start + 1 <= end)
            if steps:
                out[node.name] = steps
    return out


def step_functions(source):
    """Names of the top-level functions of `source` that hold a step region."""
    return list(regions_by_function(source))


def steps_by_function(lab):
    """{step function name: [its steps]} from the lab's starter."""
    return regions_by_function(source_text.read(lab.starter))


def _starter(path):
    """(compiled starter, its step functions), read once per process."""
    if path not in _STARTERS:
        source = source_text.read(path)
        _STARTERS[path] = (compile(source, path, "exec"), step_functions(source))
    return _STARTERS[path]


def splice_source(mine, theirs, function, steps):
    """The student's `function` with the inside of each step in `steps` taken from the solution.

    mine, theirs: the lab's and the solution's source text. Returns {"first": the function's first
    line index, "text": its source} (compiled in the child at the lab's own line numbers), or None
    when the function or the steps' markers cannot be found.
    """
    try:
        mine, theirs = source_text.lines(mine), source_text.lines(theirs)
        my_regions, their_regions = step_regions(mine), step_regions(theirs)
        tree = ast.parse("\n".join(mine))
    except (MarkerError, SyntaxError, ValueError):
        return None
    node = next((n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == function), None)
    if node is None or any(step not in my_regions or step not in their_regions for step in steps):
        return None
    first, last = node.lineno - 1, node.end_lineno
    lines = list(mine)
    for step in sorted(steps, reverse=True):
        start, end, indent = my_regions[step]
        their_start, their_end, their_indent = their_regions[step]
        if not first < start < end < last + 1:
            return None
        body = [indent + line[len(their_indent):] if line.startswith(their_indent) else line
                for line in theirs[their_start + 1:their_end]]
        last += len(body) - (end - start - 1)
        lines[start + 1:end] = body
    return {"first": first, "text": "\n".join(lines[first:last]) + "\n"}


def handout_namespace(lab):
    """A fresh namespace of the lab's starter, run as a module (its main() never called): the handout."""
    namespace = {"__name__": "lab_handout", "__builtins__": __builtins__}
    exec(_starter(lab.starter)[0], namespace)
    return namespace


def handout_constants(lab):
    """{name: value} of the starter's top-level constants (numbers, text, tuples of them): the values the
    probes read, in the grader and, sent with the settings, in the child. Never the child's."""
    if lab.starter not in _CONSTANTS:
        _CONSTANTS[lab.starter] = {name: value for name, value in handout_namespace(lab).items()
                                   if not name.startswith("_") and tape.plain(value)}
    return dict(_CONSTANTS[lab.starter])


def settings_for(lab, source, seed=None):
    """The probe run's settings: the probe module, the step functions, the splices, the handout's constants and
    the run's seed."""
    probes = importlib.import_module(lab.probes)
    steps = _starter(lab.starter)[1]
    splices = {}
    for function, wanted in getattr(probes, "SPLICES", ()):
        try:
            theirs = source_text.read(lab.solution)
        except (OSError, source_text.SourceError):
            continue
        spliced = splice_source(source, theirs, function, wanted)
        if spliced:
            splices[tape.splice_name(function, wanted)] = spliced
    constants = {name: tape.encode(value, tape.Seen()) for name, value in handout_constants(lab).items()}
    return {"probes": lab.probes, "steps": steps, "splices": splices, "constants": constants,
            "seed": secrets.randbelow(2 ** 31) if seed is None else seed}


def _shown(value):
    """A constant's value as the tape carries it, for a message: its repr, cut short."""
    if value == tape.MISSING_VALUE:
        return "nothing (deleted)"
    try:
        return value_text(tape.decode(value, tape.Seen()))
    except Exception:  # noqa: BLE001 - a forged value the tape's format does not describe
        return "a value the tape cannot carry"


def _error(message, kind="exception"):
    """An error record as the child writes one; kind "report": the grader's own account of what the child reported."""
    return {"kind": kind, "message": message, "line": None, "text": None, "traceback": ""}


def _replayed(replay, probe, function, path, child_error, pure):
    """The judged entry of one probe: its tape replayed through probe(replay, path) here."""
    try:
        data = probe(replay, path)
    except (tape.StudentRaised, tape.TapeEnded) as exc:
        return {"ok": False, "error": child_error or _error(
            f"{function}() stopped in the child, but the child gave no account of the error ({exc})", "report")}
    except tape.StudentValue as exc:   # the function left a body's vel or omega of the wrong kind
        return {"ok": False, "error": _error(str(exc), "value")}
    except tape.TapeMismatch as exc:
        return {"ok": False, "error": _error(
            f"the checker could not replay what {function}() did ({exc}): the code outside the steps "
            "does not behave like the handout's, or the child's report was changed", "report")}
    except Exception as exc:  # noqa: BLE001 - the probe's own code failed on what the function returned
        return {"ok": False, "error": child_error or _error(f"{type(exc).__name__}: {exc}")}
    if child_error is not None:
        return {"ok": False, "error": child_error}
    if not replay.finished():
        return {"ok": False, "error": _error(
            f"the child reported more calls of {function}() than the checker's probe makes", "report")}
    return {"ok": True, "data": data, "changed_arguments": replay.changed(pure), "changed_fields": replay.tampered()}


def judge(lab, path, settings, child):
    """Replay the child's probe result (`child`: run_probe's output) through the lab's probes here.

    Returns {"missing", "functions"} as the checks read it. A probe whose tape ends where the
    child's probe stopped with an error gets that error (the student's line); a tape that does not
    fit the parent's own inputs is an error naming that, never data.
    """
    probes = importlib.import_module(lab.probes)
    tapes = child.get("tapes") if isinstance(child, dict) else None
    missing = child.get("missing") if isinstance(child, dict) else None
    constants = child.get("constants", {}) if isinstance(child, dict) else None
    if not isinstance(tapes, dict) or not isinstance(missing, list) or not isinstance(constants, dict):
        return {"missing": [], "functions": {name: {"ok": False, "error": _error(
            "the probe's result is not in the checker's format (the file's code changed what the child reports)")}
            for name in probes.PROBES}}
    pure = set(getattr(probes, "PURE", ()))   # step functions that must leave their arguments as they got them
    namespace = handout_namespace(lab)   # its constants are the ones the replay reads, never the child's
    handout = handout_constants(lab)
    functions, changed = {}, {}   # changed: step function -> {handout constant: the value it set}
    try:
        _judge_all(probes, tapes, namespace, handout, settings, path, pure, functions, changed)
    except budget.Exhausted as exc:   # name what the file's steps changed, in the one error row (grade.py)
        exc.notes += [f"{changer}() set {', '.join(f'{c} to {now}' for c, (_, now) in sorted(values.items()))}"
                      for changer, values in sorted(_named(changed, handout).items())]
        raise
    # constants a step changed at run time fail that step wherever it was seen (lab_checks.function_data)
    named = _named(changed, handout)
    for entry in functions.values():
        entry["changed_constants"] = named
    return {"missing": [str(m) for m in missing], "functions": functions}


def _judge_all(probes, tapes, namespace, handout, settings, path, pure, functions, changed):
    """Replay each probe's tape (judge): fills `functions` {probe: entry} and `changed` {function: {constant:
    value}}."""
    steps = settings["steps"]
    for name, (function, probe) in probes.PROBES.items():
        record = tapes.get(name)
        if not isinstance(record, dict) or not isinstance(record.get("tape"), list):
            continue
        child_error = record.get("error") if isinstance(record.get("error"), dict) else None
        if len(record["tape"]) > MAX_TAPE:   # no probe makes that many calls: refuse before replaying any
            functions[name] = {"ok": False, "error": _error(
                f"the child reported {len(record['tape'])} calls for the probe of {function}(), more than the "
                f"checker's probe makes (at most {MAX_TAPE}): the child's report was changed", "report")}
            continue
        for changer, values in tape.changed_constants(record["tape"], handout).items():
            for constant, value in values.items():
                changed.setdefault(changer, {}).setdefault(constant, value)
        replay = tape.Replayer(namespace, steps, record["tape"], settings.get("seed", 0))
        try:
            functions[name] = _replayed(replay, probe, function, path, child_error, pure)
        except budget.Exhausted as exc:
            exc.what += f", replaying the probe of {function}()"
            raise
        finally:
            for constant, value in replay.read_constants().items():   # the child's probe read another value
                changed.setdefault(function, {}).setdefault(constant, value)


def _named(changed, handout):
    """{step function: {constant: [the handout's value, the value it set], as text}} from judge's `changed`."""
    named = {}
    for changer, values in sorted(changed.items()):
        for constant, value in sorted(values.items()):   # a splice's calls ("sat:3") are its function's
            named.setdefault(changer.split(":")[0], {}).setdefault(
                constant, [value_text(handout[constant]), _shown(value)])
    return named
