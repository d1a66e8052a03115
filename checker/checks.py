"""The check framework: small check functions, their dependencies, and their results.

In the style of check50: a lab's checks are plain functions registered in
order with @registry.check(...). A check's docstring is the description the
student sees. A check passes by returning (optionally a short message), and
fails by raising Fail(rationale, hint) or Error(rationale, hint) (the lab
crashed, looped or broke a limit, so nothing could be measured). A check whose
dependencies did not all pass is skipped, so a crash is reported once.
"""
import inspect
from dataclasses import dataclass, field

PASS, FAIL, SKIP, ERROR = "pass", "fail", "skip", "error"


@dataclass(frozen=True)
class Hint:
    """What to revisit: the lesson step (1-7, or None), a short title, and the advice in the lesson's terms."""
    step: int | None
    title: str
    text: str

    def render(self):
        where = f"step {self.step}" if self.step else "lesson"
        return f"[{where}: {self.title}] {self.text}"


class Fail(Exception):
    """The lab ran but does not do what the check asks."""

    def __init__(self, rationale, hint=None):
        super().__init__(rationale)
        self.rationale = rationale
        self.hint = hint


class Error(Fail):
    """The lab could not be measured: it crashed, looped, exited or broke a limit."""


@dataclass
class Check:
    """A registered check: id, the function, what it depends on, and its weight."""
    id: str
    func: object
    depends: tuple
    max_score: float

    @property
    def description(self):
        return inspect.cleandoc(self.func.__doc__ or self.id).split("\n\n")[0].replace("\n", " ")


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

    def to_json(self):
        return {"id": self.id, "name": self.name, "status": self.status, "message": self.message,
                "hint": self.hint, "step": self.step, "score": self.score, "max_score": self.max_score}


class Registry:
    """An ordered set of checks for one lab."""

    def __init__(self):
        self.checks = []

    def check(self, depends=(), max_score=1.0):
        """Decorator: register the function as the next check, depending on the ids in `depends`."""
        def register(func):
            known = {c.id for c in self.checks}
            missing = [d for d in depends if d not in known]
            if missing:
                raise ValueError(f"check {func.__name__} depends on unknown or later checks {missing}")
            self.checks.append(Check(func.__name__, func, tuple(depends), float(max_score)))
            return func
        return register

    def run(self, context):
        """Run every check in order against `context`; returns a list of Result in registration order."""
        results = {}
        ordered = []
        for chk in self.checks:
            blocked = [d for d in chk.depends if results[d].status != PASS]
            if blocked:
                result = Result(chk.id, chk.description, SKIP,
                                message=f"skipped: needs '{blocked[0]}' to pass first", max_score=chk.max_score)
            else:
                try:
                    message = chk.func(context)
                    result = Result(chk.id, chk.description, PASS, message=message or "",
                                    score=chk.max_score, max_score=chk.max_score)
                except Error as exc:
                    result = _failed(chk, ERROR, exc)
                except Fail as exc:
                    result = _failed(chk, FAIL, exc)
            results[chk.id] = result
            ordered.append(result)
        return ordered


def _failed(chk, status, exc):
    hint = exc.hint
    return Result(chk.id, chk.description, status, message=exc.rationale,
                  hint=hint.render() if hint else "", step=hint.step if hint else None,
                  score=0.0, max_score=chk.max_score)


def skipped_all(registry, message):
    """Every check of a lab marked as an error with one message (e.g. the run's time limit ran out)."""
    return [Result(c.id, c.description, ERROR if i == 0 else SKIP, message=message if i == 0 else
                   f"skipped: needs '{registry.checks[0].id}' to pass first", max_score=c.max_score)
            for i, c in enumerate(registry.checks)]
