"""Text report spoofing by a terminal's control characters (after issue 39.9 indented every message line).

A message line is indented, but on a terminal a backspace walks back over the indentation, `ESC [ 1 A` moves the
cursor up and `ESC [ 2 K` erases a line: an exception text holding them printed a row of its own at the left
margin or erased the classmates' rows above it. A student's folder name can hold them too (the progress lines
and the summary name it). One CLI run as it is used (as root the child runs as `nobody`) over a class folder:
- zoe: the starter with an exception at import whose text backs over its indentation and prints a fake row, then
  moves up and erases; her twin erin: the same import, no attack (tests/test_report_rows.py's twin).
- the folder `yan<ESC>[2J` holding the starter: its name clears the screen wherever it is printed.
Every control character now prints as its escape (`\\x1b`, `\\x08`); the scores are the twins' scores.
"""
import json
import os
import subprocess
import sys

from test_report_rows import FAKE_ROW, after_imports, starter

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONTROLS = ("\x1b", "\x08", "\x7f", "\x9b", "\u202e")


def test_control_characters_in_a_message_or_a_name_print_as_escapes(tmp_path):
    text = starter()
    spoof = ("raise RuntimeError('boom' + '\\x08' * 12 + " + repr(FAKE_ROW)
             + " + '\\x1b[1A\\x1b[2K\\x1b[1A\\x1b[2K\\x9b2J\\u202e71/0\\x7f')\n")
    files = {"zoe": after_imports(text, spoof), "erin": after_imports(text, "import os as _os\n"),
             "yan\x1b[2J": text}
    for name, body in files.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "tumbling_crates.py").write_text(body, encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", str(tmp_path), "--jobs", "2", "--timeout", "10"],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 1, proc.stderr[-3000:]
    for stream in (proc.stdout, proc.stderr):
        assert not [c for c in CONTROLS if c in stream], stream[-3000:]
    assert "\\x08" in proc.stdout and "\\x1b[1A" in proc.stdout and "yan\\x1b[2J" in proc.stdout, proc.stdout
    assert "[3/3]" in proc.stderr or "yan\\x1b[2J" in proc.stderr, proc.stderr   # the progress lines, escaped
    lines = proc.stdout.splitlines()
    assert not [line for line in lines if FAKE_ROW in line and not line.startswith(" ")], proc.stdout
    again = subprocess.run([sys.executable, "-m", "checker", str(tmp_path), "--json", "--quiet", "--jobs", "2",
                            "--timeout", "10"], cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    rows = {os.path.basename(os.path.dirname(r["path"])): r for r in json.loads(again.stdout)["labs"]}
    assert rows["zoe"]["score"] <= rows["erin"]["score"] == 3, rows   # the attack gains nothing over its twin
    assert rows["yan\x1b[2J"]["score"] == 3   # JSON keeps the name as it is (json escapes it)
