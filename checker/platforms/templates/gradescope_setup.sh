#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder image (this folder is /autograder/source).
# It makes a venv with a released Python 3.10 or newer: python{{PYTHON}} (the version the package was built
# with) when it is installed and a final release, else the system's python3 (Ubuntu 22.04: 3.10, 24.04: 3.12);
# never a release candidate (Ubuntu 22.04's python3.11 package is 3.11.0rc1). Then the pins: {{PINS}}.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
export DEBIAN_FRONTEND=noninteractive
released() {  # a final release, 3.10 or newer, with venv and ensurepip
    command -v "$1" >/dev/null && "$1" -c 'import sys, venv, ensurepip
sys.exit(sys.version_info.releaselevel != "final" or sys.version_info < (3, 10))' 2>/dev/null
}
PY=""
for candidate in "python{{PYTHON}}" python3; do
    if released "$candidate"; then PY="$candidate"; break; fi
done
if [ -z "$PY" ]; then
    apt-get update
    apt-get install -y python3 python3-venv
    released python3 || { echo "setup.sh: no released Python 3.10 or newer with venv here: $(python3 --version 2>&1)" >&2; exit 1; }
    PY=python3
fi
echo "setup.sh: $("$PY" --version) ($(command -v "$PY"))"
"$PY" -m venv "$HERE/venv"
"$HERE/venv/bin/python" -m pip install --upgrade pip
if ! "$HERE/venv/bin/python" -m pip install {{PINS}}; then
    echo "setup.sh: the pinned versions do not all install on $("$PY" --version); pygame-ce as pinned where it" \
         "can, numpy the newest for this Python" >&2
    "$HERE/venv/bin/python" -m pip install {{PYGAME_PIN}} numpy || "$HERE/venv/bin/python" -m pip install pygame-ce numpy
fi
"$HERE/venv/bin/python" -m pip install --no-deps -e "$HERE/project"
# the student's code runs as this user, not as root
id student >/dev/null 2>&1 || useradd --create-home --shell /usr/sbin/nologin student
chmod -R a+rX "$HERE"
# the answers stay with the grader: it runs as root, the student's code (as student) cannot read them
chmod -R go-rwx "$HERE/project/solutions"
