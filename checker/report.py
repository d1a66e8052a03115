"""Outputs: the readable report, --json, --gradescope results.json, the summary table and the CSV.

JSON schema (`--json`, version 1):
{
  "schema": "lesson11-checker/1",
  "passed": bool,                       # every graded lab passed every check
  "score": float, "max_score": float,   # sums over all graded labs
  "labs": [{
      "path": str, "lab": str (lab id), "title": str,
      "status": "pass" | "fail" | "error",
      "score": float, "max_score": float, "seconds": float,
      "criteria": [{                     # in the lab's fixed order
          "id": str,                     # stable check id, e.g. "corner_tips"
          "name": str,                   # the check's description (its docstring)
          "status": "pass" | "fail" | "skip" | "error",
          "message": str,                # what was measured / what went wrong ("" when silent)
          "hint": str,                   # what to revisit: "[step N: title] advice" ("" on pass/skip)
          "step": int | null,            # the lesson step (1-7) the hint names
          "score": float, "max_score": float}]}],
  "errors": [{"path": str, "message": str}]   # paths that do not exist or are not labs
}
"""
import csv
import json
import os

SYMBOL = {"pass": ":)", "fail": ":(", "skip": ":|", "error": ":("}


def text_report(report, stream, root=None):
    """The readable report of one lab: a mark per check, the message, and the hint under each failure."""
    name = _rel(report.path, root)
    stream.write(f"{name} - {report.lab.title}: {report.score:g}/{report.max_score:g} "
                 f"({report.status}, {report.seconds:.1f} s)\n")
    for r in report.results:
        stream.write(f"  {SYMBOL[r.status]} {r.name}\n")
        if r.message:
            stream.write(f"      {r.message}\n")
        if r.hint:
            stream.write(f"      hint {r.hint}\n")
    stream.write("\n")


def to_json(reports, errors, root=None):
    """The whole run as the documented JSON document (a dict)."""
    return {
        "schema": "lesson11-checker/1",
        "passed": bool(reports) and all(r.passed for r in reports) and not errors,
        "score": sum(r.score for r in reports),
        "max_score": sum(r.max_score for r in reports),
        "labs": [{"path": _rel(r.path, root), "lab": r.lab.id, "title": r.lab.title, "status": r.status,
                  "score": r.score, "max_score": r.max_score, "seconds": round(r.seconds, 2),
                  "criteria": [c.to_json() for c in r.results]} for r in reports],
        "errors": [{"path": p, "message": m} for p, m in errors],
    }


def gradescope(reports, root=None):
    """Gradescope's results.json: top-level score, and one test per check (name, score, max_score, status, output)."""
    tests = []
    for report in reports:
        prefix = f"{_rel(report.path, root)}: " if len(reports) > 1 else ""
        for r in report.results:
            output = "\n".join(part for part in (r.message, ("Hint " + r.hint) if r.hint else "") if part)
            tests.append({"name": prefix + r.name, "score": r.score, "max_score": r.max_score,
                          "status": "passed" if r.status == "pass" else "failed",
                          "output": output or ("skipped" if r.status == "skip" else ""), "visibility": "visible"})
    return {"score": sum(r.score for r in reports), "output": _summary_line(reports),
            "visibility": "visible", "stdout_visibility": "hidden", "tests": tests}


def _summary_line(reports):
    passed = sum(1 for r in reports if r.passed)
    return f"{passed} of {len(reports)} lab file(s) pass every check."


def summary_table(reports, stream, root=None):
    """One line per graded file: score, status and the first check that did not pass."""
    width = max([len(_rel(r.path, root)) for r in reports] + [4])
    stream.write(f"{'file':<{width}}  score   status  first problem\n")
    for r in reports:
        first = next((c for c in r.results if c.status != "pass"), None)
        problem = f"{first.id} ({first.status})" if first else ""
        stream.write(f"{_rel(r.path, root):<{width}}  {r.score:>2g}/{r.max_score:<3g} {r.status:<7} {problem}\n")
    stream.write(_summary_line(reports) + "\n")


def write_csv(reports, path, root=None):
    """One row per file: path, lab, status, score, max_score, then each check's status in order."""
    ids = []
    for r in reports:
        for c in r.results:
            if c.id not in ids:
                ids.append(c.id)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["path", "lab", "status", "score", "max_score", *ids])
        for r in reports:
            by_id = {c.id: c.status for c in r.results}
            writer.writerow([_rel(r.path, root), r.lab.id, r.status, f"{r.score:g}", f"{r.max_score:g}",
                             *[by_id.get(i, "") for i in ids]])


def _rel(path, root):
    try:
        return os.path.relpath(path, root or os.getcwd())
    except ValueError:
        return path
