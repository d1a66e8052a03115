"""The lab runtime: the few hooks a lab file calls on lines marked `# lab runtime`.

When a student runs a lab, every hook is a pass-through: `tick` is
clock.tick(fps), `events` is pygame.event.get(), `frame_budget` is always
True, `seed(n)` is n, `scene(bodies)` returns bodies, `record` does nothing.
The program behaves exactly as if the hooks were not there.

Under the checker (settings given by `configure`, or as a JSON file named by
the LESSON11_LAB_SETTINGS environment variable), the same hooks run the lab
for a fixed number of frames as fast as the CPU allows: a fixed frame time,
no sleeping, a fixed seed, scripted clicks and keys, an optional scenario in
place of the lab's own crates, and a record of body states written as JSON
when the process exits.

Settings (all optional):
  frames        frames to run before frame_budget() says stop (default 600)
  fps           frame rate the fixed frame time stands for (default 60)
  seed          replaces the lab's seed
  script        list of {"frame": n, "type": "click", "pos": [x, y]} /
                {"frame": n, "type": "key", "key": "r"} / {"frame": n, "type": "quit"}
  scenario      list of bodies {"pos": [x, y], "angle" (rad), "vel", "omega", ...} that
                replace the lab's dynamic bodies (static ones are kept); each is made
                by the lab's `build` function given to scene(), by default a crate
                {"w", "h", ...} of mass w·h/1000
  record        path of the JSON record to write at exit
  record_every  record one frame in this many (default 1); the last frame is always recorded
  screenshot    path of a PNG of the window as it looked after the last frame

Each recorded frame holds "frame", "contacts" (how many), "touching" (each
contact: body indices "a" and "b", "point", "normal" A→B, "depth") and
"bodies" (each: "static", "asleep" (the "sleep" effect), "pos", "vel", "angle", "omega", "points",
"radius" for a circle, whose "points" are [], and "color", the RGB the lab draws it with, when it is one).
A frame also holds "world", the World's settings (solver, order, iterations, substeps, warm_starting,
correction, contact_rule, effects, step_seconds) as the solver panel's advance() last told them (note_world),
on the first recorded frame and on every recorded frame where they changed; a lab run without the panel
records none.
"""
import atexit
import json
import os

import pygame

from .console import safe_output
from .physics2d import Body, box_points

safe_output()  # a lab window's prints (and the student's) survive a console that is not UTF-8

# The labs play no sound: without a sound card SDL's audio prints 9 ALSA lines at pygame.init(). A driver set
# in the environment is kept.
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

ENV_VAR = "LESSON11_LAB_SETTINGS"
SETTINGS = {"frames": int, "fps": (int, float), "seed": (int, float, str), "script": list, "scenario": list,
            "record": str, "record_every": int, "screenshot": str}

_settings = None       # None: a student's run, every hook passes through
_frame = 0
_records = []
_written = False
_world = None          # the World's settings as the panel last noted them (plain data), or None
_world_written = None  # the settings last put in a recorded frame
WORLD_TEXT = 60        # characters: longest string kept of a noted setting (a recorded value is data, not a text)


def check_settings(settings, source="lab settings"):
    """Raise ValueError (one line naming `source` and the key) unless `settings` is a valid settings dict."""
    if not isinstance(settings, dict):
        raise ValueError(f"{source}: expected a JSON object of settings, got {type(settings).__name__}")
    for key, value in settings.items():
        if key not in SETTINGS:
            raise ValueError(f"{source}: unknown setting {key!r}; known: {', '.join(SETTINGS)}")
        if isinstance(value, bool) or not isinstance(value, SETTINGS[key]):
            raise ValueError(f"{source}: setting {key!r} has the wrong type ({value!r})")
    for key in ("fps", "record_every"):
        if key in settings and settings[key] <= 0:
            raise ValueError(f"{source}: setting {key!r} must be > 0, got {settings[key]!r}")
    if settings.get("frames", 0) < 0:
        raise ValueError(f"{source}: setting 'frames' must be >= 0, got {settings['frames']!r}")
    for item in settings.get("script", []):
        if not isinstance(item, dict) or not isinstance(item.get("frame"), int) \
                or item.get("type") not in ("click", "key", "quit"):
            raise ValueError(f"{source}: bad script item {item!r}; "
                             'expected {"frame": n, "type": "click"|"key"|"quit", ...}')
    for item in settings.get("scenario", []):
        if not isinstance(item, dict) or "pos" not in item:
            raise ValueError(f"{source}: bad scenario body {item!r}; expected {{\"pos\": [x, y], ...}}")


def configure(settings, source="lab settings"):
    """Switch the hooks to checker mode with `settings` (a dict, see the module docstring)."""
    global _settings, _frame, _records, _written, _world, _world_written
    check_settings(settings, source)
    _settings = dict(settings)
    _frame = 0
    _records = []
    _written = False
    _world = _world_written = None
    if _settings.get("record"):
        atexit.register(write_record)


def reset():
    """Back to a student's run: every hook passes through again (nothing recorded so far is written)."""
    global _settings, _frame, _records, _written, _world, _world_written
    _settings, _frame, _records, _written, _world, _world_written = None, 0, [], False, None, None


def _load_from_environment():
    """Configure from the JSON file named by LESSON11_LAB_SETTINGS; a bad file stops with a one-line message."""
    path = os.environ.get(ENV_VAR)
    if not path or _settings is not None:
        return
    source = f"{ENV_VAR}={path}"
    try:
        with open(path, encoding="utf-8") as handle:
            settings = json.load(handle)
        configure(settings, source)
    except OSError as exc:
        raise SystemExit(f"{source}: cannot read the settings file ({exc.strerror})") from None
    except json.JSONDecodeError as exc:
        raise SystemExit(f"{source}: not valid JSON (line {exc.lineno}: {exc.msg})") from None
    except ValueError as exc:
        raise SystemExit(str(exc)) from None


def active():
    """True when the checker drives this run."""
    return _settings is not None


def seed(default):
    """The random seed to use: `default`, or the checker's seed."""
    if _settings is None or "seed" not in _settings:
        return default
    return _settings["seed"]


def frame_budget():
    """True while the lab may run another frame (always True for a student's run)."""
    global _frame
    if _settings is None:
        return True
    _frame += 1
    if _frame <= _settings.get("frames", 600):
        return True
    if _frame == _settings.get("frames", 600) + 1:
        _save_screenshot()
    return False


def _save_screenshot():
    """Save the window as it looked after the last frame to the settings' `screenshot` path (if any)."""
    path = _settings.get("screenshot")
    surface = pygame.display.get_surface() if pygame.display.get_init() else None
    if path and surface is not None:
        pygame.image.save(surface, path)


def tick(clock, fps):
    """Milliseconds since the last frame: clock.tick(fps), or the fixed 1000/fps under the checker."""
    if _settings is None:
        return clock.tick(fps)
    return 1000.0 / _settings.get("fps", fps)


def events():
    """This frame's events: pygame.event.get(), plus the checker's scripted events."""
    pending = pygame.event.get()
    if _settings is None:
        return pending
    pending = [event for event in pending if event.type != pygame.QUIT]
    for item in _settings.get("script", []):
        if item["frame"] != _frame:
            continue
        if item["type"] == "click":
            pending.append(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=tuple(item["pos"]), button=1))
        elif item["type"] == "key":
            key = pygame.key.key_code(item["key"])
            pending.append(pygame.event.Event(pygame.KEYDOWN, key=key, mod=0, unicode=item["key"]))
        elif item["type"] == "quit":
            pending.append(pygame.event.Event(pygame.QUIT))
    return pending


def crate(item):
    """The default scenario body: a w × h px crate of mass w·h/1000 at item["pos"] (angle, vel, omega optional)."""
    if "w" not in item or "h" not in item:
        raise ValueError(f"scenario body {item!r}: a crate needs \"w\" and \"h\" (px)")
    w, h = item["w"], item["h"]
    return Body(box_points(w, h), item["pos"], mass=w * h / 1000, angle=item.get("angle", 0.0),
                vel=item.get("vel", (0, 0)), omega=item.get("omega", 0.0))


def scene(bodies, build=crate):
    """The bodies to simulate: the lab's own, or its static bodies plus the checker's scenario bodies.

    `build(item)` makes one Body from one scenario item (a dict with "pos"); a
    lab whose bodies are not crates passes its own.
    """
    if _settings is None or "scenario" not in _settings:
        return bodies
    kept = [body for body in bodies if body.inv_mass == 0]
    kept.extend(build(item) for item in _settings["scenario"])
    return kept


def recording():
    """True when the checker records this run (so the panel has something to tell note_world)."""
    return _settings is not None and bool(_settings.get("record"))


def _plain(value):
    """A setting as JSON data: a bool, int, float, str (cut to WORLD_TEXT) or None as it is, a set of names as a
    sorted list of them, anything else as its repr, cut (the checker validates what it reads back)."""
    if value is None or type(value) in (bool, int, float):
        return value
    if type(value) is str:
        return value[:WORLD_TEXT]
    if type(value) in (set, frozenset, list, tuple):
        return sorted(_plain(item) if type(item) is str else repr(item)[:WORLD_TEXT] for item in value)
    return repr(value)[:WORLD_TEXT]


def note_world(settings):
    """Remember the World's settings {name: value} for the frames recorded next; nothing for a student's run."""
    global _world
    if not recording():
        return
    try:
        _world = {str(name)[:WORLD_TEXT]: _plain(value) for name, value in settings.items()}
    except Exception:   # a value whose repr fails: {} (none readable) for these frames, the run goes on
        _world = {}


def record(bodies, contacts=()):
    """Remember this frame's body states (and contact count) for the checker; nothing for a student."""
    if _settings is None or not _settings.get("record"):
        return
    last = _frame == _settings.get("frames", 600)
    if (_frame - 1) % _settings.get("record_every", 1) and not last:
        return
    global _world_written
    index = {id(body): i for i, body in enumerate(bodies)}
    _records.append({
        "frame": _frame,
        "contacts": len(contacts),
        "touching": [_contact(c, index) for c in contacts],
        "bodies": [{
            "static": body.inv_mass == 0,
            "asleep": bool(getattr(body, "asleep", False)),
            "pos": [body.pos.x, body.pos.y],
            "vel": [body.vel.x, body.vel.y],
            "angle": body.angle,
            "omega": body.omega,
            "points": [[p.x, p.y] for p in body.world_points()],
            **({"radius": body.radius} if getattr(getattr(body, "shape", None), "kind", None) == "circle" else {}),
            **({"color": list(body.color)} if _colour(getattr(body, "color", None)) else {}),
        } for body in bodies],
    })
    if _world is not None and _world != _world_written:   # the settings, when they are new since the last frame
        _records[-1]["world"] = _world_written = _world


def _colour(value):
    """True when `value` is an RGB colour the lab draws with: three ints 0-255."""
    return isinstance(value, (tuple, list)) and len(value) == 3 and \
        all(isinstance(c, int) and not isinstance(c, bool) and 0 <= c <= 255 for c in value)


def _contact(contact, index):
    """One contact as plain data; works for physics2d Contact tuples (a, b, point, normal, depth)."""
    return {"a": index.get(id(contact.a)), "b": index.get(id(contact.b)),
            "point": [contact.point.x, contact.point.y], "normal": [contact.normal.x, contact.normal.y],
            "depth": contact.depth}


def write_record():
    """Write the recorded frames to the settings' `record` path (once; also runs at exit)."""
    global _written
    if _settings is None or not _settings.get("record") or _written:
        return
    _written = True
    with open(_settings["record"], "w", encoding="utf-8") as handle:
        json.dump({"frames_run": min(_frame, _settings.get("frames", 600)), "records": _records}, handle)


_load_from_environment()
