"""A lab is one folder: a new lab is graded without touching child.py, grade.py, cli.py or report.py.

The test writes a toy lab's checks, probes and scenes modules into a fresh folder of checker/labs/,
as a real lab is added, and its solution and starter where the lab's id puts them, under a temporary root
(solutions/<id>.py; starters/<id>_starter.py, the handout, written from the toy's annotated solution by
checker/authoring/assign.py as every lab's is: the parent replays the probe's calls of the step functions through it);
it adds the lab, found from its id, to checker.labs.LABS for this process only, and grades the
toy file with the command line in-process: the probe runs in the child (which imports the
lab's probe module by the name its id gives), a scene runs under the lab runtime, and the
checks receive what the checks they depend on returned.
"""
import json
import os
import shutil
import sys
import textwrap
import uuid

import pytest

from checker.authoring import assign
from checker import cli, labs

# the toy lab's one source, annotated as a real lab's solution is (checker/authoring/assign.py); the student hands it in
SOLUTION = '''
"""Toy Lab: a made-up exercise for the plug-in test."""
from lesson11 import runtime as lab


def double(x):
    # --- step 1: double x ---
    # BEGIN PROMPT
    # Step 1: return twice x.
    # starter: return None  # placeholder: replace this line with your step 1
    # END PROMPT
    return 2 * x
    # --- end of step 1 ---


def main():
    frames = 0
    while lab.frame_budget():
        frames += 1
        lab.record([])
    print(f"ran {frames} frames")
'''

PROBES = '''
"""The toy lab's probe, run in the checker's child process."""
REQUIRED = ("double", "main")


def probe_double(module, lab_path):
    return [module.double(x) for x in (1, 2.5, -4)]


PROBES = {"double": ("double", probe_double)}
'''

STARTER = assign.starter_text(SOLUTION, "the toy lab's solution")   # made the way every lab's starter is

SCENES = '''
"""The toy lab's scene."""


def short():
    return {"frames": 5, "fps": 60}


SCENARIOS = {"short": short}
'''

CHECKS = '''
"""The toy lab's checks."""
from checker.judging.checks import Fail, Passed, Registry

TITLE = "Toy Lab"
CHECKS = Registry()


def recognise(path, source):
    return "toy lab" in source.lower()


@CHECKS.check()
def loads(sub):
    """The file imports."""
    if sub.probe.status != "done":
        raise Fail("the file did not import")
    return sub.probe.result["probe"]["functions"]


@CHECKS.check(depends=["loads"])
def doubles(sub, functions):
    """double() doubles."""
    got = functions["double"]["data"]
    if got != [2, 5.0, -8]:
        raise Fail(f"double gave {got}")
    return Passed("double doubles", value=sum(got))


@CHECKS.check(depends=["doubles"], max_score=2, needs_scenarios=True)
def runs(sub, total):
    """main() runs the short scene."""
    run = sub.scenarios["short"]
    if run.status != "done" or "ran 5 frames" not in run.stdout:
        raise Fail(f"the scene ended {run.status}: {run.stdout!r}")
    return f"5 frames; the doubles summed to {total:g}"
'''


@pytest.fixture
def toy_lab(tmp_path, monkeypatch):
    """The toy lab registered for this process; returns its Lab (its id is its folder's name) and the student file.

    Its modules go where a real lab's do, a folder of checker/labs/ (a fresh name, removed afterwards; a
    leading _ keeps other tests' registries from finding it): the child has only the project on its path,
    never the student's folder, where they once sat."""
    lab_id = f"_toy_{uuid.uuid4().hex[:12]}"
    folder = os.path.join(os.path.dirname(labs.__file__), lab_id)
    package = f"checker.labs.{lab_id}"
    os.mkdir(folder)
    try:
        for name, text in (("__init__.py", ""), ("probes.py", textwrap.dedent(PROBES)),
                           ("checks.py", textwrap.dedent(CHECKS)), ("scenes.py", textwrap.dedent(SCENES))):
            with open(os.path.join(folder, name), "w", encoding="utf-8") as handle:
                handle.write(text)
        (tmp_path / "starters").mkdir()
        (tmp_path / "starters" / f"{lab_id}_starter.py").write_text(STARTER, encoding="utf-8")
        student = tmp_path / "toy.py"
        student.write_text(SOLUTION, encoding="utf-8")
        (tmp_path / "solutions").mkdir()
        (tmp_path / "solutions" / f"{lab_id}.py").write_text(SOLUTION, encoding="utf-8")
        lab = labs.Lab(lab_id, root=str(tmp_path))
        monkeypatch.setattr(labs, "LABS", labs.LABS + (lab,))
        yield lab, student
    finally:
        shutil.rmtree(folder, ignore_errors=True)
        for name in [name for name in sys.modules if name.startswith(package)]:
            sys.modules.pop(name, None)


def test_a_new_lab_is_graded_from_its_folder(toy_lab, capsys):
    toy, student = toy_lab
    status = cli.main(["--json", "--quiet", str(student)])
    document = json.loads(capsys.readouterr().out)
    assert status == 0, document
    (lab,) = document["labs"]
    assert lab["lab"] == toy.id and lab["title"] == "Toy Lab" and lab["score"] == lab["max_score"] == 4
    messages = {c["id"]: c["message"] for c in lab["criteria"]}
    assert messages["doubles"] == "double doubles"
    assert messages["runs"] == "5 frames; the doubles summed to -1"  # the value `doubles` handed on


def test_list_shows_the_new_lab(toy_lab, capsys):
    assert cli.main(["--list"]) == 0
    assert f"Toy Lab ({toy_lab[0].id}): 3 checks, 4 points" in capsys.readouterr().out
