"""Each package graded by its platform's own procedure, in clean root file systems, as the platform runs it.

    python tests/platform_acceptance.py [--only NAME,...] [--cache DIR] [--keep]

As root. For each platform a clean root file system is built once with debootstrap (kept in --cache,
default /var/cache/lesson11-acceptance), the platform's set-up runs in a layer on top of it, with the
network, and every submission is graded in a fresh overlay of the set-up root with the network cut
(unshare --net), as root, so that the grader itself picks the user the student's code runs as:

  gradescope-22.04, gradescope-24.04   Ubuntu jammy / noble (minbase). The zip is unpacked into
      /autograder/source and setup.sh runs there; per submission the files go to /autograder/submission,
      run_autograder is copied to /autograder/run_autograder and that copy runs from /autograder with a
      clean environment; /autograder/results/results.json is read.
  prairielearn   Debian bookworm with a released CPython at /usr/local (python:3.11-slim is that: this
      machine's CPython is copied in). The package's Dockerfile is followed step by step (ENV, RUN, COPY);
      per submission the files go to /grade/student and the entrypoint /grader/run_prairielearn runs with
      the Dockerfile's environment; /grade/results/results.json is read.
  classroom      Ubuntu noble, a venv standing in for actions/setup-python. The template repository
      (.github/workflows/classroom.yml and .autograder/project) is checked out and the workflow's
      "Install" step runs once; per submission the student's files are added, the "Grade" step runs and
      then every autograding-command-grader step's command with the environment reset to PATH, HOME and
      FORCE_COLOR, as that action does; a step that exits 0 earns its max-score.

Mirrors come from the environment: UBUNTU_MIRROR (default: debootstrap's own for Ubuntu) and
DEBIAN_MIRROR (default: the first URI of this machine's Debian apt sources). Ubuntu's archive key is not
on a Debian machine, so the Ubuntu roots are built with --no-check-gpg unless UBUNTU_KEYRING names one.
The host's DNS and, if PIP_CERT or SSL_CERT_FILE names one, its CA bundle are handed to the set-up steps
only (a network that inspects TLS); grading runs with the network cut. Prints one table, platform x submission: score, seconds, whether it is what the submission deserves, and
the message the student reads. Exit status 0 when every row is as expected, 1 if not, 2 if it cannot run.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLATFORMS = ("gradescope-22.04", "gradescope-24.04", "prairielearn", "classroom")
SUITES = {"gradescope-22.04": "jammy", "gradescope-24.04": "noble", "prairielearn": "bookworm",
          "classroom": "noble"}
PATH = "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"
HOST_PYTHON = os.path.realpath(sys.base_prefix)   # a released CPython built from source, for prairielearn
REPO = "/home/runner/work/lab/lab"                 # where actions/checkout puts the repository


class CannotRun(Exception):
    """A one-line reason the acceptance run cannot start here."""


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


# ------------------------------------------------------------------ the submissions and what each deserves

def answer_reader():
    """The starter with its functions taken from the shipped solutions, wherever a package put them."""
    return read("starters/tumbling_crates_starter.py") + '''

import importlib.util as _util
import os as _os
for _path in ("/autograder/source/project/solutions/tumbling_crates.py",
              "/grader/project/solutions/tumbling_crates.py", ".autograder/project/solutions/tumbling_crates.py"):
    try:
        _spec = _util.spec_from_file_location("_answers", _path)
        _answers = _util.module_from_spec(_spec)
        _spec.loader.exec_module(_answers)
    except Exception as _exc:
        print("could not read", _path, _exc)
        continue
    sat, apply_impulse, resolve = _answers.sat, _answers.apply_impulse, _answers.resolve
    print("read the answers from", _path)
    break
'''


def answer_opener():
    """The solution, with one more line at the top that opens the shipped solutions where a package put them.

    Where the student's code runs as `student` and solutions/ is root's alone (Gradescope, PrairieLearn) the
    open raises PermissionError and the file scores 0 with that error named; on Classroom (the student's own
    repository) the open works and the step rules fail the steps (`open` outside the steps)."""
    return '''for _path in ("/autograder/source/project/solutions/tumbling_crates.py",
              "/grader/project/solutions/tumbling_crates.py", ".autograder/project/solutions/tumbling_crates.py"):
    try:
        _answers = open(_path).read()
    except FileNotFoundError:
        pass
''' + read("solutions/tumbling_crates.py")


def denied(score, top, starter, platform, doc):
    """No more than the starter, and where the grader keeps the answers, the student reads 'Permission denied'."""
    return score <= starter and (platform == "classroom" or "Permission denied" in json.dumps(doc))


def slop_six():
    """Ball on the Ramp with SLOP = 6: the function checks pass, the ball stays 6 px in a crate (a failed scene)."""
    text = read("solutions/ball_on_ramp.py")
    return text.replace("\nSLOP = 0.5 ", "\nSLOP = 6 ", 1)


def submissions():
    """[(name, {path: text}, expectation)]; expectation(score, max, starter score, platform, doc) -> bool."""
    solution, starter = read("solutions/tumbling_crates.py"), read("starters/tumbling_crates_starter.py")
    full = lambda s, m, st, p, d: s == m                                       # noqa: E731
    zero = lambda s, m, st, p, d: s == 0                                       # noqa: E731
    top_only = lambda s, m, st, p, d: s == 0 if p == "classroom" else s == m   # noqa: E731
    return [
        ("solution", {"tumbling_crates.py": solution}, full),
        ("starter", {"tumbling_crates.py": starter}, lambda s, m, st, p, d: 0 < s < m),
        ("in a folder", {"lab/tumbling_crates.py": solution}, top_only),
        ("wrong name", {"my_crates.py": solution}, top_only),
        ("empty", {}, zero),
        ("not Python", {"notes.txt": "my lab is on my laptop\n"}, zero),
        ("two files", {"a.py": "x = 1\n", "b.py": "y = 2\n"}, zero),
        ("crash at import", {"tumbling_crates.py": "raise RuntimeError('boom')\n" + starter}, zero),
        ("endless loop", {"tumbling_crates.py": "while True:\n    pass\n"}, zero),
        ("2 GB of memory", {"tumbling_crates.py": "hog = bytearray(2 * 1024 ** 3)\n" + solution}, zero),
        ("sys.exit", {"tumbling_crates.py": "import sys\nsys.exit(0)\n" + solution}, zero),
        ("another lab", {"bullets.py": read("solutions/bullets.py")}, zero),
        ("reads the answers", {"tumbling_crates.py": answer_reader()}, lambda s, m, st, p, d: s <= st),
        ("opens the answers", {"tumbling_crates.py": answer_opener()}, denied),
    ] + issue35_rows()


GRADED = {}   # name -> score of the rows graded so far on the current platform (the honest files come first)


def issue35_rows():
    """Tumbling Crates' issue-35 entries of tests/corpus_attacks.py, each after its honest file (the same file
    without the attack): an attack scores no more than its honest file did on the same platform; a control
    gets full marks."""
    import corpus_attacks as corpus
    rows = []
    for entry in corpus.BY_LAB["tumbling_crates"]:
        if not entry.mechanism:
            continue
        files = {"tumbling_crates.py": corpus.build(entry), **dict(entry.extra_files)}
        if entry.target is None:
            rows.append((entry.name, files, lambda s, m, st, p, d: s == m))
            continue
        honest = corpus.HONEST[entry.name]
        rows.append((honest.name, {"tumbling_crates.py": corpus.build(honest)}, lambda s, m, st, p, d: True))
        rows.append((entry.name, files, lambda s, m, st, p, d, h=honest.name: s <= GRADED.get(h, -1)))
    return rows


# ------------------------------------------------------------------ root file systems

def run(command, **kwargs):
    """subprocess.run with text output; raises CannotRun with the command's last words if it fails."""
    done = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if done.returncode != 0:
        tail = (done.stderr or done.stdout).strip().splitlines()[-3:]
        raise CannotRun(f"{' '.join(map(str, command))[:120]} failed ({done.returncode}): {' / '.join(tail)}")
    return done


def debian_mirror():
    if os.environ.get("DEBIAN_MIRROR"):
        return os.environ["DEBIAN_MIRROR"]
    for path in ("/etc/apt/sources.list.d/debian.sources", "/etc/apt/sources.list"):
        try:
            text = open(path, encoding="utf-8").read()
        except OSError:
            continue
        found = re.search(r"^URIs:\s*(\S+/debian)\s*$", text, re.M) or re.search(r"^deb\s+(\S+/debian)\s", text, re.M)
        if found:
            return found.group(1)
    raise CannotRun("no Debian mirror: set DEBIAN_MIRROR")


def base_root(cache, suite):
    """cache/suite, a minbase root of the suite, built once with debootstrap."""
    target = os.path.join(cache, suite)
    if os.path.isdir(target):
        return standard_sources(target, suite)
    if suite == "bookworm":
        command = ["debootstrap", "--variant=minbase", suite, target + ".tmp", debian_mirror()]
    else:
        keyring = os.environ.get("UBUNTU_KEYRING")
        command = ["debootstrap", "--variant=minbase", f"--keyring={keyring}" if keyring else "--no-check-gpg",
                   suite, target + ".tmp"]
        command += [os.environ["UBUNTU_MIRROR"]] if os.environ.get("UBUNTU_MIRROR") else \
            ["http://archive.ubuntu.com/ubuntu"]
        command.append("/usr/share/debootstrap/scripts/gutsy")   # every Ubuntu suite's script
    print(f"building {suite} in {target} ...", file=sys.stderr, flush=True)
    shutil.rmtree(target + ".tmp", ignore_errors=True)
    run(command, timeout=1800)
    os.rename(target + ".tmp", target)
    return standard_sources(target, suite)


def standard_sources(target, suite):
    """An Ubuntu root gets the sources of a standard Ubuntu image (main to multiverse, -updates, -security), as
    Gradescope's base images have; debootstrap writes main only."""
    if suite != "bookworm":
        mirror = os.environ.get("UBUNTU_MIRROR", "http://archive.ubuntu.com/ubuntu")
        with open(os.path.join(target, "etc", "apt", "sources.list"), "w", encoding="utf-8") as handle:
            for pocket in ("", "-updates", "-security"):
                handle.write(f"deb {mirror} {suite}{pocket} main restricted universe multiverse\n")
    return target


class Layer:
    """An overlay mount: `lowers` (top first) read-only, changes in `upper`, seen at `merged`; with /dev and
    /proc bound, the host's resolv.conf for set-up. Use as a context manager."""

    def __init__(self, lowers, upper, merged):
        self.lowers, self.upper, self.merged = lowers, upper, merged
        self.mounts = []

    def __enter__(self):
        work = self.upper + ".work"
        for folder in (self.upper, work, self.merged):
            os.makedirs(folder, exist_ok=True)
        run(["mount", "-t", "overlay", "overlay", "-o",
             f"lowerdir={':'.join(self.lowers)},upperdir={self.upper},workdir={work}", self.merged])
        self.mounts.append(self.merged)
        for source, kind in (("/dev", "--bind"), ("proc", "proc")):
            target = os.path.join(self.merged, source.strip("/"))
            os.makedirs(target, exist_ok=True)
            if kind == "--bind":   # /dev with /dev/shm and /dev/pts; rslave: nothing done here reaches the host
                run(["mount", "--rbind", source, target])
                run(["mount", "--make-rslave", target])
            else:
                run(["mount", "-t", "proc", "proc", target])
            self.mounts.append(target)
        return self

    def __exit__(self, *exc):
        for target in reversed(self.mounts):
            subprocess.run(["umount", "-l", target], capture_output=True)
        return False

    def path(self, inside):
        return os.path.join(self.merged, inside.lstrip("/"))

    def shell(self, script, env, network=True, timeout=1800, cwd="/"):
        """Run `script` with bash in the root, environment exactly `env`; network cut unless `network`."""
        command = ["chroot", self.merged, "/usr/bin/env", "-i", *[f"{k}={v}" for k, v in env.items()],
                   "/bin/bash", "-c", f"cd {cwd} && {script}"]
        if not network:
            command = ["unshare", "--net", "--"] + command
        started = time.monotonic()
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        return done, time.monotonic() - started


def resolv(layer, env):
    """The host's DNS for the set-up steps, and the host's CA bundle if the environment names one (PIP_CERT or
    SSL_CERT_FILE: a network that inspects TLS); `env` (the set-up steps' environment) gets PIP_CERT for it."""
    target = layer.path("/etc/resolv.conf")
    if os.path.islink(target):
        os.unlink(target)
    shutil.copyfile("/etc/resolv.conf", target)
    bundle = os.environ.get("PIP_CERT") or os.environ.get("SSL_CERT_FILE")
    if bundle and os.path.isfile(bundle):
        os.makedirs(layer.path("/etc/ssl"), exist_ok=True)
        shutil.copyfile(bundle, layer.path("/etc/ssl/host-ca-bundle.crt"))
        env.update(PIP_CERT="/etc/ssl/host-ca-bundle.crt", SSL_CERT_FILE="/etc/ssl/host-ca-bundle.crt")


# ------------------------------------------------------------------ the platforms

def build_package(platform, out, labs, allow_edits=False):
    kind = platform.split("-")[0]
    target = os.path.join(out, "autograder.zip" if kind == "gradescope" else kind)
    run([sys.executable, "-m", "checker", "package", kind, "--out", target, "--labs", *labs], cwd=ROOT,
        env=dict(os.environ, PYTHONPATH=ROOT))
    if allow_edits:   # the picture case edits a handed-out constant; graded with allow_edits, as the tests do
        folder = target
        if kind == "gradescope":
            folder = target + ".d"
            unzip(target, folder)
        config_path = os.path.join(folder, "autograder.json")
        config = json.load(open(config_path, encoding="utf-8"))
        config["allow_edits"] = True
        json.dump(config, open(config_path, "w", encoding="utf-8"))
        return folder
    return target


def unzip(zip_path, folder):
    """Unpack as Gradescope does, the executable bits kept."""
    with zipfile.ZipFile(zip_path) as archive:
        archive.extractall(folder)
        for info in archive.infolist():
            mode = info.external_attr >> 16
            if mode:
                os.chmod(os.path.join(folder, info.filename), mode & 0o777)


def copy_package(package, target):
    if os.path.isfile(package):
        unzip(package, target)
    else:
        shutil.copytree(package, target, dirs_exist_ok=True)


class Gradescope:
    def __init__(self, name, base, work, package):
        self.name, self.base, self.work, self.package = name, base, work, package
        self.env = {"PATH": PATH, "HOME": "/root", "DEBIAN_FRONTEND": "noninteractive", "LANG": "C.UTF-8"}

    def setup(self):
        with Layer([self.base], self.setup_dir, self.work + "/setup-root") as layer:
            env = dict(self.env)
            resolv(layer, env)
            copy_package(self.package, layer.path("/autograder/source"))
            done, seconds = layer.shell("bash ./setup.sh", env, cwd="/autograder/source")
            if done.returncode != 0:
                raise CannotRun(f"{self.name}: setup.sh failed: {done.stderr.strip().splitlines()[-3:]}")
            python = re.search(r"setup.sh: (Python \S+)", done.stdout)
            return f"setup.sh {seconds:.0f} s, {python.group(1) if python else 'Python ?'}"

    @property
    def setup_dir(self):
        return self.work + "/setup"

    def grade(self, files, index):
        with Layer([self.setup_dir, self.base], f"{self.work}/s{index}", f"{self.work}/s{index}-root") as layer:
            folder = layer.path("/autograder/submission")
            os.makedirs(folder, exist_ok=True)
            write_files(folder, files)
            shutil.copy2(layer.path("/autograder/source/run_autograder"), layer.path("/autograder/run_autograder"))
            done, seconds = layer.shell("./run_autograder", {"PATH": PATH, "HOME": "/root"}, network=False,
                                        cwd="/autograder", timeout=900)
            doc = read_json(layer.path("/autograder/results/results.json"))
            score = doc.get("score", 0.0) if doc else None
            top = sum(t.get("max_score", 0) for t in doc.get("tests", [])) if doc else None
            self.ran_as = ran_as(done.stderr, (doc or {}).get("output", ""))
            return score, top, seconds, (doc or {}).get("output", done.stderr[-200:]), doc


class PrairieLearn(Gradescope):
    def setup(self):
        with Layer([self.base], self.setup_dir, self.work + "/setup-root") as layer:
            resolv(layer, self.env)
            # python:3.11-slim: Debian with the libraries CPython needs, and a CPython built from source in
            # /usr/local (here: this machine's, a released 3.11 built from source)
            done, _ = layer.shell("apt-get update -qq && apt-get install -y -qq ca-certificates netbase tzdata "
                                  "libssl3 libffi8 libsqlite3-0 libbz2-1.0 liblzma5 zlib1g libreadline8 "
                                  "libncursesw6 libuuid1 >/dev/null", self.env)
            if done.returncode:
                raise CannotRun(f"prairielearn: the slim image's libraries: {done.stderr[-300:]}")
            shutil.copytree(HOST_PYTHON, layer.path(HOST_PYTHON), symlinks=True, dirs_exist_ok=True,
                            ignore=shutil.ignore_patterns("__pycache__", "test", "tests", "idlelib", "site-packages"))
            os.makedirs(layer.path(f"{HOST_PYTHON}/lib/python{sys.version_info.major}.{sys.version_info.minor}"
                                   f"/site-packages"), exist_ok=True)
            os.chmod(layer.path("/root"), 0o711)   # the copy sits at this machine's path, under /root: let
            # every user reach it, as every user reaches the image's /usr/local/bin/python
            for name in ("python", "python3", "pip", "pip3"):
                link = layer.path(f"/usr/local/bin/{name}")
                os.makedirs(os.path.dirname(link), exist_ok=True)
                target = f"{HOST_PYTHON}/bin/python3" if name.startswith("python") else None
                if target:
                    os.symlink(target, link)
            done, _ = layer.shell("python -m ensurepip --default-pip >/dev/null && ln -sf "
                                  f"{HOST_PYTHON}/bin/pip3 /usr/local/bin/pip", self.env)
            if done.returncode:
                raise CannotRun(f"prairielearn: ensurepip failed: {done.stderr[-300:]}")
            started, env = time.monotonic(), dict(self.env)
            for instruction, argument in dockerfile(os.path.join(self.package, "Dockerfile")):
                if instruction == "ENV":
                    env.update(dict(pair.split("=", 1) for pair in argument.split()))
                elif instruction == "COPY":
                    source, target = argument.split()
                    shutil.copytree(os.path.join(self.package, source), layer.path(target), dirs_exist_ok=True)
                elif instruction == "RUN":
                    done, _ = layer.shell(argument, env)
                    if done.returncode:
                        log = os.path.join(self.work, "dockerfile-run.log")
                        with open(log, "w", encoding="utf-8") as handle:
                            handle.write(done.stdout + "\n" + done.stderr)
                        errors = [line for line in (done.stdout + done.stderr).splitlines() if "rror" in line]
                        raise CannotRun(f"prairielearn: RUN {argument[:60]} failed: {' / '.join(errors[:4])} "
                                        f"(the whole output: {log}, kept with --keep)")
            self.image_env = env
            version = layer.shell("python --version", env)[0].stdout.strip()
            return f"Dockerfile {time.monotonic() - started:.0f} s, {version}"

    def grade(self, files, index):
        with Layer([self.setup_dir, self.base], f"{self.work}/s{index}", f"{self.work}/s{index}-root") as layer:
            folder = layer.path("/grade/student")
            os.makedirs(folder, exist_ok=True)
            write_files(folder, files)
            done, seconds = layer.shell("/grader/run_prairielearn", dict(self.image_env), network=False,
                                        cwd="/grade", timeout=900)
            doc = read_json(layer.path("/grade/results/results.json"))
            top = sum(t.get("max_points", 0) for t in doc.get("tests", [])) if doc else None
            self.ran_as = ran_as(done.stderr, (doc or {}).get("message", ""))
            score = None if doc is None else round(doc.get("score", 0.0) * (self.max_score or 0), 3)
            return score, top, seconds, (doc or {}).get("message", done.stderr[-200:]), doc


class Classroom(Gradescope):
    def setup(self):
        with Layer([self.base], self.setup_dir, self.work + "/setup-root") as layer:
            resolv(layer, self.env)
            repo = layer.path(REPO)
            copy_package(self.package, repo)
            done, seconds = layer.shell("apt-get update -qq && apt-get install -y -qq python3 python3-venv "
                                        ">/dev/null && python3 -m venv /opt/python", self.env)
            if done.returncode:
                raise CannotRun(f"classroom: python3-venv failed: {done.stderr[-300:]}")
            self.steps = workflow(os.path.join(self.package, ".github", "workflows", "classroom.yml"))
            self.job_env = dict(self.env, PATH="/opt/python/bin:" + PATH, **self.steps["env"])
            for name, script, env in self.steps["runs"]:
                if name.startswith("Install"):
                    done, more = layer.shell(script, dict(self.job_env, **env), cwd=REPO)
                    if done.returncode:
                        raise CannotRun(f"classroom: {name} failed: {done.stderr[-300:]}")
                    seconds += more
            return f"install {seconds:.0f} s, " + layer.shell("python --version", self.job_env)[0].stdout.strip()

    def grade(self, files, index):
        with Layer([self.setup_dir, self.base], f"{self.work}/s{index}", f"{self.work}/s{index}-root") as layer:
            write_files(layer.path(REPO), files)
            total = score = 0.0
            started = time.monotonic()
            for name, script, env in self.steps["runs"]:
                if name.startswith("Grade"):
                    layer.shell(script, dict(self.job_env, **env), network=False, cwd=REPO, timeout=900)
            messages = []
            for name, command, points in self.steps["graders"]:
                reset = {"PATH": self.job_env["PATH"], "HOME": "/root", "FORCE_COLOR": "true"}
                done, _ = layer.shell(command, reset, network=False, cwd=REPO, timeout=60)
                total += points
                score += points if done.returncode == 0 else 0
                if done.returncode and not messages:
                    said = [line for line in done.stdout.strip().splitlines() if line.strip()]
                    messages.append(f"{name}: " + " ".join(said[-2:] if len(said) > 1 else said))
            self.ran_as = "runner"   # the Actions runner's user: the student's own repository
            return score, total, time.monotonic() - started, "; ".join(messages) or "every step passed", None


def ran_as(stderr, message):
    """Who ran the student's code: grade_submission says on stderr when it falls back to root; "-" if nothing
    was run (no file to grade)."""
    if "runs as root" in stderr:
        return "root"
    return "student" if message.startswith("Graded") else "-"


def dockerfile(path):
    """[(INSTRUCTION, argument)] of a Dockerfile, continuation lines joined, comments left out."""
    text = open(path, encoding="utf-8").read().replace("\\\n", " ")
    return [tuple(line.split(None, 1)) for line in text.splitlines()
            if line.strip() and not line.lstrip().startswith("#")]


def workflow(path):
    """The classroom workflow's job env, its run steps [(name, script, env)] and its command-grader steps
    [(name, command, max-score)] (the file is ours, written by checker/platforms/package.py: a line parser is enough)."""
    lines = open(path, encoding="utf-8").read().splitlines()
    found = {"env": {}, "runs": [], "graders": []}
    step = None
    for line in lines + ["      - end"]:
        if line.startswith("      - "):
            if step and step.get("run"):
                found["runs"].append((step.get("name", ""), step["run"], step.get("env", {})))
            if step and step.get("command"):
                found["graders"].append((step.get("test-name", step.get("name", "")), step["command"],
                                         float(step.get("max-score", 0))))
            step = {}
            line = line.replace("- ", "  ", 1)
        key_value = re.match(r"^\s+([\w-]+): (.*)$", line)
        if not key_value:
            continue
        key, value = key_value.group(1), key_value.group(2).strip()
        if len(value) > 1 and value[0] == value[-1] == '"':
            value = value[1:-1]
        if step is None:
            if re.match(r"^      [A-Z_]+: ", line):
                found["env"][key] = value
        elif re.match(r"^          [A-Z_]+: ", line):
            step.setdefault("env", {})[key] = value
        else:
            step[key] = value
    return found


def write_files(folder, files):
    for rel, text in files.items():
        target = os.path.join(folder, rel)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "w", encoding="utf-8") as handle:
            handle.write(text)


def read_json(path):
    try:
        with open(path, encoding="utf-8") as handle:
            return json.load(handle)
    except (OSError, ValueError):
        return None


# ------------------------------------------------------------------ the run

def preflight():
    if os.geteuid() != 0:
        raise CannotRun("run as root: it builds root file systems and mounts overlays")
    for tool in ("debootstrap", "chroot", "unshare", "mount"):
        if not shutil.which(tool):
            raise CannotRun(f"{tool} is not installed (apt-get install debootstrap util-linux)")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python tests/platform_acceptance.py", description=__doc__.splitlines()[0])
    parser.add_argument("--only", default=",".join(PLATFORMS), help="comma-separated platforms")
    parser.add_argument("--cache", default="/var/cache/lesson11-acceptance", help="where the base roots are kept")
    parser.add_argument("--keep", action="store_true", help="keep the work folder (printed)")
    args = parser.parse_args(argv)
    rows, problems = [], []
    try:
        preflight()
        chosen = [p.strip() for p in args.only.split(",") if p.strip()]
        unknown = [p for p in chosen if p not in PLATFORMS]
        if unknown:
            raise CannotRun(f"--only: unknown platform {', '.join(unknown)} (known: {', '.join(PLATFORMS)})")
    except CannotRun as exc:
        print(f"platform_acceptance: {exc}", file=sys.stderr)
        return 2
    work_all = tempfile.mkdtemp(prefix="l11-acceptance-", dir="/var/tmp")
    sys.path.insert(0, ROOT)
    from checker import labs
    max_score = {lab.id: lab.checks.max_score for lab in labs.LABS}
    notes = {}
    try:
        for platform in chosen:
            kind = platform.split("-")[0]
            try:
                base = base_root(args.cache, SUITES[platform])
                out = tempfile.mkdtemp(prefix="package-", dir=work_all)
                crates = build_package(platform, out, ["tumbling_crates"])
                cases = [(name, files, expect, crates) for name, files, expect in submissions()]
                if kind != "classroom":
                    ramp = build_package(platform, tempfile.mkdtemp(prefix="ramp-", dir=work_all),
                                         ["ball_on_ramp"], allow_edits=True)
                    cases.append(("failed scene, picture", {"ball_on_ramp.py": slop_six()}, pictured, ramp))
                cls = {"gradescope": Gradescope, "prairielearn": PrairieLearn, "classroom": Classroom}[kind]
                graders = {}
                starter_score = None
                GRADED.clear()
                for index, (name, files, expect, package) in enumerate(cases):
                    if package not in graders:
                        grader = cls(platform, base, tempfile.mkdtemp(prefix=f"{platform}-", dir=work_all),
                                     package)
                        grader.max_score = max_score["ball_on_ramp" if "ramp" in package else "tumbling_crates"]
                        notes.setdefault(platform, []).append(grader.setup())
                        graders[package] = grader
                    score, top, seconds, message, doc = graders[package].grade(files, index)
                    if name == "starter":
                        starter_score = score
                    GRADED[name] = score
                    ok = score is not None and expect(score, top, starter_score, platform, doc)
                    rows.append((platform, name, score, top, seconds, ok, message, graders[package].ran_as))
                    print(f"  {platform:17} {name:22} {score}/{top} {seconds:5.1f} s {'ok' if ok else 'NOT AS EXPECTED'}",
                          file=sys.stderr, flush=True)
            except (CannotRun, subprocess.TimeoutExpired) as exc:
                problems.append(f"{platform}: {exc}")
                print(f"  {platform}: {exc}", file=sys.stderr, flush=True)
    finally:
        if args.keep:
            print(f"work folder kept: {work_all}", file=sys.stderr)
        else:
            subprocess.run(["umount", "-R", "-l", work_all], capture_output=True)
            shutil.rmtree(work_all, ignore_errors=True)
    print(table(rows, notes, problems))
    return 0 if rows and all(row[5] for row in rows) and not problems else 1


def pictured(score, top, starter, platform, doc):
    """The Ball on the Ramp file that fails one scene: that scene's points lost and its picture attached."""
    if doc is None or score != top - 2.0:
        return False
    if platform.startswith("gradescope"):
        return any("<img" in t.get("output", "") for t in doc.get("tests", []) if t.get("status") == "failed")
    return bool(doc.get("images"))


def table(rows, notes, problems):
    lines = ["| platform | submission | score | seconds | code ran as | as it deserves | what the student reads |",
             "|---|---|---:|---:|---|---|---|"]
    for platform, name, score, top, seconds, ok, message, ran_as in rows:
        text = " ".join(str(message).split())
        text = (text[:140] + "…") if len(text) > 140 else text
        shown = "no result" if score is None else f"{score:g}/{top:g}"
        lines.append(f"| {platform} | {name} | {shown} | {seconds:.1f} | {ran_as} | {'yes' if ok else '**no**'} | "
                     f"{text.replace('|', '/')} |")
    for platform, setups in notes.items():
        lines.append(f"\n{platform}: " + "; ".join(setups))
    lines += [f"\nCOULD NOT RUN {problem}" for problem in problems]
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main())
