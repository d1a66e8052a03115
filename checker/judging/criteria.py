"""A scene criterion declared as data: what it measures and its bounds; the framework compares and words it.

A lab lists its Criterion rows in checks.py and calls register(); each becomes a check that takes what the
lab's `runs` check returned, measures it (a dict of metrics, or a list of them, one per body, checked in turn)
and fails at the first Bound broken, in two lines: the bound's sentence (what is wrong), then the evidence,
"<metric> <value> <unit> (bound <limit>)". A passing check lists the metrics it bounded.
"""
from dataclasses import dataclass

from .checks import Fail, Passed
from .common import shown


@dataclass(frozen=True)
class Bound:
    """One bound: metric (a key of the measure's dict) at most limit (least: at least); sentence: what is wrong
    when it is broken; hint: the key of the lab's HINTS; unit, and scale (value and limit are shown times it,
    e.g. 180/pi for degrees). A value None (it never happened) or NaN breaks it."""
    metric: str
    limit: float
    sentence: str
    hint: str
    unit: str = ""
    least: bool = False
    scale: float = 1.0

    def broken(self, value):
        return value is None or not (value >= self.limit if self.least else value <= self.limit)

    def shown(self, value, against=True):
        """'<metric> <value> <unit>', the value with enough digits not to read as the limit (against), else 3."""
        name = self.metric.replace("_", " ")
        if value is None or isinstance(value, bool):
            return f"{name}: {'never' if value is None else 'yes' if value else 'no'}"
        number = shown(value * self.scale, self.limit * self.scale) if against else f"{value * self.scale:.3g}"
        return f"{name} {number}{' ' + self.unit if self.unit else ''}"

    def message(self, value):
        bound = "" if value is None or isinstance(value, bool) else f" (bound {self.limit * self.scale:g})"
        return f"{self.sentence}.\n{self.shown(value)}{bound}."


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


def register(registry, hints, criteria, depends=("runs",)):
    """Register each Criterion as a check of `registry` taking the value of `depends` (the check that ran the
    scenes)."""
    for criterion in criteria:
        registry.check(depends=list(depends), max_score=criterion.max_score,
                       needs_scenarios=True)(_check(criterion, hints))


def _check(criterion, hints):
    """The check function of one criterion (named and described as the criterion)."""
    def check(records):
        measured = criterion.measure(records)
        every = measured if isinstance(measured, list) else [measured]
        for metrics in every:
            for bound in criterion.bounds:
                if bound.broken(metrics.get(bound.metric)):
                    raise Fail(bound.message(metrics.get(bound.metric)), hints[bound.hint])
        if criterion.passed is not None:
            return Passed(criterion.passed(every[-1]), value=measured)
        worst = {b.metric: b for b in criterion.bounds}.values()
        return Passed(", ".join(b.shown(every[-1][b.metric], False) for b in worst), value=measured)
    check.__name__ = check.__qualname__ = criterion.id
    check.__doc__ = criterion.doc
    return check
