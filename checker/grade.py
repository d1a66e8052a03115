"""Grading one lab file, and many in parallel.

A lab file is graded in two stages, each in isolated child processes:
  1. the probe: import the file and test its own functions (one child);
  2. if the checks that read the scenes can run (every check they depend on
     passed): one child per scenario.
All children of all files share one pool of `jobs` worker slots, so a class
folder keeps every core busy; a freed slot goes to the waiting run expected
to take longest (probes first, then scenes by their lab's SCENE_SECONDS). A file's source is read once (the checker never
writes to it), as the compiler reads it (checker/source.py: a file declaring another coding than UTF-8 is an
error); if the file changes while it is graded the result is an error.
"""
import hashlib
import heapq
import itertools
import math
import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field

from . import budget, probing, source, step_rules
from .checks import ERROR, FAIL, PASS, skipped_all
from .sandbox import Limits, run_child, wall_limit


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
    flags: list = field(default_factory=list)   # what the step rules flagged (checker/step_rules.py Breach)
    function_steps: dict = field(default_factory=dict)   # step function name -> its steps (the starter's)
    scenarios: dict = field(default_factory=dict)
    options: dict = field(default_factory=dict)
    starter: str = ""   # path of the lab's handout, which the code outside the steps must match


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
                limits = Limits(min(limits.timeout, max(left, 0.5)), limits.memory_mb, limits.max_output, limits.user)
            run = run_child(lab_path, task, settings, limits)
        finally:
            self.slots.release()
        run.lab_path = lab_path
        run.timeout = limits.timeout
        run.cut_short = limits.timeout < self.limits.timeout and run.status == "timeout"
        run.total_timeout = self.total_timeout
        run.memory_mb = limits.memory_mb
        run.max_output = limits.max_output
        return run

    def grade(self, path, lab):
        """Grade one file as `lab`; returns a LabReport. Never raises for anything the file does."""
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
        sub.flags = step_rules.scan_lab(sub.source, lab, path)   # the steps' code, read before any of it runs
        sub.function_steps = probing.steps_by_function(lab)
        settings = probing.settings_for(lab, sub.source, self.seed)
        sub.probe = self.run(path, "probe", settings)
        if sub.probe is None:
            return LabReport(given, lab, skipped_all(lab.checks, self._late_message()), time.monotonic() - start,
                             seed=settings["seed"], flags=[asdict(b) for b in sub.flags])
        try:   # the grader's own work on what the child reported runs under a budget (checker/budget.py)
            with self._budget():
                if sub.probe.status == "done":   # the verdicts' data: the child's tapes replayed and judged here
                    sub.probe.result["probe"] = probing.judge(lab, path, settings, sub.probe.result.get("probe"))
                state = lab.checks.run(sub, stop_at_scenarios=True)
        except budget.Exhausted as exc:
            return LabReport(given, lab, skipped_all(lab.checks, exc.message()), time.monotonic() - start,
                             seed=settings["seed"], flags=[asdict(b) for b in sub.flags])
        if lab.checks.wants_scenarios(state):
            wanted = lab.scenarios()
            with ThreadPoolExecutor(max_workers=len(wanted)) as pool:
                futures = {name: pool.submit(self.run, path, "scenario", dict(settings, probes=lab.probes),
                                             lab.scene_seconds(name, settings))
                           for name, settings in wanted.items()}
                for name, future in futures.items():
                    run = future.result()
                    if run is not None:
                        sub.scenarios[name] = run
        try:
            with self._budget():
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
            records = {name: run.record for name, run in sub.scenarios.items()
                       if name in wanted and getattr(run, "record", None)}
        preview = ""
        if self.keep_records and not sub.scenarios and self._wants_preview(results):
            # a function check failed, so no scene ran: run the lab's own scene anyway, for a picture only
            # (not graded), so the file that needs a picture most gets one beside the solution's
            name = lab.preview_scene   # (scene_settings, not settings: the report's seed is the probe's)
            scene_settings = lab.scenarios().get(name) if name else None
            run = self.run(path, "scenario", dict(scene_settings, probes=lab.probes),
                           lab.scene_seconds(name, scene_settings)) if scene_settings is not None else None
            if run is not None and getattr(run, "record", None) and run.record.get("records"):
                records[name], preview = run.record, name
        runs = [sub.probe, *sub.scenarios.values()]
        notes = sorted({note for run in runs for note in getattr(run, "notes", ())})
        return LabReport(given, lab, results, time.monotonic() - start, records, preview, settings["seed"],
                         [asdict(b) for b in sub.flags], notes)

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
