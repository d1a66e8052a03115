"""python -m checker package: each package against its platform's documented fields, and the Gradescope
bundle run end to end by Gradescope's own procedure (grade_gradescope: unpacked into ROOT/source, a copy of
run_autograder run from ROOT) on a passing, a failing, a missing, a misnamed, a hostile submission and a
broken checker."""
import base64
import importlib.util
import json
import os
import re
import shutil
import stat
import subprocess
import sys
import zipfile

import pytest

from checker import labs
from checker.platforms import package

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRADESCOPE_VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
MAX = {lab.id: lab.checks.max_score for lab in labs.LABS}
PNG = b"\x89PNG\r\n\x1a\n"
DATA_IMAGE = re.compile(r'<img [^>]*src="data:image/png;base64,([A-Za-z0-9+/=]+)"')


def run_package(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "checker", "package", *args], cwd=cwd or ROOT,
                          capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=ROOT))


def assert_gradescope(doc):
    """Gradescope's results.json: top-level score and output, tests[] with name/score/max_score/status/output/
    visibility."""
    assert isinstance(doc["score"], (int, float)) and isinstance(doc["output"], str) and doc["output"]
    assert doc.get("visibility", "visible") in GRADESCOPE_VISIBILITY
    assert doc["tests"], "every result has at least one test (the reason when nothing was graded)"
    for test in doc["tests"]:
        assert isinstance(test["name"], str) and test["name"]
        assert isinstance(test["score"], (int, float)) and isinstance(test["max_score"], (int, float))
        assert 0 <= test["score"] <= test["max_score"]
        assert test["status"] in {"passed", "failed"}
        assert isinstance(test["output"], str)
        assert test["visibility"] in GRADESCOPE_VISIBILITY
    assert doc["score"] == pytest.approx(sum(t["score"] for t in doc["tests"]))


def assert_prairielearn(doc):
    """PrairieLearn's results.json: gradable, score 0-1, message, tests[] with name/points/max_points, images[]."""
    assert doc["gradable"] is True
    assert 0.0 <= doc["score"] <= 1.0
    assert isinstance(doc["message"], str) and doc["message"]
    assert isinstance(doc["images"], list)
    for image in doc["images"]:  # PrairieLearn's documented image entry: a label and a data: URL
        assert isinstance(image["label"], str) and image["label"]
        assert image["url"].startswith("data:image/png;base64,")
        assert base64.b64decode(image["url"].split(",", 1)[1]).startswith(PNG)
    for test in doc["tests"]:
        assert isinstance(test["name"], str) and test["name"]
        assert 0 <= test["points"] <= test["max_points"]
        assert isinstance(test["output"], str)


@pytest.fixture(scope="module")
def bundle(tmp_path_factory):
    """The Gradescope zip (Bullets and Tumbling Crates, one check hidden) and its unpacked source folder."""
    base = tmp_path_factory.mktemp("gradescope")
    out = base / "autograder.zip"
    done = run_package("gradescope", "--out", str(out), "--labs", "bullets", "tumbling_crates",
                       "--hide", "crate_momentum")
    assert done.returncode == 0, done.stderr
    source = base / "source"
    with zipfile.ZipFile(out) as archive:
        archive.extractall(source)
        modes = {info.filename: info.external_attr >> 16 for info in archive.infolist()}
    for name in ("setup.sh", "run_autograder"):  # zipfile drops the modes: set them as Gradescope's unzip does
        os.chmod(source / name, modes[name] & 0o777)
    return out, source, modes


def gradescope_setup_stand_in(source):
    """What setup.sh leaves behind, made quickly: source/venv/bin/python. The real setup.sh makes a venv and
    pip-installs the pinned pygame-ce and numpy into it (minutes, and the network); here venv/bin/python hands
    over to this test's interpreter, which has them. The acceptance script runs the real setup.sh."""
    python = source / "venv" / "bin" / "python"
    python.parent.mkdir(parents=True, exist_ok=True)
    python.write_text(f"#!/bin/sh\nexec {sys.executable} \"$@\"\n", encoding="utf-8")
    python.chmod(0o755)


def grade_gradescope(source, tmp_path, files, env=None, in_place=False):
    """Grade a submission made of `files` {relative path: text} as Gradescope does; its results.json.

    Gradescope's procedure, step by step: the package is unpacked into /autograder/source and setup.sh runs
    there (here: a copy of the unpacked package, and gradescope_setup_stand_in); the submission goes to
    /autograder/submission; run_autograder is copied to /autograder/run_autograder and that copy runs, from
    /autograder, in a clean environment. What differs: the root is a temporary folder named by AUTOGRADER_ROOT
    instead of /autograder, and AUTOGRADER_USER="" grades as the current user (Gradescope's grader is root and
    grades as `student`; the acceptance script does that in a clean root file system). in_place=True runs
    source/run_autograder itself, as an instructor trying the package by hand would.
    """
    root = tmp_path / "autograder"
    shutil.copytree(source, root / "source", symlinks=True)
    if not (root / "source" / "venv").exists():
        gradescope_setup_stand_in(root / "source")
    (root / "submission").mkdir(parents=True)
    for rel, text in files.items():
        target = root / "submission" / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
    script = root / "source" / "run_autograder"
    if not in_place:
        script = shutil.copy2(script, root / "run_autograder")
    environment = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "HOME": str(root),
                   "AUTOGRADER_ROOT": str(root), "AUTOGRADER_USER": ""}
    environment.update(env or {})
    done = subprocess.run([str(script)], cwd=root, env=environment, capture_output=True,
                          text=True, timeout=180)
    assert done.returncode == 0, done.stderr
    with open(root / "results" / "results.json", encoding="utf-8") as handle:
        doc = json.load(handle)
    assert_gradescope(doc)
    return doc


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


def test_gradescope_zip_layout(bundle):
    out, source, modes = bundle
    assert modes["setup.sh"] & 0o111 and modes["run_autograder"] & 0o111
    names = set(modes)
    for rel in ("project/pyproject.toml", "project/checker/cli.py", "project/lesson11/runtime.py",
                "project/starters/bullets_starter.py", "project/solutions/tumbling_crates.py",
                "grade_submission.py", "autograder.json"):
        assert rel in names, rel
    assert not any("__pycache__" in n or n.endswith(".pyc") for n in names)
    setup = (source / "setup.sh").read_text()
    for name, version in package.installed_versions().items():
        assert f"{name}=={version}" in setup
    assert "useradd" in setup and "pip install --no-deps -e" in setup
    run = (source / "run_autograder").read_text()
    for variable in ("SDL_VIDEODRIVER=dummy", "SDL_AUDIODRIVER=dummy", "PYGAME_HIDE_SUPPORT_PROMPT=1",
                     "AUTOGRADER_ROOT:-/autograder"):
        assert variable in run
    for script in ("setup.sh", "run_autograder"):
        assert subprocess.run(["bash", "-n", str(source / script)]).returncode == 0, script
    config = json.loads((source / "autograder.json").read_text())
    assert [lab["file"] for lab in config["labs"]] == ["bullets.py", "tumbling_crates.py"]
    assert config["hide"] == ["crate_momentum"]


def test_gradescope_passing_submission(bundle, tmp_path):
    doc = grade_gradescope(bundle[1], tmp_path, {"tumbling_crates.py": read("solutions/tumbling_crates.py")})
    assert doc["score"] == MAX["tumbling_crates"] == sum(t["max_score"] for t in doc["tests"])
    assert all(t["status"] == "passed" for t in doc["tests"])
    visible = sum(t["max_score"] for t in doc["tests"] if t["visibility"] == "visible")
    assert "Graded tumbling_crates.py" in doc["output"]
    assert f"{visible:g}/{visible:g} on the visible checks, passes every visible check" in doc["output"]
    assert not any("output_format" in t or "<img" in t["output"] for t in doc["tests"]), "no pictures"


def test_gradescope_run_in_place_grades_the_same(bundle, tmp_path):
    doc = grade_gradescope(bundle[1], tmp_path, {"tumbling_crates.py": read("solutions/tumbling_crates.py")},
                           in_place=True)
    assert doc["score"] == MAX["tumbling_crates"] and "passes every visible check" in doc["output"]


def test_gradescope_without_the_package_says_so(bundle, tmp_path):
    """A copied run_autograder with no source/ beside it (a broken upload) still leaves a results file."""
    root = tmp_path / "autograder"
    (root / "submission").mkdir(parents=True)
    shutil.copy2(bundle[1] / "run_autograder", root / "run_autograder")
    done = subprocess.run([str(root / "run_autograder")], cwd=root, capture_output=True, text=True, timeout=60,
                          env={"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "AUTOGRADER_ROOT": str(root)})
    assert done.returncode == 0 and "no grade_submission.py" in done.stderr
    doc = json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))
    assert doc["score"] == 0.0 and "tell your instructor" in doc["output"]


def test_gradescope_failing_submission_in_a_folder(bundle, tmp_path):
    doc = grade_gradescope(bundle[1], tmp_path, {"lab/bullets.py": read("starters/bullets_starter.py")})
    assert doc["score"] == 3.0 and sum(t["max_score"] for t in doc["tests"]) == MAX["bullets"]
    assert "lab/bullets.py" in doc["output"] and "found in a folder" in doc["output"]
    failed = [t for t in doc["tests"] if t["status"] == "failed"]
    assert failed and all(t["output"] for t in failed), "a failed check says why"
    hidden = [t for t in doc["tests"] if t["visibility"] == "hidden"]
    assert [t["name"].split(":")[0] for t in hidden] == ["crate_momentum"]


def test_gradescope_missing_submission(bundle, tmp_path):
    doc = grade_gradescope(bundle[1], tmp_path, {})
    assert doc["score"] == 0 and "No Python file" in doc["output"] and "bullets.py" in doc["output"]
    assert doc["tests"][0]["max_score"] == max(MAX["bullets"], MAX["tumbling_crates"])


def test_gradescope_wrong_name_and_several_files(bundle, tmp_path):
    doc = grade_gradescope(bundle[1], tmp_path / "one", {"my_lab.py": read("starters/bullets_starter.py")})
    assert doc["score"] == 3.0 and "my_lab.py" in doc["output"] and "expected name" in doc["output"]
    doc = grade_gradescope(bundle[1], tmp_path / "two", {"a.py": "x = 1\n", "b.py": "y = 2\n"})
    assert doc["score"] == 0 and "a.py" in doc["output"] and "b.py" in doc["output"]
    doc = grade_gradescope(bundle[1], tmp_path / "three", {"notes.txt": "my lab is in my other folder"})
    assert doc["score"] == 0 and "notes.txt" in doc["output"]


def test_gradescope_hostile_submission(bundle, tmp_path):
    hostile = "import sys\nsys.exit(3)\n" + read("starters/bullets_starter.py")
    doc = grade_gradescope(bundle[1], tmp_path, {"bullets.py": hostile})
    assert doc["score"] < MAX["bullets"]
    assert doc["tests"][0]["status"] == "failed" and doc["tests"][0]["output"]


def test_gradescope_checker_crash_still_writes_results(bundle, tmp_path):
    broken = tmp_path / "source"
    shutil.copytree(bundle[1], broken)
    (broken / "project" / "checker" / "cli.py").write_text("raise RuntimeError('a checker bug')\n")
    doc = grade_gradescope(broken, tmp_path, {"bullets.py": read("starters/bullets_starter.py")})
    assert doc["score"] == 0 and "could not grade" in doc["output"]


def test_prairielearn_package_and_entrypoint(tmp_path):
    out = tmp_path / "pl"
    done = run_package("prairielearn", "--out", str(out), "--labs", "bullets", "--image", "me/l11")
    assert done.returncode == 0, done.stderr
    snippet = json.loads((out / "info.json.snippet").read_text())
    options = snippet["externalGradingOptions"]
    assert snippet["gradingMethod"] == "External" and options["enabled"] is True
    assert options["image"] == "me/l11" and options["entrypoint"] == "/grader/run_prairielearn"
    assert isinstance(options["timeout"], int) and options["timeout"] > 0
    dockerfile = (out / "Dockerfile").read_text()
    assert re.search(r"^FROM python:\d+\.\d+-slim$", dockerfile, re.M) and "COPY . /grader" in dockerfile
    for name, version in package.installed_versions().items():
        assert f"{name}=={version}" in dockerfile
    assert os.stat(out / "run_prairielearn").st_mode & stat.S_IXUSR
    assert 'file-names="bullets.py"' in (out / "question.html").read_text()
    # PrairieLearn's procedure: the image is the Dockerfile's (COPY . /grader, its ENV), the submission goes to
    # /grade/student and the entrypoint info.json names runs. Here /grader is the package folder, GRADE_ROOT
    # moves /grade, the image's python is this test's (first on PATH), and AUTOGRADER_USER="" grades as the
    # current user; tests/platform_acceptance.py follows the Dockerfile in a Debian root and grades as student.
    grade = tmp_path / "grade"
    (grade / "student").mkdir(parents=True)
    (grade / "student" / "bullets.py").write_text(read("starters/bullets_starter.py"), encoding="utf-8")
    image_env = dict(pair.split("=", 1) for line in dockerfile.splitlines() if line.startswith("ENV ")
                     for pair in line[4:].split())
    env = dict(image_env, PATH=os.path.dirname(sys.executable) + os.pathsep + os.environ.get("PATH", ""),
               HOME=str(tmp_path), GRADE_ROOT=str(grade), AUTOGRADER_USER="")
    entrypoint = out / os.path.relpath(options["entrypoint"], "/grader")
    done = subprocess.run([str(entrypoint)], env=env, cwd=grade, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    doc = json.loads((grade / "results" / "results.json").read_text())
    assert_prairielearn(doc)
    # fails the function checks, so no graded scene ran: the lab's scene, run ungraded, pictures the first one
    assert [image["label"] for image in doc["images"]] == ["toi_matches_root: toi_matches_root"]
    assert doc["score"] == pytest.approx(3.0 / MAX["bullets"])
    assert sum(t["max_points"] for t in doc["tests"]) == MAX["bullets"]
    shutil.rmtree(grade / "student")  # nothing submitted: still a valid result
    subprocess.run([str(entrypoint)], env=env, cwd=grade, capture_output=True, timeout=60)
    doc = json.loads((grade / "results" / "results.json").read_text())
    assert_prairielearn(doc)
    assert doc["score"] == 0 and "nothing was submitted" in doc["message"]


def test_classroom_workflow(tmp_path):
    out = tmp_path / "cl"
    done = run_package("classroom", "--out", str(out), "--labs", "bullets")
    assert done.returncode == 0, done.stderr
    assert "solutions" in done.stdout  # the warning: the copy in the repository holds the solutions
    workflow = (out / ".github" / "workflows" / "classroom.yml").read_text()
    assert (out / ".autograder" / "project" / "starters" / "bullets_starter.py").is_file()
    checks = labs.LABS[[lab.id for lab in labs.LABS].index("bullets")].checks.checks
    ids = re.findall(r"^        id: (\S+)$", workflow, re.M)
    assert ids == [f"bullets_{c.id}" for c in checks]
    assert workflow.count("uses: classroom-resources/autograding-command-grader@v1") == len(checks)
    points = [float(p) for p in re.findall(r"^          max-score: (\S+)$", workflow, re.M)]
    assert points == [c.max_score for c in checks]
    assert "uses: classroom-resources/autograding-grading-reporter@v1" in workflow
    assert re.search(r"^          runners: (\S+)$", workflow, re.M).group(1).split(",") == ids
    for step_id in ids:
        assert f"{step_id.upper()}_RESULTS: \"${{{{steps.{step_id}.outputs.result}}}}\"" in workflow
    assert "SDL_VIDEODRIVER: dummy" in workflow and "\t" not in workflow
    done = run_package("classroom", "--out", str(tmp_path / "src"), "--labs", "bullets", "--source", "git+https://example.org/l11")
    assert done.returncode == 0 and not (tmp_path / "src" / ".autograder").exists()


def test_classroom_workflow_steps_grade_as_the_command_grader_runs_them(tmp_path):
    """GitHub Classroom's procedure: the template repository (the package's files) holds the student's file; the
    workflow's "Grade" step runs with its env, then each autograding-command-grader step's command runs with the
    environment reset to PATH, HOME and FORCE_COLOR, and earns its max-score if it exits 0. Not run here: the
    checkout, setup-python and "Install" steps (this test's interpreter already has the checker, first on
    PATH); tests/platform_acceptance.py runs those in an Ubuntu root."""
    import platform_acceptance
    out = tmp_path / "template"
    assert run_package("classroom", "--out", str(out), "--labs", "tumbling_crates").returncode == 0
    steps = platform_acceptance.workflow(out / ".github" / "workflows" / "classroom.yml")
    assert [name for name, _, _ in steps["runs"]] == ["Install the checker", "Grade tumbling_crates.py"]
    assert steps["env"] == {"CHECKER_SOURCE": ".autograder/project"}
    path = os.path.dirname(sys.executable) + os.pathsep + os.environ.get("PATH", "")
    scores = {}
    for case, files in (("solution", {"tumbling_crates.py": read("solutions/tumbling_crates.py")}),
                        ("starter", {"tumbling_crates.py": read("starters/tumbling_crates_starter.py")}),
                        ("missing", {})):
        repo = tmp_path / case
        shutil.copytree(out, repo)
        for rel, text in files.items():
            (repo / rel).write_text(text, encoding="utf-8")
        for name, script, env in steps["runs"]:
            if name.startswith("Grade"):
                subprocess.run(["bash", "-c", script], cwd=repo, capture_output=True, timeout=300,
                               env=dict(env, PATH=path, HOME=str(tmp_path), **steps["env"]))
        earned = 0.0
        for name, command, points in steps["graders"]:
            done = subprocess.run(["bash", "-c", command], cwd=repo, capture_output=True, text=True, timeout=60,
                                  env={"PATH": path, "HOME": str(tmp_path), "FORCE_COLOR": "true"})
            earned += points if done.returncode == 0 else 0.0
            assert done.stdout.strip(), f"{case}: {name} says nothing"
        scores[case] = (earned, sum(points for _, _, points in steps["graders"]))
    assert scores["solution"] == (MAX["tumbling_crates"], MAX["tumbling_crates"])
    assert 0 < scores["starter"][0] < MAX["tumbling_crates"]
    assert scores["missing"][0] == 0


def test_classroom_verdict(tmp_path, capsys):
    result = tmp_path / "bullets.json"
    result.write_text(json.dumps({"labs": [{"lab": "bullets", "message": "", "criteria": [
        {"id": "loads", "name": "loads", "status": "pass", "message": "", "hint": ""},
        {"id": "broad_test", "name": "broad", "status": "fail", "message": "missed a hit", "hint": "[step 4] x"}]}]}))
    assert package.verdict([str(result), "bullets", "loads"]) == 0
    assert package.verdict([str(result), "bullets", "broad_test"]) == 1
    assert "missed a hit" in capsys.readouterr().out
    result.write_text("")  # the checker wrote nothing (no bullets.py in the repository)
    assert package.verdict([str(result), "bullets", "loads"]) == 1
    assert "bullets.py" in capsys.readouterr().out


def test_refuses_existing_output_and_bad_options(tmp_path):
    out = tmp_path / "autograder.zip"
    out.write_text("keep me")
    done = run_package("gradescope", "--out", str(out), "--labs", "bullets")
    assert done.returncode == 2 and out.read_text() == "keep me"
    assert done.stderr.strip().count("\n") == 0 and str(out) in done.stderr and "--force" in done.stderr
    assert run_package("gradescope", "--out", str(out), "--labs", "bullets", "--force").returncode == 0
    assert zipfile.is_zipfile(out)
    folder = tmp_path / "pl"
    folder.mkdir()
    assert run_package("prairielearn", "--out", str(folder), "--labs", "bullets").returncode == 2
    assert run_package("gradescope", "--out", os.path.join(ROOT, "starters", "x.zip"), "--labs", "bullets").returncode == 2
    assert not os.path.exists(os.path.join(ROOT, "starters", "x.zip"))
    done = run_package("gradescope", "--out", str(tmp_path / "a.zip"), "--labs", "bullets", "--hide", "no_such_check")
    assert done.returncode == 2 and "no_such_check" in done.stderr
    done = run_package("gradescope", "--out", str(tmp_path / "b.zip"), "--labs", "nope")
    assert done.returncode == 2 and "nope" in done.stderr
    for platform, out in (("gradescope", tmp_path / "c.zip"), ("classroom", tmp_path / "c"),
                          ("prairielearn", tmp_path / "d")):
        done = run_package(platform, "--out", str(out))   # no --labs: a package names what it grades
        assert done.returncode == 2 and not os.path.exists(out), platform
        assert done.stderr.strip().count("\n") == 0 and "--labs is required" in done.stderr


# ---------------------------------------------------------------- pictures of failed behaviour checks

def slop_six():
    """The Ball on the Ramp solution with SLOP = 6: every function check passes, the ball started inside a
    crate stays 6 px in (pushed_out_of_crate fails); it edits a handed-out constant, so grade with allow_edits."""
    text = read("solutions/ball_on_ramp.py")
    assert "\nSLOP = 0.5 " in text
    return text.replace("\nSLOP = 0.5 ", "\nSLOP = 6 ", 1)


def allow_edits(folder):
    path = os.path.join(folder, "autograder.json")
    with open(path, encoding="utf-8") as handle:
        config = json.load(handle)
    assert config["pictures"] is True
    config["allow_edits"] = True
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(config, handle)


@pytest.fixture(scope="module")
def ramp_bundle(tmp_path_factory):
    """The Gradescope bundle of Ball on the Ramp, unpacked, with "allow_edits": true in autograder.json."""
    base = tmp_path_factory.mktemp("ramp")
    done = run_package("gradescope", "--out", str(base / "autograder.zip"), "--labs", "ball_on_ramp")
    assert done.returncode == 0, done.stderr
    source = base / "source"
    with zipfile.ZipFile(base / "autograder.zip") as archive:
        archive.extractall(source)
    os.chmod(source / "run_autograder", 0o755)
    allow_edits(source)
    return source


def test_gradescope_failed_scene_has_a_picture(ramp_bundle, tmp_path):
    doc = grade_gradescope(ramp_bundle, tmp_path, {"ball_on_ramp.py": slop_six()})
    size = (tmp_path / "autograder" / "results" / "results.json").stat().st_size
    assert size < 200_000, size
    failed = [t for t in doc["tests"] if t["status"] == "failed"]
    assert [t["name"].split(":")[0] for t in failed] == ["pushed_out_of_crate"]
    test = failed[0]
    assert test["output_format"] == "html" and test["output"].startswith("<pre>")
    assert "depth 5.9 px" in test["output"] and "ball&#x27;s center" in test["output"]  # escaped text
    images = DATA_IMAGE.findall(test["output"])
    assert images and all(base64.b64decode(i).startswith(PNG) for i in images)
    passed = [t for t in doc["tests"] if t["status"] == "passed"]
    assert passed and not any("output_format" in t or "<img" in t["output"] for t in passed)


def test_gradescope_another_labs_file_scores_zero(ramp_bundle, tmp_path):
    """A Ball on the Ramp assignment given the Bullets solution: 0, and the message names both labs."""
    doc = grade_gradescope(ramp_bundle, tmp_path, {"bullets.py": read("solutions/bullets.py")})
    assert doc["score"] == 0
    assert "Bullets" in doc["output"] and "ball_on_ramp.py" in doc["output"], doc["output"]


def test_gradescope_pictures_that_cannot_be_drawn_cost_nothing(ramp_bundle, tmp_path):
    broken = tmp_path / "source"
    shutil.copytree(ramp_bundle, broken)
    pictures = broken / "project" / "checker" / "replay" / "pictures.py"
    assert pictures.is_file()   # the bug goes into the module that draws, not into a new file beside it
    with open(pictures, "a", encoding="utf-8") as handle:
        handle.write("\n\ndef filmstrip(*args, **kwargs):\n    raise RuntimeError('a drawing bug')\n")
    doc = grade_gradescope(broken, tmp_path, {"ball_on_ramp.py": slop_six()})
    assert doc["score"] == MAX["ball_on_ramp"] - 2.0
    assert not any("output_format" in t or "<img" in t["output"] for t in doc["tests"])


def test_prairielearn_failed_scene_has_images(tmp_path):
    out = tmp_path / "pl"
    done = run_package("prairielearn", "--out", str(out), "--labs", "ball_on_ramp", "--image", "me/l11")
    assert done.returncode == 0, done.stderr
    allow_edits(out)
    grade = tmp_path / "grade"
    (grade / "student").mkdir(parents=True)
    (grade / "student" / "ball_on_ramp.py").write_text(slop_six(), encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(GRADE_ROOT=str(grade), GRADER_PYTHON=sys.executable, AUTOGRADER_USER="")
    done = subprocess.run([str(out / "run_prairielearn")], env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    doc = json.loads((grade / "results" / "results.json").read_text())
    assert_prairielearn(doc)
    assert doc["images"] and all(i["label"].startswith("pushed_out_of_crate") for i in doc["images"])
    assert doc["score"] == pytest.approx((MAX["ball_on_ramp"] - 2.0) / MAX["ball_on_ramp"])


def grading_script():
    spec = importlib.util.spec_from_file_location("grade_submission",
                                                  os.path.join(ROOT, "checker", "platforms", "templates", "grade_submission.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_pictures_capped_and_read_only_from_the_folder(tmp_path):
    script = grading_script()
    folder = tmp_path / "pictures"
    folder.mkdir()
    png = PNG + b"x" * 100_000
    paths = []
    for k in range(6):
        (folder / f"p{k}.png").write_bytes(png)
        paths.append(str(folder / f"p{k}.png"))
    (folder / "big.png").write_bytes(PNG + b"x" * (script.MAX_PICTURE_BYTES + 1))
    (folder / "text.png").write_bytes(b"not a png")
    secret = tmp_path / "secret.png"
    secret.write_bytes(PNG + b"secret")
    (folder / "link.png").symlink_to(secret)
    odd = [str(folder / n) for n in ("big.png", "text.png", "link.png")] + [str(secret), 42]

    def criteria():
        return [{"id": "a", "name": "A", "status": "fail", "message": "m <b>", "hint": "", "score": 0.0,
                 "max_score": 1.0, "pictures": odd + paths[:3]},
                {"id": "b", "name": "B", "status": "fail", "message": "n", "hint": "", "score": 0.0,
                 "max_score": 1.0, "pictures": paths[3:]},
                {"id": "c", "name": "C", "status": "pass", "message": "", "hint": "", "score": 1.0,
                 "max_score": 1.0, "pictures": []}]
    document = {"labs": [{"title": "T", "status": "fail", "score": 1.0, "max_score": 3.0, "message": "",
                          "criteria": criteria()}]}
    script.attach_pictures(document, str(folder))
    row = document["labs"][0]
    a, b, c = row["criteria"]
    assert len(a["images"]) == 3 and "images_left_out" not in a  # only the three good files
    assert len(b["images"]) == 1 and b["images_left_out"] == 2   # 450 kB of PNG at most
    assert "images" not in c and all("pictures" not in x for x in (a, b, c))
    config = {"hide": []}
    results = script.gradescope_results(row, "Graded t.py.", 3.0, config)
    json_size = len(json.dumps(results))
    assert json_size < 700_000, json_size
    tests = {t["name"][0]: t for t in results["tests"]}
    assert tests["a"]["output_format"] == "html" and tests["a"]["output"].startswith("<pre>m &lt;b&gt;</pre>")
    assert len(DATA_IMAGE.findall(tests["a"]["output"])) == 3
    assert "2 more picture(s) not shown" in tests["b"]["output"]
    assert "output_format" not in tests["c"]
    assert_gradescope(results)
    pl = script.prairielearn_results(row, "Graded t.py.", 3.0, config)
    assert len(pl["images"]) == 4 and "2 more picture(s) not shown" in pl["tests"][1]["output"]
    assert_prairielearn(dict(pl, message=pl["message"] or "x"))
    assert script.prairielearn_results(row, "Graded t.py.", 3.0, {"hide": ["a"]})["images"] == pl["images"][3:]


def test_the_summary_keeps_hidden_checks_hidden_and_names_the_students_error():
    script = grading_script()

    def check(id, status, score, message=""):
        return {"id": id, "name": id, "status": status, "score": score, "max_score": 1.0, "message": message,
                "hint": ""}
    row = {"title": "Tumbling Crates", "status": "fail", "score": 2.0, "max_score": 3.0, "message": "",
           "criteria": [check("a", "pass", 1.0), check("b", "pass", 1.0), check("secret", "fail", 0.0, "off")]}
    shown = script.gradescope_results(row, "Graded t.py.", 3.0, {"hide": ["secret"]})
    assert "2/2 on the visible checks, passes every visible check" in shown["output"]
    assert "fail" not in shown["output"] and "3" not in shown["output"].replace("Graded t.py.", "")
    assert script.prairielearn_results(row, "Graded t.py.", 3.0, {"hide": ["secret"]})["message"] == \
        shown["output"]
    assert "2/3, fails some checks" in script.gradescope_results(row, "Graded t.py.", 3.0, {"hide": []})["output"]
    crash = "The file raised ZeroDivisionError: division by zero at bullets.py, line 4: return 1/0."
    row = {"title": "Bullets", "status": "error", "score": 0.0, "max_score": 2.0, "message": "",
           "criteria": [check("loads", "error", 0.0, crash),
                        check("broad", "skip", 0.0, "skipped: needs 'loads' to pass first")]}
    shown = script.gradescope_results(row, "Graded bullets.py.", 2.0, {"hide": []})
    assert f"your code stopped with an error in loads: {crash}" in shown["output"]
    assert "could not" not in shown["output"]
    skipped = shown["tests"][1]
    assert skipped["status"] == "failed" and skipped["score"] == 0   # Gradescope has no skipped status
    assert skipped["output"] == "not run: needs 'loads' to pass first (it scores 0 until then)"
