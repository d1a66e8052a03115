"""python -m checker package PLATFORM --out PATH: the checker packaged for an autograding platform.

    gradescope     a zip (setup.sh, run_autograder at its root) to upload as a Gradescope autograder
    classroom      a folder with .github/workflows/classroom.yml (one step per check) for GitHub Classroom
    prairielearn   a folder with a Dockerfile, an entrypoint and the info.json snippet for PrairieLearn

Every package holds a copy of the project the checker needs at grading time
(checker/, lesson11/, starters/, solutions/, pyproject.toml, README.md): grading
compares a file with its lab's starter and probes steps with the solution's
code. The runner each package uses, templates/grade_submission.py (standard
library only), finds the lab file in the submission, grades it with
`python -m checker FILE --json` in a child process (as a non-root user when run
as root and that user exists) and always writes the platform's results.json.

`python -m checker.platforms.package verdict FILE LAB CHECK` is the per-check step of
the GitHub Classroom workflow: exit 0 if CHECK passed in the checker's --json
output FILE.
"""
import argparse
import io
import json
import os
import sys
import zipfile

from checker import labs as lab_registry
from checker.project import PROJECT_ROOT
from checker.reporting.outputs import inside

TEMPLATES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "templates")
PROJECT_DIRS = ("checker", "lesson11", "starters", "solutions")
PROJECT_FILES = ("pyproject.toml", "README.md")
SKIP = {"__pycache__", ".pytest_cache", ".hypothesis"}
PLATFORMS = ("gradescope", "classroom", "prairielearn")
TOTAL_TIMEOUT = 420.0       # s: one submission's grading, pictures and the retry without them included
MAX_TOTAL_TIMEOUT = 540.0   # s: Gradescope stops a run at 600 s by default; this leaves time to write results


class PackageError(Exception):
    """A one-line reason the package cannot be written."""


def installed_versions():
    """{distribution: version} of what the checker runs on here, pinned in every package."""
    from importlib import metadata
    versions = {}
    for name in ("pygame-ce", "numpy"):
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = None
    return versions


def pins(versions):
    return " ".join(f"{name}=={v}" if v else name for name, v in versions.items())


def python_version():
    return f"{sys.version_info.major}.{sys.version_info.minor}"


def project_files():
    """[(path relative to the project, absolute path)] of every file a package ships."""
    found = [(name, os.path.join(PROJECT_ROOT, name)) for name in PROJECT_FILES]
    for top in PROJECT_DIRS:
        for root, dirs, files in os.walk(os.path.join(PROJECT_ROOT, top)):
            dirs[:] = sorted(d for d in dirs if d not in SKIP and not d.startswith("."))
            for name in sorted(files):
                if name.endswith((".pyc", ".pyo")) or name.startswith("."):
                    continue
                full = os.path.join(root, name)
                found.append((os.path.relpath(full, PROJECT_ROOT), full))
    return found


def template(name, **values):
    with open(os.path.join(TEMPLATES, name), encoding="utf-8") as handle:
        text = handle.read()
    for key, value in values.items():
        text = text.replace("{{" + key + "}}", str(value))
    return text


def config(labs, hide, args):
    """autograder.json: the labs graded (file name, points), checks hidden, limits."""
    return {
        "labs": [{"id": lab.id, "title": lab.title, "file": lab.id + ".py", "max_score": lab.checks.max_score}
                 for lab in labs],
        "hide": list(hide), "user": "student", "timeout": args.timeout, "total_timeout": args.total_timeout,
        "pictures": True,
        "versions": installed_versions(), "built_with_python": python_version(),
    }


def choose_labs(names):
    by_id = {lab.id: lab for lab in lab_registry.LABS}
    if not names:  # a package that graded every lab gave full marks for any lab's solution on any assignment
        raise PackageError(f"--labs is required: name the lab(s) this assignment grades "
                           f"(one of {', '.join(by_id)}); a file of another lab then scores 0")
    unknown = [n for n in names if n not in by_id]
    if unknown:
        raise PackageError(f"--labs: unknown lab {', '.join(unknown)} (known: {', '.join(by_id)})")
    return [by_id[n] for n in names]


def check_hide(labs, hide):
    ids = {c.id for lab in labs for c in lab.checks.checks}
    unknown = [h for h in hide if h not in ids]
    if unknown:
        raise PackageError(f"--hide: no check {', '.join(unknown)} in {', '.join(l.id for l in labs)} "
                           f"(python -m checker --list shows the ids)")


def check_out(out, kind, force):
    """Refuse an output that exists (unless force), a .py, or a path inside the project's graded folders."""
    real = os.path.realpath(out)
    for top in ("starters", "solutions") + PROJECT_DIRS:
        folder = os.path.realpath(os.path.join(PROJECT_ROOT, top))
        if inside(real, folder):
            raise PackageError(f"--out {out}: inside {folder}, which the package copies; choose a path outside it")
    if out.lower().endswith(".py"):
        raise PackageError(f"--out {out}: refusing to write to a .py file (it may be a submission)")
    if os.path.lexists(out):
        if not force:
            raise PackageError(f"--out {out}: already exists; remove it or pass --force to replace it")
        if kind == "file" and not os.path.isfile(out):
            raise PackageError(f"--out {out}: exists and is not a file")
        if kind == "folder" and not os.path.isdir(out):
            raise PackageError(f"--out {out}: exists and is not a folder")
    parent = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(parent):
        raise PackageError(f"--out {out}: the folder {parent} does not exist")


def bundle(labs, hide, args, extra):
    """{path inside the package: (text or bytes, executable)}: the runner, its config, the project, `extra`."""
    files = {"grade_submission.py": (template("grade_submission.py"), False),
             "autograder.json": (json.dumps(config(labs, hide, args), indent=2) + "\n", False)}
    for rel, full in project_files():
        with open(full, "rb") as handle:
            files["project/" + rel.replace(os.sep, "/")] = (handle.read(), False)
    files.update(extra)
    return files


def write_zip(path, files):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for name in sorted(files):
            data, executable = files[name]
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = (0o100755 if executable else 0o100644) << 16
            archive.writestr(info, data)
    temp = path + ".tmp"
    with open(temp, "wb") as handle:
        handle.write(buffer.getvalue())
    os.replace(temp, path)


def write_folder(path, files):
    os.makedirs(path, exist_ok=True)
    for name, (data, executable) in sorted(files.items()):
        target = os.path.join(path, *name.split("/"))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "wb") as handle:
            handle.write(data.encode("utf-8") if isinstance(data, str) else data)
        os.chmod(target, 0o755 if executable else 0o644)


def assignment(labs, hide):
    """What students submit and what it is worth, in one sentence (printed by the command and in README.txt)."""
    files = " or ".join(f"{lab.id}.py ({lab.title}, {lab.checks.max_score:g} points)" for lab in labs)
    points = sorted({lab.checks.max_score for lab in labs})
    worth = f"{points[0]:g} points" if len(points) == 1 else "its lab's points"
    hidden = f"; {len(hide)} check(s) hidden from students ({', '.join(hide)}) still count" if hide else ""
    return (f"Students submit {files}. A submission scores out of {worth}: set the assignment's total to that"
            f"{hidden}.")


def gradescope_readme(labs, hide, args):
    lines = ["Gradescope autograder for Lesson 11 (python -m checker package gradescope).", "",
             assignment(labs, hide), "",
             "Checks, in the order students see them (id, points, what it checks):"]
    for lab in labs:
        lines.append(f"  {lab.title} ({lab.id}.py), {lab.checks.max_score:g} points:")
        lines += [f"    {c.id:<24} {c.max_score:g}  {c.description}" + ("  [hidden]" if c.id in hide else "")
                  for c in lab.checks.checks]
    lines += ["", "A submission may be the file alone or the file in a folder; another name is graded when it is "
              "the only .py file, with a note. A file of another lab scores 0.",
              f"Limits: {args.timeout:g} CPU s per run, {args.total_timeout:g} s of wall clock per submission.",
              "Upload this zip as the assignment's autograder (Configure Autograder, Zip file upload, Ubuntu 22.04 "
              "or later).", ""]
    return "\n".join(lines)


def gradescope(labs, hide, args):
    versions = installed_versions()
    pygame_pin = pins({"pygame-ce": versions.get("pygame-ce")})
    extra = {"setup.sh": (template("gradescope_setup.sh", PINS=pins(versions), PYGAME_PIN=pygame_pin,
                                   PYTHON=python_version()), True),
             "run_autograder": (template("gradescope_run_autograder"), True),
             "README.txt": (gradescope_readme(labs, hide, args), False)}
    files = bundle(labs, hide, args, extra)
    write_zip(args.out, files)
    return f"Gradescope autograder written to {args.out} ({os.path.getsize(args.out) / 1024:.0f} KB): upload it " \
           f"as the assignment's autograder (Configure Autograder, Zip file upload, Ubuntu 22.04 or later). " \
           f"{assignment(labs, hide)}"


def classroom_steps(labs, pin_text):
    steps = [
        "      - uses: actions/checkout@v4",
        "      - uses: actions/setup-python@v5",
        "        with:",
        f"          python-version: \"{python_version()}\"",
        "      - name: Install the checker",
        f"        run: python -m pip install {pin_text} && python -m pip install --no-deps -e \"$CHECKER_SOURCE\"",
    ]
    runners = []
    for lab in labs:
        steps += [
            f"      - name: Grade {lab.id}.py",
            f"        run: mkdir -p .autograder && python -m checker {lab.id}.py --json --quiet > .autograder/{lab.id}.json "
            "|| true",
            "        env:",
            "          SDL_VIDEODRIVER: dummy",
            "          SDL_AUDIODRIVER: dummy",
            "          PYGAME_HIDE_SUPPORT_PROMPT: \"1\"",
        ]
        for check in lab.checks.checks:
            step_id = f"{lab.id}_{check.id}"
            runners.append(step_id)
            steps += [
                f"      - name: \"{lab.id}: {check.id}\"",
                f"        id: {step_id}",
                "        uses: classroom-resources/autograding-command-grader@v1",
                "        with:",
                f"          test-name: \"{lab.title}: {check.id}\"",
                f"          command: python -m checker.platforms.package verdict .autograder/{lab.id}.json {lab.id} {check.id}",
                "          timeout: 1",
                f"          max-score: {check.max_score:g}",
            ]
    steps += [
        "      - name: Autograding Reporter",
        "        uses: classroom-resources/autograding-grading-reporter@v1",
        "        env:",
        *[f"          {r.upper()}_RESULTS: \"${{{{steps.{r}.outputs.result}}}}\"" for r in runners],
        "        with:",
        f"          runners: {','.join(runners)}",
    ]
    return "\n".join(steps) + "\n"


def classroom(labs, hide, args):
    source = args.source or ".autograder/project"
    workflow = template("classroom.yml", SOURCE=source, STEPS=classroom_steps(labs, pins(installed_versions())))
    extra = {".github/workflows/classroom.yml": (workflow, False)}
    if args.source:
        files = extra
    else:
        files = {".autograder/" + name: value for name, value in bundle(labs, hide, args, {}).items()
                 if name.startswith("project/")}
        files.update(extra)
    write_folder(args.out, files)
    warning = "" if args.source else (
        "\nNote: .autograder/project holds the lab solutions (grading needs them); in a student repository they "
        "are readable by the student. Use --source PIP_SPEC (e.g. a private package) to install the checker "
        "from elsewhere instead.")
    return f"GitHub Classroom workflow written to {os.path.join(args.out, '.github', 'workflows', 'classroom.yml')}: " \
           f"copy {args.out}'s contents into the assignment's template repository.{warning}"


def prairielearn(labs, hide, args):
    versions = installed_versions()
    snippet = {"gradingMethod": "External", "singleVariant": True,
               "externalGradingOptions": {"enabled": True, "image": args.image,
                                          "entrypoint": "/grader/run_prairielearn",
                                          "timeout": int(args.total_timeout + 60)}}
    extra = {"Dockerfile": (template("Dockerfile", PINS=pins(versions), PYTHON=python_version()), False),
             "run_prairielearn": (template("run_prairielearn"), True),
             "info.json.snippet": (json.dumps(snippet, indent=2) + "\n", False),
             "question.html": (template("question.html", FILES=",".join(lab.id + ".py" for lab in labs)), False)}
    files = bundle(labs, hide, args, extra)
    write_folder(args.out, files)
    return f"PrairieLearn grader written to {args.out}: docker build -t {args.image} {args.out} && docker push " \
           f"{args.image}; merge {os.path.join(args.out, 'info.json.snippet')} into the question's info.json."


def parse(argv):
    parser = argparse.ArgumentParser(prog="python -m checker package", allow_abbrev=False,
                                     description="Package the checker for an autograding platform.")
    parser.add_argument("platform", choices=PLATFORMS)
    parser.add_argument("--out", required=True, help="the zip (gradescope) or folder (classroom, prairielearn)")
    parser.add_argument("--labs", nargs="+", metavar="LAB", help="the labs this assignment grades (required; usually one)")
    parser.add_argument("--hide", nargs="+", default=[], metavar="CHECK_ID",
                        help="checks whose result students do not see (Gradescope: visibility hidden)")
    parser.add_argument("--force", action="store_true", help="replace an existing --out")
    parser.add_argument("--timeout", type=float, default=20.0, help="CPU seconds per run of a lab (default 20)")
    parser.add_argument("--total-timeout", type=float, default=TOTAL_TIMEOUT,
                        help=f"wall-clock seconds to grade one submission, at most {MAX_TOTAL_TIMEOUT:g} so that a "
                             f"results file is written inside Gradescope's default 10-minute limit "
                             f"(default {TOTAL_TIMEOUT:g})")
    parser.add_argument("--source", help="classroom: a pip requirement to install the checker from instead of "
                                         "a copy in the repository")
    parser.add_argument("--image", default="yourname/lesson11-grader",
                        help="prairielearn: the Docker image name in info.json (default %(default)s)")
    return parser.parse_args(argv)


def main(argv):
    """python -m checker package ...; returns the exit status (0 written, 2 refused or a wrong command line)."""
    try:
        args = parse(argv)
    except SystemExit as exc:
        return 0 if exc.code == 0 else 2
    try:
        if not 0 < args.total_timeout <= MAX_TOTAL_TIMEOUT or not 0 < args.timeout <= args.total_timeout:
            raise PackageError(f"--total-timeout {args.total_timeout:g} / --timeout {args.timeout:g}: need "
                               f"0 < timeout <= total-timeout <= {MAX_TOTAL_TIMEOUT:g} s")
        labs = choose_labs(args.labs)
        check_hide(labs, args.hide)
        check_out(args.out, "file" if args.platform == "gradescope" else "folder", args.force)
        message = {"gradescope": gradescope, "classroom": classroom, "prairielearn": prairielearn}[args.platform](
            labs, args.hide, args)
    except PackageError as exc:
        print(f"checker: error: {exc}", file=sys.stderr)
        return 2
    print(message)
    return 0


def verdict(argv):
    """verdict FILE LAB CHECK: print the check's result from the checker's --json FILE; exit 0 if it passed."""
    path, lab, check = argv
    try:
        with open(path, encoding="utf-8") as handle:
            document = json.load(handle)
        row = next(r for r in document["labs"] if r.get("lab") == lab or not r.get("lab"))
    except (OSError, ValueError, KeyError, StopIteration):
        print(f"No result for {lab}: is {lab}.py at the top of the repository? The checker's output is in {path}.")
        return 1
    if row.get("message"):
        print(row["message"])
    result = next((c for c in row.get("criteria", []) if c["id"] == check), None)
    if result is None:
        return 1
    print(f"{result['status']}: {result['name']}")
    for part in (result.get("message"), result.get("hint") and "Hint " + result["hint"]):
        if part:
            print(part)
    return 0 if result["status"] == "pass" else 1


if __name__ == "__main__":
    if sys.argv[1:2] == ["verdict"] and len(sys.argv) == 5:
        sys.exit(verdict(sys.argv[2:]))
    print("usage: python -m checker.platforms.package verdict FILE LAB CHECK", file=sys.stderr)
    sys.exit(2)
