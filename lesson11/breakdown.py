"""When a student's function breaks the simulation: the lab window pauses on that frame and says what happened.

Every lab gets this through the shared runtime, with nothing in the lab file (the window itself is
pause_window.py):
  - the solver panel's advance() (panel.py) catches an error raised inside the World's step
    (sat, resolve, apply_impulse, separate, circle_polygon, the sleep and swept hooks, ...);
  - the lab runtime (runtime.py) installs `excepthook` for an error in the lab's own main-loop code.
Instead of closing, the window stays open on the frame that broke: the bodies, the two bodies of
the call outlined, its contact point and normal, and which function of the student's file did it,
at which line, the error, and what a known mistake means (lesson11/mistakes.py: the checker's
words). R restarts the lab from its file (after a fix); Escape closes it.

A value of the wrong kind or a non-finite one left on a body (omega a Vector2, vel None, NaN) is
named at the end of the call that left it: the panel keeps a copy of the bodies before each frame
(Snapshot), and after an error it runs that frame again from the copy with a line tracer on the
student's file (replay), which stops at the first line after which a body holds such a value. So
nothing runs per call while nothing breaks: the cost is the copy, once a frame
(lesson11/bench/pause_cost.py measures it).

The terminal gets the student's frames only, with one line naming the engine phase that called
them; LESSON11_TRACEBACK=1 prints the full traceback as well. Under the checker none of this runs: the
error ends the run as before (the checker reports it), unless LESSON11_PAUSE_REPORT names a file, where
the tests have the pause write what it shows (JSON, and a PNG beside it) and then press Escape.
"""
import contextlib
import io
import linecache
import os
import sys
import traceback

import pygame

from . import mistakes
from .pause_window import REPORT_VAR, body_name, pause
from .physics2d.bodies import Body

TRACEBACK_VAR = "LESSON11_TRACEBACK"   # "1": print the full traceback too


# the World's methods (and the engine's functions) that call a lab's hooks, as the terminal and the window name them
PHASES = {"resolve_calls": "the World's resolve pass", "resolve_pass": "the World's resolve pass",
          "push_out": "the World's push-out", "step_move_first": "the World's contact pass (move-first order)",
          "_plain_manifolds": "the World's contact search", "manifolds": "the World's contact search",
          "collide": "the World's contact search", "_speculative_manifolds": "the World's contact search",
          "integrate_positions": "the World's move", "_move_bodies": "the World's move",
          "integrate_velocities": "the World's gravity kick", "update": "the World's sleep update",
          "update_sleep": "the World's sleep update", "end_step": "the end of the World's step",
          "swept_move": "the World's swept move", "advance": "the World's step", "step": "the World's step"}

_HERE = os.path.abspath(__file__)
_PANEL = os.path.join(os.path.dirname(_HERE), "panel.py")
_CLOCK = os.path.join(os.path.dirname(_HERE), "hook_clock.py")   # the full panel's timers wrap the lab's hooks
_panel = None          # the lab's solver panel (LabPanel registers itself): its world and frame count
_checker_run = [lambda: False]   # runtime.active, once the runtime installs this module (install)


def watch(panel):
    """Remember the lab's solver panel: the excepthook draws its world and counts its frames."""
    global _panel
    _panel = panel


def install(checker_run):
    """Called by the lab runtime: `checker_run()` says whether the checker drives this run; an error in the lab's
    own code pauses the window too (sys.excepthook, unless something else set its own)."""
    _checker_run[0] = checker_run
    if sys.excepthook is sys.__excepthook__:
        sys.excepthook = excepthook


def enabled():
    """True when an error pauses the window: a student's run (not the checker's), or a test's LESSON11_PAUSE_REPORT."""
    return not _checker_run[0]() or bool(os.environ.get(REPORT_VAR))


def lab_file():
    """The student's file: the script this Python runs (its __main__), as an absolute path, or None."""
    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    return os.path.abspath(path) if path else None


# ---------------------------------------------------------------- the copy before each frame


class Snapshot:
    """The World and its bodies as they were before a frame: restore() puts them back, for the replay."""

    def __init__(self, world):
        self.world = world
        self.world_vars = {name: _copied(value) for name, value in vars(world).items()}
        self.bodies = [(body, _body_vars(body)) for body in world.bodies]

    def restore(self):
        for body, saved in self.bodies:
            vars(body).clear()
            vars(body).update(_body_vars_of(saved))
        vars(self.world).clear()
        vars(self.world).update({name: _copied(value) for name, value in self.world_vars.items()})


def _body_vars(body, _vector=pygame.Vector2):
    """A body's attributes, its position and velocity copied (a step changes them in place; the rest it replaces)."""
    saved = dict(vars(body))
    try:
        saved["_pos"], saved["vel"] = _vector(saved["_pos"]), _vector(saved["vel"])
    except (KeyError, TypeError, ValueError):   # not a plain Body: copy whatever a step may change in place
        saved = {name: _copied(value) for name, value in saved.items()}
    return saved


def _body_vars_of(saved):
    """A copy of saved body attributes to restore (the snapshot stays as it was, for a second restore)."""
    return {name: _copied(value) for name, value in saved.items()}


def _copied(value):
    """A copy of what a step changes in place (a Vector2, a list, a dict, a set); anything else as it is."""
    kind = type(value)
    if kind is pygame.Vector2 or kind in (list, dict, set):
        return kind(value)
    return value


# ---------------------------------------------------------------- what broke


class _Found(BaseException):
    """Raised by the tracer into the replayed frame at the first bad value (not an Exception: a student's
    `except Exception` does not swallow it)."""


class Finding:
    """What broke: kind "raised" (a function raised), "value" (a function left a bad value on a body) or
    "main" (the lab's own main-loop code raised).

    function, line, text   the student's function, the line of the student's file and its source
    message                "ZeroDivisionError: float division by zero" or "left a body's omega as ..."
    meaning                a known mistake's meaning (mistakes.meaning), or ""
    chain                  [(frame, line)] outermost first, for the terminal
    bodies, point, normal  what to draw: the call's bodies (A, B), its contact point and normal (or None)
    polygons               point lists of the call (sat's pa, pb) when it has no bodies
    phase                  "called by the World's resolve pass, contact 3 of 12, between body 4 and body 0 (static)"
    """

    def __init__(self, kind, chain, message, error=None):
        self.kind, self.chain, self.message, self.error = kind, chain, message, error
        self.file = lab_file()
        own = [(frame, line) for frame, line in chain if _is_lab(frame.f_code, self.file)]
        frame, self.line = own[-1] if own else (chain[-1] if chain else (None, 0))
        self.function = frame.f_code.co_name if frame is not None else "main"   # no frame: the lab's loop
        self.text = _source(frame, self.line)
        self.frame = frame
        self.meaning = (mistakes.meaning(problem=message) if kind == "value"
                        else mistakes.meaning(message, self.text))
        self.bodies, self.point, self.normal, self.polygons = [], None, None, []
        self.phase = ""

    def headline(self):
        """One line: what the function did."""
        if self.kind == "main" and self.frame is None:   # a bad value found before the World's step ran
            return f"the lab's own code {self.message}"
        if self.kind == "value":
            return f"{self.function}() {self.message}"
        return f"{self.function}() raised {self.message}"


def _is_lab(code, path, _seen={}):
    """True if `code` is a function of the student's file `path`."""
    key = (code.co_filename, path)
    if key not in _seen:
        _seen[key] = path is not None and os.path.abspath(code.co_filename) == path
    return _seen[key]


def _source(frame, line):
    return linecache.getline(frame.f_code.co_filename, line).strip() if frame is not None else ""


class _Tracer:
    """sys.settrace for the replay: after every line of the student's file, check the bodies that line could
    reach (the function's Body arguments; at a return, every body of the World)."""

    def __init__(self, world, path):
        self.world, self.path, self.found = world, path, None

    def calls(self, frame, event, arg):
        if event == "call" and _is_lab(frame.f_code, self.path):
            return self.lines(frame)
        return None

    def lines(self, frame):
        last = [frame.f_lineno]

        def trace(frame, event, arg):
            if event in ("line", "return"):
                bodies = self.world.bodies if event == "return" else \
                    [value for value in frame.f_locals.values() if isinstance(value, Body)]
                problem = mistakes.motion_problem(bodies)
                if not problem and event == "return" and frame.f_back is not None \
                        and not _is_lab(frame.f_back.f_code, self.path):
                    problem = mistakes.return_problem(arg)   # a hook's answer to the World (sat's normal, depth)
                if problem:
                    self.found = (frame, frame.f_lineno if event == "return" else last[0], problem)
                    raise _Found()
                last[0] = frame.f_lineno
            return trace
        return trace


def replay(world, snapshot, dt):
    """Run the frame again from `snapshot` with the tracer; returns (finding of a bad value or None, the error the
    replay raised or None). The student's prints during the replay are dropped (they were printed once)."""
    path = lab_file()
    snapshot.restore()
    before = mistakes.motion_problem(world.bodies)
    if before:   # bad before the World ran: the lab's own code between frames left it
        return Finding("main", [], f"{before}, before the World's step (in the main loop)"), None
    tracer, raised = _Tracer(world, path), None
    with contextlib.redirect_stdout(io.StringIO()):
        sys.settrace(tracer.calls)
        try:
            world.advance(dt)
        except _Found:
            pass
        except Exception as error:   # noqa: BLE001 - the student's error again (or another): reported, not raised
            raised = error
        finally:
            sys.settrace(None)
    if tracer.found is None:
        return None, raised
    frame, line, problem = tracer.found
    chain, walk = [], frame
    while walk is not None:
        chain.append((walk, line if walk is frame else walk.f_lineno))
        walk = walk.f_back
    return Finding("value", chain[::-1], problem), None


def from_error(error, kind="raised"):
    """The Finding for an exception: its traceback's frames."""
    chain = [(tb.tb_frame, tb.tb_lineno) for tb in _tracebacks(error.__traceback__)]
    callers, walk = [], chain[0][0].f_back if chain else None   # where it was caught: the frames above it too
    while walk is not None:
        callers.append((walk, walk.f_lineno))
        walk = walk.f_back
    chain = [item for item in callers[::-1] if not _is_lab(item[0].f_code, _HERE)] + chain
    return Finding(kind, chain, f"{type(error).__name__}: {error}", error)


def _tracebacks(tb):
    while tb is not None:
        yield tb
        tb = tb.tb_next


def diagnose(world, error, snapshot, dt):
    """The Finding for `error` raised by world.advance(dt): a bad value found by replaying the frame, else the
    error itself (the replay's, whose frames hold the state when it was raised, if it raised the same)."""
    finding = raised = None
    if snapshot is not None:
        try:
            finding, raised = replay(world, snapshot, dt)
        except Exception:   # noqa: BLE001 - a replay that cannot run: the error as it was raised
            finding = raised = None
    outer = [(frame, line) for frame, line in from_error(error).chain]
    if finding is None:
        same = raised is not None and type(raised) is type(error) and str(raised) == str(error)
        finding = from_error(raised if same else error)
    if finding.chain and finding.chain is not outer:   # the replay's frames, below the lab's call of the panel
        mine = [i for i, (frame, _) in enumerate(finding.chain) if _is_lab(frame.f_code, _HERE)]
        if mine:
            cut = max(mine)
            top = next((i for i, (frame, _) in enumerate(outer) if _is_lab(frame.f_code, _PANEL)), None)
            finding.chain = (outer[:top + 1] if top is not None else []) + finding.chain[cut + 1:]
    if finding.error is None:   # a bad value: LESSON11_TRACEBACK=1 prints where the engine met it
        finding.error = error
    describe_call(finding, world)
    return finding


def describe_call(finding, world):
    """Fill in what to draw (the call's bodies, point, normal or polygons) and the engine phase that called it."""
    bodies = world.bodies if world is not None else []
    own = [i for i, (frame, _) in enumerate(finding.chain) if _is_lab(frame.f_code, finding.file)]
    if not own:
        return
    frame = finding.chain[own[-1]][0]
    values = frame.f_locals
    found = [value for value in values.values() if isinstance(value, Body) and any(value is b for b in bodies)]
    finding.bodies = found[:2]
    # the call that was being made: the outermost frame of the student's innermost run of calls from the engine
    first = own[-1]
    while first - 1 in own:
        first -= 1
    before = [frame for frame, _ in finding.chain[:first] if not _is_lab(frame.f_code, _CLOCK)]   # the panel's
    caller = before[-1] if before else None                                                   # timers aside
    top = finding.chain[first][0].f_locals
    for name in ("normal", "n"):
        if isinstance(top.get(name), pygame.Vector2):
            finding.normal = pygame.Vector2(top[name])
            break
    point = top.get("point") if isinstance(top.get("point"), pygame.Vector2) else None
    if point is None and isinstance(values.get("ra"), pygame.Vector2) and finding.bodies:
        point = finding.bodies[0].pos + values["ra"]
    finding.point = pygame.Vector2(point) if point is not None else None
    if finding.kind == "main":   # the main loop's locals are not a call's pair: nothing outlined
        finding.bodies = []
    if not finding.bodies:
        finding.bodies = [value for value in top.values() if isinstance(value, Body)][:2]
        finding.polygons = [list(value) for value in top.values() if isinstance(value, list) and value
                            and all(isinstance(p, pygame.Vector2) for p in value)][:2]
        if finding.polygons and not finding.bodies:   # sat(pa, pb): the bodies whose outlines these are
            finding.bodies = [body for points in finding.polygons for body in bodies if _outlines(body, points)][:2]
    if caller is None or _is_lab(caller.f_code, finding.file):
        finding.phase = "" if finding.kind != "main" else "in your main loop"
        return
    name = caller.f_code.co_name
    phase = PHASES.get(name, f"physics2d's {name}()")
    pair = finding.bodies or [value for value in (caller.f_locals.get("a"), caller.f_locals.get("b"),
                                                  caller.f_locals.get("body")) if isinstance(value, Body)][:2]
    finding.bodies = pair
    detail = _contact_number(caller, top)
    if len(pair) == 2:
        detail += f"{', ' if detail else ''}between {body_name(pair[0], bodies)} and {body_name(pair[1], bodies)}"
    elif len(pair) == 1:
        detail += f"{', ' if detail else ''}for {body_name(pair[0], bodies)}"
    finding.phase = f"called by {phase}" + (f", {detail}" if detail else "")


def _outlines(body, points):
    """True if `points` are the body's world points (the polygon a hook such as sat was handed)."""
    try:
        return [tuple(p) for p in body.world_points()] == [tuple(p) for p in points]
    except Exception:   # noqa: BLE001 - a body in a bad state matches nothing
        return False


def _contact_number(caller, call):
    """"contact 3 of 12" when the engine frame is the resolve pass and the call is found in its list, else ""."""
    calls = caller.f_locals.get("calls")
    a, b, point = call.get("a"), call.get("b"), call.get("point")
    if not isinstance(calls, list) or point is None:
        return ""
    for k, item in enumerate(calls):
        if isinstance(item, tuple) and len(item) == 4 and item[0] is a and item[1] is b and item[3] is point:
            return f"contact {k + 1} of {len(calls)}"
    return ""


# ---------------------------------------------------------------- the terminal


def terminal_text(finding, frame_number=None):
    """The student's frames only, traceback-style, with one line naming the engine phase that called them."""
    lines = [f"The lab paused{f' on frame {frame_number}' if frame_number else ''}: "
             f"{finding.headline()}",
             f"Your code only ({TRACEBACK_VAR}=1 shows the engine's frames too):"]
    previous_own = None
    for frame, line in finding.chain:
        own = _is_lab(frame.f_code, finding.file)
        if own:
            if previous_own is False and frame is finding.chain[_first_of_last_run(finding)][0] and finding.phase:
                lines.append(f"  ... {finding.phase}")
            elif previous_own is False and len(lines) > 2:
                lines.append("  ... called by physics2d")
            lines.append(f'  File "{_shown_path(frame.f_code.co_filename)}", line {line}, in {frame.f_code.co_name}')
            text = _source(frame, line)
            if text:
                lines.append(f"    {text}")
        previous_own = own
    if finding.chain and not _is_lab(finding.chain[-1][0].f_code, finding.file) and finding.kind != "value":
        inner = finding.chain[-1][0].f_code
        owner = "physics2d's " if "physics2d" in inner.co_filename else ""
        lines.append(f"  ... inside {owner}{inner.co_name}(), called by the line above")
    lines.append(finding.message if finding.kind != "value" else f"{finding.function}() {finding.message}")
    if finding.meaning:
        lines.append(f"What it means: {finding.meaning}.")
    return "\n".join(lines)


def _first_of_last_run(finding):
    own = [i for i, (frame, _) in enumerate(finding.chain) if _is_lab(frame.f_code, finding.file)]
    first = own[-1]
    while first - 1 in own:
        first -= 1
    return first


def _shown_path(path):
    try:
        relative = os.path.relpath(path)
    except ValueError:   # another drive (Windows)
        return path
    return relative if len(relative) < len(path) else path


def print_report(finding, frame_number=None):
    """Print the finding to stderr; the full traceback first when LESSON11_TRACEBACK=1."""
    if os.environ.get(TRACEBACK_VAR, "") not in ("", "0") and finding.error is not None:
        traceback.print_exception(type(finding.error), finding.error, finding.error.__traceback__)
    print(terminal_text(finding, frame_number), file=sys.stderr, flush=True)


# ---------------------------------------------------------------- the two ways in


def halt(world, error, snapshot, dt, frame_number):
    """An error out of world.advance(dt) on frame `frame_number`: diagnose it, print it, pause the window.
    Returns when pausing is off (the checker's run), or if the diagnosis itself fails: the caller then raises
    the error as before (never a second error of ours in its place)."""
    if not enabled() or isinstance(error, _Found):
        return
    try:
        finding = diagnose(world, error, snapshot, dt)
        print_report(finding, frame_number)
    except Exception:   # noqa: BLE001 - our own failure must not hide the student's error
        return
    pause(world, finding, frame_number)


def excepthook(kind, error, tb, _default=sys.excepthook):
    """sys.excepthook for a student's run: an error in the lab's own code (outside the World's step) pauses the
    window the same way, on the last world the panel drew; with no window yet, the student's lines are printed;
    anything else, or the checker's run, as Python does."""
    if not enabled() or not isinstance(error, Exception) or error.__traceback__ is None:
        return _default(kind, error, tb)
    try:
        finding = from_error(error, "main")
        if not any(_is_lab(frame.f_code, finding.file) for frame, _ in finding.chain):
            return _default(kind, error, tb)
        world = getattr(_panel, "world", None)
        describe_call(finding, world)
        if not finding.phase:
            finding.phase = "in your main loop, outside the World's step"
        frame_number = getattr(_panel, "advances", None)
        print_report(finding, frame_number)
    except Exception:   # noqa: BLE001 - our own failure must not hide the student's error
        return _default(kind, error, tb)
    if pygame.display.get_init() and pygame.display.get_surface() is not None:
        with contextlib.suppress(SystemExit):
            pause(world, finding, frame_number)
