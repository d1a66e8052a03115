"""The scene run for a failed function check (its graded scenes never ran): what the failing step does.

A function check grades one lesson step, so no scene ran. Its picture (--pictures) and its replay (--show)
run one of the lab's scenes ungraded, in the isolated child like every run of the student's code, on the
student's file with one change: every step region but the failing step's holds the solution's code
(replay_source: text only, written to a temporary folder; this process never runs it). The run then shows
that step's symptom alone, not the symptom of a later step the student has not written yet.

The scene is the lab's preview scene, unless the run there never differs visibly from the solution's
(VISIBLE_PX or VISIBLE_DEG); then the lab's first other scene where it does (choose).
"""
import math
import os
import tempfile
import threading

from checker.reading import source as source_text
from checker.reading.handout import MarkerError, step_regions
from checker.isolation.sandbox import Limits, run_child

VISIBLE_PX = 5.0    # px: a body this far from the solution's is visibly elsewhere at the window's scale
VISIBLE_DEG = 5.0   # degrees: a body turned this much more or less than the solution's visibly differs


def apart(frame, reference):
    """(px, degrees): how far the student's bodies are from the solution's in the same frame, the largest over
    bodies of the same index (both infinite when the frames hold different numbers of bodies)."""
    if reference is None:
        return 0.0, 0.0
    mine, theirs = frame["bodies"], reference["bodies"]
    if len(mine) != len(theirs):
        return math.inf, math.inf
    px = max([math.dist(a["pos"], b["pos"]) for a, b in zip(mine, theirs)] + [0.0])
    deg = max([abs(math.degrees(a["angle"] - b["angle"])) for a, b in zip(mine, theirs)
               if not a.get("static")] + [0.0])
    return px, deg


def visible(frame, reference):
    """True when some body is VISIBLE_PX from the solution's or turned VISIBLE_DEG differently (NaN counts)."""
    px, deg = apart(frame, reference)
    return not (px < VISIBLE_PX and deg < VISIBLE_DEG)


def recorded_colour(body):
    """The colour the lab drew a recorded body with (its "color": three ints 0-255), or None (none recorded, or
    one the record cannot hold: the record comes from the child)."""
    value = body.get("color")
    if isinstance(value, list) and len(value) == 3 and \
            all(isinstance(c, int) and not isinstance(c, bool) and 0 <= c <= 255 for c in value):
        return tuple(value)
    return None


def nearest(frames, number):
    """The recorded frame with this frame number (nearest), or None."""
    return min(frames, key=lambda f: abs(f.get("frame", 0) - number)) if frames else None


def first_visible(frames, reference):
    """The number of the first frame in which the run visibly differs from the solution's, or None."""
    for frame in frames:
        if visible(frame, nearest(reference, frame["frame"])):
            return frame["frame"]
    return None


def trusted_frames(lab, scene, record):
    """The record's frames when they can be what lesson11.runtime wrote for the scene (checker/judging/lab_checks.py
    record_problem), else []: the record comes from the child, where the student's code ran."""
    from checker.judging.lab_checks import record_problem
    settings = lab.scenarios().get(scene)
    if not record or settings is None or record_problem(record, settings):
        return []
    return record["records"]


# ---------------------------------------------------------------- the solution's runs (cached)

_REFERENCE = {}
_REFERENCE_LOCK = threading.Lock()


def reference_record(lab, scene, limits=None):
    """The record of the lab's SOLUTION running `scene` (one child run per process and scene), or None."""
    key = (getattr(lab, "id", None), scene)
    with _REFERENCE_LOCK:
        if key in _REFERENCE:
            return _REFERENCE[key]
        record = None
        solution = getattr(lab, "solution", None)
        settings = lab.scenarios().get(scene) if solution and os.path.isfile(solution) else None
        if settings is not None:
            run = run_child(solution, "scenario", dict(settings, probes=lab.probes), limits or Limits())
            record = getattr(run, "record", None)
        _REFERENCE[key] = record
        return record


# ---------------------------------------------------------------- the student's step with the lesson's others

def replay_source(mine, theirs, step):
    """The student's source `mine` with the inside of every step region but `step` taken from the solution's
    source `theirs` (re-indented to the student's marker), or None when either file's markers cannot be read or
    the student's file has no region for `step`. Returns (text, [the steps taken from the solution])."""
    try:
        mine, theirs = source_text.lines(mine), source_text.lines(theirs)
        my_regions, their_regions = step_regions(mine), step_regions(theirs)
    except (MarkerError, ValueError):
        return None
    if step not in my_regions:
        return None
    lines, taken = list(mine), []
    for other in sorted(my_regions, key=lambda s: my_regions[s][0], reverse=True):   # bottom up: indices hold
        if other == step or other not in their_regions:
            continue
        start, end, indent = my_regions[other]
        their_start, their_end, their_indent = their_regions[other]
        lines[start + 1:end] = [indent + line[len(their_indent):] if line.startswith(their_indent) else line
                                for line in theirs[their_start + 1:their_end]]
        taken.append(other)
    return "\n".join(lines) + "\n", sorted(taken)


def describe(step, taken):
    """The line the picture and the window show about a spliced run: "your step 5 with the lesson's steps 2-4,
    6" ("" when nothing was spliced)."""
    if not taken:
        return ""
    runs = []   # consecutive steps as one range: [2, 3, 4, 6] -> "2-4", "6"
    for s in sorted(taken):
        if runs and s == runs[-1][1] + 1:
            runs[-1][1] = s
        else:
            runs.append([s, s])
    text = ", ".join(f"{a}" if a == b else f"{a}, {b}" if b == a + 1 else f"{a}-{b}" for a, b in runs)
    return f"your step {step} with the lesson's step{'s' if len(taken) > 1 else ''} {text}"


def runner(run, path, lab, text=None):
    """run_scene(name) -> the record of the lab's scene `name` run ungraded in the child, or None.

    run: Grader.run (the grader's limits and slots); text: the changed source to run instead of the file
    (written to a temporary folder under the file's own name, removed afterwards)."""
    def run_scene(name):
        settings = lab.scenarios().get(name)
        if settings is None:
            return None
        with tempfile.TemporaryDirectory(prefix="checker-replay-", ignore_cleanup_errors=True) as folder:
            target = os.path.abspath(path)
            if text is not None:
                target = os.path.join(folder, os.path.basename(path))
                with open(target, "x", encoding="utf-8", newline="") as handle:
                    handle.write(text)
            result = run(target, "scenario", dict(settings, probes=lab.probes), lab.scene_seconds(name, settings))
        record = getattr(result, "record", None) if result is not None and result.status == "done" else None
        return record if record and record.get("records") else None
    return run_scene


def choose(lab, run_scene, reference_record, first=None):
    """(scene, record) of the lab's scene to show: `first` (default the lab's preview scene) when its run
    visibly differs from the solution's somewhere, else the lab's first other scene where it does, else `first`
    (None, None when no scene could be recorded)."""
    first = first or lab.preview_scene
    names = [first] + [name for name in lab.scenarios() if name != first]
    fallback = (None, None)
    for name in names:
        record = run_scene(name)
        frames = trusted_frames(lab, name, record)
        if not frames:
            continue
        theirs = (reference_record(lab, name) or {}).get("records") or []
        if first_visible(frames, theirs) is not None:
            return name, record
        if fallback[0] is None:
            fallback = (name, record)
    return fallback


def failing_step(results):
    """The first failed (or erred) result of a graded file, or None."""
    return next((r for r in results if r.status in ("fail", "error")), None)


def scene_for(run, path, text, lab, result, reference_record):
    """(scene, record, note) to show for a failed function check `result` of the file at `path` (its source
    `text`): the student's failing step with the solution's other steps (note: describe()'s line; the whole file,
    note "", when the check names no step, the markers cannot be read or the spliced file runs to the end in no
    scene), in the scene choose() picks.
    run: Grader.run; reference_record(lab, scene): the solution's record (checker/replay/pictures.py's)."""
    step = getattr(result, "step", None)
    spliced = None
    if step and getattr(lab, "solution", None):
        try:
            spliced = replay_source(text, source_text.read(lab.solution), step)
        except (OSError, source_text.SourceError):
            spliced = None
    changed, taken = spliced or (None, [])
    name, record = choose(lab, runner(run, path, lab, changed if taken else None), reference_record)
    if record is None and taken:   # the spliced file ran in no scene (the student's step reads a name of their
        name, record = choose(lab, runner(run, path, lab), reference_record)   # own other step): the whole file
        taken = []
    return name, record, describe(step, taken)
