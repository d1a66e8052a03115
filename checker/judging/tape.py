"""What a student's functions did, recorded in the child and replayed in the grading parent.

The verdict must not be something the graded code can write. So the child
(untrusted: the student's code runs there) sends back only a *tape*: for each
call a probe made of one of the student's step functions, the arguments it
got, what the function returned (or the error it raised), the state it left
its arguments in, and any call it made to a function the probe put in its
place (a hook, such as the library's apply_impulse under resolve()). The
parent (trusted) then runs the very same probe code itself, with the lab's
handout (the starter) as the module and every step function replaced by a
replay of the tape. Every reference value and every comparison is computed
in the parent; the child never holds one.

What a forged tape can do: nothing a function could not have done. A replayed
call is checked against the arguments the parent's own probe passes (a tape
made for other inputs does not fit), and what it can claim - a return value,
changed arguments, calls of the hooks - is exactly what a student's function
is able to do anyway. A hook event may name only a function the probe put in
the student's place in this probe (never another name of the handout, such as
main); a call that changes a body's mass, inertia, material or shape (FROZEN)
is noted (Replayer.tampered) and fails its check with the field named. The
constants a probe reads are the handout's in the parent, whatever the tape
says: the child's reading only keeps the tape in step, and a reading that
differs (Replayer.read_constants), or a call the child saw change a handout
constant (`consts` on its entry, changed_constants), fails that step, named.

The probes keep the child free of answers too: a helper that computes a
reference is marked @reference and raises if called while a Recorder runs a
probe (Recorder.run), so the lesson's answers exist only in the parent.

Values cross the pipe as JSON with small tags: {"v": [x, y]} a Vector2,
{"l": [...]} a list, {"t": [...]} a tuple, {"d": {...}} a dict, {"b": k, ...}
a Body, {"w": k, ...} a World (its bodies and counters), {"r": k} the k-th
body or world seen in this call's arguments, {"o": type, "repr": text}
anything else (kept as an opaque stand-in).
"""
import functools
import hashlib
import json
import math
import numbers
import random
import time

from pygame import Vector2

from lesson11.physics2d import Body, World
from lesson11.physics2d import shapes as _shapes

from lesson11.mistakes import MOTION, motion_problem  # noqa: F401 (the window names a wrong kind in the same words)

# bound when the child imports this module, before any lab: a lab that replaces json.dumps or hashlib.sha256
# does not change how the recorder tells a changed argument from an unchanged one
_dumps, _sha256 = json.dumps, hashlib.sha256
SHAPES = {"Polygon": _shapes.Polygon, "Circle": _shapes.Circle}
# what a Body carries over the tape: the fields Body() sets. The world's own bookkeeping on a body
# (a sleeping island, caches) stays with the world that made it.
BODY_FIELDS = ("shape", "pos", "vel", "angle", "omega", "restitution", "friction", "color", "bullet", "asleep",
               "sleep_time", "mass", "inertia", "inv_mass", "inv_inertia")


def splice_name(function, steps):
    """The tape's name of `function` with the solution's `steps` spliced in: "sat:3"."""
    return f"{function}:{'+'.join(str(step) for step in steps)}"


def run_rng(module, salt):
    """A random.Random for one probe's drawn inputs: the run's seed (run_seed) with the probe's name as salt."""
    return random.Random(f"{run_seed(module)}:{salt}")


def clock(module):
    """CPU seconds for a probe's timing: recorded in the child, read back from the tape in the parent."""
    return module.clock() if isinstance(module, (Recorder, Replayer)) else time.process_time()


def run_seed(module):
    """The grading run's seed, drawn by the parent: a Recorder's or Replayer's `seed`; 0 for a plain module."""
    return vars(module)["seed"] if isinstance(module, (Recorder, Replayer)) else 0


# ---------------------------------------------------------------- references: computed in the parent only

_IN_CHILD = [False]   # True while a Recorder runs a probe: the child, where the student's code runs


class ReferenceInChild(RuntimeError):
    """A reference helper was called while the child ran a probe (a probe that computes the answer there)."""


def reference(function):
    """`function`, marked as computing a reference value: it runs in the grading parent only.

    A probe's child half only calls the student's functions on inputs and records; the lesson's
    answers are computed when the parent replays the tape. Called in the child, a reference raises
    ReferenceInChild, so a probe that computes one there is an error, not an answer in reach of the
    student's code (which could read it from the probe's frames).
    """
    @functools.wraps(function)
    def parent_only(*args, **kwargs):
        if _IN_CHILD[0]:
            raise ReferenceInChild(f"{function.__name__}() is a reference and runs in the grader only")
        return function(*args, **kwargs)

    parent_only.__reference__ = True
    return parent_only


def judging(module):
    """True in the grading parent (a Replayer or a plain module), False in the child (a Recorder)."""
    return not isinstance(module, Recorder)


class TapeMismatch(Exception):
    """The parent's probe asked for a call the tape does not hold (other inputs, another order)."""


class StudentValue(Exception):
    """A replayed call left a body's pos, vel, angle or omega as something a body's motion cannot be (a Vector2
    omega, a tuple or None for vel, NaN): the student's mistake, named, where arithmetic on it would fail in the
    grader."""


class StudentRaised(Exception):
    """A replayed call that raised in the child: carries the child's account of the error."""

    def __init__(self, error):
        super().__init__(error.get("message", "the function raised an error"))
        self.error = error


# ---------------------------------------------------------------- encoding


class Seen:
    """The bodies and worlds met while encoding one call, numbered in the order they were met."""

    def __init__(self):
        self.ids, self.objects = {}, []

    def number(self, obj):
        key = id(obj)
        if key in self.ids:
            return self.ids[key], False
        self.ids[key] = len(self.objects)
        self.objects.append(obj)
        return self.ids[key], True


MAX_DEPTH = 40   # levels of nesting encode() writes at most; decode() refuses deeper


def encode(value, seen, depth=0):
    """`value` as JSON-ready tagged data (see the module docstring); `seen` numbers bodies and worlds."""
    if depth > MAX_DEPTH:
        return {"o": type(value).__name__, "repr": "(nested too deep)"}
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, numbers.Integral):   # beyond a float's range no step's answer is right, and a JSON text of
        # more than 4300 digits is refused by json itself: carried as a stand-in that names its size
        return int(value) if int(value).bit_length() <= 1024 else \
            {"o": "int", "repr": f"<an int of {int(value).bit_length()} bits: too large for a float>"}
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, Vector2):
        return {"v": [value.x, value.y]}
    if isinstance(value, Body):
        k, new = seen.number(value)
        if not new:
            return {"r": k}
        return {"b": k, "vars": {name: encode(getattr(value, name), seen, depth + 1)
                                 for name in BODY_FIELDS if hasattr(value, name)}}
    if isinstance(value, World):
        k, new = seen.number(value)
        if not new:
            return {"r": k}
        return {"w": k, "bodies": encode(value.bodies, seen, depth + 1),
                "counters": encode(dict(value.counters), seen, depth + 1)}
    if isinstance(value, tuple(SHAPES.values())):
        return {"shape": type(value).__name__, "vars": {name: encode(item, seen, depth + 1)
                                                         for name, item in sorted(vars(value).items())}}
    if isinstance(value, list):
        return {"l": [encode(item, seen, depth + 1) for item in value]}
    if isinstance(value, tuple):
        return {"t": [encode(item, seen, depth + 1) for item in value]}
    if isinstance(value, dict) and all(isinstance(key, str) for key in value):
        return {"d": {key: encode(item, seen, depth + 1) for key, item in value.items()}}
    if isinstance(value, (set, frozenset)):
        items = [encode(item, seen, depth + 1) for item in value]
        return {"s": sorted(items, key=lambda item: _dumps(item, sort_keys=True))}
    if callable(value):
        return {"o": "function", "repr": getattr(value, "__qualname__", "a function")}
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - a student's object whose repr raises
        text = f"<{type(value).__name__}>"
    return {"o": type(value).__name__, "repr": text[:200]}


def key(data):
    """A canonical text of encoded data, to compare two encodings exactly."""
    return _dumps(data, sort_keys=True, allow_nan=True)


def digest(data):
    """A short fingerprint of encoded data: the tape keeps a call's arguments as this, not in full."""
    return _sha256(key(data).encode()).hexdigest()[:24]


# ---------------------------------------------------------------- decoding (in the parent)

def opaque(type_name, text):
    """A stand-in for a value the tape could not carry: an object of a class named like it, with its repr."""
    cls = type(str(type_name)[:60] or "object", (), {"__repr__": lambda self: text, "__slots__": ()})
    return cls()


def decode(data, seen, depth=0):
    """The value tagged `data` describes; {"r": k} is the k-th object of `seen`, new bodies are added to it."""
    if data is None or isinstance(data, (bool, int, float, str)):
        return data
    if depth > MAX_DEPTH + 2:   # encode() never nests deeper: a forged tape must not exhaust the grader's stack
        raise TapeMismatch("a value on the tape is nested deeper than the child ever writes")
    depth += 1
    if isinstance(data, list):   # not produced by encode(); a forged tape gets plain lists
        return [decode(item, seen, depth) for item in data]
    if not isinstance(data, dict) or len(data) == 0:
        raise TapeMismatch("a value on the tape is not in the tape's format")
    if "v" in data:
        x, y = data["v"]
        return Vector2(float(x), float(y))
    if "l" in data:
        return [decode(item, seen, depth) for item in data["l"]]
    if "t" in data:
        return tuple(decode(item, seen, depth) for item in data["t"])
    if "d" in data:
        return {str(k): decode(item, seen, depth) for k, item in data["d"].items()}
    if "s" in data:
        return set(decode(item, seen, depth) for item in data["s"])
    if "r" in data:
        index = data["r"]
        if not isinstance(index, int) or not 0 <= index < len(seen.objects):
            raise TapeMismatch("the tape refers to an object the call was not given")
        return seen.objects[index]
    if "b" in data:
        body = Body.__new__(Body)
        seen.number(body)
        for name, item in data["vars"].items():
            setattr(body, str(name), decode(item, seen, depth))
        return body
    if "shape" in data:
        cls = SHAPES.get(data["shape"])
        if cls is None:
            raise TapeMismatch("the tape holds a shape of an unknown kind")
        shape = cls.__new__(cls)
        for name, item in data["vars"].items():
            setattr(shape, str(name), decode(item, seen, depth))
        return shape
    if "w" in data:
        return opaque("World", "<a World>")
    if "o" in data:
        return opaque(data["o"], str(data.get("repr", "")))
    raise TapeMismatch("a value on the tape is not in the tape's format")


def restore(target, data, seen):
    """Put `target` (one of the parent's arguments) in the state `data` records; returns the value to keep.

    Mutable things (a Vector2, a list, a dict, a Body, a World's bodies and counters) are changed in
    place, as the student's function changed the child's; anything else is replaced by its decoded value.
    """
    if isinstance(target, Vector2) and isinstance(data, dict) and "v" in data:
        target.x, target.y = (float(c) for c in data["v"])
        return target
    if isinstance(target, list) and isinstance(data, dict) and "l" in data:
        items = data["l"]
        if len(items) == len(target):
            for index, item in enumerate(items):
                target[index] = restore(target[index], item, seen)
        else:
            target[:] = [decode(item, seen) for item in items]
        return target
    if isinstance(target, dict) and isinstance(data, dict) and "d" in data:
        for name, item in data["d"].items():
            target[name] = restore(target[name], item, seen) if name in target else decode(item, seen)
        for name in set(target) - set(data["d"]):
            del target[name]
        return target
    if isinstance(target, Body) and isinstance(data, dict) and "b" in data:
        for name, item in data["vars"].items():
            current = getattr(target, name, None)
            setattr(target, name, restore(current, item, seen))
        return target
    if isinstance(target, World) and isinstance(data, dict) and "w" in data:
        restore(target.bodies, data["bodies"], seen)
        restore(target.counters, data["counters"], seen)
        return target
    if isinstance(data, dict) and "r" in data:
        return decode(data, seen)
    if isinstance(target, tuple) and isinstance(data, dict) and "t" in data and len(data["t"]) == len(target):
        for item, part in zip(target, data["t"]):
            restore(item, part, seen)
        return target
    return decode(data, seen)


# ---------------------------------------------------------------- recording (in the child)

class Recorder:
    """The child's side: the student module with its step functions recorded, as a probe sees it.

    A probe reads `facade.sat` and calls it; sets `facade.apply_impulse = hook` to put a function of its
    own in the student's place (and sets the one it read back afterwards); reads constants with
    getattr(facade, NAME, default). Calls from the probe, the handout code or the library (depth 0) are
    recorded; calls a step function makes inside another run through unrecorded (they are part of
    the outer call), except calls of a hook, which are recorded as events of the outer call.
    """

    def __init__(self, module, steps, splices=None, lab_path="", seed=0, clock=time.process_time, constants=None):
        object.__setattr__(self, "_module", module)
        # the handout's constants (the grader sends them): set before each probe, watched around each call
        object.__setattr__(self, "_constants", {str(name): decode(value, Seen())
                                                for name, value in dict(constants or {}).items()})
        object.__setattr__(self, "_splices", dict(splices or {}))
        object.__setattr__(self, "_lab_path", lab_path)
        object.__setattr__(self, "seed", seed)
        object.__setattr__(self, "_tape", [])
        object.__setattr__(self, "_depth", [0])
        object.__setattr__(self, "_current", [None])
        object.__setattr__(self, "_clock", clock)
        originals, wrappers = {}, {}
        for name in steps:
            func = module.__dict__.get(name)
            if callable(func):
                originals[name] = func
                wrappers[name] = self._recording(name, func)
                module.__dict__[name] = wrappers[name]
        object.__setattr__(self, "_originals", originals)
        object.__setattr__(self, "_wrappers", wrappers)
        object.__setattr__(self, "_saved", {})

    # the probe's view of the module

    def __getattr__(self, name):
        module = self._module
        if name in self._wrappers:
            return module.__dict__.get(name, self._wrappers[name])
        if name not in module.__dict__:
            self._tape.append({"k": "const", "name": name, "missing": True})
            raise AttributeError(name)
        value = module.__dict__[name]
        if _plain(value):
            self._tape.append({"k": "const", "name": name, "value": encode(value, Seen())})
        return value

    def __setattr__(self, name, value):
        module = self._module
        if name not in self._saved:
            self._saved[name] = module.__dict__.get(name, _MISSING)
        original = self._wrappers.get(name, self._saved[name])
        if value is original or value is self._saved[name]:
            module.__dict__[name] = original   # the probe puts the student's function back
        else:
            module.__dict__[name] = self._hook(name, value)

    def spliced(self, name, function):
        """`function` as the parent spliced it (the solution's other steps in it), recorded; None if it has no splice.

        The spliced source is compiled under the lab's file name at the lab's own line numbers and
        run in a copy of the lab's globals, so a traceback names the student's line.
        """
        source, spliced = self._splices.get(name), None
        if source:
            try:
                namespace = dict(self._module.__dict__)
                exec(compile("\n" * int(source["first"]) + source["text"], self._lab_path, "exec"), namespace)
                spliced = namespace.get(function)
            except SyntaxError:
                spliced = None
        self._tape.append({"k": "splice", "name": name, "ok": callable(spliced)})
        return self._recording(name, spliced) if callable(spliced) else None

    def run(self, probe, lab_path):
        """probe(self, lab_path) as the child runs it: no reference helper may run meanwhile (`reference`).

        The module's constants are the handout's again first: a probe sees the handout's numbers whatever
        the file (or a step run in an earlier probe) set them to.
        """
        self._module.__dict__.update(self._constants)
        _IN_CHILD[0] = True
        try:
            return probe(self, lab_path)
        finally:
            _IN_CHILD[0] = False

    def clock(self):
        """process_time(), recorded so the parent's replay reports the child's timings."""
        now = self._clock()
        self._tape.append({"k": "clock", "t": now})
        return now

    def take(self):
        """The tape so far, and a fresh one for the next probe."""
        tape = self._tape[:]
        self._tape.clear()
        return tape

    # the wrappers

    def _recording(self, name, func):
        depth, current, tape = self._depth, self._current, self._tape
        namespace, watched = self._module.__dict__, tuple(self._constants)

        def constants_after(entry, before):
            """Note on the call's entry each handout constant the call left changed (`consts`: name -> value)."""
            changed = {}
            for constant, old in zip(watched, before):
                new = namespace.get(constant, _MISSING)
                if new is not old and (new is _MISSING or old is _MISSING or
                                       key(encode(new, Seen())) != key(encode(old, Seen()))):
                    changed[constant] = MISSING_VALUE if new is _MISSING else encode(new, Seen())
            if changed:
                entry["consts"] = changed

        def recorded(*args, **kwargs):
            if depth[0] > 0:
                depth[0] += 1
                try:
                    return func(*args, **kwargs)
                finally:
                    depth[0] -= 1
            entry = {"k": "call", "fn": name, "events": []}
            arguments = (args, kwargs)
            before = encode(arguments, Seen())
            entry["args"] = digest(before)
            tape.append(entry)
            depth[0], current[0] = 1, (entry, arguments)
            constants = [namespace.get(constant, _MISSING) for constant in watched]
            try:
                value = func(*args, **kwargs)
            except BaseException:
                depth[0], current[0] = 0, None
                entry["post"] = _changed(before, encode(arguments, Seen()))
                entry["raised"] = True
                constants_after(entry, constants)
                raise
            depth[0], current[0] = 0, None
            constants_after(entry, constants)
            seen = Seen()
            entry["post"] = _changed(before, encode(arguments, seen))
            entry["ret"] = encode(value, seen)
            return value

        recorded.__name__ = getattr(func, "__name__", name)
        recorded.__wrapped_step__ = name
        return recorded

    def _hook(self, name, hook):
        depth, current = self._depth, self._current

        def hooked(*args, **kwargs):
            if depth[0] == 0 or current[0] is None:
                return hook(*args, **kwargs)
            entry, arguments = current[0]
            seen = Seen()
            state = encode(arguments, seen)
            event = {"hook": name, "state": state, "args": encode((args, kwargs), seen)}
            entry["events"].append(event)
            saved = depth[0]
            depth[0] = 0
            try:
                return hook(*args, **kwargs)
            finally:
                depth[0] = saved

        return hooked


_MISSING = object()
MISSING_VALUE = {"o": "missing", "repr": "(deleted)"}   # a constant a call deleted, as the tape says so


def _changed(before, after):
    """`after`, or None when the call left its arguments as they were (the common case: a short tape)."""
    return None if key(after) == key(before) else after


def _plain(value):
    """True for the constants a probe may read from the lab (numbers, text, tuples of them)."""
    if value is None or isinstance(value, (bool, str, numbers.Real)):
        return True
    return isinstance(value, tuple) and all(_plain(item) for item in value)


plain = _plain


def mark_error(entry_error, tape):
    """The child's account of an error ends a probe's tape (the parent uses it when its replay runs off the end)."""
    return {"tape": tape, "error": entry_error}


# ---------------------------------------------------------------- replaying (in the parent)

class Replayer:
    """The parent's side: the handout (the starter, trusted) as the module, step functions replayed.

    `namespace` is the starter's globals after running its source (its main() is never called);
    each step function in it is replaced by a replay of the tape, in order.
    """

    def __init__(self, namespace, steps, tape, seed=0):
        object.__setattr__(self, "_ns", namespace)
        object.__setattr__(self, "seed", seed)
        object.__setattr__(self, "_tape", list(tape))
        object.__setattr__(self, "_at", [0])
        object.__setattr__(self, "_saved", {})
        object.__setattr__(self, "_hooks", {})       # name -> the function this probe put in the student's place
        object.__setattr__(self, "_tampered", {})    # step function -> body fields it changed (FROZEN)
        object.__setattr__(self, "_read", {})        # handout constant -> the other value the child's probe read
        replays = {}
        for name in steps:
            replays[name] = self._replay(name)
            namespace[name] = replays[name]
        object.__setattr__(self, "_replays", replays)

    def _next(self, kind, name=None):
        at = self._at[0]
        if at >= len(self._tape):
            raise TapeEnded()
        entry = self._tape[at]
        if not isinstance(entry, dict) or entry.get("k") != kind or (name is not None and entry.get("name",
                                                                                                      entry.get("fn")) != name):
            raise TapeMismatch(f"the probe expected a {kind} of {name} next on the tape")
        self._at[0] = at + 1
        return entry

    def __getattr__(self, name):
        ns = self._ns
        if name in self._replays:
            return ns.get(name, self._replays[name])
        if name not in ns or _plain(ns[name]):
            # a constant: always the handout's value (or missing, as in the handout); the child's reading only
            # keeps the tape in step, and one that differs is noted (read_constants) and fails the probe's step
            entry = self._next("const", name)
            if name not in ns:
                raise AttributeError(name)
            told = MISSING_VALUE if entry.get("missing") else entry.get("value")
            if key(told) != key(encode(ns[name], Seen())):
                self._read.setdefault(name, told)
            return ns[name]
        return ns[name]

    def __setattr__(self, name, value):
        ns = self._ns
        if name not in self._saved:
            self._saved[name] = ns.get(name, _MISSING)
        original = self._replays.get(name, self._saved[name])
        if value is original or value is self._saved[name]:
            ns[name] = original
            self._hooks.pop(name, None)
        else:
            ns[name] = self._hooks[name] = value

    def spliced(self, name, function):
        """The replay of a spliced step function, or None if the child could not build it."""
        entry = self._next("splice", name)
        if not entry.get("ok"):
            return None
        return self._replay(name)

    def clock(self):
        value = self._next("clock").get("t")
        return float(value) if isinstance(value, (int, float)) and math.isfinite(value) else 0.0

    def changed(self, names):
        """The functions among `names` that changed an argument in place in some replayed call (sorted)."""
        return sorted({entry.get("fn") for entry in self._tape[:self._at[0]]
                       if isinstance(entry, dict) and entry.get("k") == "call" and entry.get("fn") in names
                       and entry.get("post") is not None})

    def tampered(self):
        """{step function: [the body fields (FROZEN) it changed in some replayed call]}, sorted."""
        return {name: sorted(fields) for name, fields in sorted(self._tampered.items())}

    def read_constants(self):
        """{handout constant: the encoded value the child's probe read instead of the handout's}."""
        return dict(self._read)

    def finished(self):
        """True when the probe used the whole tape (a longer tape was made for other inputs)."""
        return self._at[0] == len(self._tape)

    def _replay(self, name):
        def replayed(*args, **kwargs):
            entry = self._next("call", name)
            arguments = (args, kwargs)
            seen = Seen()
            if digest(encode(arguments, seen)) != entry.get("args"):
                raise TapeMismatch(f"{name}() was called with other arguments in the child")
            events = entry.get("events") or []
            if not isinstance(events, list):
                raise TapeMismatch("a call's hook events on the tape are not a list")
            bodies = [obj for obj in seen.objects if isinstance(obj, Body)]
            restored = events or entry.get("post") is not None
            frozen = _frozen(bodies) if restored else None   # nothing restored: nothing changed
            for event in events:
                hook_name = event.get("hook") if isinstance(event, dict) else None
                hook = self._hooks.get(hook_name) if isinstance(hook_name, str) else None
                if hook is None:   # only a function this probe put in the student's place, never anything else
                    raise TapeMismatch("the tape calls a function the probe did not put in the student's place")
                restore(arguments, event.get("state"), seen)
                self._guard(name, bodies, frozen)
                self._motion(bodies)
                hook_args, hook_kwargs = decode(event.get("args"), seen)
                hook(*hook_args, **hook_kwargs)
            if entry.get("post") is not None:
                restore(arguments, entry["post"], seen)
                self._guard(name, bodies, frozen)
                self._motion(bodies)
            if entry.get("raised"):
                raise StudentRaised({"kind": "exception", "message": "raised"})
            return decode(entry.get("ret"), seen)

        replayed.__name__ = name
        return replayed


    @staticmethod
    def _motion(bodies):
        """Raise StudentValue if a replayed call left a body's vel or omega of the wrong kind (motion_problem)."""
        problem = motion_problem(bodies)
        if problem:
            raise StudentValue(problem)

    def _guard(self, name, bodies, frozen):
        """Note the FROZEN fields of `bodies` that differ from `frozen` (their state before the call)."""
        changed = {field for before, now in zip(frozen, _frozen(bodies)) for field in FROZEN
                   if before[field] != now[field]}
        if changed:
            self._tampered.setdefault(name, set()).update(changed)


def changed_constants(tape, handout):
    """{step function: {constant: encoded value}}: the handout constants (`handout`: {name: value}) that a call on
    `tape` left changed, as the child's recorder saw it (Recorder: `consts`). An observation that can only fail
    the file: the grader's own replay reads the handout's values whatever the tape says."""
    out = {}
    for entry in tape:
        consts = entry.get("consts") if isinstance(entry, dict) and entry.get("k") == "call" else None
        if isinstance(consts, dict) and isinstance(entry.get("fn"), str):
            for name, value in consts.items():
                if name in handout and key(value) != key(encode(handout[name], Seen())):
                    out.setdefault(entry["fn"], {}).setdefault(name, value)
    return out


# what a step function may never change on a body it is given: the body's mass, inertia, material and shape
# (a resolve() that zeroes inv_inertia or raises friction would make the lesson's formula agree with it)
FROZEN = ("mass", "inv_mass", "inertia", "inv_inertia", "friction", "restitution", "shape")


def _frozen(bodies):
    """Per body, the canonical text of each FROZEN field (absent fields as None)."""
    return [{field: key(encode(getattr(body, field, None), Seen())) for field in FROZEN} for body in bodies]


class TapeEnded(Exception):
    """The parent's probe asked for more than the tape holds: the child's probe stopped there."""
