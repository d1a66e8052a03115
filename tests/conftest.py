"""Shared test set-up: any test that opens a window uses SDL's dummy drivers; the longest files start first."""
import os
import sys

import pytest
from hypothesis import settings

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

# Hypothesis: random examples on a developer's machine (new cases get found there), the same examples
# on every CI run (CI=true), so a merge is judged by its code and never by the draw. A case a developer's
# run finds is added to its test with @example, so CI keeps checking it.
settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

# The files that take longest, longest first (CPU seconds of the full run on the 2-core machine, issue 13).
# With `--dist loadfile --no-loadscope-reorder` (pyproject's addopts) pytest-xdist hands whole files to the
# workers in collection order, so these start first and the short files fill in around them. xdist's own
# order (most tests first) handed out the 10⁵-step file last, and it ran alone at the end while the other
# worker idled. The first two go one to each worker; the third waits behind the first on its worker.
LONGEST_FIRST = (
    "test_checker_portable.py",         # every corpus graded again through the portable path (no zygote)
    "test_corpus_attacks.py",           # 166 attacks and their honest files, two grading modes
    "test_stability_long.py",           # the 10⁵-step busy scene (slow): one process, nothing parallel inside
    "test_corpus_labs.py",              # every lab's corpus, one checker run a lab (Tumbling Crates: 73 files)
    "test_stability_dynamics.py",       # the base-8 pyramid (slow), the resting pile, the 10-box stack
    "test_checker.py",                  # the solutions, mutants, hostile files
    "test_stability_grid.py",           # 3 solvers × 7 settings × 5 scenes, energy books (~30 s)
    "test_bench.py",                    # the accuracy-cost study at tiny sizes
    "test_checker_package.py",          # the bundles' run_autograder end to end
    "test_lab_criteria.py",             # four runs of the solution's own scenes
)


# Files that test what exists only on POSIX or on the graders' Linux: a Windows runner (.github/workflows/tests.yml)
# skips them with the reason; the checker's portable path, which Windows takes, is tested on Linux every run
# (tests/test_checker_portable.py) and by the workflow's `python -m checker solutions/`.
POSIX_ONLY = {
    "test_checker_zygote.py": "the zygote forks its children (POSIX only)",
    "test_checker_safe_default.py": "a root grader switching the child's user (POSIX only)",
    "test_checker_package.py": "the packages run on the graders' Linux (bash scripts, users)",
    "test_platform_acceptance.py": "debootstrapped Linux roots",
    "test_checker_cli.py": "its class folder holds a FIFO and symbolic links",
}


def pytest_collection_modifyitems(config, items):
    """Put the files of LONGEST_FIRST first, in that order; every other file keeps its place after them.
    On Windows, skip the files of POSIX_ONLY."""
    rank = {name: place for place, name in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))
    if sys.platform == "win32":
        for item in items:
            if item.path.name in POSIX_ONLY:
                item.add_marker(pytest.mark.skip(reason=f"POSIX only: {POSIX_ONLY[item.path.name]}"))
