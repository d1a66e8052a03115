"""The platforms' own procedures in clean root file systems (tests/platform_acceptance.py), as a test.

It needs root, debootstrap, overlay mounts and the distributions' mirrors, and takes about 10 minutes the
first time (the roots are then kept in /var/cache/lesson11-acceptance), so it runs only when asked:
L11_PLATFORMS=1 python -m pytest -m platforms -n 0. The default suite follows each platform's procedure
in a temporary root instead (tests/test_checker_package.py).
"""
import os
import shutil
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))


@pytest.mark.platforms
def test_every_package_grades_every_submission_as_it_deserves():
    if os.environ.get("L11_PLATFORMS") != "1":
        pytest.skip("set L11_PLATFORMS=1 to build Ubuntu and Debian roots with debootstrap and grade in them "
                    "(root, network, about 10 minutes)")
    if os.geteuid() != 0 or not shutil.which("debootstrap"):
        pytest.skip("needs root and debootstrap")
    done = subprocess.run([sys.executable, os.path.join(HERE, "platform_acceptance.py")], capture_output=True,
                          text=True, timeout=3600)
    print(done.stdout)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-2000:]
