"""The worked k and j of lesson11/README.md section 5 (and of quiz question 6) are what physics2d computes.

The scene is tests/contact_shot.py's, drawn in assets/contact_picture.png: a 60 × 40 px crate of mass 2.4
turned by atan(5/12), its lowest corner on a static floor at rb = (20, 30), moving at (60, 200) px/s.
"""
import math
import os

import pytest
from pygame import Vector2

import contact_shot
from lesson11.physics2d import cross, spin_velocity
from lesson11.physics2d.response import effective_mass_inverse, resolve

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def lesson():
    with open(os.path.join(ROOT, "lesson11", "README.md"), encoding="utf-8") as handle:
        return " ".join(handle.read().split())


def test_the_contact_in_the_picture():
    floor, crate, point, normal = contact_shot.scene()
    rb = point - crate.pos
    assert rb.x == pytest.approx(20, abs=1e-9) and rb.y == pytest.approx(30, abs=1e-9)
    assert crate.inertia == pytest.approx(1040)            # m (w² + h²) / 12 = 2.4 × 5200 / 12
    assert cross(rb, normal) == pytest.approx(-20)         # rb × n = 20·(−1) − 30·0
    rel = crate.vel + spin_velocity(crate.omega, rb)
    assert rel.dot(normal) == pytest.approx(-200)          # vn: closing at 200 px/s


def test_the_worked_k_and_j():
    floor, crate, point, normal = contact_shot.scene()
    ra, rb = point - floor.pos, point - crate.pos
    k = effective_mass_inverse(floor, crate, ra, rb, normal)
    assert k == pytest.approx(1 / 2.4 + 20 ** 2 / 1040)
    assert round(k, 4) == 0.8013 and round(1 / 2.4, 4) == 0.4167 and round(400 / 1040, 4) == 0.3846
    e = min(floor.restitution, crate.restitution)
    j = -(1 + e) * -200 / k
    assert e == 0.2 and round(j, 1) == 299.5
    text = lesson()
    for number in ("0.4167", "0.3846", "0.8013", "299.5", "1040"):
        assert number in text, number


def test_after_the_impulse_the_corner_leaves_at_e_times_its_approach():
    floor, crate, point, normal = contact_shot.scene()
    crate.vel = Vector2(0, 200)                            # straight down: no friction, the normal impulse alone
    resolve(floor, crate, normal, point, friction=False)
    rb = point - crate.pos
    after = (crate.vel + spin_velocity(crate.omega, rb)).dot(normal)
    assert after == pytest.approx(40)                      # −e·vn = 0.2 × 200
    assert crate.omega == pytest.approx(299.52 * -20 / 1040, rel=1e-4)   # Δω = j (rb × n) / I ≈ −5.76 rad/s
    assert math.isclose(crate.vel.y, 200 - 299.52 / 2.4, rel_tol=1e-4)     # Δv = j n / m: 124.8 px/s up
