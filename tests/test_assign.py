"""python -m checker assign: each lab's starter is written from its annotated solution (checker/authoring/assign.py).

The committed starters must be exactly what assign writes (the drift test is
in test_lab_starter.py); here: what a prompt block turns into, that assign
never writes over a file unasked, --check and --out, and a corpus of bad
annotations, each refused with one line naming the file and the line.
"""
import os
import shutil
import stat
import subprocess
import sys

import pytest

from checker.authoring import assign
from checker import cli

SOLUTION = '''"""A lab."""


def double(x):
    """Twice x."""
    # --- step 2: double x ---
    # BEGIN PROMPT
    # Step 2: return twice x.
    # starter: return None  # placeholder: replace this line
    # END PROMPT
    return 2 * x
    # --- end of step 2 ---


def loop(n):
    total = 0
    for i in range(n):
        # --- step 3: add i ---
        # BEGIN PROMPT
        # Step 3: add i to total.
        # starter: if i:
        # starter:     pass
        # END PROMPT
        total += i
        # --- end of step 3 ---
    return total
'''

STARTER = '''"""A lab."""


def double(x):
    """Twice x."""
    # --- step 2: double x ---
    # Step 2: return twice x.
    return None  # placeholder: replace this line
    # --- end of step 2 ---


def loop(n):
    total = 0
    for i in range(n):
        # --- step 3: add i ---
        # Step 3: add i to total.
        if i:
            pass
        # --- end of step 3 ---
    return total
'''


def test_a_prompt_becomes_the_region_and_everything_else_is_copied():
    assert assign.starter_text(SOLUTION, "lab.py") == STARTER


def test_line_ends_are_kept_byte_for_byte():
    """On Windows a checkout with core.autocrlf gives solution and starter CRLF ends alike; assign keeps each line's
    end, so --check holds there too (emulated here by converting the text, not by a Windows checkout)."""
    crlf = SOLUTION.replace("\n", "\r\n")
    assert assign.starter_text(crlf, "lab.py") == STARTER.replace("\n", "\r\n")
    assert assign.starter_text(SOLUTION.rstrip("\n"), "lab.py") == STARTER.rstrip("\n")


def test_the_solution_runs_its_answer_and_the_starter_its_placeholder():
    solution, starter = {}, {}
    exec(SOLUTION, solution)
    exec(assign.starter_text(SOLUTION, "lab.py"), starter)
    assert (solution["double"](3), starter["double"](3)) == (6, None)
    assert (solution["loop"](4), starter["loop"](4)) == (6, 0)


def _with(old, new, count=1):
    assert SOLUTION.count(old) >= 1
    return SOLUTION.replace(old, new, count)


# bad annotations -> (the line the message must name, words it must contain)
BAD = {
    "region opened, never closed": (_with("        # --- end of step 3 ---\n", ""), 18, "no `# --- end of step 3"),
    "prompt never closed": (_with("        # END PROMPT\n", ""), 23, "opened on line 19"),
    "prompt not closed before the region ends": (_with("    # END PROMPT\n", ""), 10, "opened on line 7"),
    "prompt outside a region": (SOLUTION + "# BEGIN PROMPT\n# x\n# END PROMPT\n", 27, "outside a step region"),
    "END PROMPT alone": (_with("    return 2 * x\n", "    return 2 * x\n    # END PROMPT\n"), 12,
                         "without a `# BEGIN PROMPT`"),
    "code in a prompt": (_with("    # Step 2: return twice x.\n", "    x = 1\n"), 8, "opened on line 7"),
    "region without a prompt": (_with("    # BEGIN PROMPT\n    # Step 2: return twice x.\n"
                                      "    # starter: return None  # placeholder: replace this line\n"
                                      "    # END PROMPT\n", ""), 6, "no prompt"),
    "two prompts in a region": (_with("    return 2 * x\n", "    # BEGIN PROMPT\n    # more\n    # END PROMPT\n"
                                      "    return 2 * x\n"), 11, "second prompt"),
    "prompt marker in a string": (_with("    return 2 * x\n", "    return '''\n    # BEGIN PROMPT\n'''\n"), 12,
                                  "inside a string"),
    "placeholder outside a prompt": (_with("    return 2 * x\n", "    # starter: return 0\n    return 2 * x\n"), 11,
                                     "outside a prompt"),
    "starter that is not Python": (_with("# starter: return None", "# starter: return (None"), None,
                                   "not Python"),
}


@pytest.mark.parametrize("case", BAD)
def test_bad_annotations_are_one_line_naming_file_and_line(case):
    text, line, words = BAD[case]
    with pytest.raises(assign.AssignError) as caught:
        assign.starter_text(text, "solutions/lab.py")
    message = str(caught.value)
    assert "\n" not in message and message.startswith("solutions/lab.py")
    assert words in message
    if line is not None:
        assert f"line {line}" in message


@pytest.fixture
def labs(tmp_path, monkeypatch):
    """Two solutions (one good, one broken) and a starters folder holding an old starter and another file."""
    solutions, starters = tmp_path / "solutions", tmp_path / "starters"
    solutions.mkdir()
    starters.mkdir()
    (solutions / "good.py").write_text(SOLUTION, encoding="utf-8")
    (solutions / "broken.py").write_text(BAD["prompt never closed"][0], encoding="utf-8")
    (starters / "good_starter.py").write_text("old\n", encoding="utf-8")
    (starters / "notes.txt").write_text("mine\n", encoding="utf-8")
    monkeypatch.setattr(assign, "STARTERS", str(starters))
    return solutions, starters


def test_default_rewrites_only_the_starters_and_one_bad_file_is_one_error(labs, capsys):
    solutions, starters = labs
    status = cli.main(["assign", str(solutions / "broken.py"), str(solutions / "good.py")])
    out, err = capsys.readouterr()
    assert status == 1
    assert (starters / "good_starter.py").read_text(encoding="utf-8") == STARTER
    assert sorted(os.listdir(starters)) == ["good_starter.py", "notes.txt"]   # no broken_starter.py, no temp file
    assert (starters / "notes.txt").read_text(encoding="utf-8") == "mine\n"
    assert len(err.strip().splitlines()) == 1 and "broken.py, line 23" in err
    assert "good_starter.py: written" in out


def test_a_missing_solution_is_one_error_row(labs, capsys):
    solutions, starters = labs
    assert cli.main(["assign", str(solutions / "gone.py"), str(solutions / "good.py")]) == 1
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert "gone.py: cannot read it" in line
    assert (starters / "good_starter.py").read_text(encoding="utf-8") == STARTER


def test_check_writes_nothing_and_names_each_drift_in_one_line(labs, capsys):
    solutions, starters = labs
    good = str(solutions / "good.py")
    assert cli.main(["assign", "--check", good]) == 1
    out = capsys.readouterr().out.strip().splitlines()
    assert out == [f"{starters / 'good_starter.py'} differs from what python -m checker assign writes from "
                   f"{good}: 20 line(s) differ, the first at line 1"]
    assert (starters / "good_starter.py").read_text(encoding="utf-8") == "old\n"
    assert cli.main(["assign", good]) == 0
    assert cli.main(["assign", "--check", good]) == 0
    os.remove(starters / "good_starter.py")
    assert cli.main(["assign", "--check", good]) == 1
    assert "good_starter.py is missing" in capsys.readouterr().out


def test_out_never_replaces_a_file_already_there(labs, tmp_path, capsys):
    solutions, _ = labs
    out = tmp_path / "out"
    out.mkdir()
    good = str(solutions / "good.py")
    assert cli.main(["assign", "--out", str(out), good]) == 0
    assert (out / "good_starter.py").read_text(encoding="utf-8") == STARTER
    (out / "good_starter.py").write_text("edited by hand\n", encoding="utf-8")
    assert cli.main(["assign", "--out", str(out), good]) == 1
    assert "exists: not replaced" in capsys.readouterr().err
    assert (out / "good_starter.py").read_text(encoding="utf-8") == "edited by hand\n"
    assert cli.main(["assign", "--out", str(tmp_path / "nowhere"), good]) == 2


def test_the_project_starters_are_current_by_the_command(capsys):
    """`python -m checker assign --check` on the project itself: every committed starter is what assign writes."""
    assert cli.main(["assign", "--check"]) == 0, capsys.readouterr().out


def test_a_copy_of_the_project_that_drifted_fails_check(tmp_path, capsys):
    """The maintainer path: edit a starter by hand and --check names it."""
    out = tmp_path / "starters"
    shutil.copytree(assign.STARTERS, out)
    path = out / "bullets_starter.py"
    path.write_bytes(path.read_bytes().replace(b"# Step 1:", b"# Step one:", 1))
    assert cli.main(["assign", "--check", "--out", str(out)]) == 1
    (line,) = capsys.readouterr().out.strip().splitlines()
    assert "bullets_starter.py differs" in line and "1 line(s) differ" in line


def test_a_rewritten_starter_keeps_its_permissions(labs):
    """mkstemp makes 0o600 files: a starter rewritten through one must still be readable as before."""
    solutions, starters = labs
    target = starters / "good_starter.py"
    os.chmod(target, 0o644)
    assert assign.run([str(solutions / "good.py")]) == 0
    assert stat.S_IMODE(os.stat(target).st_mode) == 0o644


def test_the_command_as_a_maintainer_types_it(tmp_path):
    """`python -m checker assign --check --out DIR` in a child process: the real entry point (no zygote started)."""
    out = tmp_path / "starters"
    shutil.copytree(assign.STARTERS, out)
    command = [sys.executable, "-m", "checker", "assign", "--check", "--out", str(out)]
    done = subprocess.run(command, cwd=assign.ROOT, capture_output=True, text=True, timeout=120)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")
    os.remove(out / "more_shapes_starter.py")
    done = subprocess.run(command, cwd=assign.ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 1 and done.stdout.count("\n") == 1 and "more_shapes_starter.py is missing" in done.stdout
