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
  scenario      list of crates {"w", "h", "pos": [x, y], "angle" (rad), "vel", "omega"}
                that replace the lab's dynamic bodies (static ones are kept)
  record        path of the JSON record to write at exit
  record_every  record one frame in this many (default 1)
"""
import atexit
import json
import os

import pygame

from .physics2d import Body, box_points

ENV_VAR = "LESSON11_LAB_SETTINGS"

_settings = None       # None: a student's run, every hook passes through
_frame = 0
_records = []
_written = False


def configure(settings):
    """Switch the hooks to checker mode with `settings` (a dict, see the module docstring)."""
    global _settings, _frame, _records, _written
    _settings = dict(settings)
    _frame = 0
    _records = []
    _written = False
    if _settings.get("record"):
        atexit.register(write_record)


def _load_from_environment():
    path = os.environ.get(ENV_VAR)
    if path and _settings is None:
        with open(path, encoding="utf-8") as handle:
            configure(json.load(handle))



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
    return _frame <= _settings.get("frames", 600)


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


def scene(bodies):
    """The bodies to simulate: the lab's own, or its static bodies plus the checker's scenario crates."""
    if _settings is None or "scenario" not in _settings:
        return bodies
    kept = [body for body in bodies if body.inv_mass == 0]
    for crate in _settings["scenario"]:
        w, h = crate["w"], crate["h"]
        kept.append(Body(box_points(w, h), crate["pos"], mass=w * h / 1000, angle=crate.get("angle", 0.0),
                         vel=crate.get("vel", (0, 0)), omega=crate.get("omega", 0.0)))
    return kept


def record(bodies, contacts=()):
    """Remember this frame's body states (and contact count) for the checker; nothing for a student."""
    if _settings is None or not _settings.get("record"):
        return
    if (_frame - 1) % _settings.get("record_every", 1):
        return
    _records.append({
        "frame": _frame,
        "contacts": len(contacts),
        "bodies": [{
            "static": body.inv_mass == 0,
            "pos": [body.pos.x, body.pos.y],
            "vel": [body.vel.x, body.vel.y],
            "angle": body.angle,
            "omega": body.omega,
            "points": [[p.x, p.y] for p in body.world_points()],
        } for body in bodies],
    })


def write_record():
    """Write the recorded frames to the settings' `record` path (once; also runs at exit)."""
    global _written
    if _settings is None or not _settings.get("record") or _written:
        return
    _written = True
    with open(_settings["record"], "w", encoding="utf-8") as handle:
        json.dump({"frames_run": min(_frame, _settings.get("frames", 600)), "records": _records}, handle)


_load_from_environment()
