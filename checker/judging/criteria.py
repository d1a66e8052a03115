"""A scene criterion declared as data: what it measures and its bounds; the framework compares and words it.

A lab lists its Criterion rows in checks.py and calls register(); each becomes a check that takes what the
lab's `runs` check returned, measures it (a dict of metrics, or a list of them, one per body, checked in turn)
and fails at the first Bound broken, in two lines: the bound's sentence (what is wrong), then the evidence,
"<metric> <value> <unit> (bound <limit>)". A passing check lists the metrics it bounded
(but those that must be 0 or only happen).
"""
import inspect
import math
from dataclasses import dataclass

from .checks import Fail, Passed
from .common import shown


@dataclass(frozen=True)
class Bound:
    """One bound: metric (a key of the measure's dict) at most limit (least: at least); sentence: what is wrong
    when it is broken ("{name}": the value of metric `name`, e.g. which body); hint: the key of the lab's HINTS; unit, and scale (value and limit are shown times it,
    e.g. 180/pi for degrees). A value None (it never happened) or NaN breaks it."""
    metric: str
    limit: float
    sentence: str
    hint: str
    unit: str = ""
    least: bool = False
    scale: float = 1.0
    frame: str | None = None   # a metric holding the frame it happened at: "... at frame N" (the replay marks it)

    def broken(self, value):
        return value is None or not (value >= self.limit if self.least else value <= self.limit)

    def shown(self, value, against=True):
        """'<metric> <value> <unit>', the value with enough digits not to read as the limit (against), else 3."""
        name = self.metric.replace("_", " ")
        if value is None or isinstance(value, bool):
            return f"{name}: {'never' if value is None else 'yes' if value else 'no'}"
        number = shown(value * self.scale, self.limit * self.scale) if against else f"{value * self.scale:.3g}"
        return f"{name} {number}{' ' + self.unit if self.unit else ''}"

    def message(self, metrics):
        """The two lines of the failure: the sentence ("{name}" in it: that metric's value), then the evidence."""
        value = metrics.get(self.metric)
        bound = "" if value is None or isinstance(value, bool) else f" (bound {self.limit * self.scale:g})"
        at = f" at frame {metrics[self.frame]}" if self.frame and metrics.get(self.frame) is not None else ""
        return f"{self.sentence.format_map(metrics)}.\n{self.shown(value)}{at}{bound}."


@dataclass(frozen=True)
class Criterion:
    """A scene criterion: its check id, its description (the docstring), measure(records) -> {metric: value}
    (or a list of them), its Bounds in the order they are tried; passed(metrics): the passing message (None:
    each bounded metric's value)."""
    id: str
    doc: str
    measure: object
    bounds: tuple
    passed: object = None
    max_score: float = 2


def register(registry, hints, criteria, depends=("runs",), after=(), needs_scenarios=True):
    """Register each Criterion as a check of `registry` taking the values of `depends` (by default the check
    that ran the scenes); its measure takes what the check takes (`sub` first to read the submission)."""
    for criterion in criteria:
        registry.check(depends=list(depends), after=list(after), max_score=criterion.max_score,
                       needs_scenarios=needs_scenarios)(_check(criterion, hints))


def _check(criterion, hints):
    """The check function of one criterion (named and described as the criterion)."""
    def check(*values):
        measured = criterion.measure(*values)
        every = measured if isinstance(measured, list) else [measured]
        for metrics in every:
            for bound in criterion.bounds:
                if bound.broken(metrics.get(bound.metric)):
                    raise Fail(bound.message(metrics), hints[bound.hint])
        if criterion.passed is not None:
            return Passed(criterion.passed(every[-1]), value=measured)
        measures = {b.metric: b for b in criterion.bounds if b.limit not in (0, math.inf)}.values()
        return Passed(", ".join(b.shown(every[-1][b.metric], False) for b in measures), value=measured)
    check.__name__ = check.__qualname__ = criterion.id
    check.__doc__ = criterion.doc
    check.__signature__ = inspect.signature(criterion.measure)
    check.criterion = criterion   # for tests/test_criteria.py: every lab's bounds are short and name a hint it has
    return check


def escapes(summary, exploded=math.inf):
    """How a scene's bodies escaped, from its lesson11.records.summary: flung (one rose 50 px above the screen, or
    faster than `exploded` px/s some left the screen while not all fell through), how many fell through the floor
    and how many left the screen; with escape_bounds, every criterion's first bounds."""
    flung = summary["highest_y"] < -50 or (summary["peak_speed"] > exploded and summary["off_screen"] > 0
                                           and summary["fell_through"] < summary["crates"])
    return {"flung": flung, "fell_through": summary["fell_through"], "off_screen": summary["off_screen"]}


def escape_bounds(what, hint):
    """The Bounds of escapes(): none flung, none through the floor, none off the screen."""
    return (Bound("flung", 0, f"{what} were flung apart", hint), Bound("fell_through", 0, f"{what} fell through the "
            "floor", hint), Bound("off_screen", 0, f"{what} left the screen", hint))
