"""The command line: python -m checker PATH... [options]. See checker/README.md."""
import argparse
import json
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed

from . import report
from .grade import Grader
from .labs import LABS, identify
from .sandbox import Limits

SKIP_DIRS = {"__pycache__", ".git", ".venv", "venv", "node_modules"}


class PathError(Exception):
    """A path that does not exist or holds no lab."""


def _read(path):
    try:
        with open(path, "rb") as handle:
            return handle.read(2_000_000).decode("utf-8", "replace")
    except OSError as exc:
        raise PathError(f"cannot read {path}: {exc.strerror}")


def find_labs(path):
    """[(file, Lab)] for a lab file, a folder of lab files, or a folder of submission folders."""
    if not os.path.exists(path):
        raise PathError(f"{path}: no such file or folder")
    if os.path.isfile(path):
        if not path.endswith(".py"):
            raise PathError(f"{path}: not a lab (a lab is a .py file)")
        lab = identify(path, _read(path))
        if lab is None:
            raise PathError(f"{path}: not a lab this checker knows ({', '.join(l.title for l in LABS)})")
        return [(path, lab)]
    found = []
    for folder, dirs, files in os.walk(path):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
        for name in sorted(files):
            if name.endswith(".py"):
                file = os.path.join(folder, name)
                lab = identify(file, _read(file))
                if lab is not None:
                    found.append((file, lab))
    if not found:
        raise PathError(f"{path}: no lab files found in this folder")
    return found


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="python -m checker",
        description="Grade Lesson 11 lab files headless: each file runs in its own limited process.")
    parser.add_argument("paths", nargs="+", metavar="PATH",
                        help="lab files, folders of lab files, or folders of submission folders")
    parser.add_argument("--json", action="store_true", help="print the results as JSON (schema in checker/README.md)")
    parser.add_argument("--gradescope", nargs="?", const="results.json", metavar="PATH",
                        help="write Gradescope's results.json to PATH (default: results.json)")
    parser.add_argument("--csv", metavar="PATH",
                        help="write one CSV row per file (default when grading 2+ files: grades.csv; 'none' turns it off)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="child processes at once (default: all cores, %(default)s here)")
    parser.add_argument("--timeout", type=float, default=20.0,
                        help="wall-clock seconds for each run of a lab (its import check and each scene; default 20)")
    parser.add_argument("--total-timeout", type=float, default=1800.0,
                        help="wall-clock seconds for the whole run; labs not started by then are errors (default 1800)")
    parser.add_argument("--memory", type=int, default=768, help="address-space limit per run in MB (default 768)")
    parser.add_argument("--max-output", type=int, default=256,
                        help="KB of stdout + stderr a run may print before it is stopped (default 256)")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    parser.add_argument("--allow-edits", action="store_true",
                        help="code changed outside the steps is a warning, not a failure (the scenes still run)")
    args = parser.parse_args(argv)
    for name in ("timeout", "total_timeout"):
        if getattr(args, name) <= 0:
            parser.error(f"--{name.replace('_', '-')} must be > 0 s, got {getattr(args, name):g}")
    if args.jobs < 1:
        parser.error(f"--jobs must be >= 1, got {args.jobs}")
    if args.memory < 64:
        parser.error(f"--memory must be >= 64 MB, got {args.memory}")
    if args.max_output < 1:
        parser.error(f"--max-output must be >= 1 KB, got {args.max_output}")
    return args


def main(argv=None):
    """Grade the paths; exit status 0 only if every graded lab passes every check, 2 for bad paths."""
    args = parse_args(sys.argv[1:] if argv is None else argv)
    errors, labs = [], []
    for path in args.paths:
        try:
            for item in find_labs(path):
                if os.path.abspath(item[0]) not in {os.path.abspath(f) for f, _ in labs}:
                    labs.append(item)
        except PathError as exc:
            errors.append((path, str(exc)))
            print(f"checker: error: {exc}", file=sys.stderr)
    grader = Grader(Limits(args.timeout, args.memory, args.max_output * 1024), args.jobs, args.total_timeout,
                    options={"allow_edits": args.allow_edits})
    start = time.monotonic()
    reports = [None] * len(labs)
    progress = not args.quiet and len(labs) > 1
    with ThreadPoolExecutor(max_workers=max(1, min(len(labs), args.jobs * 2))) as pool:
        futures = {pool.submit(grader.grade, path, lab): index for index, (path, lab) in enumerate(labs)}
        for done, future in enumerate(as_completed(futures), 1):
            index = futures[future]
            reports[index] = future.result()
            if progress:
                r = reports[index]
                print(f"[{done}/{len(labs)}] {os.path.relpath(r.path)}: {r.score:g}/{r.max_score:g} {r.status} "
                      f"({time.monotonic() - start:.1f} s)", file=sys.stderr, flush=True)
    if args.json:
        json.dump(report.to_json(reports, errors), sys.stdout, indent=2)
        sys.stdout.write("\n")
    else:
        for r in reports:
            report.text_report(r, sys.stdout)
        if len(reports) > 1:
            report.summary_table(reports, sys.stdout)
    if args.gradescope:
        with open(args.gradescope, "w", encoding="utf-8") as handle:
            json.dump(report.gradescope(reports), handle, indent=2)
    csv_path = args.csv if args.csv else ("grades.csv" if len(reports) > 1 else None)
    if csv_path and csv_path.lower() != "none" and reports:
        report.write_csv(reports, csv_path)
        if not args.json:
            print(f"CSV written to {csv_path}")
    if errors:
        return 2
    return 0 if reports and all(r.passed for r in reports) else 1
