"""A student's function's answer as plain data, for a declared Step's `answer` (checker/judging/declared.py).

Each turns what the function returned into the plain data the probe records (floats, lists of floats), or,
when it is not that kind of value, into the text of what it is (common.value_text: a short repr). A Step
then calls a str answer malformed (bad=is_text) and its message shows that text.
"""
from pygame import Vector2

from .common import real, value_text


def is_text(answer):
    """True for an answer that was not the kind asked for (these functions gave its text instead)."""
    return isinstance(answer, str)


def as_number(value):
    """A number as a float (not a str, a bool or anything else float() would read), else its text."""
    try:
        return real(value)
    except (TypeError, ValueError):
        return value_text(value)


def as_point(value):
    """A point or vector, anything Vector2() takes, as [x, y], else its text."""
    try:
        v = Vector2(value)
    except (TypeError, ValueError):
        return value_text(value)
    return [v.x, v.y]


def as_points(value):
    """A list of points as [[x, y], ...], else the list's text."""
    try:
        return [[float(Vector2(p).x), float(Vector2(p).y)] for p in value]
    except (TypeError, ValueError):
        return value_text(value)
