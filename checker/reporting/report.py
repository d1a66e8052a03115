"""Outputs: the readable report, --json, Gradescope's results.json, the summary table and the CSV.

Every function takes a list of rows. A row is a LabReport (checker/grade.py:
path, lab, results, seconds, score, max_score, passed, status) or a NotGraded
(below): an entry that could not be graded, with the reason. Both have the
same attributes, so every output has one row per entry.

JSON schema (`--json`, version 1):
{
  "schema": "lesson11-checker/1",
  "passed": bool,                       # every row passed every check
  "score": float, "max_score": float,   # sums over all rows
  "labs": [{                            # one per entry, in command-line order
      "path": str, "lab": str | null (lab id), "title": str | null,
      "status": "pass" | "fail" | "error",
      "score": float, "max_score": float, "seconds": float,
      "seed": int | null,               # the seed of the inputs the probes drew (checker --seed N repeats them)
      "flags": [{"step": int, "line": int, "rule": str, "what": str, "text": str}],   # constructs in the
                                        # step regions the step rules flagged (checker/reading/step_rules.py), [] if none
      "message": str,                   # why the entry could not be graded ("" when it was)
      "criteria": [{                     # in the lab's fixed order ([] when not graded)
          "id": str,                     # stable check id, e.g. "corner_tips"
          "name": str,                   # the check's description (its docstring)
          "status": "pass" | "fail" | "skip" | "error",
          "message": str,                # what was measured / what went wrong ("" when silent)
          "hint": str,                   # what to revisit: "[step N: title] advice" ("" on pass/skip)
          "step": int | null,            # the lesson step (1-7) the hint names
          "score": float, "max_score": float,
          "mistake": {"id": str, "text": str} | null}]}],   # the known mistake a failing check named
  "errors": [{"path": str, "message": str}]   # the rows that could not be graded, again
}
"""
import csv
import html
import io
import json
import os
import stat
import tempfile
import unicodedata
from dataclasses import dataclass

from checker.judging.checks import step_of
from checker.reporting.outputs import relative, submission_names, temporary_removed_on_failure

SYMBOL = {"pass": ":)", "fail": ":(", "skip": ":|", "error": ":("}


@dataclass
class NotGraded:
    """A row for an entry that could not be graded; reads like a LabReport with status "error" and no results.

    lab is the Lab when it is known (by the file's name or text), else None;
    max_score is then that lab's total, so a lost submission counts 0 of it.
    """
    path: str
    lab: object
    message: str
    seconds: float = 0.0
    counted: bool = False   # a submission that scores 0 though no lab is known (an empty or unreadable file)

    results = ()
    score = 0.0
    passed = False
    status = "error"

    @property
    def max_score(self):
        checks = getattr(getattr(self.lab, "checks", None), "checks", None) or ()
        return float(sum(getattr(c, "max_score", 0.0) for c in checks))


def message_of(row):
    return getattr(row, "message", "") or ""


REASON_LIMIT = 300   # characters of a check's message in a row's reason


def reason(row):
    """Why a row scored what it did, in one line: why it was not graded, else the first check that failed or erred
    with its message ("Step 2 (sat_axes): fail: ..."), else "all checks pass"."""
    if isinstance(row, NotGraded) or not row.results:
        return one_line(message_of(row)) or "not graded"
    first = next((r for r in row.results if r.status in ("fail", "error")), None) or \
        next((r for r in row.results if r.status != "pass"), None)
    if first is None:
        return "all checks pass"
    text = one_line(first.message)
    text = text if len(text) <= REASON_LIMIT else text[:REASON_LIMIT - 3] + "..."
    return f"{check_label(first)}: {first.status}" + (f": {text}" if text else "")


def printable(text):
    """text with each control character but the tab (a backspace, ESC and the terminal sequences it starts, DEL,
    C1) and each bidirectional override written as its escape (`\\x1b`): on a terminal they move the cursor,
    so a student's exception text could erase the lines above or back over its indentation and print a row."""
    return "".join(c if c == "\t" or not (unicodedata.category(c) == "Cc" or c in BIDI_CONTROLS)
                   else ascii(c)[1:-1] for c in str(text))


BIDI_CONTROLS = frozenset("\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def indented(text, indent):
    """text with `indent` before each of its lines (every line break Python's str.splitlines() knows, \\r and
    form feeds included): a message holding line breaks, which may come from the student's code (an exception's
    text), stays under its check and cannot print a line that reads like another file's row (nor reach one by
    a terminal's control characters: printable())."""
    return "\n".join(indent + printable(line) for line in str(text).splitlines() or [""])


def one_line(text):
    """text on one line: its line breaks as spaces (for a table cell), its control characters escaped."""
    return printable(" ".join(str(text).splitlines()))


def text_report(report, stream, root=None, pictures=None):
    """The readable report of one row: a mark per check, the message, and the hint under each failure.

    pictures: {check id: [PNG paths]} (--pictures), each listed under its check. Every line of a message or
    hint is indented (indented()), so no message can print a line at the left margin.
    """
    name = one_line(_rel(report.path, root))
    if isinstance(report, NotGraded):
        title = f" - {report.lab.title}" if report.lab is not None else ""
        first, *rest = [printable(line) for line in str(report.message).splitlines()] or [""]
        stream.write(f"{name}{title}: 0/{report.max_score:g} (error, not graded)\n"
                     f"  :( could not be graded: {first}\n" + "".join(f"      {line}\n" for line in rest) + "\n")
        return
    stream.write(f"{name} - {report.lab.title}: {report.score:g}/{report.max_score:g} "
                 f"({report.status}, {report.seconds:.1f} s)\n")
    for r in report.results:
        stream.write(f"  {SYMBOL[r.status]} {one_line(r.name)}\n")
        if r.message:
            stream.write(indented(r.message, "      ") + "\n")
        if r.hint:
            stream.write(indented("hint " + r.hint, "      ") + "\n")
        for picture in (pictures or {}).get(r.id, ()):
            stream.write(f"      picture {picture}\n")
    stream.write("\n")


def to_json(reports, errors=(), root=None, pictures=None):
    """The whole run as the documented JSON document (a dict). `errors`: extra (path, message) pairs.
    pictures: {row path: {check id: [PNG paths]}} (--pictures): then each criterion gets "pictures": [paths]."""
    not_graded = [(_rel(r.path, root), message_of(r)) for r in reports if isinstance(r, NotGraded)]
    all_errors = not_graded + [(p, m) for p, m in errors]
    return {
        "schema": "lesson11-checker/1",
        "passed": bool(reports) and all(r.passed for r in reports) and not all_errors,
        "score": sum(r.score for r in reports),
        "max_score": sum(r.max_score for r in reports),
        "labs": [{"path": _rel(r.path, root), "lab": r.lab.id if r.lab is not None else None,
                  "title": r.lab.title if r.lab is not None else None, "status": r.status,
                  "score": r.score, "max_score": r.max_score, "seconds": round(r.seconds, 2),
                  "seed": getattr(r, "seed", None), "message": message_of(r),
                  "flags": list(getattr(r, "flags", ()) or ()), "notes": list(getattr(r, "notes", ()) or ()),
                  "criteria": [_criterion_json(c, r, pictures) for c in r.results]}
                 for r in reports],
        "errors": [{"path": p, "message": m} for p, m in all_errors],
    }


def _criterion_json(result, report, pictures):
    document = result.to_json()
    if pictures is not None:
        document["pictures"] = list(((pictures.get(report.path) or {}).get(result.id)) or ())
    return document


def gradescope(reports, root=None, pictures=None):
    """Gradescope's results.json: top-level score, and one test per check (name, score, max_score, status, output).

    Meant for one submission (one row); a row that could not be graded is one failed test saying why.
    pictures: {row path: {check id: [checker.replay.pictures.Picture]}} (--pictures): a test with pictures gets
    output_format "html", its text in a <pre> and each picture as an <img> with a data: URI.
    """
    tests = []
    for report in reports:
        prefix = f"{_rel(report.path, root)}: " if len(reports) > 1 else ""
        if isinstance(report, NotGraded):
            tests.append({"name": prefix + "could not be graded", "score": 0.0, "max_score": report.max_score,
                          "status": "failed", "output": f"{_rel(report.path, root)}: {report.message}",
                          "visibility": "visible"})
            continue
        for r in report.results:
            output = "\n".join(part for part in (r.message, ("Hint " + r.hint) if r.hint else "") if part)
            test = {"name": prefix + r.name, "score": r.score, "max_score": r.max_score,
                    "status": "passed" if r.status == "pass" else "failed",
                    "output": output or ("skipped" if r.status == "skip" else ""), "visibility": "visible"}
            if getattr(r, "mistake", None) is not None:   # Gradescope keeps a test's extra_data as given
                test["extra_data"] = {"mistake": r.mistake.to_json()}
            shown = ((pictures or {}).get(report.path) or {}).get(r.id)
            if shown:
                test["output_format"] = "html"
                test["output"] = f"<pre>{html.escape(test['output'])}</pre>" + "".join(
                    f'<p><img alt="{html.escape(p.check_id)}: scene {html.escape(p.scene)}" src="{p.data_url}"></p>'
                    for p in shown)
            tests.append(test)
    return {"score": sum(r.score for r in reports), "output": _summary_line(reports),
            "visibility": "visible", "stdout_visibility": "hidden", "tests": tests}


def _summary_line(reports):
    """"3 of 9 lab files pass every check." Files that are no lab at all are counted apart, not as lab files."""
    lab_rows = [r for r in reports if r.lab is not None]
    passed = sum(1 for r in lab_rows if r.passed)
    line = f"{passed} of {len(lab_rows)} lab file(s) pass every check."
    lost = sum(1 for r in lab_rows if isinstance(r, NotGraded))
    if lost:
        line += f" {lost} could not be graded."
    others = len(reports) - len(lab_rows)
    if others:
        line += f" {others} other file(s) could not be graded as a lab (not counted; see their rows)."
    return line


def lab_means(reports):
    """{lab title: (files, mean fraction of the lab's points)} over the lab files; a score out of its own lab's
    total, so labs out of 15, 17 and 18 points are not averaged together."""
    by_lab = {}
    for r in reports:
        if r.lab is not None and r.max_score:
            by_lab.setdefault(r.lab.title, []).append(r.score / r.max_score)
    return {title: (len(fractions), sum(fractions) / len(fractions)) for title, fractions in by_lab.items()}


def check_label(result):
    """A check as an instructor reads it: "Step 2 (sat_axes)" for a lesson step's check, else its id."""
    step = step_of(result.name)
    return f"Step {step} ({result.id})" if step else result.id


def student_of(name):
    """The student a submission belongs to: the folder of its name below the class folder ("alice" for
    alice/tumbling_crates), or the file's name when it lies in the class folder itself."""
    return name.replace("\\", "/").split("/")[0]


def summary_table(reports, stream, root=None):
    """One line per row: score, status and the first check that did not pass (or why it was not graded)."""
    width = max([len(_rel(r.path, root)) for r in reports] + [4])
    stream.write(f"{'file':<{width}}  score   status  first problem\n")
    for r in reports:
        if isinstance(r, NotGraded):
            problem = one_line(f"not graded: {r.message}")
        else:
            first = next((c for c in r.results if c.status != "pass"), None)
            problem = f"{check_label(first)}: {first.status}" if first else ""
        stream.write(f"{one_line(_rel(r.path, root)):<{width}}  {r.score:>2g}/{r.max_score:<3g} {r.status:<7} {problem}\n")
    stream.write(_summary_line(reports) + "\n")


FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")   # what a spreadsheet reads as a formula at a cell's start


def inert(text):
    """A CSV cell a spreadsheet shows as text: a cell from a student's folder name, path or message that starts
    like a formula (`=HYPERLINK(...)`) gets a leading apostrophe, so opening the grades runs nothing."""
    return "'" + text if text.startswith(FORMULA_STARTS) else text


def csv_text(reports, root=None):
    """One row per entry: student (the submission's folder), path, lab, status, score, max_score, fraction (of
    its own lab's points; 0 for a file that scores 0 of no lab's points, such as an empty one), each check's
    status, mistakes (mistakes_text), then message: the row's reason (reason()). With several labs a check's
    column is "lab:check", so no column mixes two labs' checks."""
    several = len({r.lab.id for r in reports if r.lab is not None}) > 1
    columns = []
    for r in reports:
        for c in r.results:
            key = (r.lab.id if r.lab is not None else "", c.id)
            if key not in columns:
                columns.append(key)
    names = submission_names([r.path for r in reports])
    out = io.StringIO(newline="")
    writer = csv.writer(out)
    writer.writerow(["student", "path", "lab", "status", "score", "max_score", "fraction",
                     *[f"{lab}:{check}" if several else check for lab, check in columns], "mistakes", "message"])
    for r in reports:
        lab = r.lab.id if r.lab is not None else ""
        by_id = {(lab, c.id): c.status for c in r.results}
        fraction = f"{r.score / r.max_score:.3f}" if r.max_score else ("0.000" if getattr(r, "counted", False) else "")
        writer.writerow([inert(student_of(names[r.path])), inert(_rel(r.path, root)), lab, r.status, f"{r.score:g}",
                         f"{r.max_score:g}", fraction, *[by_id.get(key, "") for key in columns],
                         inert(mistakes_text(r)), inert(reason(r))])
    return out.getvalue()


def mistakes_text(row):
    """The CSV's `mistakes` cell: "check=mistake id" for each failing check that named one, "; " between."""
    return "; ".join(f"{r.id}={r.mistake.id}" for r in row.results if getattr(r, "mistake", None) is not None)


def class_mistakes(rows):
    """What the class got wrong, per check: [(lab title, check label, files failing it, files graded, [(mistake id,
    sentence, [file paths])] most made first, [paths failing it with no mistake named])], in the labs' check
    order, for the checks some file failed (fail or error, not skip)."""
    order, by_check = [], {}
    for row in rows:
        for r in row.results:
            key = (row.lab.id if row.lab is not None else "", r.id)
            if key not in by_check:
                order.append(key)
                by_check[key] = {"title": row.lab.title if row.lab is not None else "", "label": check_label(r),
                                 "graded": 0, "failing": [], "named": {}, "unnamed": []}
            entry = by_check[key]
            entry["graded"] += 1
            if r.status not in ("fail", "error"):
                continue
            entry["failing"].append(row.path)
            mistake = getattr(r, "mistake", None)
            if mistake is None:
                entry["unnamed"].append(row.path)
            else:
                entry["named"].setdefault(mistake.id, (mistake.text, []))[1].append(row.path)
    out = []
    for key in order:
        entry = by_check[key]
        if entry["failing"]:
            named = sorted(((mid, text, paths) for mid, (text, paths) in entry["named"].items()),
                           key=lambda item: -len(item[2]))
            out.append((entry["title"], entry["label"], len(entry["failing"]), entry["graded"], named,
                        entry["unnamed"]))
    return out


def mistakes_csv_text(reports, root=None):
    """The class's mistakes (--mistakes-csv): one row per named mistake of a check some file failed, then one
    "(not named)" row for the files failing it with no mistake named: lab, check, step, failing (files failing
    the check), graded (files graded by it), mistake (id), sentence, files (how many made it), paths."""
    out = io.StringIO(newline="")
    writer = csv.writer(out)
    writer.writerow(["lab", "check", "step", "failing", "graded", "mistake", "sentence", "files", "paths"])
    for title, label, failing, graded, named, unnamed in class_mistakes(reports):
        step = step_of(label)
        rows = [(mid, text, paths) for mid, text, paths in named] + ([("(not named)", "", unnamed)] if unnamed else [])
        for mid, text, paths in rows:
            writer.writerow([title, label, step if step is not None else "", failing, graded, mid, text, len(paths),
                             inert("; ".join(_rel(p, root) for p in paths))])
    return out.getvalue()


def write_csv(reports, path, root=None):
    """Write csv_text(reports) to path, atomically."""
    write_atomic(path, csv_text(reports, root))


def gradescope_text(reports, root=None, pictures=None):
    return json.dumps(gradescope(reports, root, pictures), indent=2) + "\n"


def write_atomic(path, text):
    """Write text (UTF-8) to path through a temporary file in the same folder and os.replace().

    A crash leaves either the old file or the new one, never half of one. The
    new file gets the old one's permissions, or the usual ones (umask) if new.
    """
    folder = os.path.dirname(os.path.abspath(path))
    fd, temp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", suffix=".tmp", dir=folder)
    with temporary_removed_on_failure(temp):
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
            handle.flush()
            os.fsync(handle.fileno())
        try:   # the old file's permissions: of the file itself, never of what a link there points to
            info = os.lstat(path)
            if not stat.S_ISREG(info.st_mode):
                raise OSError("not a regular file")
            mode = info.st_mode & 0o777
        except OSError:
            umask = os.umask(0)
            os.umask(umask)
            mode = 0o666 & ~umask
        os.chmod(temp, mode)
        os.replace(temp, path)


def _rel(path, root):
    """The path relative to root (default: the current folder) when below it, else as given: a path typed
    relative is shown as typed (`starters\\x.py` on Windows, `starters/x.py` elsewhere)."""
    return relative(path, root)


def list_labs(labs, stream):
    """Every lab with its checks in order: id, points, and the description the student sees."""
    for lab in labs:
        checks = lab.checks.checks
        stream.write(f"{lab.title} ({lab.id}): {len(checks)} checks, {lab.checks.max_score:g} points\n")
        width = max(len(c.id) for c in checks)
        for c in checks:
            stream.write(f"  {c.id:<{width}}  {c.max_score:g} pt  {c.description}\n")
        stream.write("\n")
