"""Gradescope's own procedure, for tests: the package's run_autograder copied to the autograder root and run from
there, as root, with the student's code as `nobody` (Gradescope's image has `student`; this machine has none).

What the real one does differently: setup.sh builds the package's venv in Gradescope's image; here a two-line
shell script stands in for that venv's python and runs this test's Python, and the root is a temporary folder
(AUTOGRADER_ROOT) instead of /autograder.
"""
import json
import os
import shutil
import subprocess
import sys
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build(bundle, labs):
    """Write the Gradescope package for `labs` (a list of lab ids) to the zip `bundle`."""
    built = subprocess.run([sys.executable, "-m", "checker", "package", "gradescope", "--out", str(bundle),
                            "--labs", *labs], cwd=ROOT, capture_output=True, text=True,
                           env=dict(os.environ, PYTHONPATH=ROOT))
    assert built.returncode == 0, built.stderr


def run(bundle, root, submitted, text):
    """Unpack `bundle` into root/source, submit `text` as root/submission/<submitted> and run run_autograder as
    Gradescope does; (its CompletedProcess, results.json as a dict or None)."""
    with zipfile.ZipFile(bundle) as archive:
        archive.extractall(root / "source")
    for script in ("setup.sh", "run_autograder"):
        os.chmod(root / "source" / script, 0o755)
    python = root / "source" / "venv" / "bin" / "python"   # setup.sh's venv, stood in for by this Python
    python.parent.mkdir(parents=True)
    python.write_text(f"#!/bin/sh\nexec {sys.executable} \"$@\"\n", encoding="utf-8")
    python.chmod(0o755)
    subprocess.run(["chmod", "-R", "go-rwx", str(root / "source" / "project" / "solutions")], check=True)
    (root / "submission").mkdir()
    (root / "submission" / submitted).write_text(text, encoding="utf-8")
    runner = shutil.copy2(root / "source" / "run_autograder", root / "run_autograder")
    environment = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "HOME": str(root),
                   "AUTOGRADER_ROOT": str(root), "AUTOGRADER_USER": "nobody"}
    done = subprocess.run([str(runner)], cwd=root, env=environment, capture_output=True, text=True, timeout=300)
    results = root / "results" / "results.json"
    return done, (json.loads(results.read_text(encoding="utf-8")) if results.exists() else None)
