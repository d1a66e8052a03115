"""Grade one submission for an autograding platform; ALWAYS writes a valid results file.

Shipped by `python -m checker package ...` next to autograder.json (which labs,
hidden checks, limits). Standard library only, and the checker runs in a child
process, so a submission (or a checker bug) that crashes still ends in a
results file with score 0 and the reason.

    python3 grade_submission.py gradescope      # $AUTOGRADER_ROOT (default /autograder)
    python3 grade_submission.py prairielearn    # $GRADE_ROOT (default /grade)
"""
import base64
import html
import json
import os
import pwd
import shutil
import subprocess
import sys
import tempfile
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP_DIRS = {"__pycache__", ".git", ".venv", "venv", "node_modules", "__MACOSX"}
PNG = b"\x89PNG\r\n\x1a\n"
MAX_PICTURE_BYTES = 200_000   # one picture (they are 15-40 kB); a bigger one is left out
MAX_PICTURES = 8              # pictures in one results file
MAX_PICTURES_BYTES = 450_000  # all pictures of one results file (base64 makes them 4/3 bigger): well under 1 MB


def load_config():
    with open(os.path.join(HERE, "autograder.json"), encoding="utf-8") as handle:
        return json.load(handle)


def python_files(folder):
    """Every *.py under folder (hidden files and SKIP_DIRS left out), shallowest first."""
    found = []
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d not in SKIP_DIRS)
        found += [os.path.join(root, f) for f in sorted(files) if f.endswith(".py") and not f.startswith(".")
                  and not os.path.islink(os.path.join(root, f))]  # a link could point at the grader's files
    return sorted(found, key=lambda p: (p.count(os.sep), p))


def find_lab_file(folder, config):
    """(path, note) of the file to grade, or (None, why not) naming what was found."""
    expected = [lab["file"] for lab in config["labs"]]
    names = " or ".join(expected)
    if not os.path.isdir(folder):
        return None, f"No submission folder ({folder}): nothing was submitted. Submit {names}."
    files = python_files(folder)
    for path in files:
        if os.path.basename(path) in expected:
            rel = os.path.relpath(path, folder)
            note = f"Graded {rel}." if rel == os.path.basename(path) else f"Graded {rel} (found in a folder)."
            return path, note
    if len(files) == 1:
        rel = os.path.relpath(files[0], folder)
        return files[0], f"Graded {rel}: the expected name is {names}; please submit it under that name."
    if not files:
        others = sorted(os.path.relpath(os.path.join(r, f), folder) for r, _, fs in os.walk(folder) for f in fs)
        seen = f" Found instead: {', '.join(others[:10])}." if others else " The submission is empty."
        return None, f"No Python file was submitted: expected {names}.{seen}"
    listed = ", ".join(os.path.relpath(p, folder) for p in files[:10])
    return None, f"Expected one file named {names}; found {len(files)} Python files and none with that name: {listed}."


def run_as(config):
    """The --child-user to pass, when root: $AUTOGRADER_USER, else config's ("student"); "" = root itself.

    None passes nothing: a grader that is not root runs the student's code as itself, and a root grader
    whose user does not exist leaves the choice to the checker (its default unprivileged user). The checker's
    children need not run this Python themselves (they are forked from a process that imported everything),
    and where they would have to and cannot, the checker says so in one line."""
    name = os.environ.get("AUTOGRADER_USER", config.get("user", "student"))
    if os.geteuid() != 0:
        return None
    if not name:
        return "root"   # asked for: the student's code runs as the grader's own user
    try:
        pwd.getpwnam(name)
    except KeyError:
        print(f"grade_submission: no user {name!r}: the checker runs the student's code as its default user",
              file=sys.stderr)
        return None
    return name


def read_picture(path, folder):
    """The PNG bytes at path when it is a regular file inside folder, a PNG, not too big; else None.
    (The folder is the grader's own; a link or another file is still never read from it.)"""
    try:
        real = os.path.realpath(path)
        if os.path.commonpath([real, os.path.realpath(folder)]) != os.path.realpath(folder):
            return None
        fd = os.open(real, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as handle:
            if not os.path.isfile(real) or os.fstat(handle.fileno()).st_size > MAX_PICTURE_BYTES:
                return None
            data = handle.read(MAX_PICTURE_BYTES + 1)
    except (OSError, ValueError, TypeError):
        return None
    return data if data.startswith(PNG) and len(data) <= MAX_PICTURE_BYTES else None


def attach_pictures(document, folder):
    """Replace each criterion's "pictures" (PNG paths the checker wrote, --pictures) by
    "images": [{"label", "data": base64}] for failed checks, within MAX_PICTURES / MAX_PICTURES_BYTES;
    "images_left_out": how many were not attached because of those caps."""
    budget, count = MAX_PICTURES_BYTES, 0
    for row in document.get("labs") or []:
        for check in row.get("criteria") or []:
            paths = check.pop("pictures", None)
            if check.get("status") not in ("fail", "error") or not isinstance(paths, list):
                continue
            images, left_out = [], 0
            for path in paths:
                data = read_picture(path, folder) if isinstance(path, str) else None
                if data is None:
                    continue
                if count >= MAX_PICTURES or len(data) > budget:
                    left_out += 1
                    continue
                budget -= len(data)
                count += 1
                name = os.path.splitext(os.path.basename(path))[0]
                images.append({"label": name, "data": base64.b64encode(data).decode("ascii")})
            if images:
                check["images"] = images
            if left_out:
                check["images_left_out"] = left_out


def checker_command(copy, config, pictures=None, seconds=None):
    """The checker's command line for the copy; `seconds` (wall clock) caps its --total-timeout."""
    total = config.get("total_timeout", 420) if seconds is None else min(seconds, config.get("total_timeout", 420))
    command = [sys.executable, "-m", "checker", copy, "--json", "--quiet",
               "--jobs", str(config.get("jobs", os.cpu_count() or 1)),
               "--timeout", str(config.get("timeout", 20)),
               "--total-timeout", f"{max(total, 1):.0f}"]
    if config.get("allow_edits"):
        command.append("--allow-edits")
    if pictures:
        command += ["--pictures", pictures]
    return command


def run_checker(path, config):
    """The checker's --json document for path (a dict), or raises RuntimeError saying what went wrong.
    Failed behaviour checks get "images" (base64 PNGs, see attach_pictures) unless config's "pictures" is false;
    when the run with pictures gives no result, the file is graded again without them."""
    deadline = time.monotonic() + config.get("total_timeout", 420) + 30   # the whole grading, retry included
    work = tempfile.mkdtemp(prefix="autograde-")
    try:
        os.chmod(work, 0o755)
        copy = os.path.join(work, os.path.basename(path))  # a private copy: the original is never touched
        shutil.copyfile(path, copy)
        os.chmod(copy, 0o644)
        env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYGAME_HIDE_SUPPORT_PROMPT="1",
                   PYTHONDONTWRITEBYTECODE="1", PYTHONPATH=os.path.join(HERE, "project"), HOME=work)
        user = run_as(config)
        pictures = None
        if config.get("pictures", True):
            try:   # the grader's own folder (mode 700): the student's user cannot plant a link in it, and the
                # checker writes each picture there with no-follow, exclusive opens (checker/reporting/outputs.py)
                pictures = tempfile.mkdtemp(prefix="pictures-", dir=work)
            except OSError as exc:
                print(f"grade_submission: no pictures ({exc})", file=sys.stderr)
                pictures = None
        attempts = [pictures, None] if pictures else [None]
        for attempt in attempts:
            left = deadline - time.monotonic()
            if left < 5:
                raise RuntimeError("the checker ran out of time on this submission")
            command = checker_command(copy, config, attempt, left - 5)
            if user:   # the grader stays root (it alone reads the solutions); only the student's code runs as user
                command += ["--child-user", user]
            proc = subprocess.run(command, cwd=work, env=env, stdin=subprocess.DEVNULL, capture_output=True,
                                  timeout=left)
            try:
                document = json.loads(proc.stdout.decode("utf-8", "replace"))
                document["labs"][0]
            except (ValueError, KeyError, IndexError, TypeError):
                tail = proc.stderr.decode("utf-8", "replace").strip()[-1500:]
                if attempt:  # perhaps the pictures: grade once more without them
                    print(f"grade_submission: no result with --pictures ({tail[-300:]}); again without",
                          file=sys.stderr)
                    continue
                raise RuntimeError(f"the checker stopped without a result (exit status {proc.returncode}). {tail}")
            break
        try:
            attach_pictures(document, pictures or work)
        except Exception:  # pictures are a bonus: never the reason a grade is lost
            traceback.print_exc()
            for row in document.get("labs") or []:
                for check in row.get("criteria") or []:
                    if isinstance(check, dict):
                        for key in ("pictures", "images", "images_left_out"):
                            check.pop(key, None)
        document["ran_as"] = user or ""
        return document
    except subprocess.TimeoutExpired:
        raise RuntimeError("the checker ran out of time on this submission")
    finally:
        shutil.rmtree(work, ignore_errors=True)


def grade(submission_folder, config):
    """(labs entry of the checker's JSON or None, note, max_score) for the submission."""
    path, note = find_lab_file(submission_folder, config)
    max_score = max((lab["max_score"] for lab in config["labs"]), default=0.0)
    if path is None:
        return None, note, max_score
    document = run_checker(path, config)
    row = document["labs"][0]
    known = {lab["id"]: lab for lab in config["labs"]}
    if row.get("lab") and row["lab"] not in known:
        return None, (f"{note} It is the {row.get('title')} lab, which this assignment does not grade "
                      f"(expected {' or '.join(lab['file'] for lab in config['labs'])})."), max_score
    return row, note, row.get("max_score") or max_score


def check_output(check):
    """A check's text for the student: its message and hint; a skipped check says it was not run and why."""
    message = check.get("message") or ""
    if check.get("status") == "skip":
        reason = message[len("skipped: "):] if message.startswith("skipped: ") else "an earlier check must pass first"
        return f"not run: {reason} (it scores 0 until then)"
    parts = [message, ("Hint " + check["hint"]) if check.get("hint") else ""]
    return "\n".join(p for p in parts if p)


def summary(row, note, hidden=()):
    """The one paragraph every student sees. With hidden checks it speaks of the visible ones only, so that it
    never tells whether a hidden check passed; an error in the student's code is named as theirs, with its line."""
    if row is None:
        return note
    criteria = [c for c in row.get("criteria") or [] if isinstance(c, dict)]
    visible = [c for c in criteria if c.get("id") not in hidden]
    if hidden and criteria:
        figures = f"{sum(c['score'] for c in visible):g}/{sum(c['max_score'] for c in visible):g} " \
                  f"on the visible checks"
        every = "passes every visible check"
    else:
        figures, every = f"{row['score']:g}/{row['max_score']:g}", "passes every check"
    errors = [c for c in visible if c.get("status") == "error"]
    if errors:
        state = f"your code stopped with an error in {errors[0]['id']}: {errors[0].get('message') or 'see that check'}"
    elif criteria and all(c.get("status") == "pass" for c in visible):
        state = every
    elif not criteria:
        state = {"pass": every, "fail": "fails some checks"}.get(row.get("status"), "was not graded")
    else:
        state = "fails some checks"
    line = f"{note} {row.get('title') or 'The file'}: {figures}, {state}"
    line += "" if line.endswith(".") else "."
    if row.get("message"):
        line += f" {row['message']}"
    return line


def left_out_note(check):
    left = check.get("images_left_out")
    return (f"{left} more picture(s) not shown: a results file holds at most {MAX_PICTURES} pictures "
            f"and {MAX_PICTURES_BYTES // 1000} kB of them." if left else "")


def gradescope_test(check, hidden):
    test = {"name": f"{check['id']}: {check['name']}", "score": check["score"], "max_score": check["max_score"],
            "status": "passed" if check["status"] == "pass" else "failed", "output": check_output(check),
            "visibility": "hidden" if check["id"] in hidden else "visible"}
    if isinstance(check.get("mistake"), dict):   # the named mistake, for the instructor's exports (not shown)
        test["extra_data"] = {"mistake": check["mistake"]}
    images = check.get("images") or []
    if images and test["status"] == "failed":
        test["output_format"] = "html"
        note = left_out_note(check)
        test["output"] = (f"<pre>{html.escape(test['output'])}</pre>" + "".join(
            f'<p><img alt="{html.escape(image["label"])}" src="data:image/png;base64,{image["data"]}"></p>'
            for image in images) + (f"<p>{html.escape(note)}</p>" if note else ""))
    elif check.get("images_left_out"):
        test["output"] = "\n".join(p for p in (test["output"], left_out_note(check)) if p)
    return test


def prairielearn_images(row, hidden):
    """PrairieLearn's images[]: {"label", "url": data: URI} for each picture of a failed, visible check."""
    return [{"label": f"{c['id']}: {image['label']}", "url": "data:image/png;base64," + image["data"]}
            for c in row["criteria"] if c["id"] not in hidden and c["status"] != "pass"
            for image in c.get("images") or []]


def gradescope_results(row, note, max_score, config):
    hidden = set(config.get("hide", []))
    if row is None or not row.get("criteria"):
        reason = summary(row, note, hidden)
        return {"score": 0.0, "output": reason, "visibility": "visible", "stdout_visibility": "hidden",
                "tests": [{"name": "Submission graded", "score": 0.0, "max_score": max_score, "status": "failed",
                           "output": reason, "visibility": "visible"}]}
    tests = [gradescope_test(c, hidden) for c in row["criteria"]]
    return {"score": row["score"], "output": summary(row, note, hidden), "visibility": "visible",
            "stdout_visibility": "hidden", "tests": tests}


def prairielearn_results(row, note, max_score, config):
    hidden = set(config.get("hide", []))
    if row is None or not row.get("criteria"):
        reason = summary(row, note, hidden)
        return {"gradable": True, "score": 0.0, "message": reason, "output": reason, "images": [],
                "tests": [{"name": "Submission graded", "points": 0.0, "max_points": max_score,
                           "output": reason, "message": reason}]}
    tests = [{"name": f"{c['id']}: {c['name']}", "points": c["score"], "max_points": c["max_score"],
              "message": c["status"], "output": "\n".join(p for p in (check_output(c), left_out_note(c)) if p),
              **({"mistake": c["mistake"]} if isinstance(c.get("mistake"), dict) else {})}
             for c in row["criteria"] if c["id"] not in hidden]
    total = row["max_score"] or 1.0
    return {"gradable": True, "score": round(row["score"] / total, 6), "message": summary(row, note, hidden),
            "output": summary(row, note, hidden), "images": prairielearn_images(row, hidden), "tests": tests}


def fallback(platform, message):
    """A valid results document when everything else failed."""
    if platform == "gradescope":
        return {"score": 0.0, "output": message, "tests": [{"name": "Submission graded", "score": 0.0,
                "max_score": 0.0, "status": "failed", "output": message, "visibility": "visible"}]}
    return {"gradable": True, "score": 0.0, "message": message, "output": message, "images": [], "tests": []}


def write_json(path, document):
    """Write the results file through a new temporary file beside it (created exclusively, never through a link)
    renamed over it: a link at `path` is replaced, not followed."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fd, temp = tempfile.mkstemp(prefix=".results-", suffix=".tmp", dir=os.path.dirname(path))
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            json.dump(document, handle, indent=2)
            handle.write("\n")
        os.chmod(temp, 0o644)
        os.replace(temp, path)
    except BaseException:
        try:
            os.unlink(temp)
        except OSError:
            pass
        raise


def main(argv):
    platform = argv[1] if len(argv) > 1 else "gradescope"
    if platform == "gradescope":
        root = os.environ.get("AUTOGRADER_ROOT", "/autograder")
        submission, results = os.path.join(root, "submission"), os.path.join(root, "results", "results.json")
        build = gradescope_results
    else:
        root = os.environ.get("GRADE_ROOT", "/grade")
        submission, results = os.path.join(root, "student"), os.path.join(root, "results", "results.json")
        build = prairielearn_results
    try:
        config = load_config()
        row, note, max_score = grade(submission, config)
        document = build(row, note, max_score, config)
    except Exception as exc:  # a checker failure must still give the student a result
        traceback.print_exc()
        document = fallback(platform, f"The autograder could not grade this submission ({exc}). "
                                      f"Please tell your instructor.")
    write_json(results, document)
    print(document.get("output") or document.get("message"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
