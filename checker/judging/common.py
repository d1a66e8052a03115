"""What the checks of every lab share: accounts of failed runs, numbers shown beside their bounds, and the kinds of
the values a student's function returns (a number, a vector) told apart from what only looks like one."""
import math
import numbers
import re

from pygame import Vector2

from lesson11.mistakes import VALUE_RULE, meaning, number_problem, value_text, vector_problem  # noqa: F401

from checker.isolation import disk
from checker.reading import source


CHILD_KINDS = ("exception", "exit", "memory", "flood", "syntax", "timeout")   # the kinds of error the child writes
UNREADABLE_ERROR = ("the child's result names an error in a form the child never writes (the file's code wrote "
                    "on the checker's result channel); nothing the child reports is graded then")


def _line_text(value, limit):
    """A str from the child cut to `limit` characters, else None."""
    return value[:limit] if isinstance(value, str) else None


def child_error(value):
    """The child's account of an error ({"kind", "message", "line", "text", "traceback"}, as checker/isolation/child.py
    writes it) checked before any of it is used, or None for no error.

    The account comes from the child, where the student's code runs, so it may be anything: a kind the
    child never writes (or one only the grader writes: "report", "value") becomes "exception", a line that
    is not a positive int is None, strings are cut; a value that is not such an account at all (`"error":
    "x"`) becomes the grader's own account saying so (kind "report"), never the grader's exception.
    """
    if value is None:
        return None
    if not isinstance(value, dict) or not isinstance(value.get("message"), str):
        return {"kind": "report", "message": UNREADABLE_ERROR, "line": None, "text": None, "traceback": ""}
    line = value.get("line")
    return {"kind": value.get("kind") if value.get("kind") in CHILD_KINDS else "exception",
            "message": value["message"][:600] or "an error",
            "line": line if isinstance(line, int) and not isinstance(line, bool) and 0 < line < 10 ** 7 else None,
            "text": _line_text(value.get("text"), 200), "traceback": _line_text(value.get("traceback"), 4000) or ""}


def checked_result(result):
    """The child's result line with every error in it (its own, each probe tape's) through child_error, in place.
    A result that is not a dict is {}."""
    if not isinstance(result, dict):
        return {}
    if "error" in result:
        result["error"] = child_error(result["error"]) or child_error({})
    probe = result.get("probe")
    tapes = probe.get("tapes") if isinstance(probe, dict) else None
    for record in (tapes.values() if isinstance(tapes, dict) else ()):
        if isinstance(record, dict) and record.get("error") is not None:
            record["error"] = child_error(record["error"])
    return result


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
            return (f"{what} did not finish importing within {run.timeout:.3g} s of CPU time{where}: is there an endless loop "
                    "outside main()?")
        return (f"{what} was stopped after {run.timeout:.3g} s of CPU time{where}: the loop never ended. Is "
                "`and lab.frame_budget()` still in the while condition?")
    if error.get("kind") == "report":   # the grader's account of what the child reported
        return f"{what} did not finish: {error['message']}."
    if error.get("kind") == "flood":
        return (f"{what} printed more than {run.max_output // 1024} KB of output and was stopped; it was "
                f"printing at {at}{text}.")
    if run.status == "flood":
        return f"{what} printed more than {run.max_output // 1024} KB of output and was stopped."
    if run.status == "disk":
        return disk.message(what, run.disk_mb)
    if error.get("kind") == "exit":
        return f"{what} ended the program: {_cut(error['message'])}.\nat {_cut(at + text, 190)}."
    if error.get("kind") == "memory" or (run.returncode or 0) in (-9,) and not error:
        return f"{what} ran out of memory (limit {run.memory_mb} MB).\nat {_cut(at + text, 190)}."
    if error:
        return f"{what} raised {_cut(error['message'])}.\nat {_cut(at + text, 190)}."
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
        lines = source.lines(source.read(lab_path))
        return found, lines[found - 1].strip() if 0 < found <= len(lines) else ""
    except (OSError, source.SourceError):
        return found, ""




def describe_function_error(name, error, lab_name):
    """Two short lines for a lab function that raised, looped or left a wrong value while the checker probed it."""
    at = f"{lab_name}, line {error['line']}" if error.get("line") else lab_name
    text = f": {error['text']}" if error.get("text") else ""
    if error.get("kind") == "timeout":
        return f"{error['message']} (it was at {at}{text}): is there an endless loop?"
    if error.get("kind") == "flood":
        return f"{name}() {error['message']} of output (printing at {at}{text}); remove the print."
    if error.get("kind") == "value":   # the grader's account: the function left a body's motion of the wrong kind
        said = meaning(problem=error["message"])   # the window's words too (lesson11/mistakes.py)
        return f"{name}() {_cut(error['message'], 140)}.\n{_cut(_capital(said or VALUE_RULE), 196)}."
    if error.get("kind") == "report":   # the grader's account of the child's report, not something the function raised
        return error["message"].rstrip(".") + "."
    if error.get("kind") == "exit":
        return f"{name}() ended the program: {_cut(error['message'])}.\nat {_cut(at + text, 190)}."
    # a known mistake's meaning (the window's words too, lesson11/mistakes.py) is the second line, the line the first
    said = meaning(error.get("message") or "", error.get("text") or "")
    if said:
        kind = error["message"].split(":")[0]   # the exception's name: the second line says what it means
        first = f"{name}() raised {_cut(kind, 40)} at {at}{text}"
        return f"{_cut(first, 158)}.\n{_cut(_capital(said), 196)}."
    return f"{name}() raised {_cut(error['message'])}.\nat {_cut(at + text, 190)}."


def _capital(text):
    """text with its first letter a capital (a sentence of its own on the message's second line)."""
    return text[:1].upper() + text[1:]


def _cut(text, limit=130):
    """text cut to `limit` characters ("..." at the end), so a message's line stays short whatever was raised."""
    text = str(text).rstrip(".")
    return text if len(text) <= limit else text[:limit - 3] + "..."


def shown(value, bound, unit=""):
    """`value` with just enough digits that it never reads equal to `bound` (e.g. 5.004 beside a bound of 5)."""
    for digits in range(1, 7):
        text, limit = f"{value:.{digits}f}", f"{bound:.{digits}f}"
        if text != limit or value == bound:
            return text.rstrip("0").rstrip(".") if "." in text and digits > 1 and text != limit else text
    return repr(value)


def real(value):
    """float(value) for a value a student's function may return as a number; TypeError for a string, a bool or any
    other kind (float() would read "1.5" and True), ValueError for an int too large for a float (not OverflowError,
    so the probes' `except (TypeError, ValueError)` names it as the function's answer)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{value_text(value)} is not a number")
    try:
        return float(value)
    except OverflowError:
        raise ValueError(f"an int of {value.bit_length()} bits is too large for a float") from None


def close(got, want, rel=1e-7, floor=1e-7):
    """|got - want| within floor + rel·|want|: the same answer computed in another order of operations."""
    return abs(got - want) <= floor + rel * abs(want)


def same_point(got, want):
    """got is a point (a list, as the probes record one) whose every coordinate is close to want's."""
    return isinstance(got, list) and len(got) == len(want) and all(close(g, w) for g, w in zip(got, want))


def answer_number(value, none=False, finite=False):
    """A returned number as a float, or {"bad": what it is} (a string, a bool, a tuple, ...); with `none`, None
    stays None (an answer that may be "nothing"); with `finite`, NaN and infinity are bad too."""
    if none and value is None:
        return None
    try:
        number = real(value)
    except (TypeError, ValueError):
        return {"bad": value_text(value)}
    return number if not finite or math.isfinite(number) else {"bad": f"a number that is not finite: {number!r}"}


def answer_point(value):
    """A returned point as [x, y], or {"bad": what it is} when it is not a finite 2D point.

    A bare number is no point (Vector2(0.3) would make it (0.3, 0.3)): {"bad": ..., "number": value}.
    """
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        try:
            return {"bad": f"the number {value_text(value)}, not a point", "number": real(value)}
        except ValueError:   # an int too large for a float
            return {"bad": f"the number {value_text(value)}, not a point"}
    try:
        point = Vector2(value)
    except (TypeError, ValueError):
        return {"bad": value_text(value)}
    if not (math.isfinite(point.x) and math.isfinite(point.y)):
        return {"bad": f"a point that is not finite: {value_text(value)}"}
    return [point.x, point.y]


# ---------------------------------------------------------------- answers as plain data, else their text
# (a declared Step's `answer`; a str answer is then malformed, bad=is_text, and its message shows the text)

def is_text(answer):
    """True for an answer that was not the kind asked for (these functions gave its text instead)."""
    return isinstance(answer, str)


def as_number(value):
    """answer_number's reading, with what is wrong as text: a float, else the text of what the value is."""
    answer = answer_number(value)
    return answer["bad"] if isinstance(answer, dict) else answer


def as_point(value):
    """answer_point's reading, with what is wrong as text: [x, y], else the text of what the value is (a bare
    number or a point that is not finite included)."""
    answer = answer_point(value)
    return answer["bad"] if isinstance(answer, dict) else answer


def as_points(value):
    """A list of points as [[x, y], ...], else the list's text."""
    try:
        return [[float(Vector2(p).x), float(Vector2(p).y)] for p in value]
    except (TypeError, ValueError):
        return value_text(value)
