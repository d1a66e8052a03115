"""python -m checker new-lab ID --title "..." (checker/authoring/new_lab.py, its files in lab_template.py).

In a copy of the project (a new lab is a folder of checker/labs/: writing one into this project would make it a
lab for every other test running at the time), as an instructor types the commands: new-lab writes the lab;
at once lint-lab passes, the solution passes every check, the starter fails step 2 only, and the corpus test
it wrote passes; a second new-lab writes over nothing. The copy holds the project's files but no .git and no
venv: the commands run with this venv's Python and the copy first on the path.
"""
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

from checker.authoring import new_lab

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LAB_ID, TITLE = "pendulum_demo", "Pendulum Demo"   # no lab of the bundle's


def run(copy, *args, timeout=600):
    env = dict(os.environ, PYTHONPATH=str(copy), SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               PYTHONDONTWRITEBYTECODE="1")
    done = subprocess.run([sys.executable, *args], cwd=copy, env=env, capture_output=True, text=True,
                          timeout=timeout)
    return done.returncode, done.stdout, done.stderr


@pytest.fixture(scope="module")
def project(tmp_path_factory):
    """A copy of the project with the new lab written by the command; returns (copy, new-lab's stdout)."""
    copy = tmp_path_factory.mktemp("project") / "lab_bundle"
    shutil.copytree(ROOT, copy, ignore=shutil.ignore_patterns(".git", ".venv", "__pycache__", "*.egg-info",
                                                              ".pytest_cache", ".hypothesis", "assets"))
    status, out, err = run(copy, "-m", "checker", "new-lab", LAB_ID, "--title", TITLE)
    assert (status, err) == (0, ""), err
    return copy, out


def test_new_lab_writes_the_lab_s_files_and_nothing_else(project):
    copy, out = project
    written = sorted(line.split(": ")[0] for line in out.splitlines() if line.endswith(": written"))
    assert written == sorted(new_lab.planned(LAB_ID, TITLE)) == sorted([
        f"solutions/{LAB_ID}.py", f"starters/{LAB_ID}_starter.py", f"tests/corpus_{LAB_ID}.py"] + [
        f"checker/labs/{LAB_ID}/{name}" for name in ("__init__.py", "checks.py", "probes.py", "scenes.py", "show.py")])
    assert all((copy / path).is_file() for path in written)


def test_the_new_lab_keeps_every_rule_at_once(project):
    status, out, err = run(project[0], "-m", "checker", "lint-lab", LAB_ID)
    assert (status, err) == (0, "") and out.startswith(f"lab {LAB_ID} keeps all "), out


def test_the_solution_passes_and_the_starter_fails_step_2_only(project):
    copy = project[0]
    status, out, err = run(copy, "-m", "checker", "--json", "--quiet", f"solutions/{LAB_ID}.py",
                           f"starters/{LAB_ID}_starter.py")
    rows = {os.path.basename(row["path"]): row for row in json.loads(out)["labs"]}
    solution, starter = rows[f"{LAB_ID}.py"], rows[f"{LAB_ID}_starter.py"]
    assert solution["lab"] == starter["lab"] == LAB_ID and solution["title"] == TITLE
    assert solution["score"] == solution["max_score"] == 5, solution["criteria"]
    assert {c["id"]: c["status"] for c in starter["criteria"]} == {
        "loads": "pass", "handout_unchanged": "pass", "runtime_lines": "pass", "normal_speed_right": "fail",
        "runs": "skip"}
    assert status == 1


def test_the_corpus_new_lab_wrote_gets_its_verdicts(project):
    status, out, err = run(project[0], "-m", "pytest", "-o", "addopts=", "-q", "-p", "no:cacheprovider",
                           "tests/test_corpus_labs.py", "-k", LAB_ID)
    assert status == 0, out[-3000:]
    passed = int(out.splitlines()[-1].split(" passed")[0])
    assert passed >= 32 and " failed" not in out.splitlines()[-1], out[-500:]   # 16 entries, two tests each, and more


def _tests_of(lab_id, ids):
    """The test functions (file::name) with a parameter naming `lab_id` among the collected `ids`."""
    pattern = re.compile(rf"(^|[\[\-_]){lab_id}([\]\-_]|$)")
    return {i.split("[")[0] for i in ids if "[" in i and pattern.search(i.split("[", 1)[1])}


def test_every_test_that_covers_each_lab_covers_the_new_one(project):
    """Part of "the tests find the labs": every test function run for each lab of the bundle (Billiards, added
    after the lesson's five, among them) is run for the new lab too (collected in the copy, the new lab's files
    and nothing else added). Tests of the lesson's labs only (its Hint tables, attacks written against their
    steps' code) cover no added lab, so they are not in that intersection."""
    from checker import labs
    status, out, err = run(project[0], "-m", "pytest", "--collect-only", "-q", "-n", "0", "-o", "addopts=",
                           "-p", "no:cacheprovider")
    assert status == 0, (out + err)[-3000:]
    ids = [line.strip() for line in out.splitlines() if "::" in line]
    each = set.intersection(*[_tests_of(lab.id, ids) for lab in labs.LABS])
    assert len(each) > 30, sorted(each)
    missing = each - _tests_of(LAB_ID, ids)
    assert not missing, f"tests that skip a lab added by new-lab: {sorted(missing)}"


def test_new_lab_writes_over_nothing(project):
    copy = project[0]
    before = (copy / "solutions" / f"{LAB_ID}.py").read_bytes()
    status, out, err = run(copy, "-m", "checker", "new-lab", LAB_ID, "--title", "Another Title")
    assert (status, out) == (2, "") and err.count("\n") == 1
    assert f"solutions/{LAB_ID}.py exists: new-lab writes over nothing" in err
    assert (copy / "solutions" / f"{LAB_ID}.py").read_bytes() == before


@pytest.mark.parametrize("lab_id, title, words", [
    ("Bad-Id", "Pendulum Demo", "'Bad-Id' is not a lab id"),
    ("class", "Pendulum Demo", "'class' is not a lab id"),
    ("pool", "", "--title ''"),
    ("pool", 'say "hi"', "without"),
    ("pool", "Tumbling Crates", "a lab has that title already"),
    ("tumbling_crates", "Tumbles", "checker/labs/tumbling_crates exists"),
])
def test_a_bad_id_or_title_is_one_line_and_nothing_is_written(lab_id, title, words, tmp_path, capsys):
    root = tmp_path / "root"
    root.mkdir()
    (root / "checker" / "labs" / "tumbling_crates").mkdir(parents=True)
    assert new_lab.main([lab_id, "--title", title], root=str(root)) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and words in err, err
    assert sorted(p.name for p in root.rglob("*")) == ["checker", "labs", "tumbling_crates"]


def test_one_existing_file_stops_the_whole_lab(tmp_path, capsys):
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "corpus_pool.py").write_text("mine\n", encoding="utf-8")
    assert new_lab.main(["pool", "--title", "Pool"], root=str(tmp_path)) == 2
    assert "tests/corpus_pool.py exists" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["corpus_pool.py", "tests"]
    assert (tmp_path / "tests" / "corpus_pool.py").read_text(encoding="utf-8") == "mine\n"
