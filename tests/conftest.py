"""Shared test set-up: any test that opens a window uses SDL's dummy drivers; the longest files start first."""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

# The files that take longest, longest first. With `--dist loadfile --no-loadscope-reorder` (pyproject's
# addopts) pytest-xdist hands whole files to the workers in collection order, so these start at once and
# the short files fill in around them; otherwise a long file handed out last (xdist's default order is by
# number of tests) runs alone at the end while the other worker idles. The `slow` marker is registered in pyproject.toml.
LONGEST_FIRST = (
    "test_stability_long.py",           # the 10⁵-step busy scene (slow), one process, no parallelism inside
    "test_corpus_tumbling_crates.py",   # 73 files graded by one checker run (its own 2 jobs)
    "test_stability_dynamics.py",       # the base-8 pyramid (slow)
)


def pytest_collection_modifyitems(config, items):
    """Put the files of LONGEST_FIRST first, in that order; every other file keeps its place after them."""
    rank = {name: place for place, name in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))
