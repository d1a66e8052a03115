"""The framework names no lab (issue 42 part 3): what is a lab's lives in its folder, found by convention.

No module of checker/ outside checker/labs/ names a lab's id, its title or one of its own check ids in its
code; the labs and their checks come from the registry (checker.labs.LABS and each lab's CHECKS), never from a
hand list here. What --show and --pictures draw for a lab's checks is its checker/labs/<id>/show.py (SERIES and
CASES); a lab without one gets no plot and no case drawing, and the replay still works.

Read as Python reads it (ast): identifiers, attribute names and import paths, and the string constants that are
code (docstrings and comments may use a lab as an example: they key nothing).
"""
import ast
import glob
import os
import sys

import pytest

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

from checker.authoring import lab_rules
from checker.judging import checks, lab_checks
from checker import labs
from checker.replay import show_cases, show_series   # noqa: E402

CHECKER = os.path.dirname(labs.HERE)


def framework_modules():
    """Every Python file of checker/ outside checker/labs/ (the platforms' templates too) but new-lab's lab template."""
    paths = glob.glob(os.path.join(CHECKER, "**", "*.py"), recursive=True)
    # new-lab's template is the text a new lab is written from: a lab made with it has the template's check ids
    template = os.path.join(CHECKER, "authoring", "lab_template.py")
    return sorted(p for p in paths if not p.startswith(labs.HERE + os.sep) and p != template)


def framework_checks():
    """The ids of the checks the framework itself gives every lab (lab_checks.register_common: loads, ...) or
    requires of every lab (lab_rules.RUNS_CHECK)."""
    registry = checks.Registry()
    lab_checks.register_common(registry, {}, ("f",))
    return {c.id for c in registry.checks} | {lab_rules.RUNS_CHECK}   # and the one every lab must have


def lab_words():
    """(lab ids, lab titles, the labs' own check ids), from the registry."""
    own = {c.id for lab in labs.LABS for c in lab.checks.checks} - framework_checks()
    return {lab.id for lab in labs.LABS}, {lab.title for lab in labs.LABS}, own


def _docstrings(tree):
    return {id(node.body[0].value) for node in ast.walk(tree)
            if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body
            and isinstance(node.body[0], ast.Expr) and isinstance(node.body[0].value, ast.Constant)}


def _words(text):
    return set("".join(c if c.isalnum() or c == "_" else " " for c in text).split())


def named(source, lab_ids, titles, check_ids):
    """[(line, what)]: where the source's code names a lab id (an identifier, an attribute, an import path or a
    word of a string), a lab title (in a string) or a lab's check id (a word of a string). A check id that is an
    English word the framework's messages use ("runs": "each file runs in its own process") counts only as a
    whole string: that is how code keys on a check."""
    tree = ast.parse(source)
    docs = _docstrings(tree)
    found = []
    for node in ast.walk(tree):
        names = []
        if isinstance(node, ast.Name):
            names = [node.id]
        elif isinstance(node, ast.Attribute):
            names = [node.attr]
        elif isinstance(node, ast.ImportFrom):
            names = (node.module or "").split(".") + [alias.name for alias in node.names]
        elif isinstance(node, ast.Import):
            names = [part for alias in node.names for part in alias.name.split(".")]
        found += [(node.lineno, name) for name in names if name in lab_ids]
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docs:
            words = _words(node.value)
            found += [(node.lineno, word) for word in sorted(words & lab_ids)]
            found += [(node.lineno, title) for title in sorted(titles) if title in node.value]
            found += [(node.lineno, word) for word in sorted(words & check_ids)
                      if "_" in word or node.value == word]
    return found


def test_no_framework_module_names_a_lab_or_a_labs_check():
    lab_ids, titles, check_ids = lab_words()
    assert len(lab_ids) == len(labs.LABS) >= 5 and len(check_ids) > 30   # the registry was read
    modules = framework_modules()
    assert os.path.join(CHECKER, "replay", "show.py") in modules and os.path.join(CHECKER, "grade.py") in modules
    naming = {}
    for path in modules:
        with open(path, encoding="utf-8") as handle:
            hits = named(handle.read(), lab_ids, titles, check_ids)
        if hits:
            naming[os.path.relpath(path, CHECKER)] = hits
    assert naming == {}


def test_the_finder_sees_a_lab_named_in_code():
    """The scanner itself: each way the old replay modules named labs is found, and an English word is not."""
    lab_ids, titles, check_ids = lab_words()
    lab, check = labs.LABS[-1], next(c.id for c in labs.LABS[0].checks.checks if "_" in c.id
                                     and c.id not in framework_checks())
    assert named(f'if lab.id == "{lab.id}":\n    pass\n', lab_ids, titles, check_ids) == [(1, lab.id)]
    assert named(f"from .labs.{lab.id} import probes\n", lab_ids, titles, check_ids) == [(1, lab.id)]
    assert named(f"import checker.labs.{lab.id}.checks\n", lab_ids, titles, check_ids) == [(1, lab.id)]
    assert named(f'TABLE = {{\n    "{check}": 1,\n}}\n', lab_ids, titles, check_ids) == [(2, check)]
    assert named(f'name = f"{{x}} ({check})"\n', lab_ids, titles, check_ids) == [(1, check)]
    assert named('quantity = "runs" if x else None\n', lab_ids, titles, {"runs"}) == [(1, "runs")]
    assert named(f'MESSAGE = "the {lab.title} lab"\n', lab_ids, titles, check_ids) == [(1, lab.title)]
    assert named('HELP = "each file runs in its own process"\n', lab_ids, titles, {"runs"}) == []
    assert named(f'def f():\n    """As {lab.id} does: {check}."""\n', lab_ids, titles, check_ids) == []


def test_each_labs_replay_names_only_its_own_checks():
    """A lab's show.py keys SERIES and CASES by its own check ids (a typo would silently draw nothing):
    SERIES holds Quantity, CASES callables; each lab plots every check it pictures (PICTURE_SCENES)."""
    for lab in labs.LABS:
        replay = lab.replay
        assert replay is not None and replay.__name__ == f"checker.labs.{lab.id}.show", lab.id
        ids = {c.id for c in lab.checks.checks}
        assert set(replay.SERIES) <= ids and set(replay.CASES) <= ids, lab.id
        assert all(isinstance(q, show_series.Quantity) for q in replay.SERIES.values()), lab.id
        assert all(callable(cases) for cases in replay.CASES.values()), lab.id
        assert set(lab.picture_scenes) <= set(replay.SERIES), lab.id


def test_a_lab_without_a_replay_gets_no_plot_and_no_cases(monkeypatch):
    """A lab folder without show.py: Lab.replay is None, no quantity, no failing case, and failure() still finds
    the frame a run first differs from the solution's (as for any check the lab does not plot)."""
    lab = labs.LABS[0]
    monkeypatch.setitem(sys.modules, f"checker.labs.{lab.id}.show", None)   # as if the file were not there
    assert lab.replay is None
    some = next(iter(lab.picture_scenes))
    result = type("R", (), {"id": some, "status": "fail", "message": ""})()
    assert show_series.series_for(lab, some) is None
    assert show_cases.failing_cases(lab, result, {"anything": {"ok": True, "data": [{}]}}) == []
    frame = {"frame": 7, "bodies": [{"pos": [0.0, 0.0], "angle": 0.0, "points": [], "static": False}]}
    moved = {"frame": 7, "bodies": [{"pos": [50.0, 0.0], "angle": 0.0, "points": [], "static": False}]}
    fail_frame, why, quantity, values = show_series.failure(lab, result, [moved], [frame], True)
    assert quantity is show_series.DIVERGENCE and fail_frame == 7 and values == [pytest.approx(50.0)]
