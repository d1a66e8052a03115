"""What the checks of every lab share: accounts of failed runs, numbers shown beside their bounds,
and the bodies of the checks every lab has (the probe's data of one function, the handout
comparison, the lab-runtime lines), each taking the lab's own starter and hints."""
import ast
import re

from . import handout
from .checks import Error, Fail, Hint


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
    if error.get("kind") == "flood":
        return (f"{what} printed more than {run.max_output // 1024} KB of output and was stopped; it was "
                f"printing at {at}{text}.")
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




def describe_function_error(name, error, lab_name):
    """One line for a lab function that raised (or looped) while the checker probed it."""
    at = f"{lab_name}, line {error['line']}" if error.get("line") else lab_name
    text = f": {error['text']}" if error.get("text") else ""
    if error.get("kind") == "timeout":
        return f"{error['message']} (it was at {at}{text}): is there an endless loop?"
    if error.get("kind") == "flood":
        return f"{name}() {error['message']} of output (printing at {at}{text}); remove the print."
    if error.get("kind") == "exit":
        return f"{name}() ended the program: {error['message']} at {at}{text}."
    return f"{name}() raised {error['message']} at {at}{text}."


def shown(value, bound, unit=""):
    """`value` with just enough digits that it never reads equal to `bound` (e.g. 5.004 beside a bound of 5)."""
    for digits in range(1, 7):
        text, limit = f"{value:.{digits}f}", f"{bound:.{digits}f}"
        if text != limit or value == bound:
            return text.rstrip("0").rstrip(".") if "." in text and digits > 1 and text != limit else text
    return repr(value)


# ---------------------------------------------------------------- checks every lab has (Tumbling Crates, Ball on the Ramp)

def probe_data(sub, functions, probe, function, step, crash_hint):
    """The data of one probe of a lab function; Error (under the check for `step`) if it raised or looped."""
    entry = functions.get(probe)
    if entry is None:
        raise Error(f"{sub.name} defines no {function}().", crash_hint)
    if not entry["ok"]:
        hint = Hint(step, f"the error in {function}()", f"Your code in {function}() stopped with the error above; "
                    "fix it at the line shown, then run the checker again.")
        raise Error(describe_function_error(function, entry["error"], sub.name), hint)
    return entry["data"]


def compare_with_handout(sub, starter, hint):
    """handout_unchanged's body: a message if the code outside the steps is the starter's, else Fail(hint).

    With the instructor option allow_edits a difference is a warning (the message), not a failure.
    """
    try:
        with open(starter, encoding="utf-8") as handle:
            text = handle.read()
    except OSError as exc:
        raise Error(f"the checker cannot read the handout {starter} ({exc.strerror}) to compare with; "
                    "reinstall the lab bundle.")
    try:
        comparison = handout.compare(sub.source, text, sub.name, "the handout")
    except handout.MarkerError as exc:
        raise Fail(f"{exc}.", hint)
    added = f" (added imports: {'; '.join(comparison.added_imports)})" if comparison.added_imports else ""
    if comparison.same:
        return "the code outside the steps is the handout's" + added
    listed = "; ".join(comparison.problems[:handout.MAX_PROBLEMS])
    more = len(comparison.problems) - handout.MAX_PROBLEMS
    text = f"code outside the steps differs from the handout: {listed}" + (f"; and {more} more" if more > 0 else "")
    if sub.options.get("allow_edits"):
        return f"warning (allowed by --allow-edits): {text}."
    raise Fail(text + ".", hint)


def check_runtime_calls(sub, hooks, hint, crash_hint):
    """runtime_lines' body: Fail(hint) unless the source calls every lab-runtime hook in `hooks` (by name)."""
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
