"""Trajectory digests: has a change to physics2d left every simulation the same, to the last bit?

A *case* is one scene under one solver setting. Each case is stepped with
World.step() for a fixed number of 1/120 s steps (no window, no clock), and
after every step every body's pos.x, pos.y, angle, vel.x, vel.y, omega is
written as float.hex; the case's digest is the SHA-256 of that text, plus the
final states themselves (so a failing comparison names the body that differs).

Scenes: each lab's own scene as solutions/<lab>.py builds it (seed 11, with
the lab's own sat/resolve/separate/hooks; Bullets with bullets fired by the
lab's make_bullet, Tumbling Crates with eight crates dropped by the lab's
make_crate to make a pile), and lesson11/bench/scenes.py's pyramid, stack and
settling balls (the library's functions only).
Settings (SETTINGS): the scene's default; solver="accumulated"; the lesson
listing's order (order="move-first"); the "sleep" effect on.

    python tests/trajectory_digest.py            compare with the fixture (exit 1 and the differing cases if not)
    python tests/trajectory_digest.py --write    record the fixture from the current code (only on purpose:
                                                 a change meant to alter the motion)

Reuse: digests(cases) takes any {name: make_world} mapping; a fast path
(broad phase, vector maths, a solver rewrite) is bit-identical when
compare(digests()) is empty. The fixture is recorded on Linux x86_64: libm's
sin/cos may differ by an ulp on other platforms, so elsewhere a difference is
not a failure (tests/test_trajectory_digest.py skips there).
"""
import hashlib
import importlib.util
import json
import os
import platform
import random
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)
os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from lesson11.bench import scenes as bench_scenes  # noqa: E402
from lesson11.physics2d import LESSON_EFFECTS  # noqa: E402

FIXTURE = os.path.join(ROOT, "tests", "fixtures", "trajectory_digest.json")
STEPS = 240          # 2 s of 1/120 s steps: long enough for landings, bounces, piles settling and sleep
SEED = 11            # the labs' own seed
RECORDED_ON = ("Linux", "x86_64")   # (platform.system(), platform.machine()) the fixture was recorded on


def _lab(name):
    """solutions/<name>.py as a module (loaded once per process)."""
    key = f"_digest_{name}"
    if key not in sys.modules:
        spec = importlib.util.spec_from_file_location(key, os.path.join(ROOT, "solutions", f"{name}.py"))
        module = importlib.util.module_from_spec(spec)
        sys.modules[key] = module
        spec.loader.exec_module(module)
    return sys.modules[key]


def _rng():
    return random.Random(SEED)


def tumbling_crates():
    """The lab's scene plus eight of its random crates dropped over the floor (a pile forms)."""
    lab = _lab("tumbling_crates")
    rng = _rng()
    world = lab.make_world(rng)
    for k in range(8):
        world.add(lab.make_crate(rng, (560 + 70 * (k % 4), 250 + 60 * (k // 4))))
    return world


def more_shapes():
    """The lab's scene: four shapes falling on the floor and the ramp (the lab's sat)."""
    return _lab("more_shapes").make_world(_rng())


def ball_on_ramp():
    """The lab's scene: a ball rolling down the ramp into a tall crate (the lab's circle hooks)."""
    return _lab("ball_on_ramp").make_world(_rng())


def sleeping_crates():
    """The lab's scene: eight crates falling into a bin and falling asleep (the lab's sleep hooks)."""
    return _lab("sleeping_crates").make_world(_rng())


def bullets(mode):
    """The lab's scene in `mode` ("plain" or "ccd") with three bullets fired at the wall (3000-12000 px/s)."""
    lab = _lab("bullets")
    world = lab.make_world(_rng(), mode)
    for k, speed in enumerate(lab.SPEEDS):
        world.add(lab.make_bullet(lab.GUN + (0, 40 * k), (speed, -200)))
    return world


def pyramid():
    """lesson11/bench/scenes.py: the 10-crate pyramid on the floor."""
    return bench_scenes.pile_world("pyramid4")


def stack():
    """lesson11/bench/scenes.py: a column of 6 crates."""
    return bench_scenes.pile_world("stack6")


def balls():
    """lesson11/bench/scenes.py: 24 frictionless balls bouncing in a closed box."""
    return bench_scenes.settling_balls_world(LESSON_EFFECTS)


SCENES = {
    "tumbling_crates": tumbling_crates,
    "more_shapes": more_shapes,
    "ball_on_ramp": ball_on_ramp,
    "sleeping_crates": sleeping_crates,
    "bullets_plain": lambda: bullets("plain"),
    "bullets_ccd": lambda: bullets("ccd"),
    "pyramid": pyramid,
    "stack": stack,
    "balls": balls,
}


def _sleeping(world):
    world.effects = world.effects | {"sleep"}


SETTINGS = {  # name: what it changes in a freshly made world
    "default": lambda world: None,
    "accumulated": lambda world: setattr(world, "solver", "accumulated"),
    "move-first": lambda world: setattr(world, "order", "move-first"),
    "sleep": _sleeping,
}


def all_cases():
    """{"scene/setting": make_world} for every scene and setting (the fixture's cases)."""
    cases = {}
    for scene, make in SCENES.items():
        for setting, change in SETTINGS.items():
            cases[f"{scene}/{setting}"] = (lambda make=make, change=change: _changed(make(), change))
    return cases


def _changed(world, change):
    change(world)
    return world


def state(body):
    """One body's state as float.hex strings: pos.x, pos.y, angle, vel.x, vel.y, omega."""
    return [float.hex(float(v)) for v in (body.pos.x, body.pos.y, body.angle, body.vel.x, body.vel.y, body.omega)]


def run(make_world, steps=STEPS):
    """{"sha256": digest of every body's state after every step, "final": the last states} of one case."""
    world = make_world()
    digest = hashlib.sha256()
    for _ in range(steps):
        world.step()
        digest.update(json.dumps([state(body) for body in world.bodies]).encode())
    return {"sha256": digest.hexdigest(), "final": [state(body) for body in world.bodies]}


def digests(cases=None, steps=STEPS):
    """{case name: run(make_world)} for `cases` ({name: make_world}; default all_cases())."""
    return {name: run(make, steps) for name, make in (cases or all_cases()).items()}


def load_fixture(path=FIXTURE):
    with open(path, encoding="utf-8") as handle:
        return json.load(handle)["cases"]


def compare(found, expected=None):
    """One line per case of `found` whose digest differs from `expected` (default: the fixture); [] if none."""
    expected = load_fixture() if expected is None else expected
    lines = []
    for name, result in found.items():
        if name not in expected:
            lines.append(f"{name}: not in the fixture")
        elif result["sha256"] != expected[name]["sha256"]:
            differing = [k for k, (a, b) in enumerate(zip(result["final"], expected[name]["final"])) if a != b]
            lines.append(f"{name}: trajectory differs; final state differs for bodies {differing}")
    return lines


def write_fixture(found, path=FIXTURE):
    record = {"recorded_on": list(RECORDED_ON), "python": platform.python_version(), "steps": STEPS,
              "cases": found}
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(record, handle, indent=1, sort_keys=True)
        handle.write("\n")


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    found = digests()
    if "--write" in argv:
        if (platform.system(), platform.machine()) != RECORDED_ON:
            sys.exit(f"record the fixture on {RECORDED_ON}, not {(platform.system(), platform.machine())}")
        write_fixture(found)
        print(f"wrote {len(found)} cases to {FIXTURE}")
        return
    problems = compare(found)
    print("\n".join(problems) or f"all {len(found)} cases bit-identical")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
