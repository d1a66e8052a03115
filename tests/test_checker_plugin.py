"""A lab is one module: a new lab is graded without touching child.py, grade.py, cli.py or report.py.

The test writes a toy lab's checks module, probe module and starter (the handout, written from the toy's
annotated solution by checker/assign.py as every lab's is: the parent
replays the probe's calls of the step functions through it) into a fresh folder of checker/labs/,
as a real lab is added, and a student file into a temporary folder; it adds one row to checker.labs.LABS for this process only, and grades the
toy file with the command line in-process: the probe runs in the child (which imports the
lab's probe module by the name the lab gives), a scene runs under the lab runtime, and the
checks receive what the checks they depend on returned.
"""
import importlib
import json
import os
import shutil
import sys
import textwrap
import uuid

import pytest

from checker import assign, cli, labs

# the toy lab's one source, annotated as a real lab's solution is (checker/assign.py); the student hands it in
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

CHECKS = '''
"""The toy lab's checks."""
import os

from checker.checks import Fail, Passed, Registry

TITLE = "Toy Lab"
PROBES = __name__.rsplit(".", 1)[0] + ".probes"   # this lab's probe module, beside this one
STARTER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "toy_starter.py")  # the handout: its step functions
CHECKS = Registry()


def recognise(path, source):
    return "toy lab" in source.lower()


def scenarios():
    return {"short": {"frames": 5, "fps": 60}}


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
    """The toy lab registered for this process; returns the student file's path.

    Its modules go where a real lab's do, a folder of checker/labs/ (a fresh name, removed afterwards):
    the child has only the project on its path, never the student's folder, where they once sat."""
    folder = os.path.join(os.path.dirname(labs.__file__), f"_toy_{uuid.uuid4().hex[:12]}")
    package = f"checker.labs.{os.path.basename(folder)}"
    os.mkdir(folder)
    try:
        for name, text in (("__init__.py", ""), ("probes.py", textwrap.dedent(PROBES)),
                           ("checks.py", textwrap.dedent(CHECKS)), ("toy_starter.py", STARTER)):
            with open(os.path.join(folder, name), "w", encoding="utf-8") as handle:
                handle.write(text)
        student = tmp_path / "toy.py"
        student.write_text(SOLUTION, encoding="utf-8")
        module = importlib.import_module(package + ".checks")
        monkeypatch.setattr(labs, "LABS", labs.LABS + (labs.Lab("toy_lab", module.TITLE, module),))
        yield student
    finally:
        shutil.rmtree(folder, ignore_errors=True)
        for name in [name for name in sys.modules if name.startswith(package)]:
            sys.modules.pop(name, None)


def test_a_new_lab_is_graded_with_one_module_and_one_row(toy_lab, capsys):
    status = cli.main(["--json", "--quiet", str(toy_lab)])
    document = json.loads(capsys.readouterr().out)
    assert status == 0, document
    (lab,) = document["labs"]
    assert lab["lab"] == "toy_lab" and lab["title"] == "Toy Lab" and lab["score"] == lab["max_score"] == 4
    messages = {c["id"]: c["message"] for c in lab["criteria"]}
    assert messages["doubles"] == "double doubles"
    assert messages["runs"] == "5 frames; the doubles summed to -1"  # the value `doubles` handed on


def test_list_shows_the_new_lab(toy_lab, capsys):
    assert cli.main(["--list"]) == 0
    assert "Toy Lab (toy_lab): 3 checks, 4 points" in capsys.readouterr().out
