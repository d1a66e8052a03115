"""The child process that runs one lab file for the checker, isolated from the grader.

    python -m checker.child LAB_PATH TASK SETTINGS_JSON RESULT_JSON

TASK is "probe" (import the lab and test its own functions on the lesson's
cases) or "scenario" (configure the lab runtime with SETTINGS_JSON and run the
lab's main()). The child writes what happened to RESULT_JSON; the parent (the
grader) reads it and decides. The lab is compiled from its source under its own
file name (so tracebacks name the student's file and line) and imported under
the module name "lab_under_test", so its `if __name__ == "__main__":` guard does
not run main(). No bytecode is written next to the submitted file.

The parent sets the resource limits and the wall-clock timeout; this file only
arms faulthandler so that a run killed for taking too long leaves a traceback
(where the lab was looping) in "timeout_traceback.txt" in the working directory.
"""
import faulthandler
import io
import json
import math
import os
import sys
import traceback
import types

sys.dont_write_bytecode = True

MODULE_NAME = "lab_under_test"
REQUIRED = ("sat", "apply_impulse", "resolve", "main")


class LabExit(BaseException):
    """Raised in place of os._exit() so that an exit inside the lab still yields a result."""

    def __init__(self, code):
        super().__init__(code)
        self.code = code


def _blocked_os_exit(code=0):
    raise LabExit(code)


def where(exc, lab_path):
    """(line, source text) of the innermost traceback frame inside the lab file, or (None, None)."""
    if isinstance(exc, SyntaxError) and exc.filename == lab_path:
        return exc.lineno, (exc.text or "").strip()
    found = (None, None)
    for frame in traceback.extract_tb(exc.__traceback__):
        if frame.filename == lab_path:
            found = (frame.lineno, (frame.line or "").strip())
    return found


def describe(exc, lab_path):
    """A JSON-ready account of an exception raised by lab code."""
    line, text = where(exc, lab_path)
    if isinstance(exc, LabExit):
        kind, message = "exit", f"os._exit({exc.code}) was called"
    elif isinstance(exc, SystemExit):
        kind, message = "exit", f"sys.exit({exc.code!r}) was called"
    elif isinstance(exc, MemoryError):
        kind, message = "memory", "MemoryError: the lab ran out of memory"
    elif isinstance(exc, SyntaxError):
        kind, message = "syntax", f"SyntaxError: {exc.msg}"
    else:
        kind, message = "exception", f"{type(exc).__name__}: {exc}"
    tail = traceback.format_exception(type(exc), exc, exc.__traceback__)
    return {"kind": kind, "message": message, "line": line, "text": text,
            "traceback": "".join(tail)[-4000:]}


def load_lab(lab_path, copy_path):
    """Compile and run the lab's source as module MODULE_NAME; returns the module."""
    with open(lab_path, "rb") as handle:
        source = handle.read()
    code = compile(source, lab_path, "exec", dont_inherit=True)
    module = types.ModuleType(MODULE_NAME)
    module.__file__ = copy_path  # the lab sees a copy, never the submitted file
    sys.modules[MODULE_NAME] = module
    exec(code, module.__dict__)
    return module


# ---------------------------------------------------------------- probe: the student's own functions

def _vec(value):
    from pygame import Vector2
    return Vector2(value)


def _box(w, h, centre, angle_deg=0.0):
    from pygame import Vector2
    corners = [Vector2(-w / 2, -h / 2), Vector2(w / 2, -h / 2), Vector2(w / 2, h / 2), Vector2(-w / 2, h / 2)]
    return [Vector2(centre) + c.rotate(angle_deg) for c in corners]


def _result_of_sat(hit):
    """The sat() answer as plain data: None, or {"normal": [x, y], "depth": d}; raises on a bad shape."""
    if hit is None:
        return None
    normal, depth = hit
    normal = _vec(normal)
    depth = float(depth)
    return {"normal": [normal.x, normal.y], "depth": depth}


def probe_sat(sat):
    """The lesson's three pairs (A = 40 × 40 box at the origin), each also with A and B swapped."""
    a = _box(40, 40, (0, 0))
    pairs = {
        "side by side, 10 px overlap": _box(40, 40, (30, 5)),
        "diamond near a corner": _box(40, 40, (45, 45), 45),
        "diamond pushed closer": _box(40, 40, (30, 30), 45),
    }
    out = []
    for name, b in pairs.items():
        out.append({"pair": name, "order": "A, B", "result": _result_of_sat(sat(list(a), list(b)))})
        out.append({"pair": name, "order": "B, A", "result": _result_of_sat(sat(list(b), list(a)))})
    return out


def _bodies():
    from lesson11.physics2d import Body, box_points
    a = Body(box_points(60, 40), (0, 0), 2.4)
    b = Body(box_points(50, 50), (0, 0), 2.5)
    return a, b


def _state(body):
    return {"vel": [body.vel.x, body.vel.y], "omega": body.omega}


def probe_apply_impulse(apply_impulse):
    """An off-centre hit: impulse (0, 300) at ra = (25, 18), rb = (-20, -22) on two dynamic crates."""
    a, b = _bodies()
    impulse, ra, rb = _vec((0, 300)), _vec((25, 18)), _vec((-20, -22))
    before = {"a": _state(a), "b": _state(b)}
    apply_impulse(a, b, impulse, ra, rb)
    from lesson11.physics2d import cross
    expected = {
        "a": {"vel": [0.0, -300 * a.inv_mass], "omega": -cross(ra, impulse) * a.inv_inertia},
        "b": {"vel": [0.0, 300 * b.inv_mass], "omega": cross(rb, impulse) * b.inv_inertia},
    }
    return {"before": before, "after": {"a": _state(a), "b": _state(b)}, "expected": expected}


def _slip(a, b, normal, point):
    """(normal speed, tangential slip vector) of B's contact point relative to A's."""
    from lesson11.physics2d import relative_velocity
    rel = relative_velocity(a, b, point - a.pos, point - b.pos)
    vn = rel.dot(normal)
    tangent = rel - normal * vn
    return vn, tangent


def probe_resolve(resolve):
    """Three contacts between a static floor (A) and a 60 × 40 crate (B) resting on it.

    glancing: the crate slides right at 400 px/s and touches the floor at 5 px/s.
        The grader compares the crate's momentum change along x (the friction
        impulse) with mu times its change along y (the normal impulse j).
    sliding: the same at 80 px/s down into the floor, 200 px/s along it.
    corner: the crate, turned 30°, lands on its lowest corner at 200 px/s with
        friction 0 and restitution 0: the contact should stop closing (vn ≈ 0),
        which needs the spin terms in k.
    """
    from lesson11.physics2d import Body, box_points, effective_mass_inverse
    out = {}
    for name, vel, angle, mu, e in (("glancing", (400, 5), 0.0, 0.6, 0.2),
                                    ("sliding", (200, 80), 0.0, 0.6, 0.2),
                                    ("corner", (0, 200), math.radians(30), 0.0, 0.0)):
        floor = Body(box_points(400, 40), (0, 20), 0, friction=mu, restitution=e)
        crate = Body(box_points(60, 40), (0, -20), 2.4, angle=angle, vel=vel, friction=mu, restitution=e)
        normal = _vec((0, -1))  # from the floor (A, below) up to the crate (B)
        if angle:
            lowest = max(crate.world_points(), key=lambda p: p.y)
            crate.pos.y -= lowest.y - 0.5  # corner 0.5 px into the floor
            point = max(crate.world_points(), key=lambda p: p.y)
        else:
            point = _vec((-25, 0))  # a point of the crate's bottom edge, left of centre
        vn0, t0 = _slip(floor, crate, normal, point)
        omega0 = crate.omega
        vel0 = _vec(crate.vel)
        resolve(floor, crate, normal, point)
        vn1, t1 = _slip(floor, crate, normal, point)
        # the Coulomb bound on the slip change: |Δslip| <= mu * j * k_t, with j the normal impulse
        ra, rb = point - floor.pos, point - crate.pos
        k = effective_mass_inverse(floor, crate, ra, rb, normal)
        out[name] = {
            "vn_before": vn0, "vn_after": vn1,
            "slip_before": [t0.x, t0.y], "slip_after": [t1.x, t1.y],
            "omega_before": omega0, "omega_after": crate.omega,
            "vel_before": [vel0.x, vel0.y], "vel_after": [crate.vel.x, crate.vel.y],
            "k": k, "mu": mu, "restitution": e,
            "kt": effective_mass_inverse(floor, crate, ra, rb, _vec((1, 0))),
            "mass": crate.mass,
        }
    return out


def run_probe(module, lab_path):
    """Test each of the lab's functions on the lesson's cases; a failing function gets its own error."""
    result = {"functions": {}, "missing": [m for m in REQUIRED if not callable(getattr(module, m, None))]}
    for name, probe in (("sat", probe_sat), ("apply_impulse", probe_apply_impulse), ("resolve", probe_resolve)):
        func = getattr(module, name, None)
        if not callable(func):
            continue
        try:
            result["functions"][name] = {"ok": True, "data": probe(func)}
        except Exception as exc:  # the student's function raised: report it with file and line
            result["functions"][name] = {"ok": False, "error": describe(exc, lab_path)}
    return result


# ---------------------------------------------------------------- scenario: the lab's main() under the runtime

def run_scenario(module, settings):
    from lesson11 import runtime
    runtime.configure(settings)
    try:
        module.main()
    finally:
        runtime.write_record()


def main(argv):
    lab_path, task, settings_path, result_path = argv
    faulthandler.enable()
    budget = float(os.environ.get("CHECKER_FAULT_SECONDS", "0") or 0)
    trace = open("timeout_traceback.txt", "w")
    if budget > 0:
        faulthandler.dump_traceback_later(budget, exit=True, file=trace)
    os._exit = _blocked_os_exit
    with open(settings_path, encoding="utf-8") as handle:
        settings = json.load(handle)
    copy_path = os.path.abspath(os.path.basename(lab_path))
    result = {"task": task, "phase": "import"}

    def save():
        with open(result_path + ".tmp", "w", encoding="utf-8") as handle:
            json.dump(result, handle)
        os.replace(result_path + ".tmp", result_path)

    save()
    try:
        module = load_lab(lab_path, copy_path)
        result["phase"] = "run"
        save()
        if task == "probe":
            result["probe"] = run_probe(module, lab_path)
        else:
            missing = [m for m in REQUIRED if not callable(getattr(module, m, None))]
            if missing:
                raise AttributeError(f"the lab defines no {missing[0]}()")
            run_scenario(module, settings)
        result["phase"] = "done"
    except BaseException as exc:  # anything the lab raises, SystemExit included, becomes a result
        result["error"] = describe(exc, lab_path)
    faulthandler.cancel_dump_traceback_later()
    sys.stdout.flush()
    save()
    # leave without running the lab's atexit handlers twice or waiting on its threads
    sys.stdout.flush()
    sys.stderr.flush()
    os.__dict__["_exit"] = _real_exit
    _real_exit(0)


_real_exit = os._exit

if __name__ == "__main__":
    main(sys.argv[1:])
