#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder image (this folder is /autograder/source).
# It installs Python {{PYTHON}} and the versions the package was built with: {{PINS}}.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
export DEBIAN_FRONTEND=noninteractive
PY="python{{PYTHON}}"
if ! command -v "$PY" >/dev/null; then
    apt-get update
    apt-get install -y "$PY" "$PY-venv" || apt-get install -y python3 python3-venv python3-pip
fi
command -v "$PY" >/dev/null || PY=python3
"$PY" -m venv "$HERE/venv"
"$HERE/venv/bin/python" -m pip install --upgrade pip
if ! "$HERE/venv/bin/python" -m pip install {{PINS}}; then
    echo "setup.sh: the pinned versions do not install on $("$PY" --version); installing the newest ones" >&2
    "$HERE/venv/bin/python" -m pip install pygame-ce numpy
fi
"$HERE/venv/bin/python" -m pip install --no-deps -e "$HERE/project"
# the student's code runs as this user, not as root
id student >/dev/null 2>&1 || useradd --create-home --shell /usr/sbin/nologin student
chmod -R a+rX "$HERE"
