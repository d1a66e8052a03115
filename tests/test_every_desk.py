"""Every desk: the README's two commands for Linux/macOS and for Windows PowerShell, .ci/run and the CI matrix
(.github/workflows/tests.yml) say the same thing, and the GitHub Classroom package's workflow runs on Ubuntu.

What this machine cannot do: run PowerShell or a Windows/macOS runner. So the PowerShell lines are compared
step by step with the bash ones (the same venv, the same activation of it, the same pip install target and
extras, the same final command), and the workflow is read (PyYAML) the way GitHub Actions reads it: a runner
runs the steps whose `if:` holds for its runner.os, `shell: bash` as `bash --noprofile --norc -eo pipefail`
(so `&&` stops at the first failure), `shell: pwsh` as PowerShell 7, where `;` goes on after a failing step
and the job's status is the last command's exit status (here the checker's or pytest's).
"""
import os
import re
import shutil
import subprocess
import sys

import pytest
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORKFLOW = os.path.join(ROOT, ".github", "workflows", "tests.yml")
RUNNERS = {"ubuntu-latest": "Linux", "windows-latest": "Windows", "macos-latest": "macOS"}


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


def readme_commands():
    """{"bash": [command 1, command 2], "powershell": [...]}: the fenced blocks under "On a fresh machine"."""
    text = read("README.md")
    top = text[text.index("**On a fresh machine**"):text.index("## Start here")]
    blocks = {}
    for language, body in re.findall(r"^```(\w+)\n(.*?)^```$", top, re.M | re.S):
        blocks[language] = [line for line in body.splitlines() if line.strip() and not line.startswith("#")]
    return blocks


def steps(command, shell):
    """A one-line command as [(kind, detail)]: venv (its folder), activate (the folder), pip install (its
    arguments), run (anything else, word for word). Anything unrecognised in the first three places is a
    "run", so a changed or missing step shows up as a difference."""
    parts = command.split(" && ") if shell == "bash" else command.split("; ")
    patterns = [("venv", r"(?:python3|py) -m venv (\S+)"), ("activate", r"\. (\S+)/bin/activate"),
                ("activate", r"(\S+)\\Scripts\\Activate\.ps1"), ("pip install", r"pip install (.+)")]
    found = []
    for part in parts:
        kind = next(((k, m.group(1)) for k, pattern in patterns if (m := re.fullmatch(pattern, part))), None)
        found.append(kind or ("run", part))
    return found


def test_readme_names_both_desks_and_two_commands_each():
    commands = readme_commands()
    assert sorted(commands) == ["bash", "powershell"]
    assert len(commands["bash"]) == len(commands["powershell"]) == 2
    top = read("README.md").split("## Start here")[0]
    assert "Linux and macOS" in top and "Windows (PowerShell)" in top


@pytest.mark.parametrize("number", [1, 2])
def test_the_powershell_command_takes_the_same_steps_as_the_bash_one(number):
    commands = readme_commands()
    bash, pwsh = (steps(commands[shell][number - 1], shell) for shell in ("bash", "powershell"))
    assert [kind for kind, _ in bash] == ["venv", "activate", "pip install", "run"], bash
    assert pwsh == bash, f"command {number}: PowerShell {pwsh} != bash {bash}"
    assert bash[0][1] == bash[1][1] == ".venv"   # the venv made is the one activated
    assert "&&" not in commands["powershell"][number - 1]   # Windows PowerShell 5.1 has no &&
    assert commands["powershell"][number - 1].startswith("py -m venv ")   # the launcher, as python.org installs


def test_the_pip_install_targets_and_extras_exist():
    """Each `pip install -e .[extra]` names this project and an extra pyproject.toml defines (read as text:
    tomllib is 3.11+, the project supports 3.10)."""
    section = read("pyproject.toml").split("[project.optional-dependencies]")[1].split("\n[")[0]
    defined = set(re.findall(r"^([\w-]+) = \[", section, re.M))
    for shell, commands in readme_commands().items():
        for command in commands:
            target = dict(steps(command, shell))["pip install"]
            match = re.fullmatch(r'-e (?:\.|"\.\[([\w,-]+)\]")', target)
            assert match, f"{shell}: pip install {target}: not this project"
            assert set(filter(None, (match.group(1) or "").split(","))) <= defined, target
    assert "pyyaml>=6" in section   # this file reads the workflow with it


@pytest.mark.parametrize("bash, pwsh", [   # the comparison must see each of these differences
    ("python3 -m venv .venv && . .venv/bin/activate && pip install -e . && python -m checker solutions/",
     "py -m venv .venv; pip install -e .; python -m checker solutions/"),                            # no activate
    ('python3 -m venv .venv && . .venv/bin/activate && pip install -e ".[test]" && python -m pytest',
     'py -m venv .venv; .venv\\Scripts\\Activate.ps1; pip install -e ".[tests]"; python -m pytest'),  # other extra
    ('python3 -m venv .venv && . .venv/bin/activate && pip install -e ".[test]" && python -m pytest',
     'py -m venv .venv; .venv\\Scripts\\Activate.ps1; pip install -e ".[test]"; python -m pytest -x'),
    ("python3 -m venv .venv && . .venv/bin/activate && pip install -e . && python -m checker solutions/",
     "py -m venv env; env\\Scripts\\Activate.ps1; pip install -e .; python -m checker solutions/"),   # other venv
    ("python3 -m venv .venv && . .venv/bin/activate && pip install -e . && python -m checker solutions/",
     "py -m venv .venv && .venv\\Scripts\\Activate.ps1 && pip install -e . && python -m checker solutions/"),
])
def test_the_step_comparison_sees_a_difference(bash, pwsh):
    assert steps(bash, "bash") != steps(pwsh, "powershell")


def test_ci_run_runs_readme_command_2_word_for_word():
    ci = read(".ci/run")
    wanted = re.search(r"^readme_test_command='(.*)'$", ci, re.M).group(1)
    assert wanted == readme_commands()["bash"][1]
    assert ci.rstrip().splitlines()[-1] == wanted


# ---------------------------------------------------------------- the CI matrix


def workflow():
    with open(WORKFLOW, encoding="utf-8") as handle:
        return yaml.safe_load(handle)


def job():
    jobs = workflow()["jobs"]
    assert len(jobs) == 1, "one job, its matrix the desks"
    return next(iter(jobs.values()))


def applies(step, runner_os):
    """Whether a step runs on a runner of this runner.os (the two `if:` forms this workflow uses)."""
    condition = step.get("if")
    if condition is None:
        return True
    match = re.fullmatch(r"runner\.os (==|!=) '(\w+)'", condition.strip())
    assert match, f"an `if:` this test cannot read: {condition!r}"
    return (runner_os == match.group(2)) == (match.group(1) == "==")


def runs_on(runner_os):
    """[(shell, run)] of the run steps a runner of this runner.os takes, in order."""
    return [(step.get("shell"), step["run"]) for step in job()["steps"] if "run" in step and applies(step, runner_os)]


def test_the_matrix_is_three_systems_by_the_oldest_and_newest_python():
    spec = job()
    matrix = spec["strategy"]["matrix"]
    assert sorted(matrix["os"]) == sorted(RUNNERS)
    assert matrix["python-version"] == ["3.10", "3.13"]   # strings: YAML would read 3.10 as 3.1
    assert spec["strategy"]["fail-fast"] is False        # every desk reports, not just the first failure
    assert spec["runs-on"] == "${{ matrix.os }}"
    setup = next(s for s in spec["steps"] if str(s.get("uses", "")).startswith("actions/setup-python@"))
    assert setup["with"]["python-version"] == "${{ matrix.python-version }}"
    assert re.search(r'requires-python = ">=3\.10"', read("pyproject.toml"))
    assert spec["env"]["PY_PYTHON"] == "${{ matrix.python-version }}"   # py picks the matrix's Python


def test_the_workflow_has_ci_runs_environment():
    exported = re.search(r"^export (.*)$", read(".ci/run"), re.M).group(1).split()
    env = {key: str(value) for key, value in job()["env"].items()}
    for assignment in exported:
        key, value = assignment.split("=", 1)
        assert env.get(key) == value, f"{key}: .ci/run sets {value!r}, the workflow {env.get(key)!r}"
    assert env["SDL_VIDEODRIVER"] == env["SDL_AUDIODRIVER"] == "dummy"


@pytest.mark.parametrize("runner", sorted(RUNNERS))
def test_each_runner_runs_the_readme_commands_for_its_desk(runner):
    runner_os = RUNNERS[runner]
    shell, language = ("pwsh", "powershell") if runner_os == "Windows" else ("bash", "bash")
    commands = readme_commands()[language]
    taken = runs_on(runner_os)
    readme_steps = [(s, run) for s, run in taken if run in commands]
    assert readme_steps == [(shell, commands[0]), (shell, commands[1])], taken
    assert commands[0].endswith("python -m checker solutions/") and commands[1].endswith("python -m pytest")
    assert all(s in ("bash", "pwsh") for s, _ in taken), "every run step names its shell"
    assert len(taken) == 3, "the two README commands and the venv's version check, nothing else"


@pytest.mark.skipif(shutil.which("bash") is None, reason="runs the Linux runner's step with bash")
def test_the_venv_version_check_fails_on_another_python(tmp_path):
    """The check step, run here as bash runs it: passes for this venv's Python, fails for another version."""
    check = next(run for _, run in runs_on("Linux") if "pyvenv.cfg" in run)
    (tmp_path / ".venv").mkdir()
    (tmp_path / ".venv" / "pyvenv.cfg").write_text("home = /x\nversion = 3.10.11\n", encoding="utf-8")
    results = {}
    for version in ("3.10", "3.13", "3.1"):
        script = check.replace("${{ matrix.python-version }}", version)
        results[version] = subprocess.run(["bash", "-c", script], cwd=tmp_path, capture_output=True,
                                          env=dict(os.environ, PATH=os.path.dirname(sys.executable) + os.pathsep
                                                   + os.environ.get("PATH", ""))).returncode
    assert results == {"3.10": 0, "3.13": 1, "3.1": 1}


def test_the_classroom_package_workflow_runs_on_ubuntu(tmp_path):
    """python -m checker package classroom writes a workflow whose every job runs on ubuntu-latest (GitHub
    Classroom grades on its Linux runners; the checker's POSIX path)."""
    out = tmp_path / "classroom"
    done = subprocess.run([sys.executable, "-m", "checker", "package", "classroom", "--out", str(out),
                           "--labs", "tumbling_crates"], cwd=ROOT, capture_output=True, text=True,
                          encoding="utf-8", timeout=300)
    assert done.returncode == 0, done.stderr
    with open(out / ".github" / "workflows" / "classroom.yml", encoding="utf-8") as handle:
        document = yaml.safe_load(handle)
    runners = {name: spec["runs-on"] for name, spec in document["jobs"].items()}
    assert runners and set(runners.values()) == {"ubuntu-latest"}, runners


# ---------------------------------------------------------------- line endings on a Windows checkout


def test_a_windows_checkout_keeps_lf_line_endings():
    """.gitattributes: Git for Windows checks text files out with LF as here (its default would be CRLF), and
    leaves pictures alone. Read through `git check-attr`, as git itself applies it at checkout."""
    if not os.path.isdir(os.path.join(ROOT, ".git")) and not os.path.isfile(os.path.join(ROOT, ".git")):
        pytest.skip("not a git checkout")
    files = ["starters/tumbling_crates_starter.py", "checker/platforms/templates/gradescope_setup.sh", "README.md",
             ".ci/run", "assets/bullets.png"]
    done = subprocess.run(["git", "check-attr", "text", "eol", "--", *files], cwd=ROOT, capture_output=True,
                          text=True, encoding="utf-8", timeout=60)
    attributes = {}
    for line in done.stdout.splitlines():
        path, name, value = line.split(": ")
        attributes.setdefault(path, {})[name] = value
    for path in files[:-1]:
        assert attributes[path] == {"text": "auto", "eol": "lf"}, (path, attributes[path])
    assert attributes["assets/bullets.png"]["text"] == "unset"


def test_the_packages_scripts_have_lf_endings_even_from_a_crlf_checkout(tmp_path, monkeypatch):
    """A checkout that has CRLF anyway (a zip unpacked on Windows, an editor's conversion): the shell scripts
    a package ships for Linux graders are still written with LF (bash reads a CR as part of each command)."""
    from checker.platforms import package
    crlf = tmp_path / "templates"
    crlf.mkdir()
    for name in os.listdir(package.TEMPLATES):
        with open(os.path.join(package.TEMPLATES, name), "rb") as handle:
            (crlf / name).write_bytes(handle.read().replace(b"\n", b"\r\n"))
    monkeypatch.setattr(package, "TEMPLATES", str(crlf))
    for name in ("gradescope_setup.sh", "gradescope_run_autograder", "run_prairielearn", "grade_submission.py"):
        text = package.template(name, PINS="x", PYGAME_PIN="y", PYTHON="3.10")
        assert "\r" not in text and text.count("\n") > 3, name
    out = tmp_path / "out"
    package.write_folder(str(out), {"setup.sh": (package.template("gradescope_setup.sh"), True)})
    assert b"\r" not in (out / "setup.sh").read_bytes()


# ---------------------------------------------------------------- the suite itself on a Windows runner

WINDOWS_MISSING = ("resource", "pwd", "grp", "fcntl", "termios", "tty", "pty")   # modules CPython lacks there


def test_the_suite_collects_where_posix_modules_are_missing(tmp_path):
    """On a Windows runner one test module that imports `resource` at its top stops pytest before any test runs
    (a collection error ends the session). Emulated here: those modules made unimportable (sitecustomize), the
    whole suite collected. (The os/signal names Windows lacks cannot be removed before pytest starts: Linux's
    own subprocess module needs them; the checker's portable-path tests remove them inside the run.)"""
    site = tmp_path / "sitecustomize.py"
    site.write_text("import sys\nfor name in %r:\n    sys.modules[name] = None\n" % (WINDOWS_MISSING,),
                    encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-n", "0", "-p", "no:cacheprovider",
                           os.path.join(ROOT, "tests")], cwd=ROOT, capture_output=True, text=True, encoding="utf-8",
                          env=dict(os.environ, PYTHONPATH=str(tmp_path)), timeout=600)
    assert done.returncode == 0 and "ERROR collecting" not in done.stdout, done.stdout[-3000:] + done.stderr[-2000:]
    assert "tests/test_every_desk.py" in done.stdout   # it did collect (this file among the rest)
