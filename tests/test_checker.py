"""The checker grades labs headless: solutions pass, each Hint bug gets its hint, hostile files get a verdict.

Every lab run happens once per module (module-scoped fixtures run the checker's
command line with --json on a batch of files); the tests read the JSON. The
mutants and the hostile near-copies of the solution are built from
solutions/tumbling_crates.py by tests/mutants.py into a temporary directory;
the short hostile files live in tests/fixtures/checker.
"""
import hashlib
import json
import os
import subprocess
import sys

import pytest

import mutants
from checker.isolation.sandbox import Limits, wall_limit

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXTURES = os.path.join(ROOT, "tests", "fixtures", "checker")
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
ORDER = ["loads", "handout_unchanged", "runtime_lines", "sat_axes", "sat_normal", "resolve_k", "resolve_friction",
         "apply_impulse_spin", "runs", "corner_tips", "ramp_holds", "pile_stable", "fast_movers_zero"]
FUNCTIONS = ["sat_axes", "sat_normal", "resolve_k", "resolve_friction", "apply_impulse_spin"]
CRITERIA = ORDER[9:]
MAX_SCORE = 17
HOSTILE_TIMEOUT = 4.0
TIMEOUT = 60.0  # per run for files that should finish: generous, so a loaded machine cannot fail them


def fixture(name):
    return os.path.join(FIXTURES, name + ".py")


def run_checker(*args, cwd=ROOT):
    """Run `python -m checker ARGS`; returns (exit status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)
    return proc.returncode, proc.stdout, proc.stderr


def by_file(document):
    return {os.path.basename(lab["path"]): {c["id"]: c for c in lab["criteria"]} | {"_lab": lab}
            for lab in document["labs"]}


def digests(paths):
    return {p: hashlib.sha256(open(p, "rb").read()).hexdigest() for p in paths}


MUTANTS = sorted(mutants.MUTANTS)
HOSTILE_FILES = sorted(f[:-3] for f in os.listdir(FIXTURES) if f.startswith("hostile_") and f.endswith(".py"))
HOSTILE = sorted(HOSTILE_FILES + list(mutants.HOSTILE_COPIES))
EDITED = sorted(mutants.EDITED)


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """The mutants and hostile near-copies, written from the current solution: {name: path}."""
    return mutants.write_variants(tmp_path_factory.mktemp("mutants"), mutants.VARIANTS)


@pytest.fixture(scope="module")
def graded(tmp_path_factory, built):
    """The solution, every mutant and the starter (if present), graded in one run with --json."""
    files = [SOLUTION] + [built[m] for m in MUTANTS + EDITED] + ([STARTER] if os.path.exists(STARTER) else [])
    before = digests(files)
    csv_path = tmp_path_factory.mktemp("csv") / "grades.csv"
    status, out, err = run_checker("--json", "--csv", str(csv_path), "--timeout", str(TIMEOUT), *files)
    after = digests(files)
    return {"status": status, "doc": json.loads(out), "files": by_file(json.loads(out)), "stderr": err,
            "unchanged": before == after, "csv": csv_path}


@pytest.fixture(scope="module")
def hostile(tmp_path_factory, built):
    """Every hostile file (fixtures and built copies) graded in one run with short limits.

    With --allow-edits, so that copies changed outside the steps still run their scenes.
    """
    files = [built[h] if h in built else fixture(h) for h in HOSTILE]
    before = digests(files)
    results = tmp_path_factory.mktemp("gradescope")
    status, out, err = run_checker("--json", "--csv", "none", "--timeout", str(HOSTILE_TIMEOUT), "--memory", "512",
                                   "--max-output", "64", "--allow-edits", "--gradescope-dir", str(results), *files)
    return {"status": status, "doc": json.loads(out), "files": by_file(json.loads(out)),
            "unchanged": before == digests(files), "gradescope": results}


@pytest.fixture(scope="module")
def edited(built):
    """The copies edited outside the steps, graded with --allow-edits (so their scenes run)."""
    status, out, err = run_checker("--json", "--csv", "none", "--allow-edits", "--timeout", str(TIMEOUT),
                                   *[built[e] for e in EDITED])
    return {"status": status, "files": by_file(json.loads(out))}


def failing(lab):
    return {cid: c for cid, c in lab.items() if cid != "_lab" and c["status"] in ("fail", "error")}


# ---------------------------------------------------------------- the solution

def test_solution_passes_every_check_in_order(graded):
    lab = graded["files"]["tumbling_crates.py"]
    assert [c["id"] for c in lab["_lab"]["criteria"]] == ORDER
    assert failing(lab) == {}, failing(lab)
    assert lab["_lab"]["score"] == lab["_lab"]["max_score"] == MAX_SCORE


def test_solution_alone_exits_zero_and_prints_a_mark_per_check():
    from checker.labs import LABS
    status, out, err = run_checker("solutions/")  # every lab's solution (Tumbling Crates, More Shapes, Ball on the Ramp)
    assert status == 0, out + err
    assert out.count(":)") == sum(len(lab.checks.checks) for lab in LABS)
    assert f"tumbling_crates.py - Tumbling Crates: {MAX_SCORE}/{MAX_SCORE}" in out


def test_every_schema_field_is_present(graded):
    doc = graded["doc"]
    assert doc["schema"] == "lesson11-checker/1" and doc["passed"] is False
    for lab in doc["labs"]:
        assert {"path", "lab", "title", "status", "score", "max_score", "seconds", "criteria"} <= set(lab)
        for c in lab["criteria"]:
            assert set(c) == {"id", "name", "status", "message", "hint", "step", "score", "max_score", "mistake"}
            assert c["status"] in ("pass", "fail", "skip", "error")
            assert c["score"] == (c["max_score"] if c["status"] == "pass" else 0)
            assert bool(c["hint"]) == (c["status"] in ("fail", "error")) or c["id"] == "runs"
    assert graded["status"] == 1  # mutants fail, so the run fails


def test_grading_never_changes_a_submitted_file(graded, hostile, built):
    assert graded["unchanged"] and hostile["unchanged"]
    assert not os.path.exists(os.path.join(FIXTURES, "__pycache__"))
    assert not os.path.exists(os.path.join(os.path.dirname(built[MUTANTS[0]]), "__pycache__"))


# ---------------------------------------------------------------- the files built from the solution

@pytest.mark.parametrize("name", sorted(mutants.VARIANTS))
def test_each_built_file_differs_from_the_solution_only_by_its_edits(name):
    solution = open(SOLUTION, encoding="utf-8").read()
    source = mutants.variant_source(name, solution)
    _, edits = mutants.VARIANTS[name]
    assert source != solution
    for old, new in edits:
        assert new in source and (old in new or old not in source), (name, old)
    # apart from the docstring's first line (which names the bug), every new line comes from an edit
    added = [line for line in source.splitlines() if line not in solution.splitlines()]
    assert added[0].startswith(mutants.TITLE + " (")
    assert all(any(line in new for _, new in edits) for line in added[1:]), added


def test_an_edit_that_no_longer_fits_the_solution_fails_loudly():
    with pytest.raises(AssertionError, match="occurs 0 times"):
        mutants.apply_edits("a = 1\n", [("b = 2", "b = 3")], "mutant_x")
    with pytest.raises(AssertionError, match="occurs 2 times"):
        mutants.apply_edits("a = 1\na = 1\n", [("a = 1", "a = 2")], "mutant_x")


def test_csv_has_one_row_per_file(graded):
    rows = graded["csv"].read_text().strip().splitlines()
    assert rows[0].startswith("student,path,lab,status,score,max_score,fraction,")
    assert ",tumbling_crates:loads," in rows[0] or ",loads," in rows[0]   # lab:check when several labs
    assert len(rows) == 1 + len(graded["doc"]["labs"])


# ---------------------------------------------------------------- one mutant per Hint diagnosis

# mutant -> (check that must fail, lesson step named, words the hint must contain, checks that must pass); the
# hint names the step's one idea, the symptom is the lesson's table's (issue 40)
EXPECTED = {
    "mutant_sat_never_overlaps": ("sat_axes", 2, "None only when one axis shows a gap", ["loads", "handout_unchanged", "resolve_k",
                                                                   "resolve_friction", "apply_impulse_spin"]),
    "mutant_normal_not_flipped": ("sat_normal", 3, "from A to B", ["sat_axes", "resolve_k", "apply_impulse_spin"]),
    "mutant_spin_terms_missing": ("resolve_k", 4, "spin terms", ["sat_normal", "resolve_friction",
                                                                "apply_impulse_spin"]),
    "mutant_friction_unclamped": ("resolve_friction", 5, "keep jt within [-μ j, μ j]", ["sat_normal", "resolve_k",
                                                                         "apply_impulse_spin"]),
    "mutant_friction_flipped": ("resolve_friction", 5, "friction opposes the slip",
                                ["sat_normal", "resolve_k", "apply_impulse_spin"]),
    "mutant_spin_missing": ("apply_impulse_spin", 6, "each body's spin changes by r × P", ["sat_normal", "resolve_k",
                                                                       "resolve_friction"]),
    "mutant_spin_swapped": ("apply_impulse_spin", 6, "A's spin uses -=, B's +=", ["sat_normal", "resolve_k",
                                                                       "resolve_friction"]),
}


def test_there_is_a_mutant_for_every_diagnosis():
    assert sorted(EXPECTED) == MUTANTS


@pytest.mark.parametrize("mutant", sorted(EXPECTED))
def test_mutant_fails_with_its_hint(graded, mutant):
    lab = graded["files"][mutant + ".py"]
    check_id, step, words, passing = EXPECTED[mutant]
    result = lab[check_id]
    assert result["status"] == "fail", result
    assert result["step"] == step and words in result["hint"], result
    for other in passing:
        assert lab[other]["status"] == "pass", (other, lab[other])
    # a function mistake is reported once, under its step: the scenes are not run
    assert all(lab[cid]["status"] == "skip" for cid in ["runs"] + CRITERIA)


def test_an_edit_outside_the_steps_fails_naming_its_line(graded, built):
    lab = graded["files"]["mutant_no_push_out.py"]
    result = lab["handout_unchanged"]
    lines = open(built["mutant_no_push_out"], encoding="utf-8").read().splitlines()
    edited = next(i for i, text in enumerate(lines, 1) if "separate=lambda" in text)
    assert result["status"] == "fail" and f"line {edited} `" in result["message"], result
    assert "separate=lambda *args: None" in result["message"]
    assert all(lab[cid]["status"] == "pass" for cid in FUNCTIONS)
    assert all(lab[cid]["status"] == "skip" for cid in ["runs"] + CRITERIA)


def test_allow_edits_turns_the_edit_into_a_warning_and_the_pile_sinks(edited):
    lab = edited["files"]["mutant_no_push_out.py"]
    assert lab["handout_unchanged"]["status"] == "pass"
    assert lab["handout_unchanged"]["message"].startswith("warning (allowed by --allow-edits)")
    result = lab["pile_stable"]
    assert result["status"] == "fail" and result["step"] == 7 and "push-out" in result["hint"], result
    assert lab["ramp_holds"]["status"] == "pass"
    depth = float(result["message"].split("floor penetration ")[1].split(" px")[0])
    assert depth > 1.25  # 1.49 px in the 2.5 s pile (3.5 s: 2.1 px; move-first: 41.8 px); bound 1, the solution 0.57 px


def test_starter_fails_with_the_step_2_message(graded):
    lab = graded["files"]["tumbling_crates_starter.py"]
    assert [lab[c]["status"] for c in ("loads", "handout_unchanged", "runtime_lines")] == ["pass"] * 3
    assert lab["sat_axes"]["status"] == "fail" and lab["sat_axes"]["step"] == 2
    assert "never" in lab["sat_axes"]["hint"]
    # the handout's placeholder is named with its line
    line = next(i for i, text in enumerate(open(STARTER, encoding="utf-8").read().splitlines(), 1)
                if text.strip().startswith("return None  # until you write step 2"))
    assert f"line {line} of tumbling_crates_starter.py is the handout's placeholder" in lab["sat_axes"]["message"]
    assert lab["_lab"]["score"] == 3


# ---------------------------------------------------------------- hostile files

@pytest.mark.parametrize("name, words", [
    ("hostile_loop_at_import", "did not finish importing within 4 s"),
    ("hostile_exception_at_import", "IndexError"),
    ("hostile_syntax_error", "SyntaxError"),
    ("hostile_sys_exit", "sys.exit('bye')"),
    ("hostile_os_exit", "os._exit(3)"),
    ("hostile_output_flood", "printed more than 64 KB"),
    ("hostile_memory_hog", "ran out of memory"),
    ("hostile_missing_main", "defines no function"),
])
def test_hostile_file_is_reported_once_at_import(hostile, name, words):
    lab = hostile["files"][name + ".py"]
    assert lab["loads"]["status"] == "error", lab["loads"]
    assert words in lab["loads"]["message"], lab["loads"]["message"]
    assert all(lab[cid]["status"] == "skip" for cid in ORDER[1:])


@pytest.mark.parametrize("name, line", [("hostile_exception_at_import", 5), ("hostile_syntax_error", 5),
                                        ("hostile_loop_at_import", 6), ("hostile_memory_hog", 5),
                                        ("hostile_sys_exit", 4)])
def test_hostile_message_names_file_and_line(hostile, name, line):
    message = hostile["files"][name + ".py"]["loads"]["message"]
    # the endless loop is stopped wherever the CPU limit finds it: its body (line 6) or its test (line 5)
    lines = (5, 6) if name == "hostile_loop_at_import" else (line,)
    assert any(f"{name}.py, line {n}" in message for n in lines), message


def test_deleted_runtime_line_is_named(hostile):
    lab = hostile["files"]["hostile_loop_in_main.py"]
    assert lab["runtime_lines"]["status"] == "fail"
    assert "lab.frame_budget()" in lab["runtime_lines"]["message"]
    assert all(lab[cid]["status"] == "skip" for cid in ["runs"] + CRITERIA)


def test_loop_inside_the_main_loop_is_stopped_and_located(hostile, built):
    lab = hostile["files"]["hostile_loop_inside_frame.py"]
    assert lab["runs"]["status"] == "error"
    assert "was stopped after 4 s" in lab["runs"]["message"]
    lines = open(built["hostile_loop_inside_frame"], encoding="utf-8").read().splitlines()
    loop = next(i for i, text in enumerate(lines, 1) if text.strip().startswith("while dt > 0:"))
    assert f"line {loop}" in lab["runs"]["message"] or f"line {loop + 1}" in lab["runs"]["message"]
    assert all(lab[cid]["status"] == "skip" for cid in CRITERIA)
    assert lab["sat_axes"]["status"] == "pass"


def test_fake_printed_line_records_no_frames(hostile):
    lab = hostile["files"]["hostile_fake_line.py"]
    result = lab["runs"]
    assert result["status"] == "fail" and "recorded no frames" in result["message"]
    assert all(lab[cid]["status"] == "skip" for cid in CRITERIA)


def test_hostile_files_end_within_their_limits(hostile):
    for lab in hostile["doc"]["labs"]:
        # at most a probe and four scene runs, each killed by its CPU limit or at the latest by its wall limit
        assert lab["seconds"] < 5 * (wall_limit(Limits(HOSTILE_TIMEOUT)) + 2), (lab["path"], lab["seconds"])
    assert hostile["status"] == 1


def test_gradescope_results_json(hostile):
    files = sorted(hostile["gradescope"].rglob("results.json"))
    assert len(files) == len(HOSTILE)  # one results.json per submission
    for path in files:
        data = json.loads(path.read_text())
        assert set(data) >= {"score", "tests"}
        assert len(data["tests"]) == len(ORDER)
        for test in data["tests"]:
            assert {"name", "score", "max_score", "status", "output"} <= set(test)
            assert test["status"] in ("passed", "failed")
        assert data["score"] == sum(t["score"] for t in data["tests"])


# ---------------------------------------------------------------- paths

def test_missing_path_gets_a_one_line_error():
    status, out, err = run_checker("no/such/lab.py")
    assert status == 2
    assert err.strip().count("\n") == 0 and "no/such/lab.py" in err and "Traceback" not in err


def test_file_that_is_not_a_lab_gets_a_one_line_error(tmp_path):
    """A Python file of no lab (its name holds no lab's id, its text no lab's title) is one line, never graded."""
    (tmp_path / "helpers.py").write_text('"""Plotting helpers."""\nimport pytest\n', encoding="utf-8")
    status, out, err = run_checker(str(tmp_path / "helpers.py"))
    assert status == 1  # an entry that cannot be graded is a row of the report (status 2 is for usage errors)
    assert err.strip().count("\n") == 0 and "not a lab" in err
