"""The solver panel: change the physics while a lab runs, and see what accuracy costs.

Every lab window gets the same panel through four calls (solutions/tumbling_crates.py
shows them, each on a line marked `# solver panel`):

    panel = LabPanel()                     # once, before the main loop
    panel.handle(event)                    # first thing for every event
    steps = panel.advance(world, dt)       # instead of world.advance(dt); dt in s
    panel.draw(screen, world)              # after the scene, before display.flip()

Keys (none of them is used by a lab: D = debug view, R = reset, left click = drop):
  S            solver: "lesson" (the lab's own sat() and resolve()) or "accumulated"
               (the reference solver, physics2d/arbiter.py; the lab's functions are not used)
  Up / Down    solver iterations +1 / -1 (1 .. MAX_ITERATIONS)
  Right / Left sub-steps +1 / -1 (1 .. MAX_SUBSTEPS)
  W            warm starting on / off (the accumulated solver's; the lesson solver has none)
  C            positional correction on / off (the "correction" effect: the push-out)
  K            contact rule "corners" (the lesson's) / "clip" (edge clipping)
  0            back to the settings the World was built with
  P            pause / run;  O  one physics step (pauses first if running)
  H            panel size: compact (the default, a small box) -> full -> hidden -> compact

Both sizes show the solver settings, the cost of one fixed physics step (ms/step,
measured around the world's advance() with time.perf_counter and divided by the
steps run), how much of real time the simulation keeps ("1.0x real time": the
World runs at most max_steps steps a frame and drops the rest, so a slow setting
makes time slow down instead of spiralling), and the study line: what the
accuracy study (python -m lesson11.bench.accuracy_cost --frontier, its table in
lesson11/bench/frontier.json) measured for this setting, and whether it is on the
front of the cheapest settings for their error. The full panel adds the keys of
every setting, the contacts, the deepest penetration (px), the kinetic energy
(mass·px²/s²), where a frame's physics goes ("physics 9.1 ms: your sat 2.0,
your resolve 4.3, engine 2.8", see LabPanel.watch), the most accurate setting
on the study's front that would run in real time on this machine (real_time_line),
and a graph of the physics ms per frame over the last GRAPH_SECONDS s with the
60 fps frame budget (16.7 ms) as a dashed line. The compact panel's cost line
turns orange when the lab runs below 0.95x real time.

Nothing is set on a world until a key changes a setting. The panel keeps the
changed settings only (as overrides) and applies them to every World it is
handed, so after R builds a new world the new one gets them before its first
step. With no panel key pressed, which is how the checker runs a lab unless
its script presses one, advance(world, dt) is exactly world.advance(dt), and
the lab runtime's record is the same as without the panel but for the World's
settings, which advance() notes for it (runtime.note_world, recorded_settings)
only while the checker records: `python -m checker FILE --show` draws them
with draw_recorded, read-only.

The World attributes used are: solver, iterations, substeps, warm_starting,
contact_rule, effects, contacts, bodies, step_seconds and advance(dt). A World
that has no `substeps` or `warm_starting` yet still gets the attribute set;
the HUD then says the setting has no effect in this World.
"""
import json
import os
import time
from collections import deque

import pygame

from . import hook_clock
from . import runtime
from .physics2d.collision import circle_polygon as circle_polygon_of_physics2d
from .physics2d.collision import sat as sat_of_physics2d
from .physics2d.world import LESSON_EFFECTS

MAX_ITERATIONS = 50     # the Up key stops here: 50 passes of the lesson solver take ~30 ms per step
MAX_SUBSTEPS = 16       # the Right key stops here
GRAPH_SECONDS = 3       # s of history in the graph
GRAPH_FRAMES = 60 * GRAPH_SECONDS   # frames of history (the labs run at 60 fps)
FRAME_BUDGET_MS = 1000 / 60         # ms: a frame's whole time at 60 fps, the graph's dashed line
REFRESH_FRAMES = 12     # the numbers are redrawn every 12 frames (0.2 s at 60 fps) so they can be read
SCALES_MS = (5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000)  # the graph's possible top values (ms)

PANEL_WIDTH, LINE_HEIGHT, GRAPH_HEIGHT, PADDING = 400, 19, 58, 10   # px
COMPACT_WIDTH = 320     # px: the compact panel's width; with its 5 lines it stays in x 570-890, y 36-137 of a
COMPACT_LINE, COMPACT_PADDING = 17, 8   # 900 px window, clear of Tumbling Crates' four starting crates (px)
MODES = ("compact", "full", "hidden")   # H cycles through them, compact first
RATE_FRAMES = 60        # frames (1 s at 60 fps) over which ms/step and the real-time share are averaged
REAL_TIME_SHARE = 0.8   # a setting "runs in real time" if its physics takes at most this share of a 60 fps frame
                        # (the rest is left for drawing)
STUDY_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench", "frontier.json")
BACKGROUND = (12, 14, 20, 215)  # RGBA: see-through, so crates behind it stay visible
TEXT = (230, 230, 230)
DIM = (150, 155, 170)
KEY = (250, 220, 80)
CHANGED = (120, 200, 255)       # a setting that differs from the World's own
WARNING = (255, 140, 90)
GRAPH_LINE = (90, 210, 120)
GRAPH_BACKGROUND = (40, 44, 56)
BUDGET_LINE = (235, 80, 80)

SOLVERS = ("lesson", "accumulated")
CONTACT_RULES = ("corners", "clip")
SETTING_NAMES = ("solver", "iterations", "substeps", "warm_starting", "correction", "contact_rule")
RECORDED = SETTING_NAMES + ("order", "effects", "step_seconds")   # what the checker's record keeps of a World
NEW_ATTRIBUTES = {"substeps": 1, "warm_starting": True}  # their defaults, for a World that lacks them
_study = None           # the study's table, read once: {(solver, order, substeps, iterations): row}


def study_rows():
    """The accuracy study's measured settings, {(solver, order, substeps, iterations): row}; {} if it is missing.

    Each row (lesson11/bench/frontier.json, written by the study) has "ms_per_step"
    (CPU ms for one fixed step of the study's pile), "pile_speed" (px/s, the pile's
    top speed after settling), "on_front" and, off the front, "better": a setting
    that costs less and errs less.
    """
    global _study
    if _study is None:
        try:
            with open(STUDY_FILE, encoding="utf-8") as handle:
                rows = json.load(handle)["settings"]
            _study = {(r["solver"], r["order"], r["substeps"], r["iterations"]): r for r in rows}
        except (OSError, ValueError, KeyError, TypeError):
            _study = {}
    return _study


def study_row(world, settings):
    """The study's row for the world's solver (and order) at these settings, or None if it was not measured."""
    order = getattr(world, "order", "solve-first") if settings["solver"] == "lesson" else "-"
    return study_rows().get((settings["solver"], order, settings["substeps"], settings["iterations"]))


def study_lines(world, settings):
    """Two lines: what the accuracy study measured for these settings (cost, pile error) and whether they are
    on its front, or that the study has no point for them."""
    row = study_row(world, settings)
    if row is None:
        return ["study: this setting was not measured", ""]
    where = "on the front: nothing cheaper errs less" if row["on_front"] \
        else f"off the front: {row['better']} costs less, errs less"
    return [f"study: {row['ms_per_step']:.2f} ms/step, pile {row['pile_speed']:.1f} px/s", where]


def study_short(world, settings):
    """One line of the study for the compact panel: its cost and pile error, and "on front" or a better setting."""
    row = study_row(world, settings)
    if row is None:
        return "study: this setting was not measured"
    verdict = "on front" if row["on_front"] else f"{row['better']} beats it"
    return f"study: {row['ms_per_step']:.2f} ms, pile {row['pile_speed']:.1f} px/s: {verdict}"


def real_time_line(world, settings, ms_per_step):
    """Which setting on the study's front would run in real time on this machine: one line, or None if unknown.

    The study measured ms/step of every setting on its machine; this machine's
    speed is the live ms/step of the current setting over the study's for it
    (so it also covers a scene with more or fewer crates than the study's
    pile). A setting runs in real time here if (its study ms/step × that ratio)
    × steps per 60 fps frame <= REAL_TIME_SHARE of the frame. Of the front's
    settings for this solver (and order) that do, the line names the most
    accurate one (the lowest pile speed): the best this machine can run.
    """
    row = study_row(world, settings)
    if row is None or ms_per_step <= 0:
        return None
    scale = ms_per_step / row["ms_per_step"]
    steps = (1 / 60) / getattr(world, "step_seconds", 1 / 120)
    front = [other for other in study_rows().values()
             if other["on_front"] and (other["solver"], other["order"]) == (row["solver"], row["order"])]
    fits = [other for other in front if other["ms_per_step"] * scale * steps <= FRAME_BUDGET_MS * REAL_TIME_SHARE]
    if not fits:
        return "real time here: no setting on the front"
    best = min(fits, key=lambda other: other["pile_speed"])
    label = f"{best['substeps']} × {best['iterations']}"
    here = best["ms_per_step"] * scale * steps
    return f"real time here: best on the front {label}, {here:.1f} ms/frame"


def split_text(split):
    """Where the physics of a frame goes, as pieces of one sentence:
    ["physics 9.1 ms: your sat 2.0", ", your resolve 4.3", ", engine 2.8"] (the panel wraps them to its width)."""
    if not split["yours"]:  # no function of the lab ran (the reference solver, or a lab with no hooks)
        return [f"physics {split['physics']:.1f} ms: all physics2d's own"]
    parts = [f"your {name} {ms:.1f}" for name, ms in split["yours"].items()] + [f"engine {split['engine']:.1f}"]
    return [f"physics {split['physics']:.1f} ms: {parts[0]}"] + [f", {part}" for part in parts[1:]]


def rate_text(m, paused):
    """The measured cost as (left, right) text: ms per fixed step, and steps this frame or the real-time share."""
    left = f"physics {m['ms_per_step']:.2f} ms/step"
    if paused:
        return left, "PAUSED"
    share = "" if m["real_time"] is None else f", {m['real_time']:.1f}x real time"
    return left, f"{m['steps']} step{'' if m['steps'] == 1 else 's'}/frame{share}"


def read_setting(world, name):
    """The current value of one panel setting in `world` ("correction" is read from world.effects)."""
    if name == "correction":
        return "correction" in world.effects
    if name in NEW_ATTRIBUTES:
        return getattr(world, name, NEW_ATTRIBUTES[name])
    return getattr(world, name)


def recorded_settings(world):
    """The world's settings the checker records with its frames, {name: value} for RECORDED (read now, so a
    change made by the lab's own code shows too); {} when the World cannot be read (the run goes on)."""
    try:
        return {name: read_setting(world, name) if name in SETTING_NAMES else getattr(world, name)
                for name in RECORDED}
    except Exception:   # a World the lab changed so it cannot be read: the checker gets no settings, not a crash
        return {}


class _Order:
    """A stand-in World for the study's lookup of a recorded run (study_row reads only `order`)."""

    def __init__(self, order):
        self.order = order or "solve-first"


def _recorded_text(name, value):
    """One recorded setting as the panel shows it."""
    if isinstance(value, bool):
        return "on" if value else "off"
    if name == "step_seconds":
        return f"1/{round(1 / value)} s" if abs(1 / value - round(1 / value)) < 1e-6 else f"{value:.4g} s"
    if name == "effects":
        added = sorted(set(value) - LESSON_EFFECTS - {"correction"})
        dropped = sorted(LESSON_EFFECTS - set(value) - {"correction"})
        return " ".join(["lesson's"] + [f"+{e}" for e in added] + [f"-{e}" for e in dropped])
    return str(value)


RECORDED_ROWS = (("S", "solver", "solver"), ("", "order", "order"), ("Up/Down", "iterations", "iterations"),
                 ("Left/Right", "sub-steps", "substeps"), ("W", "warm start", "warm_starting"),
                 ("C", "correction", "correction"), ("K", "contact rule", "contact_rule"),
                 ("", "step", "step_seconds"), ("", "effects", "effects"))


def row_key(label):
    """The RECORDED name a row label of recorded_rows shows."""
    return next(name for _, shown, name in RECORDED_ROWS if shown == label)


def recorded_rows(mine, theirs):
    """[(key, label, my value, the solution's value or None where they agree)] of a recorded run's settings."""
    rows = []
    for key, label, name in RECORDED_ROWS:
        if name not in mine:
            continue
        value = _recorded_text(name, mine[name])
        other = _recorded_text(name, theirs[name]) if name in theirs else None
        rows.append((key, label, value, other if other is not None and other != value else None))
    return rows


def write_setting(world, name, value):
    """Set one panel setting on `world` ("correction" adds it to or removes it from world.effects).

    Raises ValueError (one line naming the value) for a value the panel never offers.
    """
    valid = {"solver": lambda v: v in SOLVERS,
             "iterations": lambda v: isinstance(v, int) and not isinstance(v, bool) and v >= 1,
             "substeps": lambda v: isinstance(v, int) and not isinstance(v, bool) and v >= 1,
             "warm_starting": lambda v: isinstance(v, bool),
             "correction": lambda v: isinstance(v, bool),
             "contact_rule": lambda v: v in CONTACT_RULES}
    if name not in valid:
        raise ValueError(f"unknown panel setting {name!r}; known: {', '.join(SETTING_NAMES)}")
    if not valid[name](value):
        raise ValueError(f"panel setting {name!r} cannot be {value!r}")
    if name == "correction":
        world.effects = frozenset(world.effects | {"correction"}) if value \
            else frozenset(world.effects - {"correction"})
    else:
        setattr(world, name, value)


class LabPanel:
    """Solver settings on keys, pause and single step, and a HUD with the measured cost. See the module docstring.

    overrides   {setting: value} changed by keys; applied to every world handed to advance()
    paused      True while P holds the physics
    history     physics ms per frame, the last GRAPH_FRAMES frames
    rates       (physics ms, steps, frame s, simulated s) of the last RATE_FRAMES frames
    mode        "compact", "full" or "hidden" (key H cycles)
    """

    def __init__(self):
        self.overrides = {}
        self.paused = False
        self.pending_steps = 0
        self.mode = MODES[0]
        self.history = deque(maxlen=GRAPH_FRAMES)
        self.rates = deque(maxlen=RATE_FRAMES)
        self.world = None
        self.base = {}          # the current world's own settings, before any override
        self.supported = {}     # setting -> does this World have the attribute of its own
        self.last_steps = 0
        self.frames = 0
        self.shown = None       # the measured numbers on screen, refreshed every REFRESH_FRAMES
        self.font = None
        self.cache = {}
        self.box = None         # after draw(): the panel's rectangle in the window (px)
        self.placed = []        # after draw(): (rectangle, text) of every line of text on the panel
        self.image = None       # the panel's picture, redrawn by render()
        self.rendered = []      # (rectangle, text) of the lines in self.image
        self.contacts_at = (0, 0)
        self.dirty = True       # redraw the picture at the next draw()
        self.tallies = {}       # full view: {hook name: [s, calls]} of the lab's functions this frame
        self.split = deque(maxlen=REFRESH_FRAMES)  # full view: (physics ms, {hook: ms}) of the last frames
        self.overhead = None    # (s added, s counted inside) per timed call: hook_clock.calibrate, once

    # ---- settings -----------------------------------------------------------------------

    def adopt(self, world):
        """Take `world` as the current world: remember its own settings, then apply the overrides to it."""
        if world is self.world:
            return
        self.world = world
        self.dirty = True
        self.supported = {name: name not in NEW_ATTRIBUTES or hasattr(world, name) for name in SETTING_NAMES}
        self.base = {name: read_setting(world, name) for name in SETTING_NAMES}
        for name, value in self.overrides.items():
            write_setting(world, name, value)

    def settings(self):
        """{setting: value} in effect for the current world (its own values with the overrides on top)."""
        return {**self.base, **self.overrides}

    def change(self, name, value):
        """Set one setting: remember it as an override and write it to the current world (if any)."""
        if self.world is not None:
            write_setting(self.world, name, value)
        if value == self.base.get(name, object()):
            self.overrides.pop(name, None)
        else:
            self.overrides[name] = value

    def restore(self):
        """Back to the current world's own settings (key 0)."""
        if self.world is not None:
            for name in self.overrides:
                write_setting(self.world, name, self.base[name])
        self.overrides.clear()

    # ---- input --------------------------------------------------------------------------

    def handle(self, event):
        """React to one pygame event; returns True if it was one of the panel's keys, else False.

        The panel's keys are not used by the labs, so a lab may ignore the return value.
        Setting keys need a world: before the first advance() they are ignored.
        """
        if event.type != pygame.KEYDOWN:
            return False
        self.dirty = True
        key = event.key
        if key == pygame.K_p:
            self.paused = not self.paused
            self.pending_steps = 0
            return True
        if key == pygame.K_o:
            self.paused = True
            self.pending_steps += 1
            return True
        if key == pygame.K_h:
            self.mode = MODES[(MODES.index(self.mode) + 1) % len(MODES)]
            return True
        if self.world is None:
            return key in (pygame.K_s, pygame.K_w, pygame.K_c, pygame.K_k, pygame.K_0,
                           pygame.K_UP, pygame.K_DOWN, pygame.K_LEFT, pygame.K_RIGHT)
        now = self.settings()
        if key == pygame.K_s:
            self.change("solver", SOLVERS[(SOLVERS.index(now["solver"]) + 1) % len(SOLVERS)]
                        if now["solver"] in SOLVERS else SOLVERS[0])
        elif key in (pygame.K_UP, pygame.K_DOWN):
            step = 1 if key == pygame.K_UP else -1
            self.change("iterations", max(1, min(MAX_ITERATIONS, now["iterations"] + step)))
        elif key in (pygame.K_RIGHT, pygame.K_LEFT):
            step = 1 if key == pygame.K_RIGHT else -1
            self.change("substeps", max(1, min(MAX_SUBSTEPS, now["substeps"] + step)))
        elif key == pygame.K_w:
            self.change("warm_starting", not now["warm_starting"])
        elif key == pygame.K_c:
            self.change("correction", not now["correction"])
        elif key == pygame.K_k:
            self.change("contact_rule", "clip" if now["contact_rule"] == "corners" else "corners")
        elif key == pygame.K_0:
            self.restore()
        else:
            return False
        return True

    # ---- stepping -----------------------------------------------------------------------

    def advance(self, world, dt):
        """Step `world` for a frame of dt s, as world.advance(dt) does, unless paused; returns the steps run.

        A world not seen before gets the overrides first (after R, the lab's new world).
        Paused: only the steps asked for with O run, each as world.advance(world.step_seconds),
        which is exactly one fixed step. The time spent is added to the graph (ms), and
        with the frame time and the time simulated to the rates (ms/step, share of real time).
        """
        self.adopt(world)
        self.watch(world)
        for tally in self.tallies.values():
            tally[0], tally[1] = 0.0, 0
        start = time.perf_counter()
        if not self.paused:
            steps = world.advance(dt)
        else:
            steps = 0
            for _ in range(self.pending_steps):
                steps += world.advance(world.step_seconds)
            self.pending_steps = 0
        spent = (time.perf_counter() - start) * 1000
        if self.tallies:  # the full view's timers: their own cost comes off every figure
            added, inside = self.overhead
            spent -= 1000 * added * sum(calls for _, calls in self.tallies.values())
            if steps:
                self.split.append((spent, {name: 1000 * (s - calls * inside)
                                           for name, (s, calls) in self.tallies.items() if calls}))
        self.history.append(spent)
        if not self.paused:
            self.rates.append((spent, steps, dt, steps * world.step_seconds))
        self.last_steps = steps
        if runtime.recording():   # only under the checker: the replay (--show) shows the settings the run had
            runtime.note_world(recorded_settings(world))
        return steps

    def watch(self, world):
        """In the full view, time the lab's own functions the World calls; in the others, take the timers off.

        The lab's functions are the World's hooks that are not the library's
        (hook_clock.lab_hooks: sat, resolve, circle_polygon, ...); each is wrapped
        (hook_clock.wrap, time.perf_counter) so the panel can say where a frame goes:
        the time inside them, inclusive of what they call, and the rest of the
        physics, the engine. The wrappers return what the functions return, so the
        simulation is the same; their own cost (hook_clock.calibrate, measured once)
        is taken off the physics time and the lab's.
        """
        full = self.mode == "full"
        if full and self.overhead is None:
            self.overhead = hook_clock.calibrate(time.perf_counter)
        for name, function in hook_clock.lab_hooks(world).items():
            timed = getattr(world, name) is not function
            if full and not timed:
                setattr(world, name, hook_clock.wrap(function, self.tallies.setdefault(name, [0.0, 0]),
                                                     time.perf_counter))
            elif not full and timed:
                setattr(world, name, function)
        if not full:
            self.tallies = {}
            self.split.clear()

    # ---- the HUD ------------------------------------------------------------------------

    def measure(self, world):
        """What the HUD shows: {"ms": mean physics ms per frame over the last refresh, "steps",
        "ms_per_step": physics ms / steps run over the last RATE_FRAMES running frames (0 before any step),
        "real_time": simulated s / frame s over those frames (1.0: keeping up; None before any frame time),
        "contacts", "deepest" (px, 0 without contacts), "energy" (mass·px²/s²),
        "split": full view, {"physics": ms per frame, "yours": {hook: ms}, "engine": ms} over the last
        REFRESH_FRAMES frames that ran a step (None otherwise)}."""
        recent = list(self.history)[-REFRESH_FRAMES:]
        spent, steps, frame_s, simulated = (sum(column) for column in zip(*self.rates)) if self.rates else (0, 0, 0, 0)
        split = None
        if self.split:  # full view: mean physics ms per frame, the lab's functions and the engine's part of it
            physics = sum(ms for ms, _ in self.split) / len(self.split)
            names = dict.fromkeys(name for _, part in self.split for name in part)  # in the order first met
            yours = {name: sum(part.get(name, 0.0) for _, part in self.split) / len(self.split) for name in names}
            split = {"physics": physics, "yours": yours, "engine": physics - sum(yours.values())}
        return {"split": split,
                "ms": sum(recent) / len(recent) if recent else 0.0,
                "steps": self.last_steps,
                "ms_per_step": spent / steps if steps else 0.0,
                "real_time": simulated / frame_s if frame_s > 0 else None,
                "contacts": len(world.contacts),
                "deepest": max([0.0] + [contact.depth for contact in world.contacts]),
                "energy": sum(body.kinetic_energy() for body in world.bodies)}

    def lines(self, world):
        """The HUD's setting rows as [(key label, setting, value, colour)], top to bottom.

        The row after the solver has no key: it says whose sat() (or circle_polygon()) and resolve() run.
        """
        now = self.settings()

        def colour(name):
            return CHANGED if name in self.overrides else TEXT

        def missing(name):
            return "" if self.supported.get(name, True) else "  (not in this World yet)"

        reference = now["solver"] == "accumulated"
        hooked = getattr(world, "resolve", None) != getattr(world, "lesson_resolve", None)
        # the lab's own functions the World runs: sat() (Tumbling Crates, More Shapes),
        # circle_polygon() (Ball on the Ramp), resolve() (Tumbling Crates, Ball on the Ramp)
        library = (("sat", sat_of_physics2d), ("circle_polygon", circle_polygon_of_physics2d))
        yours = [name for name, function in library if getattr(world, name, function) is not function]
        if hooked:
            yours.append("resolve")
        named = " and ".join(f"{name}()" for name in yours)
        if reference:
            note = (f"your {named} {'are' if len(yours) > 1 else 'is'} NOT used" if yours
                    else "the lesson's resolve() is not used", WARNING)
        elif not yours:
            note = ("runs physics2d's sat() and resolve()", DIM)
        else:
            runs = [f"your {named}"]
            if not {"sat", "circle_polygon"} & set(yours):
                runs.insert(0, "physics2d's sat()")
            if not hooked:
                runs.append("physics2d's resolve()")
            note = ("runs " + " and ".join(runs), DIM)
        warm = ("on" if now["warm_starting"] else "off") + (missing("warm_starting") or
                                                             ("" if reference else "  (reference solver only)"))
        return [("S", "solver", "accumulated (reference)" if reference else "lesson",
                 WARNING if reference else colour("solver")),
                ("", "", note[0], note[1]),
                ("Up/Down", "iterations", str(now["iterations"]), colour("iterations")),
                ("Left/Right", "sub-steps", f"{now['substeps']}{missing('substeps')}", colour("substeps")),
                ("W", "warm start", warm,
                 colour("warm_starting") if reference else DIM),
                ("C", "correction", "on" if now["correction"] else "off", colour("correction")),
                ("K", "contact rule", now["contact_rule"], colour("contact_rule"))]

    def text(self, words, colour=TEXT):
        """A rendered line of text (cached: most rows are the same from frame to frame)."""
        if self.font is None:
            self.font = pygame.font.Font(None, 20)
        key = (words, colour)
        if key not in self.cache:
            if len(self.cache) > 300:
                self.cache.clear()
            self.cache[key] = self.font.render(words, True, colour)
        return self.cache[key]

    def wrapped(self, pieces, width):
        """The pieces of a sentence joined into lines no wider than `width` px (a piece is never split)."""
        lines = []
        for piece in pieces:
            if lines and self.text(lines[-1] + piece).get_width() <= width:
                lines[-1] += piece
            else:
                lines.append(piece.lstrip(", ") if lines else piece)
        return lines

    def put(self, target, words, colour, pos):
        """Blit one line of text onto `target` at pos (px, top-left); remember where it lands in the window."""
        image = self.text(words, colour)
        target.blit(image, pos)
        self.rendered.append((image.get_rect(topleft=pos).move(self.box.topleft), words))

    def draw(self, surface, world):
        """Draw the panel in the window's top-right corner (below a lab's own HUD line), at its current size.

        The panel's picture is redrawn every REFRESH_FRAMES frames or after a key, and blitted
        in between (so it costs a lab about one blit a frame); the contact count is drawn
        every frame, like a lab's own HUD line. Afterwards self.box is the panel's rectangle
        in the window and self.placed lists (rectangle, text) of every line of text on it.
        """
        self.adopt(world)
        refresh = self.shown is None or self.frames % REFRESH_FRAMES == 0
        if refresh:
            self.shown = self.measure(world)
        self.frames += 1
        right = surface.get_width() - 10
        if self.mode == "hidden":
            label = "[H] show the solver panel"
            image = self.text(label, DIM)
            self.box = image.get_rect(topright=(right, 36))
            surface.blit(image, self.box)
            self.placed = [(self.box, label)]
            return
        if refresh or self.dirty or self.image is None or self.box.right != right:
            self.render(world, right)
        surface.blit(self.image, self.box.topleft)
        if self.mode == "compact":
            self.placed = list(self.rendered)
            return
        contacts = f"contacts {len(world.contacts)}"
        image = self.text(contacts, TEXT)
        surface.blit(image, self.contacts_at)
        self.placed = self.rendered + [(image.get_rect(topleft=self.contacts_at), contacts)]

    def start_image(self, right, width, rows, extra=0, line=LINE_HEIGHT, padding=PADDING):
        """A fresh see-through picture for `rows` lines of `line` px and `extra` px more, and self.box for it,
        its right edge at `right` px."""
        self.dirty = False
        self.rendered = []
        self.box = pygame.Rect(right - width, 36, width, padding * 2 + line * rows + extra)
        self.image = pygame.Surface(self.box.size, pygame.SRCALPHA)
        self.image.fill(BACKGROUND)
        return self.image

    def render(self, world, right):
        """Draw the panel's picture (all but the contact count) into self.image, its right edge at `right` px."""
        if self.mode == "compact":
            self.render_compact(world, right)
        else:
            self.render_full(world, right)

    def render_compact(self, world, right):
        """The compact panel, five short lines: solver, iterations, sub-steps, the cost per step and the share of
        real time, and the study's figures for this setting (the contact count is in every lab's own HUD line)."""
        now = self.settings()
        m = self.shown
        image = self.start_image(right, COMPACT_WIDTH, 5, line=COMPACT_LINE, padding=COMPACT_PADDING)
        x, y = COMPACT_PADDING, COMPACT_PADDING
        more = self.text("[H] more", DIM)
        self.put(image, "[H] more", DIM, (COMPACT_WIDTH - x - more.get_width(), y + COMPACT_LINE))  # by iterations
        reference = now["solver"] == "accumulated"
        for key, name, value, changed in (
                ("[S]", "solver", "reference" if reference else "lesson", "solver"),
                ("[Up/Down]", "iterations", str(now["iterations"]), "iterations"),
                ("[Left/Right]", "sub-steps", str(now["substeps"]), "substeps")):
            self.put(image, key, KEY, (x, y))
            self.put(image, name, DIM, (x + 100, y))
            colour = WARNING if key == "[S]" and reference else (CHANGED if changed in self.overrides else TEXT)
            self.put(image, value, colour, (x + 180, y))
            y += COMPACT_LINE
        if self.paused:
            rate, behind = f"physics {m['ms_per_step']:.2f} ms/step, PAUSED", True
        else:
            share = "" if m["real_time"] is None else f", {m['real_time']:.1f}x real time"
            rate, behind = f"physics {m['ms_per_step']:.2f} ms/step{share}", (m["real_time"] or 1) < 0.95
        self.put(image, rate, WARNING if behind else TEXT, (x, y))
        y += COMPACT_LINE
        self.put(image, study_short(world, now), DIM, (x, y))

    def render_full(self, world, right):
        """The full panel: every setting with its key, the measurements, the study and the graph."""
        rows = self.lines(world)
        m = self.shown
        rate = rate_text(m, self.paused)
        study = [line for line in study_lines(world, self.settings()) if line]
        study += [line for line in [real_time_line(world, self.settings(), m["ms_per_step"])] if line]
        split = [] if m["split"] is None else self.wrapped(split_text(m["split"]), PANEL_WIDTH - 2 * PADDING)
        notes = [(line, TEXT) for line in split] + [(line, DIM) for line in study]
        measured = [(f"physics {m['ms']:.1f} ms/frame", rate[0][len("physics "):]),
                    (None, rate[1]),   # None: the contact count, drawn every frame
                    (f"deepest {m['deepest']:.2f} px", f"kinetic energy {m['energy']:.3g}")]
        image = self.start_image(right, PANEL_WIDTH, len(rows) + len(measured) + len(notes) + 3, GRAPH_HEIGHT + 8)
        x, y = PADDING, PADDING
        self.put(image, "SOLVER PANEL", KEY, (x, y))
        self.put(image, "[H] hide", DIM, (PANEL_WIDTH - PADDING - self.text("[H] hide", DIM).get_width(), y))
        y += LINE_HEIGHT
        for key, name, value, colour in rows:
            if key:
                self.put(image, f"[{key}]", KEY, (x, y))
                self.put(image, name, DIM, (x + 95, y))
            self.put(image, value, colour, (x + (190 if key else 95), y))
            y += LINE_HEIGHT
        self.put(image, "[P] pause    [O] one step    [0] the World's own settings", KEY, (x, y))
        y += LINE_HEIGHT + 4
        for left, right_text in measured:
            if left is None:
                self.contacts_at = (self.box.x + x, self.box.y + y)
            else:
                self.put(image, left, TEXT, (x, y))
            self.put(image, right_text, WARNING if right_text == "PAUSED" else DIM, (x + 190, y))
            y += LINE_HEIGHT
        for line, colour in notes:
            self.put(image, line, colour, (x, y))
            y += LINE_HEIGHT
        top = self.draw_graph(image, pygame.Rect(x, y + 4, PANEL_WIDTH - 2 * PADDING, GRAPH_HEIGHT))
        y += GRAPH_HEIGHT + 8
        label_at = (x + 4, y - GRAPH_HEIGHT - 4 + 2)  # the graph's top value, on its own patch of background
        image.fill(GRAPH_BACKGROUND, self.text(f"{top} ms", DIM).get_rect(topleft=label_at).inflate(4, 0))
        self.put(image, f"{top} ms", DIM, label_at)
        self.put(image, f"physics ms per frame, last {GRAPH_SECONDS} s; red: 60 fps budget", DIM, (x, y))

    # ---- a recorded run (checker --show): the settings only, read-only, no timing -------------------

    def draw_recorded(self, surface, mine, theirs=None, note="", pos=None, solution_colour=CHANGED):
        """Draw the settings a recorded run had (`mine`, RECORDED's {name: value}, or None when none was recorded)
        at pos (px, top-left; default the live panel's corner), and beside each the solution's run's value
        (`theirs`) where it differs. Nothing here is measured: the last line says "replay" where the live panel
        has its ms/step. Compact: solver, iterations, sub-steps and the other settings that differ; full (H): every
        setting and the study's line for it. Returns the panel's rectangle (also self.box; self.placed as draw())."""
        image, self.rendered = self.recorded_image(mine, theirs, note, solution_colour), []
        self.box = image.get_rect(topleft=pos or (surface.get_width() - 10 - image.get_width(), 36))
        surface.blit(image, self.box)
        self.placed = [(rect.move(self.box.topleft), words) for rect, words in self.recorded_text]
        return self.box

    def recorded_size(self, mine, theirs=None, note=""):
        """The (width, height) in px draw_recorded takes for these settings at the current size (H)."""
        return self.recorded_image(mine, theirs, note).get_size()

    def recorded_image(self, mine, theirs, note, solution_colour=CHANGED):
        """The picture draw_recorded blits (see there); self.recorded_text: (rectangle in it, text) per line."""
        rows = recorded_rows(mine or {}, theirs or {})
        compact = self.mode != "full"
        if mine is None:
            lines = [("settings ignored for this frame:", WARNING), (note, DIM)] if note else \
                [("settings not recorded for this frame", WARNING)]
            rows = []
        elif compact:
            main = [row for row in rows if row[1] in ("solver", "iterations", "sub-steps")]
            others = [f"{name} {value} ({'solution ' + solution})" for _, name, value, solution in rows
                      if solution is not None and row_key(name) not in ("solver", "iterations", "substeps")]
            rows = main
            lines = [("; ".join(others) if others else "the other settings: as the solution's",
                      WARNING if others else DIM)]
        else:
            lines = [("keys S, Up/Down, W, C, K, 0 change nothing here", DIM)]
        lines.append(("replay: recorded settings, no timing measured", DIM))
        if mine is not None and not compact:
            lines.append((study_short(_Order(mine.get("order")), {**mine}), DIM))
        width = PANEL_WIDTH if not compact else COMPACT_WIDTH + 60
        wrapped = [(piece, colour) for text, colour in lines
                   for piece in self.wrapped([w + " " for w in text.split(" ")], width - 2 * COMPACT_PADDING)]
        line = LINE_HEIGHT if not compact else COMPACT_LINE
        image = pygame.Surface((width, 2 * COMPACT_PADDING + line * (1 + len(rows) + len(wrapped))), pygame.SRCALPHA)
        image.fill(BACKGROUND)
        self.recorded_text = []

        def put(words, colour, at):
            text = self.text(words.rstrip(), colour)
            image.blit(text, at)
            self.recorded_text.append((text.get_rect(topleft=at), words.rstrip()))

        x, y = COMPACT_PADDING, COMPACT_PADDING
        put("SOLVER PANEL (replay)" if not compact else "solver panel (replay)", KEY if not compact else DIM, (x, y))
        label = "[H] hide" if not compact else "[H] more"
        put(label, DIM, (width - x - self.text(label, DIM).get_width(), y))
        for _, name, value, solution in rows:   # no key labels: in a replay the keys change nothing
            y += line
            put(name, DIM, (x, y))
            put(value, WARNING if solution is not None else TEXT, (x + 110, y))
            if solution is not None:
                put(f"solution {solution}", solution_colour, (x + 120 + self.text(value, TEXT).get_width(), y))
        for words, colour in wrapped:
            y += line
            put(words, colour, (x, y))
        return image

    def draw_graph(self, surface, rect):
        """Physics ms per frame over the last GRAPH_FRAMES frames, newest on the right, in `rect` (px).

        Returns the value (ms) at the top of the graph: the smallest of SCALES_MS above the budget and
        95 % of the values, so one slow frame (a busy machine, a window drag) does not flatten the rest;
        the few frames above the top are drawn at the top.
        """
        pygame.draw.rect(surface, GRAPH_BACKGROUND, rect)
        values = list(self.history)
        typical = sorted(values)[int(0.95 * (len(values) - 1))] if values else 0.0
        top = next((s for s in SCALES_MS if s >= max(typical, FRAME_BUDGET_MS * 1.1)), SCALES_MS[-1])

        def y_of(ms):
            return rect.bottom - 1 - (rect.height - 2) * min(ms, top) / top

        budget = y_of(FRAME_BUDGET_MS)
        for x in range(rect.left, rect.right, 8):  # dashed budget line
            pygame.draw.line(surface, BUDGET_LINE, (x, budget), (min(x + 4, rect.right - 1), budget))
        if len(values) > 1:
            dx = (rect.width - 1) / (GRAPH_FRAMES - 1)
            start = rect.right - 1 - dx * (len(values) - 1)
            pygame.draw.lines(surface, GRAPH_LINE, False,
                              [(start + dx * i, y_of(v)) for i, v in enumerate(values)], 2)
        return top
