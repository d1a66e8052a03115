"""The rules a lab keeps, one small function each: `python -m checker lint-lab ID` runs them (lint_lab.py).

A rule's docstring is the rule as checker/README.md ("Writing a lab") states it, in the same order (a test
compares them). A rule returns None when the lab keeps it, else broken(what is wrong, how to fix it[, file]).
A rule whose `needs` broke is not run (its line would only repeat the first). STATED holds the rules that
need a lab run or a checker run to decide: lint-lab lists them (--rules) and leaves them to the tests.
"""
import ast
import importlib
import importlib.util
import inspect
import os
import re
import sys
import textwrap
from dataclasses import dataclass
from functools import cached_property

from checker import labs
from checker.judging.checks import Hint, Registry
from checker.project import PROJECT_ROOT
from checker.reading import handout, source

LAB_FILES = ("__init__.py", "checks.py", "probes.py", "scenes.py")
OPTIONAL_FILES = ("show.py",)   # what --show and --pictures draw for its checks (Lab.replay)
SHARED_CHECKS = ("loads", "handout_unchanged", "runtime_lines")
RUNS_CHECK = "runs"   # the check every lab has that runs its scenes to the end (a framework id, not a lab's)
HINT_LIMIT = 250     # characters of a hint as the student reads it ("[step N: title] text")
WINDOW = 22          # characters (spaces removed) of a solution's step line that a hint may not repeat
SHORT_LINE = 14      # a whole step line this long or longer may not be repeated either ("return None" may)
PLACEHOLDER = re.compile(r"  # until you write step (\d+), .*: replace this placeholder$")
REFERENCE_NAME = re.compile(r"^(reference_\w+|analytic_\w+|_\w+_reference|_k_forms|_inertia_forms|distinct_directions"
                            r"|_tied_normals|first_hit)$")   # probe helpers named like a reference: @reference
HEADER_WORDS = ("replace that line with your code", "wasted")   # the starter's docstring says both


@dataclass
class Broken:
    """One rule broken: the file to edit, what is wrong there, how to fix it."""
    what: str
    fix: str
    file: str = None


def broken(what, fix, file=None):
    return Broken(what, fix, file)


@dataclass
class Rule:
    function: object
    file: str            # the file the rule is about, with {id}
    needs: tuple = ()    # rules that must hold for this one to be checked
    tests: str = ""      # the tests (in tests/) that enforce it too

    @property
    def id(self):
        return self.function.__name__

    @property
    def text(self):
        """The rule, as the guide states it (the docstring's first paragraph on one line)."""
        return " ".join(inspect.cleandoc(self.function.__doc__).split("\n\n")[0].split())


RULES = []


def rule(file, needs=(), tests=""):
    """Register the function as the next rule; `file` names what it is about ({id}: the lab's id), `tests` the
    tests that enforce it too."""
    def register(function):
        RULES.append(Rule(function, file, tuple(needs), tests))
        return function
    return register


@dataclass(frozen=True)
class Stated:
    """A rule lint-lab states but leaves to the tests (it needs the lab, or the checker, run)."""
    text: str
    test: str


STATED = (
    Stated("The solution passes every function check, whatever inputs the probes draw (40 seeds).",
           "tests/test_probe_tape.py"),
    Stated("The solution scores full marks, its scenes included (`python -m checker solutions/` exits 0).",
           "tests/test_checker.py"),
    Stated("At least 3 distinct `@reference` helpers run in the grader when the solution is judged, and none in the "
           "child.", "tests/test_probe_references.py"),
    Stated("The step rules flag no wrong corpus entry either (an honest mistake is graded, not flagged).",
           "tests/test_step_rules.py"),
    Stated("The checker gives every corpus entry its verdict: correct ones pass, each wrong one fails its check "
           "naming its step and mistake, in a message of two short lines.", "tests/test_corpus_labs.py"),
)


@dataclass
class Subject:
    """The lab a rule reads: its Lab (starter, solution and tests/ under lab.root) and its modules' folder."""
    lab: labs.Lab
    folder: str = None   # checker/labs/<id> unless a test gives a copy

    def __post_init__(self):
        self.folder = self.folder or os.path.join(labs.HERE, self.lab.id)

    @property
    def id(self):
        return self.lab.id

    def path(self, *parts):
        return os.path.join(self.lab.root, *parts)

    @property
    def module(self):
        return self.lab.module

    @property
    def probes(self):
        return importlib.import_module(self.lab.probes)

    @property
    def scenes(self):
        return self.lab.scenes

    @cached_property
    def solution(self):
        return source.read(self.lab.solution)

    @cached_property
    def starter(self):
        return source.read(self.lab.starter)

    @cached_property
    def regions(self):
        """{step: (start, end, indent)} of the solution's step regions."""
        return handout.step_regions(source.lines(self.solution))

    @cached_property
    def corpus(self):
        """tests/corpus_<id>.py, imported with tests/ on the path as pytest has it (the project's under its own
        name, another root's under a name of its own, so it never stands in for the project's); sys.path is
        left as it was."""
        folder = self.path("tests")
        name = f"corpus_{self.id}"
        path = os.path.join(folder, f"{name}.py")
        kept = list(sys.path)
        sys.path.insert(0, folder)
        try:
            if os.path.abspath(folder) == os.path.join(PROJECT_ROOT, "tests"):
                return importlib.import_module(name)
            spec = importlib.util.spec_from_file_location(f"_lint_{name}_{abs(hash(path))}", path)
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            return module
        finally:
            sys.path[:] = kept


def relative(path):
    """`path` as a reader finds it: relative to the project when inside it."""
    inside = os.path.abspath(path).startswith(PROJECT_ROOT + os.sep)
    return os.path.relpath(path, PROJECT_ROOT) if inside else path


def region_lines(text):
    """{step: [the lines strictly inside the step's region]} of a file's text."""
    lines = source.lines(text)
    return {step: lines[start + 1:end] for step, (start, end, _) in handout.step_regions(lines).items()}


def code_lines(lines):
    """The lines that are neither blank nor comments, stripped, a trailing comment removed."""
    return [text for text in (line.split("#", 1)[0].strip() for line in lines) if text]


def squeeze(text):
    return re.sub(r"\s+", "", text)


def step_code(text):
    """The solution's step code lines (comments and blank lines left out), spaces removed."""
    return [squeeze(line.split("  #")[0]) for lines in region_lines(text).values() for line in lines
            if line.strip() and not line.strip().startswith("#")]


def handed_out(code, hint):
    """The part of a solution step line (`code`, from step_code) that the hint's text repeats, or None."""
    text = squeeze(hint)
    for line in code:
        if len(line) < WINDOW:
            if len(line) >= SHORT_LINE and line in text:
                return line
            continue
        for start in range(len(line) - WINDOW + 1):
            if line[start:start + WINDOW] in text:
                return line[start:start + WINDOW]
    return None


def unused_parameters(func):
    """The parameters of `func` its body never reads (by name, anywhere in it, nested functions included)."""
    node = ast.parse(textwrap.dedent(inspect.getsource(func))).body[0]
    arguments = node.args
    names = [a.arg for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)]
    names += [a.arg for a in (arguments.vararg, arguments.kwarg) if a is not None]
    read = {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
    return [name for name in names if name not in read]


def lesson_headings(lab_id, root=PROJECT_ROOT):
    """The headings (without their #s) of lesson11/README.md and of the lab's page lesson11/labs/<id>.md."""
    headings = set()
    for path in (os.path.join(root, "lesson11", "README.md"), os.path.join(root, "lesson11", "labs", f"{lab_id}.md")):
        if os.path.exists(path):
            with open(path, encoding="utf-8") as handle:
                headings |= {line.lstrip("#").strip() for line in handle if line.startswith("#")}
    return headings


def _listing(names):
    """The names, comma-separated; "none" for none."""
    return ", ".join(str(name) for name in names) or "none"


# ---------------------------------------------------------------- the lab's folder

@rule("checker/labs/{id}/", tests="test_lab_convention.py")
def lab_files(s):
    """`checker/labs/<id>/` holds `__init__.py`, `checks.py`, `probes.py` and `scenes.py`, optionally `show.py`
    (what `--show` and `--pictures` draw), and no other `.py` file."""
    have = {name for name in os.listdir(s.folder) if name.endswith(".py")} if os.path.isdir(s.folder) else set()
    missing, extra = sorted(set(LAB_FILES) - have), sorted(have - set(LAB_FILES + OPTIONAL_FILES))
    if missing:
        return broken(f"{_listing(missing)} missing", "add it (new-lab writes all four)")
    if extra:
        return broken(f"{_listing(extra)} is not a lab file", "move what it holds into checks.py, probes.py or "
                      "scenes.py (show.py for drawings), or into checker/judging/ if labs share it")


@rule("solutions/{id}.py", tests="test_lab_convention.py")
def solution_and_starter(s):
    """The solution is `solutions/<id>.py` and the starter `starters/<id>_starter.py`."""
    for path, fix in ((s.lab.solution, "write the annotated solution there"),
                      (s.lab.starter, "run `python -m checker assign` to write it from the solution")):
        if not os.path.isfile(path):
            return broken("no such file", fix, relative(path))


@rule("checker/labs/{id}/", needs=("lab_files",), tests="test_lab_convention.py")
def no_own_paths(s):
    """No lab module spells a path: none assigns `ROOT`, `STARTER` or `SOLUTION`, only `probes.py` assigns
    `PROBES`, and none reads `__file__` (`checker.labs.Lab` finds every file from the id)."""
    for name in LAB_FILES + OPTIONAL_FILES:
        path = os.path.join(s.folder, name)
        if not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
        assigned = {target.id for node in ast.walk(ast.parse(text)) if isinstance(node, ast.Assign)
                    for target in node.targets if isinstance(target, ast.Name)}
        spelled = sorted(assigned & {"ROOT", "STARTER", "SOLUTION"}) + (
            ["PROBES"] if "PROBES" in assigned and name != "probes.py" else [])
        if spelled or "__file__" in text:
            what = f"assigns {_listing(spelled)}" if spelled else "reads __file__"
            return broken(what, "use checker.labs.Lab (lab.solution, lab.starter, lab.probes) instead",
                          relative(path))


# ---------------------------------------------------------------- checks.py

@rule("checker/labs/{id}/checks.py", needs=("lab_files",), tests="test_message_length.py, test_step_rules.py")
def checks_names(s):
    """`checks.py` defines `TITLE` (the lab's name), `CHECKS` (a `Registry`), `HINTS` {key: `Hint`} with "crash",
    "handout" and "runtime", `STEP_LIBRARY` and `STEP_ADVICE`."""
    module = s.module
    wanted = {"TITLE": str, "CHECKS": Registry, "HINTS": dict, "STEP_LIBRARY": dict, "STEP_ADVICE": dict}
    wrong = [name for name, kind in wanted.items() if not isinstance(getattr(module, name, None), kind)]
    if wrong or not module.TITLE.strip():
        return broken(f"{_listing(wrong or ['TITLE'])} missing or of the wrong kind",
                      "define them as new-lab's template does")
    bad = sorted(key for key, hint in module.HINTS.items() if not isinstance(hint, Hint))
    missing = [key for key in ("crash", "handout", "runtime") if key not in module.HINTS]
    if bad or missing:
        return broken(f"HINTS {'lacks ' + _listing(missing) if missing else 'holds non-Hints: ' + _listing(bad)}",
                      "give each a checks.Hint (lab_checks.handout_hint, lab_checks.RUNTIME_HINT for two)")


@rule("checker/labs/{id}/checks.py", needs=("checks_names", "probes_names"), tests="test_lab_convention.py")
def shared_checks_first(s):
    """The first three checks are `loads`, `handout_unchanged` and `runtime_lines`, registered by
    `lab_checks.register_common` with the names `REQUIRED` lists, and `checks.py` does not define them itself."""
    first = s.module.CHECKS.checks[:3]
    if tuple(c.id for c in first) != SHARED_CHECKS or [c.max_score for c in first] != [1.0] * 3 \
            or [c.after for c in first] != [(), ("loads",), ("loads",)]:
        return broken(f"the first checks are {_listing(c.id for c in first)}",
                      "call lab_checks.register_common(CHECKS, HINTS, REQUIRED) before any check")
    with open(os.path.join(s.folder, "checks.py"), encoding="utf-8") as handle:
        defined = {node.name for node in ast.walk(ast.parse(handle.read())) if isinstance(node, ast.FunctionDef)}
    if defined & set(SHARED_CHECKS):
        return broken(f"defines {_listing(sorted(defined & set(SHARED_CHECKS)))} itself",
                      "remove it: lab_checks.register_common registers the shared checks")
    listed = first[0].description.split(" defines ", 1)[-1].rstrip(".").replace(" and ", ", ").split(", ")
    required = list(getattr(s.probes, "REQUIRED", ()))
    if sorted(listed) != sorted(required):
        return broken(f"loads lists {_listing(listed)}, probes.py's REQUIRED {_listing(required)}",
                      "pass register_common the names REQUIRED holds")


@rule("checker/labs/{id}/checks.py", needs=("checks_names", "solution_and_starter"),
      tests="test_step_rules.py (STEP_LIBRARY; STEP_ADVICE: lint-lab only)")
def step_rows(s):
    """`STEP_LIBRARY` and `STEP_ADVICE` have one row for each step region of the solution, and no other."""
    steps = set(s.regions)
    for name in ("STEP_LIBRARY", "STEP_ADVICE"):
        rows = set(getattr(s.module, name))
        if rows != steps:
            return broken(f"{name} has rows for steps {_listing(sorted(rows))}, the solution's steps are "
                          f"{_listing(sorted(steps))}", "give every step its row (the library functions the step "
                          "must not call; the advice that ends a step-rule message)")


@rule("checker/labs/{id}/checks.py", needs=("checks_names",), tests="test_grader_faults.py")
def runs_check(s):
    """A check with id `runs` reads the scenes (`needs_scenarios=True`): `main()` runs them to the end."""
    runs = [c for c in s.module.CHECKS.checks if c.id == RUNS_CHECK]
    if not runs or not runs[0].needs_scenarios:
        return broken("no check `runs` reading the scenes" if not runs else "`runs` does not read the scenes",
                      "register @CHECKS.check(after=[...], needs_scenarios=True) def runs(sub)")


@rule("checker/labs/{id}/checks.py", needs=("checks_names",), tests="test_checker_units.py")
def checks_read_what_they_take(s):
    """Every check reads each parameter it takes; a check that only has to pass first goes in `after=[...]`."""
    unused = {c.id: unused_parameters(c.func) for c in s.module.CHECKS.checks}
    unused = {cid: names for cid, names in unused.items() if names}
    if unused:
        cid, names = next(iter(unused.items()))
        return broken(f"check {cid} never reads {_listing(names)}", "drop the parameter; put the check it "
                      "names in after=[...] instead of depends=[...]")


@rule("checker/labs/{id}/checks.py", needs=("checks_names", "scenarios"), tests="test_checker_units.py")
def scene_seconds(s):
    """`SCENE_SECONDS` gives each scene of `SCENARIOS`, and only those, the CPU seconds the solution's run takes
    (> 0)."""
    seconds = getattr(s.module, "SCENE_SECONDS", None)
    scenes = set(s.scenes.SCENARIOS)
    if not isinstance(seconds, dict) or set(seconds) != scenes:
        have = _listing(sorted(seconds)) if isinstance(seconds, dict) and seconds else "nothing"
        return broken(f"SCENE_SECONDS names {have}, the scenes are {_listing(sorted(scenes))}",
                      "measure the solution's run of each scene and give it its seconds")
    bad = sorted(name for name, value in seconds.items() if not isinstance(value, (int, float)) or not value > 0)
    if bad:
        return broken(f"SCENE_SECONDS of {_listing(bad)} is not a number > 0", "give the measured CPU seconds")


@rule("checker/labs/{id}/checks.py", needs=("checks_names", "scenarios"), tests="test_checker_pictures.py")
def picture_scenes(s):
    """`PICTURE_SCENES` (optional, for `--pictures`) maps check ids of `CHECKS` to scenes of `SCENARIOS`."""
    pictures = getattr(s.module, "PICTURE_SCENES", {})
    ids = {c.id for c in s.module.CHECKS.checks}
    for check_id, scenes in pictures.items():
        if check_id not in ids or not set(scenes) <= set(s.scenes.SCENARIOS):
            what = f"names no check {check_id}" if check_id not in ids else \
                f"gives {check_id} scenes {_listing(sorted(set(scenes) - set(s.scenes.SCENARIOS)))} SCENARIOS lacks"
            return broken(f"PICTURE_SCENES {what}", "name a check id and the scenes it reads")


@rule("checker/labs/{id}/checks.py", needs=("checks_names",), tests="test_message_length.py")
def short_hints(s):
    """Every hint, as the student reads it ("[step N: title] text"), is at most 250 characters."""
    long = {key: len(hint.render()) for key, hint in s.module.HINTS.items() if len(hint.render()) > HINT_LIMIT}
    if long:
        key, length = next(iter(long.items()))
        return broken(f"HINTS[{key!r}] is {length} characters as shown", f"cut it to {HINT_LIMIT}: the step, the "
                      "lesson's section and the one idea")


@rule("checker/labs/{id}/checks.py", needs=("checks_names", "solution_and_starter"), tests="test_hints_coach.py")
def hints_hand_out_no_code(s):
    """No hint quotes the solution's step code: no run of 22 characters of a step line (spaces ignored), nor a
    whole step line of 14 or more."""
    code = step_code(s.solution)
    for key, hint in s.module.HINTS.items():
        part = handed_out(code, f"{hint.title} {hint.text}")
        if part:
            return broken(f"HINTS[{key!r}] repeats the solution's `{part}`",
                          "say it in words and symbols, as the lesson's Hint section does")


@rule("checker/labs/{id}/checks.py", needs=("checks_names",), tests="test_symptoms.py")
def hint_symptoms(s):
    """A hint names only symptoms its lab's rows of `lesson11/symptoms.py` show at the hint's step."""
    from lesson11 import symptoms
    rows = symptoms.rows(s.id)
    for key, hint in s.module.HINTS.items():
        at_step = [row for row in rows if row.step == hint.step] or rows
        named = symptoms.kinds_named(f"{hint.title} {hint.text}")
        shown = set().union(*(symptoms.kinds_named(row.shows) for row in at_step))
        if named - shown:
            return broken(f"HINTS[{key!r}] names the symptom {_listing(sorted(named - shown))}, which the lab's "
                          "table does not show at its step", "measure it and add the row to lesson11/symptoms.py, "
                          "or leave the symptom out")


# ---------------------------------------------------------------- scenes.py and probes.py

@rule("checker/labs/{id}/scenes.py", needs=("lab_files",), tests="test_lab_convention.py")
def scenarios(s):
    """`scenes.py`'s `SCENARIOS` maps each scene's name to a function returning its settings (a dict), at least
    one."""
    table = getattr(s.scenes, "SCENARIOS", None)
    if not isinstance(table, dict) or not table:
        return broken("no SCENARIOS, or an empty one", "add {name: function returning the scene's settings}")
    bad = sorted(name for name, build in table.items() if not callable(build) or not isinstance(build(), dict))
    if bad:
        return broken(f"SCENARIOS[{bad[0]!r}] gives no settings dict", "make it a function returning a dict")


@rule("checker/labs/{id}/probes.py", needs=("lab_files",), tests="test_lab_convention.py")
def probes_names(s):
    """`probes.py` defines `REQUIRED` (the names the file must define, `main` among them) and `PROBES` {probe
    name: (the function it calls, one of `REQUIRED`, the probe function)}."""
    required, table = getattr(s.probes, "REQUIRED", None), getattr(s.probes, "PROBES", None)
    if not isinstance(required, tuple) or "main" not in required or not isinstance(table, dict) or not table:
        return broken("REQUIRED (with main) or PROBES missing", "define both, as new-lab's template does")
    bad = sorted(name for name, entry in table.items()
                 if not (isinstance(entry, tuple) and len(entry) == 2 and entry[0] in required and callable(entry[1])))
    if bad:
        return broken(f"PROBES[{bad[0]!r}] is not (a function REQUIRED names, a probe)",
                      "give each probe the name of the function it calls and the probe function")


def _probed(s):
    return {function for function, _ in s.probes.PROBES.values()}


@rule("checker/labs/{id}/probes.py", needs=("probes_names",), tests="lint-lab only")
def pure(s):
    """`PURE` (optional) names only probed functions: each must leave its arguments as it got them."""
    extra = sorted(set(getattr(s.probes, "PURE", ())) - _probed(s))
    if extra:
        return broken(f"PURE names {_listing(extra)}, which no probe calls", "list only functions PROBES calls")


@rule("checker/labs/{id}/probes.py", needs=("probes_names", "solution_and_starter"), tests="lint-lab only")
def splices(s):
    """`SPLICES` (optional) is `((function, (step, ...)), ...)`: a probed function and steps of the solution
    inside it, which the probe splices into the student's function to grade its other steps on their own."""
    tree = ast.parse(s.solution)
    spans = {node.name: (node.lineno, node.end_lineno) for node in ast.walk(tree) if isinstance(node, ast.FunctionDef)}
    for entry in getattr(s.probes, "SPLICES", ()):
        if not (isinstance(entry, tuple) and len(entry) == 2 and isinstance(entry[1], tuple)):
            return broken(f"SPLICES holds {entry!r}", "write each as (\"function\", (step, ...))")
        function, steps = entry
        if function not in _probed(s) or function not in spans:
            return broken(f"SPLICES names {function}, not a probed function of the solution",
                          "name a function PROBES calls")
        first, last = spans[function]
        outside = [step for step in steps if step not in s.regions or not first <= s.regions[step][0] + 1 <= last]
        if outside:
            return broken(f"SPLICES gives {function} step {outside[0]}, not a step inside it in the solution",
                          f"name steps whose markers are inside def {function}")


@rule("checker/labs/{id}/probes.py", needs=("probes_names",), tests="test_probe_references.py")
def reference_names(s):
    """Every probe helper named like a reference (`reference_*`, `analytic_*`, `_*_reference` ...) is marked
    `@reference`, so it runs in the grader only; a lab has at least one."""
    probes = s.probes
    named = [name for name, value in vars(probes).items()
             if inspect.isfunction(value) and REFERENCE_NAME.match(name) and value.__module__ in (
                 probes.__name__, "checker.judging.probe_kit", "checker.judging.tape")]
    unmarked = [name for name in named if not getattr(getattr(probes, name), "__reference__", False)]
    if not named:
        return broken("no reference helper (reference_*, analytic_* ...)", "compute the lesson's answers in a "
                      "helper named reference_<what>, marked @reference (checker/judging/probe_kit.py)")
    if unmarked:
        return broken(f"{_listing(unmarked)} not marked @reference", "decorate it with @reference")



MUTATORS = ("append", "extend", "insert", "update", "setdefault", "pop", "popitem", "clear", "add", "remove",
            "discard", "__setitem__")


def module_state_writes(text):
    """(line, name) of each place a function of `text` writes a module-level name: `global`, an item or attribute
    set on it, or a mutating method called on it; a name bound to `threading.local()` is each thread's own."""
    tree = ast.parse(text)
    names = {target.id for node in tree.body if isinstance(node, (ast.Assign, ast.AnnAssign))
             for target in (node.targets if isinstance(node, ast.Assign) else [node.target])
             if isinstance(target, ast.Name) and not (isinstance(node.value, ast.Call)
                                                        and ast.unparse(node.value.func).endswith("threading.local"))}
    writes = []
    for function in (node for node in ast.walk(tree) if isinstance(node, (ast.FunctionDef, ast.Lambda))):
        for node in ast.walk(function):
            if isinstance(node, ast.Global):
                writes += [(node.lineno, name) for name in node.names]
            targets = (node.targets if isinstance(node, ast.Assign) else [node.target]
                       if isinstance(node, (ast.AugAssign, ast.AnnAssign)) else [])
            calls = [node.func] if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and node.func.attr in MUTATORS else []
            for target in [t.value for t in targets if isinstance(t, (ast.Subscript, ast.Attribute))] + \
                    [c.value for c in calls]:
                if isinstance(target, ast.Name) and target.id in names:
                    writes.append((node.lineno, target.id))
    return sorted(set(writes))


@rule("checker/labs/{id}/probes.py", tests="test_lint_lab.py")
def no_module_state(s):
    """`probes.py`, `checks.py` and `scenes.py` keep nothing at module level from one call to the next
    (`threading.local()` if they must): the checker judges a class's files in parallel threads, so a shared count
    or cache mixes two students' files."""
    for name in ("probes.py", "checks.py", "scenes.py"):
        path = os.path.join(s.folder, name)
        writes = module_state_writes(source.read(path)) if os.path.isfile(path) else []
        if writes:
            line, target = writes[0]
            return broken(f"line {line} writes the module-level {target}", "keep it in a local, a case, or a "
                          "threading.local()", relative(path))


# ---------------------------------------------------------------- the solution and its starter

@rule("solutions/{id}.py", needs=("solution_and_starter",), tests="test_assign.py, test_lab_starter.py")
def prompts(s):
    """Each step of the solution sits between `# --- step N: title ---` and `# --- end of step N ---` and opens
    with its prompt (`# BEGIN PROMPT` ... `# END PROMPT`, placeholders as `# starter: CODE`), whose first line is
    `# Step N (lesson: "..."): ...`."""
    from checker.authoring import assign
    try:
        text = assign.starter_text(s.solution, relative(s.lab.solution))
    except assign.AssignError as exc:
        return broken(str(exc).split(": ", 1)[-1], "fix the markers (python -m checker assign names the same line)")
    for step, lines in region_lines(text).items():
        comments = [line.strip() for line in lines if line.strip().startswith("#")]
        if not comments or not comments[0].startswith(f"# Step {step} "):
            return broken(f"step {step}'s prompt does not open with `# Step {step} `",
                          f"start it `# Step {step} (lesson: \"...\"): ...`")


@rule("starters/{id}_starter.py", needs=("prompts",), tests="test_lab_starter.py, test_assign.py")
def starter_is_assigned(s):
    """The starter is exactly what `python -m checker assign` writes from the solution (never edited by hand)."""
    from checker.authoring import assign
    with open(s.lab.starter, "rb") as handle:
        committed = handle.read()
    if committed != assign.starter_text(s.solution, relative(s.lab.solution)).encode("utf-8"):
        return broken("differs from what assign writes", "edit the solution, then run `python -m checker assign`")


@rule("solutions/{id}.py", needs=("prompts",), tests="test_lab_starter.py")
def placeholders(s):
    """Each step of the solution has code; in the starter the step holds only placeholders, each ending
    `# until you write step N, ...: replace this placeholder`, never the whole step."""
    answers, handed = region_lines(s.solution), region_lines(s.starter)
    for step in sorted(answers):
        answer, left = code_lines(answers[step]), code_lines(handed.get(step, []))
        if not answer:
            return broken(f"step {step} has no code", "write the lesson's answer in the step")
        if not set(answer) - set(left):
            return broken(f"the starter's step {step} holds the whole answer", "make the prompt's `# starter:` "
                          "lines a placeholder that keeps the file running, not the answer")
        for line in handed.get(step, []):
            found = PLACEHOLDER.search(line)
            if line.strip() and not line.strip().startswith("#") and (not found or found[1] != str(step)):
                return broken(f"step {step}'s placeholder `{line.strip()}` does not say to replace it",
                              f"end it `  # until you write step {step}, ...: replace this placeholder`")


@rule("solutions/{id}.py", needs=("prompts",), tests="test_lab_starter.py")
def starter_header(s):
    """The module docstring tells the student to replace each placeholder ("replace that line with your code")
    and that a step left as it is scores nothing ("wasted")."""
    parts = s.starter.split('"""')
    header = " ".join(parts[1].split()) if len(parts) > 2 else ""
    missing = [words for words in HEADER_WORDS if words not in header]
    if missing:
        return broken(f"the docstring does not say \"{missing[0]}\"", "add the sentence the other labs' "
                      "docstrings have about the placeholders")


@rule("solutions/{id}.py", needs=("prompts",), tests="test_lab_starter.py")
def lesson_citations(s):
    """Each step's prompt cites `lesson: "<heading>"`, a heading of `lesson11/README.md` or
    `lesson11/labs/<id>.md`."""
    headings = lesson_headings(s.id)
    for step, lines in sorted(region_lines(s.starter).items()):
        cited = re.findall(r'lesson: "([^"]+)"', " ".join(line.strip("# ") for line in lines))
        if not cited or not set(cited) <= headings:
            what = "cites no section of the lesson" if not cited else \
                f"cites {_listing(sorted(set(cited) - headings))}, not a heading of the lesson"
            return broken(f"step {step}'s prompt {what}", "cite a heading as written in the lesson or the lab's page")


@rule("solutions/{id}.py", needs=("prompts",), tests="test_lab_starter.py")
def numbered_steps(s):
    """The comments number the steps `# Step 1` (run it) to `# Step K+1` (watch it), K the last step region, and
    no further."""
    last = max(s.regions) + 1
    missing = [step for step in range(1, last + 1) if not re.search(rf"# Step {step}\b", s.starter)]
    if missing:
        return broken(f"no `# Step {missing[0]}` comment", f"number the steps 1 to {last} in the comments")
    if re.search(rf"# Step {last + 1}\b", s.starter):
        return broken(f"a `# Step {last + 1}` comment after the last step {last}", "number the steps 1 to K + 1")


@rule("solutions/{id}.py", needs=("checks_names", "solution_and_starter"),
      tests="test_corpus_labs.py (corpus_verdicts.assert_builds), test_lab_convention.py")
def title_names_the_file(s):
    """The solution's docstring names the lab's `TITLE`, and the lab recognises its own solution."""
    parts = s.solution.split('"""')
    if len(parts) < 3 or s.module.TITLE not in parts[1]:
        return broken(f"the module docstring does not name \"{s.module.TITLE}\"",
                      "open the docstring with the title: the checker knows the lab's files by it")
    if not s.lab.recognise(os.path.basename(s.lab.solution), s.solution):
        return broken("the lab does not recognise its own solution", "fix recognise(path, source) in checks.py")


@rule("solutions/{id}.py", needs=("solution_and_starter",), tests="test_arbiter_fast.py, test_fast_paths.py")
def world_factories(s):
    """The solution defines `make_scene(rng)` (the scene's bodies) and `make_world(rng)` (the World the window
    starts with) at the top level; any further parameter has a default, so a test builds both from the rng."""
    try:
        tree = ast.parse(s.solution)
    except SyntaxError as exc:
        return broken(f"does not parse (line {exc.lineno})", "fix the syntax error")
    defined = {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}
    for name in ("make_scene", "make_world"):
        if name not in defined:
            return broken(f"defines no {name}(rng)", f"build the {'bodies' if name == 'make_scene' else 'World'} "
                          f"in a top-level {name}(rng)")
        params = defined[name].args
        positional = params.posonlyargs + params.args
        needed = len(positional) - len(params.defaults)
        kw_needed = [arg for arg, default in zip(params.kwonlyargs, params.kw_defaults) if default is None]
        if needed != 1 or kw_needed:
            return broken(f"{name} needs {needed + len(kw_needed)} arguments", f"give {name} one parameter, the "
                          "rng, and defaults to the others")


# ---------------------------------------------------------------- tests/

@rule("tests/corpus_{id}.py", needs=("solution_and_starter",),
      tests="test_message_length.py, test_step_rules.py, test_corpus_labs.py")
def corpus(s):
    """`tests/corpus_<id>.py` builds the lab's mistake corpus: `ENTRIES` = `CORRECT` (at least 3) + `WRONG` (at
    least 10), each built by `build(name)` from the current starter."""
    path = s.path("tests", f"corpus_{s.id}.py")
    if not os.path.isfile(path):
        return broken("no such file", "write the corpus (new-lab writes a first one)", relative(path))
    module = s.corpus
    missing = [name for name in ("ENTRIES", "CORRECT", "WRONG", "build") if not hasattr(module, name)]
    if missing:
        return broken(f"defines no {_listing(missing)}", "copy the form of another lab's corpus")
    if len(module.CORRECT) < 3 or len(module.WRONG) < 10:
        return broken(f"{len(module.CORRECT)} correct and {len(module.WRONG)} wrong entries",
                      "add entries: at least 3 correct ones in other styles and 10 plausible mistakes")


@rule("solutions/{id}.py", needs=("corpus", "checks_names"), tests="test_step_rules.py")
def no_flags(s):
    """The step rules (`checker/reading/step_rules.py`) flag nothing in the solution, the starter or a correct
    corpus entry: a flag there would fail a right answer."""
    from checker.reading import step_rules
    corpus_file = relative(s.path("tests", f"corpus_{s.id}.py"))
    texts = [(relative(s.lab.solution), "", s.solution), (relative(s.lab.starter), "", s.starter)]
    texts += [(corpus_file, f"entry {e.name}, ", s.corpus.build(e.name)) for e in s.corpus.CORRECT]
    for file, where, text in texts:
        flagged = step_rules.scan_lab(text, s.lab)
        if flagged:
            return broken(f"{where}line {flagged[0].line} is flagged ({flagged[0].rule}: {flagged[0].what})",
                          "write it another way, or allow the name for that step (STEP_ALLOWED)", file)
