"""The two small vector helpers every other module uses, and input checks.

Conventions for the whole package: positions in px, time in s, angles in rad,
y grows downward, so a positive angle turns a shape clockwise on screen.
"""
import math

from pygame import Vector2

__all__ = ["Vector2", "cross", "spin_velocity", "finite_number", "finite_vector"]

# Fast paths: True runs the quicker forms (same floats, bit for bit); False runs the readable reference forms.
# tests/test_fast_paths.py steps every lab's scene both ways and compares every float.
FAST_PATHS = True


def cross_reference(a, b):
    """2D cross product of two vectors, a scalar in px² (or px²/s, ...): the readable form of `cross`.

    cross(a, b) = a.x * b.y - a.y * b.x, the z component of the 3D cross
    product. It is positive when b lies clockwise of a on the screen.
    """
    return a.x * b.y - a.y * b.x


# cross(a, b): the same formula, a.x * b.y - a.y * b.x (see cross_reference), computed by pygame's own
# Vector2.cross in C. A lab's resolve() calls it several million times in a run, and the C version takes
# a fifth of the time of the Python one; tests/test_physics2d.py checks the two agree.
cross = Vector2.cross


def spin_velocity(omega, r):
    """Velocity (px/s) of a point at offset r (px) on a body spinning at omega (rad/s).

    This is omega × r in 2D: the vector (-omega * r.y, omega * r.x), at right
    angles to r and omega * |r| long (spin_velocity_reference).
    """
    if FAST_PATHS:
        # (r omega) turned a quarter turn: pygame's rotate(90) is exactly (x, y) -> (-y, x), so this is
        # (-(r.y omega), r.x omega), the same floats as the reference, in two C calls (2× quicker)
        return (r * omega).rotate(90)
    return spin_velocity_reference(omega, r)


def spin_velocity_reference(omega, r):
    """The readable form of spin_velocity: Vector2(-omega * r.y, omega * r.x) (px/s)."""
    return Vector2(-omega * r.y, omega * r.x)


def finite_number(value, name):
    """Return value as a float, or raise ValueError naming `name` if it is NaN, infinite or not a number."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {value!r}") from None
    if not math.isfinite(number):
        raise ValueError(f"{name} must be finite, got {number}")
    return number


def finite_vector(value, name):
    """Return value as a new Vector2, or raise ValueError naming `name` if it is not two finite numbers."""
    try:
        vector = Vector2(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a pair of numbers (x, y), got {value!r}") from None
    if not (math.isfinite(vector.x) and math.isfinite(vector.y)):
        raise ValueError(f"{name} must be finite, got ({vector.x}, {vector.y})")
    return vector
