"""The command line: python -m checker PATH... [options]. See checker/README.md.

Exit status: 0 every entry was graded and passes every check; 1 an entry
fails a check or could not be graded (or an output could not be written);
2 the command line is wrong (a bad option or value, a path that does not
exist, a folder with nothing to grade, an output path that is refused), or,
without the zygote, the user the student's code would run as cannot run
Python: then nothing is graded and nothing is written.
"""
import argparse
import errno
import json
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed

from checker.reporting import html_report, outputs, report
from checker.replay import pictures
from checker.isolation import disk, sandbox, users
from checker.replay import show as show_mode
from checker.entries import discover, graded_folders
from checker.grade import Grader
from checker import labs
from checker.reporting.report import NotGraded
from checker.isolation.sandbox import Limits

FULL = tuple(getattr(errno, name) for name in ("ENOSPC", "EDQUOT") if hasattr(errno, name))   # a full disk

USAGE = 2


class UsageError(Exception):
    """The command line is wrong; the message is one line."""


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(f"{message} (python -m checker --help lists the options)")


def parse_args(argv):
    parser = Parser(
        prog="python -m checker", allow_abbrev=False,
        description="Grade Lesson 11 lab files headless: each file runs in its own limited process.",
        epilog="Exit status: 0 every entry graded and passing; 1 an entry fails or could not be graded; 2 a wrong "
               "command line (nothing graded, nothing written). No file is written unless --csv, --mistakes-csv, "
               "--gradescope, --gradescope-dir, --pictures or --html asks. See checker/README.md.")
    parser.add_argument("paths", nargs="*", metavar="PATH",
                        help="lab files, folders of lab files, or folders of submission folders")
    parser.add_argument("--list", action="store_true",
                        help="list every lab the checker knows with its checks, their steps and points, and stop")
    parser.add_argument("--json", action="store_true", help="print the results as JSON (schema in checker/README.md)")
    parser.add_argument("--csv", metavar="FILE",
                        help="write one CSV row per entry to FILE (only when asked; an existing FILE is replaced)")
    parser.add_argument("--mistakes-csv", metavar="FILE",
                        help="write the class's mistakes to FILE: per check, the files failing it and each named "
                             "mistake with its count and files (only when asked; an existing FILE is replaced)")
    parser.add_argument("--gradescope", metavar="FILE",
                        help="write Gradescope's results.json for the one submission being graded to FILE")
    parser.add_argument("--gradescope-dir", metavar="DIR",
                        help="write one Gradescope results.json per submission: DIR/<submission>/results.json")
    parser.add_argument("--pictures", metavar="DIR",
                        help="draw each failed behaviour check's scene (and the solution's) as a PNG filmstrip: "
                             "DIR/<submission>/<check>.png, listed in the report and embedded in --gradescope output")
    parser.add_argument("--html", metavar="FILE",
                        help="write a class report to FILE: one self-contained HTML page (sortable table, every "
                             "check with its hint and pictures, a histogram per check)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="child processes at once (default: all cores, %(default)s here)")
    parser.add_argument("--timeout", type=float, default=20.0,
                        help="CPU seconds for each run of a lab (its import check and each scene; default 20); "
                             "its wall-clock limit is 3 x that + 5 s")
    parser.add_argument("--total-timeout", type=float, default=1800.0,
                        help="wall-clock seconds for the whole run; labs not started by then are errors (default 1800)")
    parser.add_argument("--memory", type=int, default=768, help="address-space limit per run in MB (default 768)")
    parser.add_argument("--max-output", type=int, default=256,
                        help="KB of stdout + stderr a run may print before it is stopped (default 256)")
    parser.add_argument("--disk", type=int, default=disk.DEFAULT_MB, metavar="MB",
                        help="MB of files a run may write into its folder before it is stopped "
                             f"(default {disk.DEFAULT_MB})")
    parser.add_argument("--seed", type=int, default=None, metavar="N",
                        help="draw the probes' per-run inputs with seed N (default: a fresh seed per file, shown in "
                             "--json as each file's \"seed\"; give it here to grade a file again with the same inputs)")
    parser.add_argument("--child-user", metavar="NAME", default=None,
                        help="when the grader runs as root, run the student's code (the child processes) as NAME "
                             f"(default: {users.DEFAULT_CHILD_USER}; 'root' runs it as root); the grader stays root "
                             "and keeps what only it may read, such as the solutions. A grader that is not root "
                             "runs it as itself")
    parser.add_argument("--show", nargs="?", const="", default=None, metavar="CHECK",
                        help="grade one FILE, then replay the first failed check (or CHECK) in a window: the scene "
                             "as graded beside the solution's, or a failed function check's cases drawn "
                             "(checker/replay/show.py); with --seed N the probes draw the same inputs again")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    parser.add_argument("--allow-edits", action="store_true",
                        help="code changed outside the steps is a warning, not a failure (the scenes still run)")
    args = parser.parse_args(argv)
    if not args.paths and not args.list:
        parser.error("give at least one PATH to grade (or --list)")
    for name in ("timeout", "total_timeout"):
        if not getattr(args, name) > 0:
            parser.error(f"--{name.replace('_', '-')} must be > 0 s, got {getattr(args, name):g}")
    if args.jobs < 1:
        parser.error(f"--jobs must be >= 1, got {args.jobs}")
    if args.memory < 64:
        parser.error(f"--memory must be >= 64 MB, got {args.memory}")
    if args.max_output < 1:
        parser.error(f"--max-output must be >= 1 KB, got {args.max_output}")
    if args.disk < 1:
        parser.error(f"--disk must be >= 1 MB, got {args.disk}")
    args.child_user, problem = users.choose(args.child_user)   # root: an unprivileged user unless told otherwise
    if problem:
        parser.error(problem)
    if args.csv is not None and args.csv.lower() == "none":
        args.csv = None  # `--csv none` from older scripts: no CSV (which is now the default)
    for option in ("csv", "mistakes_csv", "gradescope", "gradescope_dir", "pictures", "html"):
        if getattr(args, option) == "":
            parser.error(f"--{option.replace('_', '-')} needs a path, got an empty one")
    if args.show is not None:
        extra = [f"--{o.replace('_', '-')}" for o in ("json", "csv", "mistakes_csv", "gradescope", "gradescope_dir",
                                                      "pictures", "html")
                 if getattr(args, o)]
        if extra:
            parser.error(f"--show opens a window for one file; it does not write {', '.join(extra)}")
    return args


def plan(args):
    """(entries, the outputs to write) for the command line; raises UsageError naming every problem."""
    entries, problems = discover(args.paths)
    wanted = [(f"--{name.replace('_', '-')}", getattr(args, name), kind)
              for name, kind in (("csv", "file"), ("mistakes_csv", "file"), ("gradescope", "file"),
                                 ("gradescope_dir", "folder"),
                                 ("pictures", "folder"), ("html", "file"))
              if getattr(args, name)]
    problems += outputs.check(wanted, args.paths, entries, graded_folders(args.paths))
    if not problems and args.gradescope and len(entries) > 1:
        problems.append(f"--gradescope {args.gradescope}: {len(entries)} files to grade, but a results.json holds "
                        f"one submission; use --gradescope-dir DIR for one results.json per submission")
    if problems:
        raise UsageError("\n".join(problems))
    return entries


def grade_all(entries, grader, jobs, progress):
    """One row per entry, in order: a LabReport, or a NotGraded when the entry (or the grader on it) failed."""
    rows = [NotGraded(e.path, e.lab, e.problem, counted=e.counted) if not e.gradable else None for e in entries]
    todo = [i for i, row in enumerate(rows) if row is None]
    start = time.monotonic()
    done = 0
    said = set()   # the checker's own one-line problems, each printed once

    def show(row):
        if progress:
            name = report.one_line(outputs.relative(row.path))   # a student's folder name may hold ESC
            print(f"[{done}/{len(rows)}] {name}: {row.score:g}/{row.max_score:g} {row.status} "
                  f"({time.monotonic() - start:.1f} s)", file=sys.stderr, flush=True)

    for row in rows:
        if row is not None:
            done += 1
            print(f"checker: {report.one_line(row.path)}: not graded: {report.one_line(row.message)}",
                  file=sys.stderr, flush=True)
    if todo:
        with ThreadPoolExecutor(max_workers=max(1, min(len(todo), jobs * 2))) as pool:
            futures = {pool.submit(grader.grade, entries[i].path, entries[i].lab): i for i in todo}
            for future in as_completed(futures):
                index = futures[future]
                entry = entries[index]
                try:
                    rows[index] = future.result()
                except users.ChildUserError as exc:  # the child's user cannot run Python: ours to fix, not the file's
                    rows[index] = NotGraded(entry.path, entry.lab, str(exc))
                    if str(exc) not in said:
                        said.add(str(exc))
                        print(f"checker: error: {exc}", file=sys.stderr, flush=True)
                except OSError as exc:  # the file went away or became unreadable after it was found
                    why = f"cannot read: {exc.strerror or exc}"
                    if exc.errno in FULL:   # the grader's own folders, not the file (another run may have filled it)
                        why = (f"not graded: the checker's temporary folder is full ({exc.strerror}); grade this "
                               "file again when there is room")
                    rows[index] = NotGraded(entry.path, entry.lab, why, counted=True)
                except Exception as exc:  # a bug of ours: this file gets an error row, the batch goes on
                    rows[index] = NotGraded(entry.path, entry.lab,
                                            f"the checker failed on this file ({type(exc).__name__}: {exc}); "
                                            f"this is a bug in the checker, please report it")
                    print(f"checker: {entry.path}: internal error {type(exc).__name__}: {exc}",
                          file=sys.stderr, flush=True)
                done += 1
                show(rows[index])
    return rows


def write_outputs(args, rows):
    """Write the outputs asked for; returns (the one-line problems (an output that could not be written),
    what was written, {row path: {check id: [picture paths]}})."""
    problems, written, links = [], [], {}
    # a picture that cannot be drawn or written costs no grade and no other row's pictures: that row goes without
    made = pictures.all_pictures(rows, problems) if args.pictures or args.html else {}
    shown = made if args.pictures else None   # pictures go into results.json only when --pictures asks
    if args.pictures:
        try:
            links = pictures.write_pictures(rows, args.pictures, outputs.submission_names([r.path for r in rows]),
                                            made, problems)
            count = sum(len(paths) for by_check in links.values() for paths in by_check.values())
            written.append(f"Pictures: {count} PNG file(s) written under {args.pictures}")
        except OSError as exc:
            problems.append(f"--pictures {args.pictures}: cannot write a picture: {exc.strerror or exc}")
    jobs = []
    if args.csv:
        jobs.append(("--csv", args.csv, lambda: report.csv_text(rows), "CSV"))
    if args.mistakes_csv:
        jobs.append(("--mistakes-csv", args.mistakes_csv, lambda: report.mistakes_csv_text(rows), "The class's mistakes"))
    if args.gradescope:
        jobs.append(("--gradescope", args.gradescope, lambda: report.gradescope_text(rows, pictures=shown),
                     "Gradescope"))
    if args.html:
        jobs.append(("--html", args.html, lambda: html_report.html_text(rows, made), "HTML report"))
    for option, path, text, what in jobs:
        try:
            report.write_atomic(path, text())
            written.append(f"{what} written to {path}")
        except OSError as exc:
            problems.append(f"{option} {path}: cannot write it: {exc.strerror or exc}")
    if args.gradescope_dir:
        names = outputs.submission_names([r.path for r in rows])
        count = 0
        for row in rows:
            target = os.path.join(args.gradescope_dir, names[row.path], "results.json")
            try:   # in folders the grader made, following no link (outputs.write_below)
                outputs.write_below(args.gradescope_dir, names[row.path], "results.json",
                                    report.gradescope_text([row], pictures=shown).encode("utf-8"))
                count += 1
            except OSError as exc:
                problems.append(f"--gradescope-dir: cannot write {target}: {exc.strerror or exc}")
        written.append(f"Gradescope: {count} results.json written under {args.gradescope_dir}")
    return problems, written, links


def main(argv=None):
    """Grade the paths; returns the exit status (see the module docstring)."""
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["package"]:  # python -m checker package PLATFORM --out ...: see checker/platforms/package.py
        from checker.platforms import package
        return package.main(argv[1:])
    if argv[:1] == ["assign"]:  # python -m checker assign [--check] [--out DIR]: see checker/authoring/assign.py
        from checker.authoring import assign
        return assign.main(argv[1:])
    if argv[:1] == ["lint-lab"]:  # python -m checker lint-lab ID: see checker/authoring/lint_lab.py
        from checker.authoring import lint_lab
        return lint_lab.main(argv[1:])
    if argv[:1] == ["new-lab"]:  # python -m checker new-lab ID --title "...": see checker/authoring/new_lab.py
        from checker.authoring import new_lab
        return new_lab.main(argv[1:])
    try:
        args = parse_args(argv)
        if args.list:
            report.list_labs(labs.LABS, sys.stdout)
            return 0
        entries = plan(args)
        if args.show is not None and len(entries) != 1:
            raise UsageError(f"--show replays one file; {len(entries)} were found in {' '.join(args.paths)}")
        if args.show is not None and show_mode.display_problem():
            raise UsageError(show_mode.display_problem())
        # without the zygote a POSIX child starts Python as that user, so it must be able to (the portable
        # child starts as the grader and switches user itself once it has imported what a lab needs)
        problem = args.child_user and not sandbox.zygote_enabled() and not sandbox.portable() and \
            users.python_problem(args.child_user, sandbox.PROJECT_ROOT)
        if not problem and args.child_user and not sandbox.jailed_runs():   # no jail: the modes must keep the answers
            problem = users.answers_problem(args.child_user, sandbox.PROJECT_ROOT)
        if problem:
            raise UsageError(problem)
    except UsageError as exc:
        for line in str(exc).splitlines():
            print(f"checker: error: {line}", file=sys.stderr)
        return USAGE
    if args.show is not None:
        return show_mode.main(args, entries)
    grader = Grader(Limits(args.timeout, args.memory, args.max_output * 1024, args.child_user, disk_mb=args.disk),
                    args.jobs,
                    args.total_timeout,
                    options={"allow_edits": args.allow_edits}, keep_records=bool(args.pictures or args.html),
                    seed=args.seed)
    rows = grade_all(entries, grader, args.jobs, progress=not args.quiet and len(entries) > 1)
    problems, written, links = write_outputs(args, rows)
    if args.json:
        json.dump(report.to_json(rows, pictures=links if args.pictures else None), sys.stdout, indent=2)
        sys.stdout.write("\n")
    else:
        for row in rows:
            report.text_report(row, sys.stdout, pictures=links.get(row.path))
            if getattr(row, "seed", None) is not None and not row.passed:
                print(f"  graded with seed {row.seed}: python -m checker {report.one_line(row.path)} --show "
                      f"--seed {row.seed} replays the first failure\n")
        if len(rows) > 1:
            report.summary_table(rows, sys.stdout)
        for line in written:
            print(line)
    for line in problems:
        print(f"checker: error: {line}", file=sys.stderr)
    return 0 if rows and all(r.passed for r in rows) and not problems else 1
