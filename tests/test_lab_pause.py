"""The lab window survives a student's mistake (issue 43): it pauses on the frame that broke and names the function,
the line and the meaning; the terminal shows the student's lines only.

Each case is one line of solutions/<lab>.py changed as a student might change it, run as `python FILE` in a child
process with SDL's dummy drivers. The run is the checker's fixed-frame run (LESSON11_LAB_SETTINGS: 60 fps, a fixed
frame time, scripted keys and clicks), so a frame number means the same in two runs; LESSON11_PAUSE_REPORT turns the
pause on (the checker's run has it off) and has the paused window write what it shows (JSON and a PNG) and then press
Escape itself. What a real student's run does differently: frame times come from the clock, and the window waits for
R or Escape.

The right frame, measured, not assumed: a mistake that raises must pause on the frame where the same file, run without
the pause, dies (the runtime's record says how many frames it began). A mistake that leaves a bad value must pause on
the frame where a twin of the file, with `raise RuntimeError` in place of the bad line, dies: the first frame that
line runs.
"""
import json
import os
import re
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BULLETS_SCRIPT = [{"frame": 1, "type": "key", "key": "5"}, {"frame": 2, "type": "click", "pos": [600, 250]}]

# lab, case, kind, (old line, new line), function named, meaning (a start of lesson11.mistakes' sentence) or None,
# and the line named when it is not the changed one
CASES = [
    ("tumbling_crates", "divide_by_inertia", "raised",
     ("k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia",
      "k += ran * ran / a.inv_inertia + rbn * rbn / b.inv_inertia"), "resolve", "dividing by I"),
    ("tumbling_crates", "cross_forgotten", "raised",
     ("a.omega -= cross(ra, impulse) * a.inv_inertia", "a.omega -= impulse * a.inv_inertia"),
     "apply_impulse", "the spin changes"),
    ("tumbling_crates", "omega_vector", "value",
     ("b.omega += cross(rb, impulse) * b.inv_inertia", "b.omega = impulse * b.inv_inertia"),
     "apply_impulse", "the spin changes"),
    ("more_shapes", "centre_by_sum", "raised",
     ("if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:",
      "if (sum(pb) / len(pb) - sum(pa) / len(pa)).dot(best_axis) < 0:"), "sat", "sum() starts"),
    ("more_shapes", "depth_infinite", "value",
     ("best_axis, best_depth = axis, overlap", "best_axis, best_depth = axis, overlap * math.inf"), "sat",
     "a NaN or an infinity", "return best_axis, best_depth"),   # a hook's answer is named where it is returned
    ("ball_on_ramp", "divide_by_mass", "raised",
     ("a.pos -= normal * (push * a.inv_mass / total)", "a.pos -= normal * (push / a.inv_mass * total)"),
     "separate", "dividing by m"),
    ("ball_on_ramp", "vel_none", "value",
     ("apply_impulse(a, b, normal * j, ra, rb)", "b.vel = b.vel.update(b.vel + normal * j * b.inv_mass)"),
     "resolve", "update(), normalize_ip()"),
    ("sleeping_crates", "spin_ratio", "raised",
     ("if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:", "if speed / abs(spin) < SLEEP_SPEED / SLEEP_SPIN:"),
     "sleep_timer", None),
    ("sleeping_crates", "timer_nan", "value", ("return timer + dt\n", 'return timer + float("nan") * dt\n'),
     "sleep_timer", "a NaN or an infinity"),
    ("bullets", "no_miss_test", "raised", ("if a == 0 or disc < 0:", "if a == 0:"), "circle_toi", "math.sqrt()",
     "t = (-b - math.sqrt(disc)) / (2 * a)  # the earlier root: first contact"),   # where it raises
    ("bullets", "reflect_ip", "value",
     ("world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)",
      "bullet.vel = bullet.vel.reflect_ip(normal)"), "swept_move", "update(), normalize_ip()"),
]


def mutant(lab, old, new, folder, name):
    """solutions/<lab>.py with the one line `old` replaced by `new`, written to folder/name.py; (path, line number)."""
    with open(os.path.join(ROOT, "solutions", f"{lab}.py"), encoding="utf-8") as handle:
        text = handle.read()
    assert text.count(old) == 1, f"{lab}: the line to change is not there once: {old}"
    text = text.replace(old, new)
    path = os.path.join(str(folder), f"{name}.py")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(text)
    line = next(k for k, row in enumerate(text.splitlines(), 1) if new.strip() in row)
    return path, line


def run(path, folder, pause, frames=240, extra_env=None):
    """Run the lab file headless for `frames` fixed frames; returns (exit code, stdout + stderr, the pause's
    report or None, the runtime's record)."""
    lab = os.path.basename(path)
    settings = {"frames": frames, "fps": 60, "record": os.path.join(str(folder), f"{lab}.record.json")}
    if "bullets" in lab:
        settings["script"] = BULLETS_SCRIPT
    settings_path = os.path.join(str(folder), f"{lab}.settings.json")
    with open(settings_path, "w", encoding="utf-8") as handle:
        json.dump(settings, handle)
    report = os.path.join(str(folder), f"{lab}.pause.json")
    env = {key: value for key, value in os.environ.items() if not key.startswith("LESSON11_")}
    env.update(LESSON11_LAB_SETTINGS=settings_path, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy",
               PYGAME_HIDE_SUPPORT_PROMPT="1", PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""),
               **(extra_env or {}))
    if pause:
        env["LESSON11_PAUSE_REPORT"] = report
    done = subprocess.run([sys.executable, path], cwd=str(folder), env=env, capture_output=True, text=True,
                          timeout=300)
    shown = None
    if pause and os.path.exists(report):
        with open(report, encoding="utf-8") as handle:
            shown = json.load(handle)
    with open(settings["record"], encoding="utf-8") as handle:
        record = json.load(handle)
    return done.returncode, done.stdout + done.stderr, shown, record


def engine_lines(output, lab_path):
    """Lines of `output` that show a frame outside the student's file (a `File "..."` line of another file, or
    any path of the library)."""
    name = os.path.basename(lab_path)
    return [line for line in output.splitlines()
            if (line.strip().startswith('File "') and name not in line) or "lesson11" in line
            or "Traceback (most recent call last)" in line]


@pytest.mark.parametrize("lab, case, kind, edit, function, meaning, named", [c + (None,) * (7 - len(c)) for c in CASES],
                         ids=[c[1] for c in CASES])
def test_the_window_pauses_on_the_frame_that_broke(tmp_path, lab, case, kind, edit, function, meaning, named):
    path, line = mutant(lab, *edit, tmp_path, f"{lab}_{case}")
    if named:
        with open(path, encoding="utf-8") as handle:
            line = next(k for k, row in enumerate(handle.read().splitlines(), 1) if row.strip() == named)
    said = named or edit[1].strip()
    if kind == "raised":
        reference = path
    else:   # the twin: the bad line raises instead, so it dies on the first frame that line runs
        indent = re.match(r"\s*", edit[1]).group(0)
        reference, _ = mutant(lab, edit[0], 'raise RuntimeError("the line runs")' + edit[0][len(edit[0].rstrip()):],
                              tmp_path, f"{lab}_{case}_twin")
        with open(reference, encoding="utf-8") as handle:
            assert f"{indent}raise RuntimeError" in handle.read()
    code, output, _, record = run(reference, tmp_path, pause=False)
    assert code != 0, f"{case}: the unpaused run did not break\n{output[-2000:]}"
    died_on = record["frames_run"]
    assert died_on < 240, f"{case}: the unpaused run went through all its frames"

    code, output, shown, record = run(path, tmp_path, pause=True)
    assert shown is not None, f"{case}: the window did not pause\n{output[-3000:]}"
    assert shown["window_open"], "the window was closed while paused"
    assert shown["frame"] == died_on, f"{case}: paused on frame {shown['frame']}, it broke on frame {died_on}"
    assert record["frames_run"] == died_on, "the lab ran on past the frame that broke"
    assert (shown["kind"], shown["function"], shown["line"]) == (kind, function, line), shown
    assert shown["text"] == said
    on_screen = "\n".join(shown["shown"])
    assert f"your {function}()" in on_screen and f"line {line}: {said}" in on_screen
    if meaning:
        assert shown["meaning"].startswith(meaning) and "What it means" in on_screen, shown
    else:
        assert shown["meaning"] == ""
    # the terminal: the student's lines and the engine phase, no engine frame
    assert engine_lines(output, path) == [], "\n".join(engine_lines(output, path))
    assert f'line {line}, in {function}' in output and said in output
    assert "called by " in output and "LESSON11_TRACEBACK=1" in output


def test_the_full_traceback_on_request(tmp_path):
    """LESSON11_TRACEBACK=1: the engine's frames are printed too (the full traceback, then the student's lines)."""
    path, line = mutant("tumbling_crates", *CASES[0][3], tmp_path, "tumbling_crates_traceback")
    code, output, shown, _ = run(path, tmp_path, pause=True, extra_env={"LESSON11_TRACEBACK": "1"})
    assert shown is not None and shown["line"] == line
    assert "Traceback (most recent call last)" in output and "world.py" in output and "resolve_calls" in output


def test_an_error_in_the_main_loop_pauses_too(tmp_path):
    """The lab's own code outside the World's step (here its HUD line) raising: the same pause, on that frame."""
    edit = ("crates = len(world.bodies) - STATIC_BODIES",
            "crates = len(world.bodies) - STATIC_BODIES if world.time < 0.5 else len(world.bodies) / 0")
    path, line = mutant("tumbling_crates", *edit, tmp_path, "tumbling_crates_hud")
    code, output, _, record = run(path, tmp_path, pause=False)
    died_on = record["frames_run"]
    code, output, shown, _ = run(path, tmp_path, pause=True)
    assert shown is not None and shown["window_open"]
    assert (shown["kind"], shown["function"], shown["line"], shown["frame"]) == ("main", "main", line, died_on)
    assert engine_lines(output, path) == [] and f"line {line}, in main" in output


def test_no_pause_under_the_checker(tmp_path):
    """The checker's run (no LESSON11_PAUSE_REPORT) ends on the error as before: no pause, the error is raised."""
    path, _ = mutant("tumbling_crates", *CASES[0][3], tmp_path, "tumbling_crates_checker")
    code, output, shown, record = run(path, tmp_path, pause=False)
    assert code != 0 and "ZeroDivisionError" in output and "The lab paused" not in output


@pytest.mark.parametrize("case", ["divide_by_inertia", "cross_forgotten", "omega_vector"])
def test_the_checker_and_the_window_say_the_same_words(tmp_path, case):
    """The meaning the paused window shows is, word for word, the one `python -m checker FILE` prints for the same
    file (both take it from lesson11/mistakes.py)."""
    lab, _, _, edit, function, _ = next(c for c in CASES if c[1] == case)[:6]
    path, line = mutant(lab, *edit, tmp_path, lab)
    _, _, shown, _ = run(path, tmp_path, pause=True)
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYGAME_HIDE_SUPPORT_PROMPT="1")
    checked = subprocess.run([sys.executable, "-m", "checker", path], cwd=ROOT, env=env, capture_output=True,
                             text=True, timeout=300).stdout
    said = shown["meaning"]
    assert said and (said in checked or said[0].upper() + said[1:] in checked), checked
    assert f"{function}() " in checked and (f"line {line}" in checked or shown["kind"] == "value")


def test_the_checker_never_pauses_even_with_the_variables_set(tmp_path):
    """LESSON11_PAUSE_REPORT and LESSON11_TRACEBACK left in the grader's shell do not reach the graded child (the
    sandbox drops every LESSON11_ variable): no pause report is written, and the verdict and lines are the same."""
    path, _ = mutant("tumbling_crates", *CASES[0][3], tmp_path, "tumbling_crates")
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYGAME_HIDE_SUPPORT_PROMPT="1")

    def grade(**extra):
        return subprocess.run([sys.executable, "-m", "checker", path, "--seed", "7"], cwd=ROOT,
                              env={**env, **extra}, capture_output=True, text=True, timeout=300).stdout

    report = tmp_path / "report.json"
    plain = grade()
    with_variables = grade(LESSON11_PAUSE_REPORT=str(report), LESSON11_TRACEBACK="1")
    assert not report.exists() and not (tmp_path / "report.png").exists()
    assert [line for line in with_variables.splitlines() if "(error, " not in line] == \
        [line for line in plain.splitlines() if "(error, " not in line]   # the first line holds the time taken


if __name__ == "__main__":   # python tests/test_lab_pause.py: regenerates assets/lab_paused_on_error.png
    import shutil
    import tempfile
    with tempfile.TemporaryDirectory() as folder:
        lab_path, _ = mutant("tumbling_crates", *CASES[0][3], folder, "tumbling_crates")
        run(lab_path, folder, pause=True)
        shutil.copy(os.path.join(folder, "tumbling_crates.py.pause.png"),
                    os.path.join(ROOT, "assets", "lab_paused_on_error.png"))
    print("wrote assets/lab_paused_on_error.png")
