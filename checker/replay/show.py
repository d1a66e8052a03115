"""`python -m checker FILE --show [CHECK] [--seed N]`: replay what the checker saw, in a window.

The file is graded exactly as `python -m checker FILE` grades it (checker/grade.py: the student's
code runs only in the isolated child, with its limits); the grader keeps the records the child wrote.
The solution's run of the same scene is computed on the grading side (checker/replay/pictures.py's
reference_record, one child run of solutions/<lab>.py). Nothing of the student's file is imported
or run in this process: the window replays recorded frames (checker/replay/show_view.py).

What is shown (Replay):
  * CHECK, or the first failed check of the file;
  * for a behaviour check, the scene it reads; for a failed function check, whose scenes never ran,
    a scene run ungraded with the student's failing step and the lesson's other steps, where it
    differs from the solution's (checker/replay/preview.py, as --pictures draws it), and its failing cases
    (the CASES of the lab's checker/labs/<id>/show.py, looked up by checker/replay/show_cases.py);
  * the check's quantity per frame with its bound (the SERIES of the lab's checker/labs/<id>/show.py;
    for a function check, how far the student's bodies are from the solution's), and the failing
    frame (checker/replay/show_series.py failure()).
"""
import math
import os
import sys
from dataclasses import dataclass, field

from lesson11 import records as metrics

from checker.replay import pictures, show_cases
from checker.reporting import report
from checker.replay import preview as previews
from checker.judging.checks import ERROR, FAIL, PASS
from checker.grade import Grader
from checker.judging.lab_checks import world_settings
from checker.replay.show_series import Quantity, failure, nearest

NO_DISPLAY = "no display: use --pictures DIR"


# ---------------------------------------------------------------- the replay

@dataclass
class Replay:
    """Everything the window shows for one check: recorded frames only, no code of the student's.

    frames / reference: the student's and the solution's recorded frames (lesson11.runtime records);
    values: the quantity per student frame; fail_frame: a recorded frame number (or None);
    cases: the failing cases of a function check (checker/replay/show_cases.py), possibly [];
    settings / reference_settings: the World's settings per student / solution frame (lab_checks.world_settings:
    validated, None where none was recorded or one was ignored); settings_note: why one was ignored, or "".
    """
    path: str
    lab: object
    check: object                # the checks.Result shown
    scene: str | None
    graded: bool                 # False: the scene ran ungraded, to show what a failed function check does
    seed: int | None
    frames: list
    reference: list
    quantity: Quantity | None
    values: list
    fail_frame: int | None
    fail_reason: str
    cases: list = field(default_factory=list)
    settings: list = field(default_factory=list)
    reference_settings: list = field(default_factory=list)
    settings_note: str = ""
    spliced: str = ""            # "your step 5 with the lesson's steps 2, 3, 4, 6" (checker/replay/preview.py), or ""

    def settings_at(self, index):
        """(the student's World settings at frames[index], the solution's at the same frame number): dicts or None."""
        if not self.frames:
            return None, None
        mine = self.settings[index] if index < len(self.settings) else None
        number = self.frames[index]["frame"]
        nearest = min(range(len(self.reference)), key=lambda i: abs(self.reference[i]["frame"] - number),
                      default=None)
        theirs = self.reference_settings[nearest] if nearest is not None and nearest < len(self.reference_settings) \
            else None
        return mine, theirs

    def reference_at(self, number):
        """The solution's recorded frame with this frame number (nearest), or None."""
        return nearest(self.reference, number)

    def index_of(self, number):
        """Index into frames of the recorded frame with this number (nearest)."""
        return min(range(len(self.frames)), key=lambda i: abs(self.frames[i]["frame"] - number)) if self.frames else 0

    def summary(self):
        """The lines --show prints before it opens the window (the seed, the check, the frame it jumps to)."""
        lines = [f"--show: {self.check.id} ({self.check.status}): {report.printable(self.check.message)}".rstrip(),
                 f"  graded with seed {self.seed}: python -m checker {report.one_line(self.path)} "
                 f"--show {self.check.id} "
                 f"--seed {self.seed} replays this run"]
        if self.scene:
            kind = "the scene it reads" if self.graded else "run ungraded to show what the check means"
            lines.append(f"  scene '{self.scene}' ({kind}): {len(self.frames)} frames, the solution's beside it")
        if self.spliced:
            lines.append(f"  the run is {self.spliced}: the failing step alone")
        if self.fail_frame is not None:
            lines.append(f"  failing frame {self.fail_frame} (t = {self.fail_frame / metrics.FPS:.2f} s): "
                         f"{self.fail_reason}")
        if self.cases:
            lines.append(f"  {len(self.cases)} failing case(s) drawn: [ and ] step through them")
        if self.settings_note:
            lines.append(f"  solver panel: {self.settings_note}")
        return lines


class ShowGrader(Grader):
    """The Grader, keeping every child run it makes (the probe's judged data, for the function cases)."""

    def __init__(self, *args, announce=None, **kwargs):
        super().__init__(*args, **kwargs)
        self.runs = []
        self.announce = announce   # called with a line to print as the work changes (None: print nothing)
        self.announced = False

    def preview_started(self):
        self.recording()

    def recording(self):
        """Say once that the replay is being recorded."""
        if self.announce is not None and not self.announced:
            self.announced = True
            self.announce("recording the replay (your run and the solution's)...")

    def run(self, lab_path, task, settings, priority=math.inf):
        result = super().run(lab_path, task, settings, priority)
        self.runs.append((task, result))
        return result

    def probe_functions(self):
        """The judged probe data {probe name: entry} of the last graded file ({} without a probe)."""
        probe = next((run for task, run in self.runs if task == "probe" and run is not None), None)
        if probe is None or probe.status != "done":
            return {}
        return ((probe.result or {}).get("probe") or {}).get("functions") or {}


def target(row, check_id=None):
    """The result --show shows: CHECK, else the first failed (or erred) check, else None."""
    if check_id:
        return next((r for r in row.results if r.id == check_id), None)
    return next((r for r in row.results if r.status in (FAIL, ERROR)), None)


trusted_frames = previews.trusted_frames


def _scene_choice(row, result, rerun, reference_record):
    """(scene, graded, student frames, solution frames, spliced note) for a result.

    A behaviour check: the scene it reads, as graded. A function check (its scenes never ran): the scene
    the grader ran ungraded for the file's first failure (checker/replay/preview.py: the failing step with the
    lesson's other steps, in a scene where the run differs from the solution's); for another check, the
    same made again for that check's own step (rerun(result): in the isolated child, as the grader does)."""
    lab = row.lab
    scenes, ungraded = pictures._scenes_of(row, result.id) if row.records else ((), False)
    if (ungraded or not scenes) and rerun is not None and result is not previews.failing_step(row.results):
        scene, record, note = rerun(result)
        frames = trusted_frames(lab, scene, record) if scene else []
        ungraded = True
    else:
        scene = next((s for s in scenes if (row.records.get(s) or {}).get("records")), None)
        frames = trusted_frames(lab, scene, row.records.get(scene)) if scene else []
        note = getattr(row, "preview_note", "") if ungraded else ""
    scene = scene if frames else None
    reference = ((reference_record(lab, scene) or {}).get("records") or []) if scene else []
    return scene, scene is not None and not ungraded, frames, reference, note if scene else ""


def build_replay(row, result, functions=None, rerun=None, reference_record=None):
    """The Replay of one graded row's result: its scene (if any was recorded), the solution's, the quantity.

    rerun(result) -> (scene, record, note): a function check's scene made for that check (see _scene_choice)."""
    lab = row.lab
    reference_record = reference_record or pictures.reference_record
    scene, graded, frames, reference, spliced = _scene_choice(row, result, rerun, reference_record)
    fail_frame, reason, quantity, values = failure(lab, result, frames, reference, graded)
    cases = show_cases.failing_cases(lab, result, functions or {}, row.seed)
    settings, note = world_settings(frames)
    reference_settings, reference_note = world_settings(reference)
    note = f"yours: {note}" if note else f"the solution's: {reference_note}" if reference_note else ""
    return Replay(row.path, lab, result, scene, graded, row.seed, frames, reference, quantity, values, fail_frame,
                  reason, cases, settings, reference_settings, note, spliced)


def prepare(path, lab, check_id=None, seed=None, limits=None, options=None, announce=None):
    """(row, Replay or None, message): grade `path` as `lab` (with the grading seed) and build the replay.

    message: why there is nothing to replay ("" when there is); announce: called with a line to print as the
    work moves from grading to recording (the command line prints them; None: silent).
    """
    grader = ShowGrader(limits, 1, None, options=options, keep_records=True, seed=seed, announce=announce)
    if announce is not None:
        announce(f"grading {path}...")
    row = grader.grade(path, lab)
    result = target(row, check_id)
    if result is None:
        return row, None, (f"{check_id}: no such check in {lab.title}" if check_id else
                           "every check passes: nothing to show")
    if result.id == "loads" and result.status != PASS:
        return row, None, "the file does not load (see above)"
    def rerun(other):   # another function check's step, run as the grader runs the preview (checker/replay/preview.py)
        from checker.reading import source
        try:
            text = source.read(path)
        except (OSError, source.SourceError):
            return None, None, ""
        return previews.scene_for(grader.run, path, text, lab, other, pictures.reference_record)

    grader.recording()
    return row, build_replay(row, result, grader.probe_functions(), rerun), ""


def display_problem(environ=None, platform=None):
    """Why no window can open here ("" when one can): a Linux or BSD desktop needs $DISPLAY or
    $WAYLAND_DISPLAY, unless SDL is told which video driver to use (the tests' dummy driver)."""
    environ = dict(os.environ, SDL_VIDEODRIVER=pictures.USER_VIDEO_DRIVER or "") if environ is None else environ
    platform = platform or sys.platform
    if environ.get("SDL_VIDEODRIVER"):
        return ""
    if platform.startswith(("win", "darwin")) or platform == "cygwin":
        return ""
    return "" if environ.get("DISPLAY") or environ.get("WAYLAND_DISPLAY") else NO_DISPLAY


def main(args, entries, events=None, frames=None, out=None, err=None):
    """Run --show for the command line (one entry); returns the exit status. events / frames: for tests
    (an event source and a frame limit, checker/replay/show_view.py)."""
    out, err = out or sys.stdout, err or sys.stderr
    entry = entries[0]
    if not entry.gradable:
        print(f"checker: {entry.path}: not graded: {entry.problem}", file=err)
        return 1
    from checker.isolation.sandbox import Limits
    limits = Limits(args.timeout, args.memory, args.max_output * 1024, args.child_user, disk_mb=args.disk)
    check_id = args.show or None
    if check_id and check_id not in [c.id for c in entry.lab.checks.checks]:
        known = ", ".join(c.id for c in entry.lab.checks.checks)
        print(f"checker: error: --show {check_id}: {entry.lab.title} has no such check; its checks: {known}",
              file=err)
        return 2
    def announce(line):   # the window takes seconds to prepare: say what is happening meanwhile
        print(line, file=err, flush=True)

    try:
        row, replay, problem = prepare(entry.path, entry.lab, check_id, args.seed, limits,
                                       {"allow_edits": args.allow_edits}, announce)
    except Exception as exc:  # noqa: BLE001 - a bug of ours on this file: one line, never a traceback
        print(f"checker: error: --show could not grade {entry.path} ({type(exc).__name__}: {exc}); this is a bug "
              "in the checker, please report it", file=err)
        return 1
    report.text_report(row, out)
    print(f"Graded with seed {row.seed} (--seed {row.seed} grades with the same inputs).", file=out)
    if replay is None:
        print(f"--show: {problem}", file=out)
        return 0 if row.passed else 1
    for line in replay.summary():
        print(line, file=out)
    from checker.replay import show_view
    try:
        show_view.run(replay, events=events, frames=frames)
    except Exception as exc:   # a bug of ours, or a window the system refused: one line, the grades stand
        print(f"checker: error: --show could not draw the replay ({type(exc).__name__}: {exc}); the report above "
              "stands", file=err)
    return 0 if row.passed else 1
