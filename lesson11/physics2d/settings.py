"""Settings checked when set: the attributes of Body and World that refuse a bad value in one line.

setting(name, check, doc) is a property: a value assigned to it on an object
(in __init__ and at any time later) goes through check(obj, value), which
returns the value to keep or raises a one-line ValueError naming the setting
and the value, and is kept in the plain attribute `_name`:

    >>> from lesson11.physics2d import World
    >>> world = World()
    >>> world.slop = 0.25          # checked, then kept: world.slop is 0.25
    >>> world.slop = -1
    Traceback (most recent call last):
    ...
    ValueError: world slop must be >= 0 px, got -1.0

Reading one calls no Python code (the getter is operator.attrgetter, in C), so
a setting read a few thousand times a step costs little; help(World.slop)
prints the setting's docstring. The checks of World's settings live here too
(one factory per kind of value); Body's are in bodies.py, next to the fields
they keep consistent.
"""
from operator import attrgetter

from .vectors import finite_number, finite_vector


def setting(name, check, doc):
    """A property `name` kept in `_name`: obj.name = value keeps check(obj, value), or raises its ValueError."""
    private = "_" + name

    def set_(obj, value):
        setattr(obj, private, check(obj, value))
    return property(attrgetter(private), set_, doc=doc)


# ---------------------------------------------------------------- checks of World's settings
# Each factory returns check(world, value) for setting(); `name` words the error.

def positive_seconds(name):
    """A number of seconds > 0."""
    def check(_, value):
        value = finite_number(value, f"world {name}")
        if value <= 0:
            raise ValueError(f"world {name} must be > 0 s, got {value}")
        return value
    return check


def whole_number(name, none_allowed=False):
    """An int >= 1 (not a bool); None too if none_allowed."""
    def check(_, value):
        if value is None and none_allowed:
            return None
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise ValueError(f"world {name} must be a whole number >= 1, got {value!r}")
        return value
    return check


def at_least_zero(name, unit):
    """A finite number >= 0 in `unit`."""
    def check(_, value):
        value = finite_number(value, f"world {name}")
        if value < 0:
            raise ValueError(f"world {name} must be >= 0 {unit}, got {value}")
        return value
    return check


def fraction(name):
    """A finite number between 0 and 1."""
    def check(_, value):
        value = finite_number(value, f"world {name}")
        if not 0 <= value <= 1:
            raise ValueError(f"world {name} must be between 0 and 1, got {value}")
        return value
    return check


def vector(name):
    """Two finite numbers (x, y), stored as a new Vector2."""
    def check(_, value):
        return finite_vector(value, f"world {name}")
    return check


def one_of(choices, name, forget_arbiters=False):
    """One of `choices`; forget_arbiters: a change drops the accumulated solver's kept contacts."""
    def check(world, value):
        if value not in choices:
            raise ValueError(f"{name} must be one of {list(choices)}, got {value!r}")
        if forget_arbiters and getattr(world, "_" + name, value) != value:
            world.arbiters = {}
        return value
    return check


def effect_set(choices):
    """A set of effect names from `choices`, stored as a frozenset."""
    def check(_, value):
        if isinstance(value, str):
            raise ValueError(f"effects must be a set of names such as {{{value!r}}}, not the string {value!r}")
        unknown = set(value) - set(choices)
        if unknown:
            raise ValueError(f"unknown effects {sorted(unknown)}; choose from {list(choices)}")
        return frozenset(value)
    return check


def hook(name):
    """A function (World(...) puts the library's in place of None before it gets here)."""
    def check(_, value):
        if not callable(value):
            raise ValueError(f"world {name} must be a function (or None for the library's), got {value!r}")
        return value
    return check


def flag(name):
    """True or False."""
    def check(_, value):
        if not isinstance(value, bool):
            raise ValueError(f"world {name} must be True or False, got {value!r}")
        return value
    return check
