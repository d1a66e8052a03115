"""What every benchmark shares: the command line, where the files go, the machine note, lockstep timing.

    bench_parser     --quick, --out-dir, --repeats, --no-plot
    output_folder    --out-dir, else assets/ for a full run and nowhere for --quick
    write_results    the .md table and the .png figure (never the full run's files from --quick)
    machine_note     cores, Python, pygame-ce, pymunk, platform, load average, physics2d's commit
    lockstep         advance measurement generators one yield each in turn
"""
import argparse
import os
import platform
import subprocess
from pathlib import Path

from lesson11.physics2d import world as world_module


def lockstep(runs):
    """Advance generator runs one yield each in turn until all have returned; their Measurements, in order."""
    results = [None] * len(runs)
    alive = list(range(len(runs)))
    while alive:
        for index in list(alive):
            try:
                next(runs[index])
            except StopIteration as done:
                results[index] = done.value
                alive.remove(index)
    return results


def pymunk_version():
    try:
        import pymunk
    except ImportError:
        return None
    return pymunk.version


def physics2d_note():
    """Which physics2d was measured: its last git commit, and whether the working tree changes it."""
    folder = Path(world_module.__file__).resolve().parent
    try:
        commit = subprocess.run(["git", "log", "-1", "--format=%h %cs", "--", "."], cwd=folder, capture_output=True,
                                text=True, encoding="utf-8", errors="replace", timeout=10).stdout.strip()
        changed = subprocess.run(["git", "status", "--porcelain", "--", "."], cwd=folder, capture_output=True,
                                 text=True, encoding="utf-8", errors="replace", timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return "physics2d: not in a git checkout"
    if not commit:
        return "physics2d: not in a git checkout"
    return f"physics2d at commit {commit}" + (" plus uncommitted changes" if changed else "")


def machine_note():
    """Cores, Python, pygame-ce, pymunk, the platform and the load when the run started."""
    import pygame
    loadavg = getattr(os, "getloadavg", None)  # not on Windows
    load = " / ".join(f"{x:.2f}" for x in loadavg()) if loadavg else "n/a"
    return (f"{os.cpu_count()} cores · Python {platform.python_version()} · pygame-ce {pygame.version.ver} · "
            f"pymunk {pymunk_version() or 'not installed'} · {platform.platform()} · load average {load} · "
            f"{physics2d_note()}")


def default_out_dir():
    """The repository's assets/ folder when run from a checkout, else ./assets."""
    repo_assets = Path(__file__).resolve().parents[2] / "assets"
    return repo_assets if repo_assets.is_dir() else Path("assets")


def positive_int(text):
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a whole number >= 1, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a whole number >= 1, got {value}")
    return value


def bench_parser(module, description, files, sizes, unit):
    """The command line every benchmark shares: --quick, --out-dir, --repeats, --no-plot.

    module: the benchmark's module name; files: the name of its .md/.png (no suffix);
    sizes: what --quick shrinks (words); unit: what one timing repeat is of (words).
    """
    parser = argparse.ArgumentParser(prog=f"python -m lesson11.bench.{module}", description=description)
    parser.add_argument("--quick", action="store_true",
                        help=f"smoke run: {sizes}, one repeat, figures not trustworthy; prints only, or with "
                             f"--out-dir writes {files}_quick.md/.png (never the full run's files)")
    parser.add_argument("--out-dir", type=Path, default=None,
                        help=f"where {files}.md/.png go (default: the repository's assets/)")
    parser.add_argument("--repeats", type=positive_int, default=None, help=f"timing repeats per {unit} (median kept)")
    parser.add_argument("--no-plot", action="store_true", help="skip the matplotlib figure")
    return parser


def output_folder(args):
    """Where a benchmark's files go: --out-dir, else assets/ for a full run and nowhere for --quick.

    Returns (folder or None, None), or (None, a one-line error) if --out-dir names a file.
    """
    out_dir = args.out_dir if args.out_dir is not None else (None if args.quick else default_out_dir())
    if out_dir is not None and out_dir.exists() and not out_dir.is_dir():
        return None, f"--out-dir {out_dir} is a file, not a folder"
    return out_dir, None


def write_results(args, out_dir, files, text, draw, smoke_words):
    """Write {files}.md (--quick: {files}_quick.md, never the full run's) into out_dir, then the figure.

    draw(path, subtitle) draws the .png and returns its path; it is skipped with
    --no-plot or without matplotlib. smoke_words open a --quick figure's subtitle.
    Prints what was written; returns the exit status 0.
    """
    if out_dir is None:
        return 0
    out_dir.mkdir(parents=True, exist_ok=True)
    stem = f"{files}_quick" if args.quick else files
    (out_dir / f"{stem}.md").write_text(text, encoding="utf-8")
    print(f"wrote {out_dir / f'{stem}.md'}")
    if args.no_plot:
        return 0
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("matplotlib is not installed: no plot (pip install -e \".[compare]\")")
        return 0
    subtitle = (f"SMOKE RUN (--quick): {smoke_words} · " if args.quick else "full run · ") + machine_note()
    print(f"wrote {draw(out_dir / f'{stem}.png', subtitle)}")
    return 0
