"""Output on a console that is not UTF-8 (lesson11/console.py): stand-ins, never a UnicodeEncodeError.

Windows gives a program its ANSI code page (cp1252 in the Americas and Western Europe) when its output is
redirected to a file or a pipe, and some terminals and CI runners use ASCII; PYTHONIOENCODING=cp1252 and
=ascii give this machine exactly those streams. (A real Windows console window is UTF-8 for Python 3.6+, so
there the characters themselves are printed.) Every program that prints is run here as a user runs it.
"""
import io
import ntpath
import os
import subprocess
import sys

import pytest

from checker.reporting import outputs
from lesson11.console import HANDLER, readable, safe_output

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join("starters", "tumbling_crates_starter.py")   # typed relative, as a student types it


def run(args, encoding, stdin=None, cwd=ROOT, **env):
    """(exit status, stdout, stderr) of `python args...` with its streams in `encoding`."""
    environment = dict(os.environ, PYTHONIOENCODING=encoding, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
                       PYGAME_HIDE_SUPPORT_PROMPT="1", **env)
    proc = subprocess.run([sys.executable, *args], cwd=cwd, env=environment, input=stdin, capture_output=True,
                          timeout=600)
    return proc.returncode, proc.stdout.decode(encoding), proc.stderr.decode(encoding)


def assert_clean(status, err, expected_status=0):
    assert "Traceback" not in err and "UnicodeEncodeError" not in err, err[-2000:]
    assert status == expected_status, err[-2000:]


# ------------------------------------------------------------------ the stand-ins themselves

@pytest.mark.parametrize("text, shown", [
    ("θ = 30°", "theta = 30 deg"), ("(ra × n)² / I", "(ra x n)^2 / I"), ("½ m v²", "1/2 m v^2"),
    ("|jt| ≤ μ j", "|jt| <= mu j"), ("A → B", "A -> B"), ("10⁻⁶ px", "10^-6 px"), ("m·g", "m*g"),
    ("José Núñez", "Jose Nunez"), ("⅝ 漢", "⅝ 漢"),   # no stand-in: kept (the handler escapes them)
])
def test_readable_stand_ins(text, shown):
    assert readable(text) == shown


@pytest.mark.parametrize("encoding, shown", [
    ("cp1252", "theta ² ½ <= 10^-6 \\u6f22\n"),   # cp1252 keeps the characters it has
    ("ascii", "theta ^2 1/2 <= 10^-6 \\u6f22\n"),  # a character with no stand-in: its escape
])
def test_a_stream_that_cannot_encode_gets_stand_ins(encoding, shown):
    raw = io.BytesIO()
    stream = io.TextIOWrapper(raw, encoding=encoding)
    safe_output([stream])
    stream.write("θ ² ½ ≤ 10⁻⁶ 漢\n")
    stream.flush()
    assert raw.getvalue().decode(encoding) == shown


def test_a_utf8_stream_and_a_stream_without_reconfigure_are_left_alone():
    stream = io.TextIOWrapper(io.BytesIO(), encoding="utf-8")
    safe_output([stream])
    assert stream.errors == "strict"
    safe_output([io.StringIO()])   # a test's capture: nothing to reconfigure, no error
    latin = io.TextIOWrapper(io.BytesIO(), encoding="latin-1")
    safe_output([latin])
    assert latin.errors == HANDLER


# ------------------------------------------------------------------ every program that prints, on such a console

@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_checker_report_on_a_console_that_is_not_utf8(encoding):
    """The starter's report (θ, ×, ², ≤, μ in its messages) prints with stand-ins; exit 1 (steps to do)."""
    status, out, err = run(["-m", "checker", STARTER], encoding)
    assert_clean(status, err, expected_status=1)
    assert out.startswith(f"{STARTER} - Tumbling Crates: "), out[:200]   # the path as typed
    assert "|jt| <= mu j" in out and "\\u" not in out
    if encoding == "ascii":
        assert "(ra x n)^2/I_A" in out


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_quiz_on_a_console_that_is_not_utf8(encoding):
    status, out, err = run(["-m", "lesson11.quiz", "--answers"], encoding)
    assert_clean(status, err)
    assert ("(ra x n)^2 / IA" if encoding == "ascii" else "(ra × n)² / IA") in out   # cp1252 has × and ²
    status, out, err = run(["-m", "lesson11.quiz"], encoding, stdin=b"A\nB\nC\nD\nA\nA\nA\n")
    assert_clean(status, err)
    assert "Score: " in out and ("(cB - cA)*n < 0" if encoding == "ascii" else "(cB - cA)·n < 0") in out


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_examples_on_a_console_that_is_not_utf8(encoding):
    status, out, err = run(["-m", "lesson11.examples"], encoding)
    assert_clean(status, err)
    wanted = ("30 x 20 box", "m (w^2 + h^2) / 12") if encoding == "ascii" else ("30 × 20 box", "m (w² + h²) / 12")
    assert all(text in out for text in wanted), out[:1500]


@pytest.mark.parametrize("encoding", ["cp1252", "ascii"])
def test_explorer_on_a_console_that_is_not_utf8(tmp_path, encoding):
    """--screenshots prints the paths it saved; a folder named θ (in neither encoding) is printed as theta."""
    folder = tmp_path / "θ"
    folder.mkdir()
    status, out, err = run(["-m", "lesson11.explorer", "--screenshots", str(folder)], encoding)
    assert_clean(status, err)
    assert os.path.join(str(tmp_path), "theta", "sat_explorer.png") in out


def test_a_lab_window_and_its_prints_on_an_ascii_console(tmp_path):
    """A lab (through lesson11.runtime) runs a few frames headless; a student's print of θ does not crash it."""
    lab = tmp_path / "tumbling_crates.py"
    with open(os.path.join(ROOT, "solutions", "tumbling_crates.py"), encoding="utf-8") as handle:
        source = handle.read()
    lab.write_text(source.replace("def main():\n", "def main():\n    print('θ ≤ ½')\n", 1), encoding="utf-8")
    settings = tmp_path / "settings.json"
    settings.write_text('{"frames": 3}', encoding="utf-8")
    status, out, err = run([str(lab)], "ascii", LESSON11_LAB_SETTINGS=str(settings), PYTHONPATH=ROOT)
    assert_clean(status, err)
    assert out.startswith("theta <= 1/2\n") and "Simulated " in out


def test_a_benchmark_on_an_ascii_console():
    status, out, err = run(["-m", "lesson11.bench.speed", "--quick"], "ascii")
    assert_clean(status, err)
    assert "Machine: " in out and " * Python " in out   # the machine line's · separators


# ------------------------------------------------------------------ paths shown as the user typed them

def test_a_typed_relative_path_is_shown_unchanged():
    assert outputs.relative(STARTER) == STARTER
    assert outputs.relative(os.path.join(ROOT, STARTER), ROOT) == STARTER
    outside = os.path.join(os.path.dirname(ROOT), "elsewhere", "tumbling_crates.py")
    assert outputs.relative(outside, ROOT) == outside          # not ../elsewhere/tumbling_crates.py
    assert outputs.relative(os.path.join(os.pardir, "x.py")) == os.path.join(os.pardir, "x.py")


def test_a_typed_path_outside_the_current_folder_is_shown_as_typed(tmp_path):
    """The report and the summary name a file outside the current folder by the path typed, not ../../x."""
    lab = tmp_path / "tumbling_crates_starter.py"
    with open(os.path.join(ROOT, STARTER), encoding="utf-8") as handle:
        lab.write_text(handle.read(), encoding="utf-8")
    status, out, err = run(["-m", "checker", str(lab), STARTER], "utf-8")
    assert_clean(status, err, expected_status=1)
    assert out.startswith(f"{lab} - Tumbling Crates: ") and f"\n{STARTER} - Tumbling Crates: " in out
    table = out[out.index("\nfile "):]
    assert f"\n{lab} " in table and f"\n{STARTER} " in table
    assert f"] {lab}: " in err and f"] {STARTER}: " in err   # the progress lines
    work = tmp_path / "work"
    work.mkdir()
    typed = os.path.join(os.pardir, lab.name)   # ../tumbling_crates_starter.py, from a folder beside it
    status, out, err = run(["-m", "checker", typed], "utf-8", cwd=str(work))
    assert_clean(status, err, expected_status=1)
    assert out.startswith(f"{typed} - Tumbling Crates: "), out[:200]


def test_windows_paths_are_shown_as_typed(monkeypatch):
    """Windows' own path rules (ntpath), as far as this machine can run them: a typed `starters\\x.py` is shown
    unchanged, and a file on another drive than the current folder is shown as typed (os.path.relpath raises
    ValueError there, which stopped the progress line). On Windows the current folder has a drive (C:\\...);
    here it is a POSIX path, which ntpath sees as a path without a drive, like another drive's."""
    monkeypatch.setattr(outputs, "os", type("os", (), {"path": ntpath}))
    assert outputs.relative("starters\\tumbling_crates_starter.py") == "starters\\tumbling_crates_starter.py"
    assert outputs.relative("D:\\class\\alice\\tumbling_crates.py") == "D:\\class\\alice\\tumbling_crates.py"
    assert outputs.relative("D:\\class\\alice\\x.py", "D:\\class") == "alice\\x.py"
    assert outputs.relative("..\\class\\x.py") == "..\\class\\x.py"
