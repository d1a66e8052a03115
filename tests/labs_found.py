"""The labs the tests cover, found as the checker finds them: every lab in checker/labs/ (checker.labs.LABS).

A test that covers labs parametrizes over LABS (or params()), never over a list of ids of its own, so a lab is
covered by being there. What a test needs of one lab comes from the lab itself:

    lab.id, lab.title, lab.solution, lab.starter, lab.module (checks.py: STEP_LIBRARY, CHECKS, ...), lab.scenarios()
    steps(lab)          the student's steps: the step regions of its solution ({step: (start, end, indent)})
    step_functions(lab) {step: (function name, its parameters)}: the handout function holding each step region
    corpus(lab)         its mistake corpus, tests/corpus_<id>.py, or None when it has none
    need_corpus(lab)    its corpus, or a test failure naming the lab and the file to write

A lab-specific value a generic test needs (which corpus entry --show opens, two mistakes made at once) is in the
lab's corpus file, never in a table in the test.
"""
import ast
import functools
import importlib
import os
import sys

import pytest

TESTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(TESTS)
for _path in (TESTS, ROOT):
    if _path not in sys.path:
        sys.path.insert(0, _path)

from checker import labs as _registry  # noqa: E402
from checker.reading.handout import step_regions   # noqa: E402

LABS = tuple(_registry.LABS)
IDS = tuple(lab.id for lab in LABS)
CORPUS_DOC = "tests/corpus_verdicts.py"   # what a corpus module holds


def by_id(lab_id):
    """The registered lab `lab_id`."""
    return next(lab for lab in LABS if lab.id == lab_id)


def params(labs=LABS):
    """pytest.param per lab, with its id as the test's id."""
    return [pytest.param(lab, id=lab.id) for lab in labs]


def _read(path):
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def corpus_file(lab):
    """Where the lab's mistake corpus is: tests/corpus_<id>.py."""
    return os.path.join(TESTS, f"corpus_{lab.id}.py")


@functools.lru_cache(maxsize=None)
def corpus(lab):
    """The lab's mistake corpus module (tests/corpus_<id>.py), or None when that file does not exist."""
    if not os.path.exists(corpus_file(lab)):
        return None
    return importlib.import_module(f"corpus_{lab.id}")


def missing_corpus(lab):
    """The failure message of a lab without a corpus: which lab, which file to write, what it holds."""
    return (f"lab {lab.id!r} ({lab.title}) has no mistake corpus: write {os.path.relpath(corpus_file(lab), ROOT)} "
            f"(plausible wrong files and correct ones in other styles, with the verdict the checker owes each; "
            f"what it holds: {CORPUS_DOC}; an example: tests/corpus_sleeping_crates.py)")


def need_corpus(lab):
    """The lab's corpus; a failed test naming the lab and the file to write when it has none."""
    module = corpus(lab)
    if module is None:
        pytest.fail(missing_corpus(lab), pytrace=False)
    return module


def with_corpus():
    """The labs that have a corpus (those without one fail test_corpus_labs.py's test_every_lab_has_a_corpus)."""
    return tuple(lab for lab in LABS if corpus(lab) is not None)


def steps(lab, path=None):
    """{step: (start, end, indent)}: the step regions of the lab's solution (or of `path`), as the checker reads them."""
    return step_regions(_read(path or lab.solution).split("\n"))


def step_functions(lab, path=None):
    """{step: (name, (parameter, ...))}: the top-level function (or method) of the solution holding each step region."""
    source = _read(path or lab.solution)
    regions = step_regions(source.split("\n"))
    holders = [node for node in ast.walk(ast.parse(source)) if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))]
    out = {}
    for step, (start, end, _) in regions.items():
        line = start + 1   # 1-based line of the step's start marker
        inside = [node for node in holders if node.lineno <= line <= node.end_lineno]
        if inside:
            node = max(inside, key=lambda n: n.lineno)   # the innermost
            out[step] = (node.name, tuple(a.arg for a in node.args.args))
    return out

