"""Grading one lab file, and many in parallel.

A lab file is graded in two stages, each in isolated child processes:
  1. the probe: import the file and test its own functions (one child);
  2. if the checks that read the scenes can run (every check they depend on
     passed): one child per scenario.
All children of all files share one pool of `jobs` worker slots, so a class
folder keeps every core busy; a freed slot goes to the waiting run expected
to take longest (probes first, then scenes by their lab's SCENE_SECONDS). A file's source is read once (the checker never
writes to it), as the compiler reads it (checker/reading/source.py: a file declaring another coding than UTF-8 is an
error); if the file changes while it is graded the result is an error.
"""
import ast
import hashlib
import heapq
import itertools
import math
import os
import shutil
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field, replace

from checker.judging import budget, probing
from checker.reading import handout, source, step_rules
from checker.judging.checks import ERROR, FAIL, PASS, skipped_all
from checker.judging.common import checked_result
from checker.judging.lab_checks import record_problem
from checker.isolation.sandbox import Limits, run_child, wall_limit


@dataclass
class Submission:
    """What a lab's checks see: the file, the runs made of it, and the grading options.

    `probe` is the probe run (a sandbox.RunResult); `scenarios` maps a scene's
    name to its run (filled only if some check that reads the scenes can run);
    `options` holds instructor options such as allow_edits.
    """
    path: str
    name: str
    source: str
    probe: object = None
    flags: list = field(default_factory=list)   # what the step rules flagged (checker/reading/step_rules.py Breach)
    function_steps: dict = field(default_factory=dict)   # step function name -> its steps (the starter's)
    scenarios: dict = field(default_factory=dict)
    options: dict = field(default_factory=dict)
    starter: str = ""   # path of the lab's handout, which the code outside the steps must match
    edits_not_run: list = field(default_factory=list)   # constants changed outside the steps that no check reads:
    # the runs put the handout's lines back (Grader.grade), handout_unchanged warns


@dataclass
class LabReport:
    """The graded result of one file.

    `records` maps a scene's name to its recorded run (lesson11.runtime's
    record), kept only when the Grader is asked to (keep_records=True, for
    --pictures and --html) and only for the scenes a failed check reads (the
    lab's picture_scenes); otherwise it is empty.
    """
    path: str
    lab: object
    results: list
    seconds: float
    records: dict = field(default_factory=dict)
    preview: str = ""   # the scene run ungraded for a picture when the graded scenes never ran (--pictures)
    seed: int | None = None   # the seed of the probe inputs drawn for this run (--seed N grades with the same)
    flags: list = field(default_factory=list)   # step_rules breaches as dicts (step, line, rule, what, text)
    notes: list = field(default_factory=list)   # limits this system refused and the runs went without (sandbox)
    preview_note: str = ""   # what the preview ran, when not the whole file: "your step 5 with the lesson's steps ..."

    @property
    def score(self):
        return sum(r.score for r in self.results)

    @property
    def max_score(self):
        return sum(r.max_score for r in self.results)

    @property
    def passed(self):
        return all(r.status == PASS for r in self.results)

    @property
    def status(self):
        if self.passed:
            return "pass"
        return "error" if any(r.status == ERROR for r in self.results) else "fail"


class Slots:
    """At most `jobs` child runs at once; a freed slot goes to the waiting run with the highest priority.

    The priority is how long a run is expected to take (s), so the grader
    schedules longest first (Graham's LPT rule): a long scene that starts
    last runs alone at the end while the other cores idle; started first, the
    short runs fill in around it. Equal priorities are served first come, first served.
    """

    def __init__(self, jobs):
        self.free = jobs
        self.waiting = []                 # heap of (-priority, ticket, event)
        self.tickets = itertools.count()
        self.lock = threading.Lock()

    def acquire(self, priority):
        """Wait for a slot; runs with a higher priority waiting at the same time get theirs first."""
        with self.lock:
            if self.free > 0 and not self.waiting:
                self.free -= 1
                return
            ready = threading.Event()
            heapq.heappush(self.waiting, (-priority, next(self.tickets), ready))
        ready.wait()                      # release() handed this run its slot

    def release(self):
        """Give the slot to the waiting run with the highest priority, or free it."""
        with self.lock:
            if self.waiting:
                heapq.heappop(self.waiting)[2].set()
            else:
                self.free += 1


class Grader:
    """Runs child processes for many labs with at most `jobs` at a time and an overall deadline."""

    def __init__(self, limits=None, jobs=None, total_timeout=None, options=None, keep_records=False, seed=None):
        self.limits = limits or Limits()
        self.seed = seed   # None: each file's probe inputs drawn with a fresh seed
        self.keep_records = keep_records
        self.options = dict(options or {})
        self.jobs = max(1, jobs or os.cpu_count() or 1)
        self.slots = Slots(self.jobs)
        self.deadline = None if not total_timeout else time.monotonic() + total_timeout
        self.total_timeout = total_timeout

    def _out_of_time(self):
        return self.deadline is not None and time.monotonic() >= self.deadline

    def run(self, lab_path, task, settings, priority=math.inf):
        """One child run, waiting for a free slot; None if the whole run's time limit has passed.

        priority: the seconds the run is expected to take (Slots: longest first);
        probes keep the default, infinity, since a file's scenes wait for its probe.
        """
        self.slots.acquire(priority)
        try:
            if self._out_of_time():
                return None
            limits = self.limits
            if self.deadline is not None:
                left = self.deadline - time.monotonic()
                limits = replace(limits, timeout=min(limits.timeout, max(left, 0.5)))
            run = run_child(lab_path, task, settings, limits)
        finally:
            self.slots.release()
        run.result = checked_result(run.result)   # the child's errors checked before any check reads them
        run.lab_path = lab_path
        run.timeout = limits.timeout
        run.cut_short = limits.timeout < self.limits.timeout and run.status == "timeout"
        run.total_timeout = self.total_timeout
        run.memory_mb = limits.memory_mb
        run.max_output = limits.max_output
        run.disk_mb = limits.disk_mb
        return run

    def grade(self, path, lab):
        """Grade one file as `lab`; returns a LabReport. Never raises for anything the file does.

        When the only edits outside the steps are changed values of constants that no step and no part of the
        lab's checks reads (MAX_CRATES = 30), the runs grade the file with those lines put back to the handout's
        (handout.constant_edits): the edits never run, so they change no grade, and handout_unchanged says so
        as a warning. When the scenes run they also run on the file itself: an edit that changes what they record
        or print is graded as any other edit is (handout_unchanged fails and the criteria wait for it).
        """
        scratch = None
        try:
            scratch, graded, edits = self._handout_copy(path, lab)
            return self._grade(path, lab, graded, edits)
        finally:
            if scratch is not None:
                shutil.rmtree(scratch, ignore_errors=True)

    def _handout_copy(self, path, lab):
        """(scratch folder or None, the copy's path, (the text it was made from, [ConstantEdit])) for the runs."""
        if self.options.get("allow_edits"):   # the instructor allows edits: the file runs as it is
            return None, None, None
        try:
            text = source.read(path, os.path.basename(path))
            starter = source.read(lab.starter)
            edits = handout.constant_edits(text, starter)
            if not edits or any(set(e.names) & checked_names(lab, text) for e in edits):
                return None, None, None   # a constant a check reads stays an edit that fails
            copy = handout.with_handout_lines(text, starter, edits)
        except (OSError, source.SourceError, ValueError, RecursionError, MemoryError):
            return None, None, None
        scratch = tempfile.mkdtemp(prefix="checker-handout-")   # the grader's own folder (mode 700)
        graded = os.path.join(scratch, os.path.basename(path))
        with open(graded, "x", encoding="utf-8") as handle:
            handle.write(copy)
        return scratch, graded, (text, edits)

    def _grade(self, path, lab, graded=None, edits=None):
        start = time.monotonic()
        given, path = path, os.path.abspath(path)   # the report names the file as the user typed it
        with open(path, "rb") as handle:
            raw = handle.read()
        digest = hashlib.sha256(raw).hexdigest()
        name = os.path.basename(path)
        try:   # the text and lines the compiler reads (the child compiles this same text)
            text = source.decode(raw, name)
            source.check(text, name)
        except source.SourceError as exc:
            return LabReport(given, lab, skipped_all(lab.checks, f"{exc}."), time.monotonic() - start)
        sub = Submission(path=path, name=name, source=text, options=dict(self.options), starter=lab.starter)
        if graded is not None and edits[0] == text:   # made from this same text: the runs grade that copy
            sub.edits_not_run = [e.problem for e in edits[1]]
        else:
            graded = None
        runs = graded or path   # the file the children run (the grader's copy with the handout's lines, or it)
        sub.flags = step_rules.scan_lab(sub.source, lab, path)   # the steps' code, read before any of it runs
        sub.function_steps = probing.steps_by_function(lab)
        settings = probing.settings_for(lab, sub.source, self.seed)
        sub.probe = self.run(runs, "probe", settings)
        if sub.probe is None:
            return LabReport(given, lab, skipped_all(lab.checks, self._late_message()), time.monotonic() - start,
                             seed=settings["seed"], flags=[asdict(b) for b in sub.flags])
        try:   # the grader's own work on what the child reported runs under a budget (checker/judging/budget.py)
            with self._budget():
                if sub.probe.status == "done":   # the verdicts' data: the child's tapes replayed and judged here
                    sub.probe.result["probe"] = probing.judge(lab, path, settings, sub.probe.result.get("probe"))
                state = lab.checks.run(sub, stop_at_scenarios=True)
        except budget.Exhausted as exc:
            return LabReport(given, lab, skipped_all(lab.checks, exc.message()), time.monotonic() - start,
                             seed=settings["seed"], flags=[asdict(b) for b in sub.flags])
        if lab.checks.wants_scenarios(state):
            sub.scenarios = self._scenes(runs, lab)
            if sub.edits_not_run and not self._same_scenes(sub.scenarios, self._scenes(path, lab)):
                # the edited constant changes what the scenes show (MAX_CRATES = 4: clicks drop nothing): an edit
                # that fails handout_unchanged, and the scenes wait for it, as for any other edit
                sub.edits_not_run, sub.scenarios = [], {}
                state = None
        try:   # the checks on the scenes' records, under the budget too
            with self._budget():
                if state is None:
                    state = lab.checks.run(sub, stop_at_scenarios=True, state=None)
                results = lab.checks.run(sub, state=state).ordered(lab.checks)
        except budget.Exhausted as exc:
            results = skipped_all(lab.checks, exc.message())
        with open(path, "rb") as handle:
            if hashlib.sha256(handle.read()).hexdigest() != digest:
                results = skipped_all(lab.checks, f"{sub.name} changed while it was being graded; grade it again.")
        records = {}
        if self.keep_records:   # only the scenes a failed check reads (the lab's picture_scenes): records are big
            scenes = getattr(lab, "picture_scenes", None) or {}
            wanted = {scene for r in results if r.status in (FAIL, ERROR) for scene in scenes.get(r.id, ())}
            settings_of = lab.scenarios()   # a record is kept only when it can be the runtime's (record_problem)
            records = {name: run.record for name, run in sub.scenarios.items()
                       if name in wanted and getattr(run, "record", None)
                       and not record_problem(run.record, settings_of.get(name) or {})}
        preview, preview_note = "", ""
        if self.keep_records and not sub.scenarios and self._wants_preview(results):
            # a function check failed, so no scene ran: run a scene anyway, for a picture only (not graded):
            # the failing step with the solution's others, where it differs from the solution (checker/replay/preview.py)
            from checker.replay import preview as previews
            self.preview_started()
            name, record, note = previews.scene_for(self.run, path, sub.source, lab, previews.failing_step(results),
                                                    previews.reference_record)
            if record:
                records[name], preview, preview_note = record, name, note
        runs = [sub.probe, *sub.scenarios.values()]
        notes = sorted({note for run in runs for note in getattr(run, "notes", ())})
        return LabReport(given, lab, results, time.monotonic() - start, records, preview, settings["seed"],
                         [asdict(b) for b in sub.flags], notes, preview_note)

    def preview_started(self):
        """Called as the ungraded scene of a failed function check starts (--show prints that it is recording)."""

    def _scenes(self, path, lab):
        """{scene name: its run} of every scene of the lab, run in parallel on `path` (a scene the whole run's time
        limit left out is missing)."""
        wanted, runs = lab.scenarios(), {}
        with ThreadPoolExecutor(max_workers=len(wanted)) as pool:
            futures = {name: pool.submit(self.run, path, "scenario", dict(settings, probes=lab.probes),
                                         lab.scene_seconds(name, settings))
                       for name, settings in wanted.items()}
            for name, future in futures.items():
                run = future.result()
                if run is not None:
                    runs[name] = run
        return runs

    @staticmethod
    def _same_scenes(graded, own):
        """True when the file's own runs of the scenes show exactly what the graded runs (the handout's lines put
        back) show: the same end, records (less the bodies' colours, which no check measures) and printed output."""
        return set(graded) == set(own) and all(
            (graded[n].status, _measured(graded[n].record), graded[n].stdout)
            == (own[n].status, _measured(own[n].record), own[n].stdout) for n in graded)

    @staticmethod
    def _wants_preview(results):
        """True when the file loaded and kept the handout but failed (or erred in) a function check."""
        by_id = {r.id: r for r in results}
        loaded = by_id.get("loads") is None or by_id["loads"].status == PASS
        return loaded and any(r.status in (FAIL, ERROR) for r in results)

    def _budget(self):
        """The budget of the grader's own work on one file's runs: a run's CPU seconds (--timeout), its wall-clock
        limit and the whole run's deadline (--total-timeout), whichever comes first."""
        deadline = time.monotonic() + wall_limit(self.limits)
        return budget.Budget(cpu=self.limits.timeout,
                             deadline=deadline if self.deadline is None else min(deadline, self.deadline))

    def _late_message(self):
        return f"not graded: the time limit for the whole run ({self.total_timeout:g} s) ran out first."


def checked_names(lab, text):
    """The names a check may read: every identifier in the step regions (the file's and the lab's solution's) and in
    the lab's checks, probes and scenes modules. A constant changed outside the steps under one of these names is
    an edit that fails handout_unchanged, never one graded as the handout's."""
    names = handout.names_read(text)
    try:
        names |= handout.names_read(source.read(lab.solution))
    except (OSError, source.SourceError):
        pass
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "labs", lab.id)
    for module in ("checks.py", "probes.py", "scenes.py"):
        try:
            with open(os.path.join(folder, module), encoding="utf-8") as handle:
                tree = ast.parse(handle.read())
        except (OSError, SyntaxError, ValueError):
            continue
        for node in ast.walk(tree):   # names, attributes, and names spelled as strings (getattr(module, "SLOP"))
            if isinstance(node, ast.Name):
                names.add(node.id)
            elif isinstance(node, ast.Attribute):
                names.add(node.attr)
            elif isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value.isidentifier():
                names.add(node.value)
    return names


def _measured(record):
    """A scene's record without the bodies' "color" (drawn by the replay, measured by no check), else as it is."""
    if not isinstance(record, dict) or not isinstance(record.get("records"), list):
        return record
    frames = [dict(frame, bodies=[{k: v for k, v in body.items() if k != "color"} if isinstance(body, dict) else body
                                  for body in frame["bodies"]])
              if isinstance(frame, dict) and isinstance(frame.get("bodies"), list) else frame
              for frame in record["records"]]
    return dict(record, records=frames)
