"""The words for a student's mistake that the checker and the lab window share (one place, the same sentences).

A value of the wrong kind left on a body (motion_problem), and the meaning of a known mistake from the
error it raised or the value it left (meaning). The checker (checker/judging/common.py, checker/judging/tape.py) and the
lab window's pause on an error (lesson11/breakdown.py) both import them. Nothing here draws or imports
a window: only pygame's Vector2.
"""
import math
import numbers
import re

from pygame import Vector2

MOTION = (("pos", "vector", "px"), ("vel", "vector", "px/s"), ("angle", "number", "rad"),
          ("omega", "number", "rad/s"))
VALUE_RULE = "a body's pos and vel stay Vector2s, its angle and omega numbers"


def value_text(value, limit=60):
    """repr(value) cut to `limit` characters for a one-line message, whatever the value (a 5000-digit int's repr
    raises, a student's object's repr may too)."""
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - ValueError for a huge int, anything from a student's __repr__
        text = f"<an int of {value.bit_length()} bits>" if isinstance(value, int) else f"<a {type(value).__name__}>"
    text = " ".join(text.split())   # one line
    return text if len(text) <= limit else text[:limit - 3] + "..."


def number_problem(value, unit=""):
    """Why `value` is not a number a float can hold (a bool, a string, a Vector2, NaN, infinity, an int too big
    for a float), or "". `unit` ends the message: "rad/s"."""
    tail = f" ({unit})" if unit else ""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return f"{value_text(value)}, not a number{tail}"
    try:
        finite = math.isfinite(value)
    except OverflowError:   # an int beyond a float's range
        return f"an int of {value.bit_length()} bits, too large for a float{tail}"
    return "" if finite else f"{value_text(value)}, not a finite number{tail}"


def vector_problem(value, unit=""):
    """Why `value` is not a pygame Vector2 of finite numbers (a tuple, a list, a number, NaN in it), or ""."""
    tail = f" ({unit})" if unit else ""
    if not isinstance(value, Vector2):
        return f"{value_text(value)}, not a Vector2{tail}"
    return "" if math.isfinite(value.x) and math.isfinite(value.y) else f"{value_text(value)}, not finite{tail}"


PROBLEMS = {"vector": vector_problem, "number": number_problem}


def body_problem(body):
    """(field, how it is wrong) for the first of pos, vel, angle, omega of `body` that breaks its kind, or None."""
    for field, kind, unit in MOTION:
        problem = PROBLEMS[kind](getattr(body, field, None), unit)
        if problem:
            return field, problem
    return None


def motion_problem(bodies):
    """How a body of `bodies` breaks its motion's kinds (pos and vel finite Vector2s in px and px/s, angle and omega
    finite numbers in rad and rad/s), or ""."""
    for body in bodies:
        found = body_problem(body)
        if found:
            return f"left a body's {found[0]} as {found[1]}"
    return ""


def return_problem(value):
    """How a value a hook hands back to the World is not finite (a number or Vector2 that is NaN or infinite, alone
    or in a tuple such as sat's (normal, depth)), or ""."""
    for item in value if type(value) in (tuple, list) and len(value) <= 4 else (value,):
        if isinstance(item, Vector2):
            bad = not (math.isfinite(item.x) and math.isfinite(item.y))
        elif isinstance(item, float):
            bad = not math.isfinite(item)
        else:
            continue
        if bad:
            return f"returned {value_text(value)}: not finite"
    return ""


# ---------------------------------------------------------------- the meaning of a known mistake

DIVIDED_BY_INERTIA = ("dividing by I is multiplying by inv_inertia (= 1 / I): write * inv_inertia where the lesson "
                      "writes / I; a static body's inv_inertia (the floor's, the ramp's) is 0")
DIVIDED_BY_MASS = ("dividing by m is multiplying by inv_mass (= 1 / m): write * inv_mass where the lesson writes / m; "
                   "a static body's inv_mass (the floor's, the ramp's) is 0")
BY_STATIC_INERTIA = ("a static body (the floor, the ramp) has inertia 0, so / I fails on it: write * inv_inertia, "
                     "which is 1 / I for a moving body and 0 for a static one")
BY_STATIC_MASS = ("a static body (the floor, the ramp) has mass 0, so / m fails on it: write * inv_mass, "
                  "which is 1 / m for a moving body and 0 for a static one")
SPIN_VECTOR = ("the spin changes by cross(r, impulse) * inv_inertia, a number; an impulse times inv_inertia alone "
               "is a Vector2 (the cross product forgotten)")
VEL_NONE = ("update(), normalize_ip(), scale_to_length() and the other in-place methods change a vector and return "
            "None: give vel a new Vector2, not what they return")
SQRT_NEGATIVE = ("math.sqrt() was handed a negative number: a negative discriminant means there is no root (the paths "
                 "miss), so test its sign before the square root")
SUM_OF_VECTORS = ("sum() starts from the number 0, and 0 + a Vector2 fails: sum(points, Vector2()) starts from a "
                  "vector (or use centre_of(points))")
NOT_FINITE = ("a NaN or an infinity spreads into every number computed from it, and through contacts to other bodies: "
              "it starts at a 0 × inf, an inf - inf or a value grown past a float's range")

_DIVIDED = re.compile(r"/\s*\(?\s*(?:\w+\.)*(inv_)?(inertia|mass)\b")   # "/ a.inv_inertia", "/ (b.mass)"


def meaning(message="", text="", problem=""):
    """What a known mistake means, in one sentence, or "": from the error's `message` ("ZeroDivisionError: ...")
    and the source `text` of its line, or from a wrong-kind `problem` (motion_problem's words)."""
    if problem:
        if problem.startswith("left a body's omega as Vector2"):
            return SPIN_VECTOR
        if problem.startswith("left a body's vel as None"):
            return VEL_NONE
        if "not finite" in problem or "not a finite number" in problem:
            return NOT_FINITE
        return ""
    divided = _DIVIDED.search(text or "")
    if message.startswith("ZeroDivisionError") and divided:
        inverse, quantity = divided.group(1), divided.group(2)
        if inverse:
            return DIVIDED_BY_INERTIA if quantity == "inertia" else DIVIDED_BY_MASS
        return BY_STATIC_INERTIA if quantity == "inertia" else BY_STATIC_MASS
    if message == "ValueError: math domain error" and "sqrt(" in (text or ""):
        return SQRT_NEGATIVE
    if message.startswith("TypeError") and "'int' and 'pygame.math.Vector2'" in message and "sum(" in (text or ""):
        return SUM_OF_VECTORS
    if message.startswith("TypeError") and "Vector2" in message and "omega" in (text or ""):
        return SPIN_VECTOR
    if message.startswith(("TypeError", "AttributeError")) and "NoneType" in message and "vel" in (text or ""):
        return VEL_NONE
    return ""
