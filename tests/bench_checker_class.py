"""Benchmark: grade a generated class of N submissions with the checker, and time it.

    python tests/bench_checker_class.py [--n 100] [--jobs J] [--root REPO] [--keep]

Writes N per-student folders (student_001/tumbling_crates.py, ...) into a
temporary directory from the mistake corpus (tests/corpus_tumbling_crates.py):
every other one a correct completion (in turn through the corpus's correct
entries), the rest its wrong completions in turn (each fails, or errs on, one check). Half
correct is a pessimistic class: a correct file runs all four scenes, a wrong
one stops after the function checks. Then
runs, from REPO (default: this repository),

    python -m checker DIR --quiet --csv OUT

and prints the wall time, files per second, and how many passed / failed /
could not be graded (read from the CSV), with the expected counts. Not a
test (pytest does not collect it: its name does not start with test_); the
figure depends on the machine and on what else runs on it, so the load
average is printed too.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import corpus_tumbling_crates as corpus  # noqa: E402  (tests/corpus_tumbling_crates.py)


def make_class(directory, n):
    """N student folders; returns {"pass": count, "fail": count} expected."""
    right = [entry.name for entry in corpus.ENTRIES if entry.check == "pass"]
    wrong = [entry.name for entry in corpus.WRONG]
    expected = {"pass": 0, "fail": 0}
    for i in range(n):
        folder = os.path.join(directory, f"student_{i + 1:03d}")
        os.makedirs(folder)
        if i % 2 == 0:
            text = corpus.build(right[(i // 2) % len(right)])
            expected["pass"] += 1
        else:
            text = corpus.build(wrong[(i // 2) % len(wrong)])
            expected["fail"] += 1
        with open(os.path.join(folder, "tumbling_crates.py"), "w", encoding="utf-8") as handle:
            handle.write(text)
    return expected


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=100, help="submissions to generate (default 100)")
    parser.add_argument("--jobs", type=int, default=None, help="passed to the checker as --jobs (default: its own)")
    parser.add_argument("--root", default=os.path.dirname(HERE),
                        help="the repository whose checker is run (default: this one)")
    parser.add_argument("--keep", action="store_true", help="keep the generated folder and CSV, and print where")
    args = parser.parse_args(argv)
    if args.n < 1:
        parser.error(f"--n must be >= 1, got {args.n}")
    work = tempfile.mkdtemp(prefix="bench-class-")
    try:
        klass = os.path.join(work, "class")
        os.makedirs(klass)
        expected = make_class(klass, args.n)
        out = os.path.join(work, "grades.csv")
        command = [sys.executable, "-m", "checker", klass, "--quiet", "--csv", out]
        if args.jobs:
            command += ["--jobs", str(args.jobs)]
        env = dict(os.environ, PYTHONPATH=args.root, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
        load_before = os.getloadavg()
        start = time.monotonic()
        proc = subprocess.run(command, cwd=args.root, env=env, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        wall = time.monotonic() - start
        load_after = os.getloadavg()
        counts = {"pass": 0, "fail": 0, "error": 0}
        if os.path.exists(out):
            with open(out, newline="", encoding="utf-8") as handle:
                for row in csv.DictReader(handle):
                    counts[row["status"]] = counts.get(row["status"], 0) + 1
        print(f"checker: {' '.join(command[1:])}  (from {args.root})")
        print(f"submissions: {args.n} ({expected['pass']} correct, {expected['fail']} wrong, from the corpus), "
              f"cores: {os.cpu_count()}, load average before/after: {load_before[0]:.2f} / {load_after[0]:.2f}")
        print(f"wall time: {wall:.1f} s   files per second: {args.n / wall:.2f}   "
              f"seconds per file: {wall / args.n:.2f}")
        print(f"passed: {counts['pass']} (expected {expected['pass']})   failed or error: "
              f"{counts['fail'] + counts['error']} (expected {expected['fail']}; error = a check whose code raised, "
              f"timed out or crashed: {counts['error']})   exit status: {proc.returncode}")
        if proc.stderr.strip():
            print("checker stderr (last lines):\n" + "\n".join(proc.stderr.strip().splitlines()[-5:]))
        if args.keep:
            print(f"kept: {work}")
        return 0 if proc.returncode in (0, 1) and sum(counts.values()) == args.n else 1
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
