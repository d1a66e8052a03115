"""A function step declared as data: its cases, the lesson's answer, its known wrong forms and its words.

A lab writes a Step once, in its probes.py; the framework makes both halves of the step's grading from it:
  - the probe (Step.probe): in the child it calls the student's function on each case and records only the
    answer; in the grading parent, replaying the tape, it adds the lesson's answer and every known wrong
    form's answer (lesson_answers, a @reference: it raises if the child ever calls it), computed from the
    case's own inputs and the handout's constants, never from anything the child sent back;
  - the check (Step.register, from the lab's checks.py): compares each case with the lesson's answer, names a
    wrong form only when it alone gives the student's answer in every case (causes.consistent_mistake), and
    words the failure as every lab does: two lines, what is wrong (the form's sentence, else the step's own
    words), then the evidence of the first case that differs.
register_together makes one check of several Steps (one lesson step seen through two functions). Steps that move
bodies are declared_acts.Acting; steps read from a probe the lab already has, declared_shared.SharedStep.
"""
from dataclasses import dataclass, field

from pygame import Vector2

from . import lab_checks
from .causes import consistent_mistake, mistake
from .checks import Fail, Passed
from .common import real, value_text
from .tape import judging, reference


@dataclass(frozen=True)
class Form:
    """A known wrong form of a step: its mistake id, the sentence that names it (in the student's terms; None:
    the shared sentence of causes.SHARED), the function that computes its answer from a case, the key of the
    hint it gives (None: the step's) and the message's first line when it says more than the sentence."""
    id: str | None
    text: str | None
    answer: object = None
    hint: str | None = None
    line: str | None = None


def forms_of(table, answers, prefix=""):
    """Forms from a table {name: sentence} whose answers one function computes together, answers(case) ->
    {name: answer} (a name it leaves out: None, no answer there); each mistake's id is prefix + name."""
    return tuple(Form(prefix + name, text, lambda case, name=name: answers(case).get(name))
                 for name, text in table.items())


def numbers(raw, size):
    """A function's answer as `size` floats, its vectors laid flat ((normal, depth): [nx, ny, depth]), for a Step's
    `answer`; None stays None; anything else is its text (a Step's `bad` can call a str malformed)."""
    try:
        flat = [real(x) for part in raw for x in (part if isinstance(part, (Vector2, tuple, list)) else [part])]
        return flat if len(flat) == size else value_text(raw)
    except (TypeError, ValueError):
        return None if raw is None else value_text(raw)


def close(relative):
    """A Step's `same` for numbers() answers: equal, or lists whose numbers each agree to `relative` of their
    size (at least 1): the same sums in another order."""
    return lambda got, want: got == want or (isinstance(got, list) and isinstance(want, list) and len(got) == len(
        want) and all(abs(g - w) <= relative * max(1.0, abs(w)) for g, w in zip(got, want)))


def listed(value):
    """A numbers() answer in a message, two decimals each: "(1.00, 0.00, 8.00)"; anything else as str()."""
    return f"({', '.join(lab_checks.number_text(x) for x in value)})" if isinstance(value, list) else str(value)


def words(text):
    """`text` as a function of a case: a lab gives its words either as a fixed sentence or as a function."""
    return text if callable(text) else (lambda case: text)


class stood_in:
    """While it is open, module.<name> is `function` for each {name: function}; then the module's own come back
    (a name the module did not have keeps its stand-in)."""
    missing = object()

    def __init__(self, module, functions):
        self.module, self.functions = module, functions
        self.own = {name: getattr(module, name, self.missing) for name in functions}

    def __enter__(self):
        for name, function in self.functions.items():
            setattr(self.module, name, function)

    def __exit__(self, *exc):
        for name, function in self.own.items():
            if function is not self.missing:
                setattr(self.module, name, function)
        return False


@dataclass
class Step:
    """One function step of a lab, as data (see the module docstring).

    check, doc: the check's id and its description (Step N: ...); step: the lesson step; function: the
    student's function; probe_name: the probe's name in PROBES (default: the function's); cases(module): the
    cases, each a dict of inputs with a "case" label (drawn ones from tape.run_rng); call(function, case): the
    student's raw answer; answer(raw): it as plain data; lesson(case): the lesson's answer, in the grader only;
    wrong: the Forms; same(got, want): True when an answer counts as the lesson's (a malformed one never does;
    default ==); bad(got): True when the answer is malformed, and malformed(case) words it (both lines; default
    "<function>() must return <kind>", then what the case returned and the lesson's answer); evidence(case):
    the message's second line
    (default "<label(case)> returned <show(got)>; expected <show(want)>"); diagnose(cases, case): a Form that this case's answer shows by itself (its id None:
    words and a hint, no mistake named), tried before the wrong forms; stand_ins(module): the lesson's functions
    that stand in for the student's other steps while this one is probed, so a mistake is graded once, under its
    own step; unnamed: the first line when no form is named; hint: the key of the step's hint in the lab's
    HINTS; passed: the passing message, "{n}" the number of cases (or a function of the cases).
    """
    check: str
    doc: str
    step: int
    function: str
    cases: object
    call: object
    lesson: object
    same: object = None       # None: got == want
    evidence: object = None   # None: "<label> returned <got>; expected <want>."
    unnamed: object = None    # None: "<function>() does not give the lesson's answer"
    hint: str = None          # required
    passed: object = None     # None: "all <n> cases match the lesson"
    wrong: tuple = ()
    answer: object = None     # answer(raw): the student's answer as plain data (None: as the call returned it)
    bad: object = None
    malformed: object = None
    diagnose: object = None   # diagnose(cases, case): a Form read from this case alone, before the one-formula rule
    stand_ins: object = None  # stand_ins(module): {name: the lesson's function} put in place while the step is probed
    probe_name: str | None = None
    extra: dict = field(default_factory=dict)   # more grader-only data per case: {key: function of a case}
    label: object = None      # label(case): the case as the messages name it (None: "for <case>")
    show: object = None       # show(answer): an answer as the messages write it (None: as it is)
    kind: str = "the lesson's kind of answer"   # what the function must return, for the default malformed
    accepts: object = None    # accepts(case): the answer counts as the lesson's, where that needs the case's inputs
    #                           (its size, the ties it allows); None: same(got, want). Forms still match by same.

    def __post_init__(self):
        assert self.hint is not None, f"{self.check}: a Step needs the key of its hint"
        self.same = self.same or (lambda got, want: got == want)
        self.evidence = self.evidence or (lambda case: f"{self.named_case(case)} returned "
                                                       f"{self.shown(case['got'])}; expected {self.shown(case['want'])}.")
        self.unnamed = self.unnamed or f"{self.function}() does not give the lesson's answer"
        self.passed = self.passed or "all {n} cases match the lesson"
        self.malformed = self.malformed or (lambda case: f"{self.function}() must return {self.kind}.\n"
                                                         f"{self.named_case(case)} returned {self.shown(case['got'])}; "
                                                         f"expected {self.shown(case['want'])}.")

    def named_case(self, case):
        return self.label(case) if self.label else f"for {case.get('case')}"

    def shown(self, answer):
        """An answer as the messages write it: a malformed one as the probe described it (a str, or {"bad": str})."""
        if isinstance(answer, dict) and "bad" in answer:
            return answer["bad"]
        return self.show(answer) if self.show and not isinstance(answer, str) else answer

    @property
    def probe_id(self):
        return self.probe_name or self.function

    # ------------------------------------------------------------ the probe (child records, parent judges)

    def probe(self, module, lab_path):
        """The student's answer in every case; in the grader also the lesson's and the wrong forms' answers."""
        with stood_in(module, self.stand_ins(module) if self.stand_ins else {}):
            out = []
            for case in self.cases(module):
                raw = self.call(getattr(module, self.function), case)
                record = dict(case, got=raw if self.answer is None else self.answer(raw))
                if judging(module):
                    record.update(lesson_answers(self, case))
                out.append(record)
            return out

    def probes(self):
        """This step's entry of a lab's PROBES: {probe name: (the function it needs, the probe)}."""
        return {self.probe_id: (self.function, self.probe)}

    # ------------------------------------------------------------ the check (in the grading parent)

    def register(self, registry, hints, depends=("loads",), after=(), max_score=1.0):
        """Register this step's check in `registry`, in the order of the call; `hints`: the lab's HINTS."""
        return register_together((self,), registry, hints, self.check, self.doc, lambda passed: passed, depends,
                                 after, max_score)

    def judge(self, cases, hints):
        """Passed with the cases when every one is the lesson's, else Fail for the first that is not."""
        for case in cases:
            if self.bad is not None and self.bad(case["got"]):
                raise Fail(self.malformed(case), hints[self.hint])
            if not (self.accepts(case) if self.accepts else self.same(case["got"], case["want"])):
                form = (self.diagnose and self.diagnose(cases, case)) or self.named(cases, case)
                found = mistake(form.id, form.text) if form and form.id else None
                first = (form and form.line) or (found.text if found else form.text if form else
                                                 words(self.unnamed)(case))
                raise Fail(f"{first}.\n{self.evidence(case)}", hints[(form and form.hint) or self.hint], found)
        passed = self.passed(cases) if callable(self.passed) else self.passed.format(n=len(cases))
        return passed if isinstance(passed, Passed) else Passed(passed, value=cases)

    def named(self, cases, case):
        """The one wrong Form that gives the student's answer in every case, or None; only forms whose answer
        differs from the lesson's in `case` can be named (causes.consistent_mistake)."""
        differs = [form for form in self.wrong if not self.same(case["forms"][form.id], case["want"])]
        return consistent_mistake(cases, lambda c, f: self.same(c["got"], c["forms"][f.id]), differs)


def register_together(steps, registry, hints, check, doc, passed, depends=("loads",), after=(), max_score=1.0):
    """Register check `check` (description `doc`) in `registry`: it judges `steps` (declared.Steps of one lesson
    step) in order and returns passed(*their Passed); `hints`: the lab's HINTS (its "crash" hint for a probe that
    raised). Each Step's own register() is not called: its probe still goes in the lab's PROBES (Step.probes())."""
    def judged(sub, functions):
        return passed(*[step.judge(lab_checks.function_data(sub, functions, step.probe_id, step.function, step.step,
                                                            hints["crash"]), hints) for step in steps])
    judged.__name__ = judged.__qualname__ = check
    judged.__doc__ = doc
    registry.check(depends=list(depends), after=list(after), max_score=max_score)(judged)
    return judged


@reference
def lesson_answers(step, case):
    """{"want": the lesson's answer, "forms": {id: each wrong form's answer}} for one case, and the step's extra
    grader-only data: computed here, in the grading parent, from the case's inputs (a @reference: never in the
    child, where the student's code could read it)."""
    out = {"want": step.lesson(case), "forms": {form.id: form.answer(case) for form in step.wrong}}
    out.update({key: compute(case) for key, compute in step.extra.items()})
    return out
