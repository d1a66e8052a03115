"""Every lab scene and bench scene, in every solver setting, moves exactly as when the fixture was recorded.

tests/trajectory_digest.py steps 9 scenes × 4 settings for 2 s and hashes every body's state after every
step (float.hex). A refactor of physics2d (issue 34: Body properties, one phase list per solver, the sleep
module) must leave all 36 digests unchanged; a change meant to alter the motion re-records the fixture
(`python tests/trajectory_digest.py --write`) and says why in its commit.
"""
import math
import platform

import pytest

import trajectory_digest

ON_RECORDING_PLATFORM = (platform.system(), platform.machine()) == trajectory_digest.RECORDED_ON


@pytest.mark.skipif(not ON_RECORDING_PLATFORM,
                    reason="the fixture is recorded on Linux x86_64; another libm's sin/cos may differ by an ulp, "
                           "and one ulp changes a trajectory's digest without anything being wrong")
def test_every_case_is_bit_identical_to_the_fixture():
    found = trajectory_digest.digests()
    assert set(found) == set(trajectory_digest.load_fixture())
    assert trajectory_digest.compare(found) == []


def test_the_digest_sees_one_ulp():
    """The digest is not blind: one ulp on one crate's x before the run changes it."""
    def nudged():
        world = trajectory_digest.pyramid()
        crate = world.bodies[1]
        crate.pos.x = math.nextafter(crate.pos.x, math.inf)
        return world
    plain = trajectory_digest.run(trajectory_digest.pyramid, steps=3)
    assert trajectory_digest.run(trajectory_digest.pyramid, steps=3) == plain
    assert trajectory_digest.run(nudged, steps=3)["sha256"] != plain["sha256"]
