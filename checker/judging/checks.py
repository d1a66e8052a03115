"""The check framework: small check functions, their dependencies, and their results.

In the style of check50: a lab's checks are plain functions registered in
order with @registry.check(...). A check's docstring is the description the
student sees. A check takes only what it reads: the submission (what was run
and recorded) when its first parameter is named `sub`, then the value of each
check in `depends`, in that order. Checks in `after` only gate: they must pass
first, but their values are not passed.

    @CHECKS.check(depends=["loads"])
    def sat_axes(sub, probe):        # probe: what `loads` returned
        ...
        return Passed("10.00 px along (1, 0)", value=cases)   # or just a value

    @CHECKS.check(depends=["runs"], after=["sat_axes"])
    def pile_stable(records):        # records: what `runs` returned; no submission
        ...

A check passes by returning: a str is shown as its message, `Passed(message,
value)` shows the message and hands `value` to its dependents, anything else is
handed on silently. It fails by raising Fail(rationale, hint), or Error(rationale,
hint) when the lab crashed, looped or broke a limit so nothing could be measured.
A check whose prerequisites (`depends` and `after`) did not all pass is skipped,
naming the earliest of them that did not, so a crash or a mistake is reported once.
No state is shared between checks except through these return values.

A check registered with `needs_scenarios=True` reads the scene runs; the
grader runs the scenes only if such a check has every prerequisite passed
(`Registry.wants_scenarios`), so a file that fails a function check costs one
probe run, not five.
"""
import inspect
import re
from dataclasses import dataclass, field

PASS, FAIL, SKIP, ERROR = "pass", "fail", "skip", "error"


@dataclass(frozen=True)
class Hint:
    """What to revisit: the lesson step (1-7, or None), a short title, and the advice in the lesson's terms."""
    step: int | None
    title: str
    text: str

    def render(self, file=None):
        """"[step N: title] text"; with `file` (the name the file was submitted under), a command in the text that
        runs the lab's own file name (`python tumbling_crates.py`) runs that file instead."""
        where = f"step {self.step}" if self.step else "lesson"
        text = self.text
        if file:
            shown = file if re.fullmatch(r"[\w.+-]+", file) else '"' + file.replace('"', '\\"') + '"'
            text = RUN_COMMAND.sub(lambda _: f"python {shown}", text)
        return f"[{where}: {self.title}] {text}"


RUN_COMMAND = re.compile(r"python [a-z][a-z0-9_]*\.py\b")   # how a hint tells the student to run their file


@dataclass(frozen=True)
class Mistake:
    """A known mistake a failing check named: a stable id (the same words in every lab, e.g. "clamp_to_mu") and
    its sentence in the student's terms. Reported as "mistake": {"id", "text"} in --json, the CSV and the
    platforms' results, and counted per step in the class report."""
    id: str
    text: str

    def to_json(self):
        return {"id": self.id, "text": self.text}


class Fail(Exception):
    """The lab ran but does not do what the check asks.

    rationale: the message, two short lines (what is wrong in the student's terms; the evidence, one case);
    hint: a Hint; mistake: the Mistake it names, when one known wrong form fits the student's answers.
    """

    def __init__(self, rationale, hint=None, mistake=None):
        super().__init__(rationale)
        self.rationale = rationale
        self.hint = hint
        self.mistake = mistake


class Error(Fail):
    """The lab could not be measured: it crashed, looped, exited or broke a limit."""


@dataclass
class Passed:
    """A passing check's message for the student and the value handed to the checks that depend on it."""
    message: str = ""
    value: object = None


@dataclass
class Check:
    """A registered check: id, the function, the checks whose values it takes (`depends`) and those that only gate
    it (`after`), its weight, whether it reads the scenes, and whether it takes the submission."""
    id: str
    func: object
    depends: tuple
    max_score: float
    needs_scenarios: bool = False
    after: tuple = ()
    takes_submission: bool = True
    prerequisites: tuple = ()   # depends and after, in the registry's order (the first not passed is named)

    @property
    def description(self):
        return inspect.cleandoc(self.func.__doc__ or self.id).split("\n\n")[0].replace("\n", " ")

    def call(self, submission, *values):
        """Run the function on what it takes: the submission if it reads it, then the values of `depends`."""
        return self.func(*((submission,) if self.takes_submission else ()), *values)


@dataclass
class Result:
    """One check's outcome, as reported in text, JSON, Gradescope and CSV."""
    id: str
    name: str
    status: str
    message: str = ""
    hint: str = ""
    step: int | None = None
    score: float = 0.0
    max_score: float = 1.0
    data: dict = field(default_factory=dict)
    mistake: Mistake | None = None   # the known mistake a failing check named, else None

    def to_json(self):
        return {"id": self.id, "name": self.name, "status": self.status, "message": self.message,
                "hint": self.hint, "step": self.step, "score": self.score, "max_score": self.max_score,
                "mistake": self.mistake.to_json() if self.mistake else None}


class Registry:
    """An ordered set of checks for one lab."""

    def __init__(self):
        self.checks = []

    def check(self, depends=(), max_score=1.0, needs_scenarios=False, after=()):
        """Decorator: register the function as the next check.

        depends: ids of earlier checks whose values it takes, in order, after the submission (passed only when the
        first parameter is named `sub`); after: ids of earlier checks that must pass first but whose values it
        does not take. A signature that does not match is a ValueError here, at import, not a wrong call later.
        """
        def register(func):
            order = {c.id: index for index, c in enumerate(self.checks)}
            missing = [d for d in (*depends, *after) if d not in order]
            if missing:
                raise ValueError(f"check {func.__name__} depends on unknown or later checks {missing}")
            takes_submission = _takes(func, len(depends))
            prerequisites = tuple(sorted(set(depends) | set(after), key=order.get))
            self.checks.append(Check(func.__name__, func, tuple(depends), float(max_score), needs_scenarios,
                                     tuple(after), takes_submission, prerequisites))
            return func
        return register

    @property
    def max_score(self):
        return sum(c.max_score for c in self.checks)

    def by_id(self, check_id):
        """The registered check with this id."""
        return next(c for c in self.checks if c.id == check_id)

    def run(self, submission, stop_at_scenarios=False, state=None):
        """Run the checks in order; returns a RunState (results so far, values handed on).

        With stop_at_scenarios=True, stop before the first check that reads the
        scenes; call again with the returned `state` to finish.
        """
        state = state or RunState()
        for chk in self.checks:
            if chk.id in state.results:
                continue
            if stop_at_scenarios and chk.needs_scenarios:
                break
            blocked = [d for d in chk.prerequisites if state.results[d].status != PASS]
            if blocked:
                state.add(Result(chk.id, chk.description, SKIP, max_score=chk.max_score,
                                 message=f"skipped: needs {needed(self.by_id(blocked[0]))} to pass first"))
                continue
            try:
                returned = chk.call(submission, *(state.values[d] for d in chk.depends))
            except Error as exc:
                state.add(state.failed(chk, ERROR, exc, getattr(submission, "name", None)))
                continue
            except Fail as exc:
                state.add(state.failed(chk, FAIL, exc, getattr(submission, "name", None)))
                continue
            if isinstance(returned, Passed):
                message, value = returned.message, returned.value
            else:
                message, value = (returned if isinstance(returned, str) else ""), returned
            state.values[chk.id] = value
            state.add(Result(chk.id, chk.description, PASS, message=message or "", score=chk.max_score,
                             max_score=chk.max_score))
        return state

    def wants_scenarios(self, state):
        """True when some check that reads the scenes has all of its prerequisites passed."""
        return any(chk.needs_scenarios and all(d in state.results and state.results[d].status == PASS
                                               for d in chk.prerequisites)
                   for chk in self.checks)


def _takes(func, values):
    """True when `func` takes the submission: its first parameter is named `sub`. ValueError unless the other
    parameters take exactly `values` values (one per check in `depends`)."""
    params = list(inspect.signature(func).parameters.values())
    takes_submission = bool(params) and params[0].name == "sub"
    rest = params[1:] if takes_submission else params
    positional = [p for p in rest if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    if len(positional) != len(rest) or len(positional) != values:
        raise ValueError(f"check {func.__name__} takes {[p.name for p in rest]} but depends on {values} check(s): "
                         "give one parameter per check in `depends` (and `sub` first to read the submission); "
                         "put checks that only gate in `after`")
    return takes_submission


class RunState:
    """The results of one run of a registry, in order, and the values passing checks handed on."""

    def __init__(self):
        self.results = {}
        self.values = {}
        self.hints_shown = {}

    def add(self, result):
        self.results[result.id] = result

    def failed(self, chk, status, exc, file=None):
        """A Result for a failed check; a hint already shown under an earlier check is referred to, not repeated.
        file: the name the file was submitted under, which the hint's commands name (Hint.render)."""
        hint = exc.hint
        text = hint.render(file) if hint else ""
        if hint is not None and hint in self.hints_shown:
            text = f"[step {hint.step}: {hint.title}] see the hint under '{self.hints_shown[hint]}' above." \
                if hint.step else f"[lesson: {hint.title}] see the hint under '{self.hints_shown[hint]}' above."
        elif hint is not None:
            self.hints_shown[hint] = chk.id
        return Result(chk.id, chk.description, status, message=exc.rationale, hint=text,
                      step=hint.step if hint else None, score=0.0, max_score=chk.max_score,
                      mistake=getattr(exc, "mistake", None))

    def ordered(self, registry):
        """The results in the registry's order."""
        return [self.results[c.id] for c in registry.checks if c.id in self.results]


def step_of(description):
    """The lesson step a check grades, from its description ("Step 5: ..." gives 5), else None."""
    found = re.match(r"Step (\d+)\b", description or "")
    return int(found.group(1)) if found else None


def needed(check):
    """How a skipped check names the one it waits for: "step 5 (resolve_friction)" when that check grades a lesson
    step, else its id in quotes."""
    step = step_of(check.description)
    return f"step {step} ({check.id})" if step else f"'{check.id}'"


def skipped_all(registry, message):
    """Every check of a lab marked as an error with one message (e.g. the run's time limit ran out)."""
    return [Result(c.id, c.description, ERROR if i == 0 else SKIP, message=message if i == 0 else
                   f"skipped: needs {needed(registry.checks[0])} to pass first", max_score=c.max_score)
            for i, c in enumerate(registry.checks)]
