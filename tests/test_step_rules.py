"""The step rules (checker/step_rules.py): they flag reaching around the exercise, never a way of writing it.

  - every corpus entry of every lab (correct completions in many styles and honest mistakes),
    every solution and every starter: no flag at all (a false flag fails a step that is right);
  - each attack, written into a real step: flagged with its step, line and rule;
  - a flagged step fails its check through the command line, with the line and the lab's advice.
"""
import importlib
import json
import os
import subprocess
import sys

import pytest

from checker import labs, step_rules

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def lab_by_id(lab_id):
    return next(lab for lab in labs.LABS if lab.id == lab_id)


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


@pytest.mark.parametrize("lab_id", [lab.id for lab in labs.LABS])
def test_no_corpus_entry_solution_or_starter_is_flagged(lab_id):
    lab = lab_by_id(lab_id)
    corpus = importlib.import_module(f"corpus_{lab_id}")
    sources = {e.name: corpus.build(e.name) for e in corpus.ENTRIES}
    sources["solution"] = read(f"solutions/{lab_id}.py")
    sources["starter"] = read(f"starters/{lab_id}_starter.py")
    flagged = {name: [(b.line, b.rule, b.text) for b in step_rules.scan_lab(text, lab.module)]
               for name, text in sources.items()}
    assert len(sources) >= 10
    assert {name: found for name, found in flagged.items() if found} == {}


def in_step(source, step, code):
    """`source` with the inside of step `step` replaced by `code` (lines at the region's indent); and its first line."""
    lines = source.splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if f"# --- step {step}:" in line)
    end = next(i for i, line in enumerate(lines) if f"# --- end of step {step} ---" in line)
    indent = lines[start][:len(lines[start]) - len(lines[start].lstrip())]
    body = "".join(indent + line + "\n" for line in code.splitlines())
    return "".join(lines[:start + 1]) + body + "".join(lines[end:]), start + 2


ATTACKS = [   # (lab, step, code, the rule that must flag it)
    ("tumbling_crates", 2, "return World().sat(pa, pb)", "reach"),
    ("tumbling_crates", 2, "return World().sat(pa, pb)", "library"),
    ("tumbling_crates", 2, "from lesson11.physics2d import sat as reference\nreturn reference(pa, pb)", "import"),
    ("tumbling_crates", 2, "return __import__('lesson11.physics2d', fromlist=['x']).sat(pa, pb)", "dunder"),
    ("tumbling_crates", 2, "import json", "import"),
    ("tumbling_crates", 2, "x = getattr(pa, 'count')", "builtin"),
    ("tumbling_crates", 2, "x = lab.frame_budget", "reach"),
    ("tumbling_crates", 2, "text = open('solutions/tumbling_crates.py').read()", "builtin"),
    ("tumbling_crates", 2, "x = eval('1')", "builtin"),
    ("tumbling_crates", 2, "g = globals()", "builtin"),
    ("tumbling_crates", 2, "d = pygame.display", "module"),
    ("tumbling_crates", 2, "r = random.random()", "module"),
    ("tumbling_crates", 2, "g = (lambda: 0).__globals__", "dunder"),
    ("tumbling_crates", 2, "c = pa.__class__", "dunder"),
    ("tumbling_crates", 2, "box = []\ndef gen():\n    yield box[0].gi_frame.f_back\nbox.append(gen())", "frame"),
    ("tumbling_crates", 3, "best_axis = World.sat", "reach"),
    ("tumbling_crates", 6, "p = LabPanel", "reach"),
    ("more_shapes", 4, "return Polygon(points).inertia(mass)", "library"),
    ("ball_on_ramp", 5, "return Circle(radius).inertia(mass)", "library"),
    ("bullets", 2, "return circle_toi(p1, v1, r1, p2, v2, r2, dt) if False else World.swept_move", "reach"),
    ("bullets", 5, "world.swept_move(bullet, dt)", "library"),
    ("sleeping_crates", 2, "return World().sleep_timer_of_world(timer, speed, spin, dt)", "library"),
]


@pytest.mark.parametrize("lab_id, step, code, rule", ATTACKS)
def test_an_attack_is_flagged_with_its_step_line_and_rule(lab_id, step, code, rule):
    lab = lab_by_id(lab_id)
    source, first = in_step(read(f"solutions/{lab_id}.py"), step, code)
    found = step_rules.scan_lab(source, lab.module)
    assert any(b.rule == rule and b.step == step and first <= b.line < first + len(code.splitlines())
               for b in found), [(b.line, b.rule) for b in found]
    breach = next(b for b in found if b.rule == rule)
    assert breach.message.startswith(f"line {breach.line} (step {step}) ")


def test_an_import_added_outside_the_steps_and_used_inside_is_flagged_but_math_is_free():
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, first = in_step("from lesson11.physics2d import sat as ref\n" + solution, 2, "return ref(pa, pb)")
    found = step_rules.scan_lab(source, lab.module)
    assert (first, "import") in [(b.line, b.rule) for b in found]                  # used in step 2
    assert {b.step for b in found if b.line == 1 and b.rule == "outside"} == {2, 3, 4, 5, 6}   # and imported
    source, _ = in_step("from math import hypot\n" + solution, 2,
                        "d = hypot(1, 2) + math.sqrt(4)\nv = pygame.Vector2(1, 0)\n" + step_code(solution, 2))
    assert step_rules.scan_lab(source, lab.module) == []


def step_code(source, step):
    lines = source.splitlines()
    start = next(i for i, line in enumerate(lines) if f"# --- step {step}:" in line)
    end = next(i for i, line in enumerate(lines) if f"# --- end of step {step} ---" in line)
    indent = lines[start][:len(lines[start]) - len(lines[start].lstrip())]
    return "\n".join(line[len(indent):] for line in lines[start + 1:end])


def test_a_flagged_step_fails_its_check_through_the_command_line(tmp_path):
    source, first = in_step(read("solutions/tumbling_crates.py"), 2, "return World().sat(pa, pb)")
    path = tmp_path / "tumbling_crates.py"
    path.write_text(source, encoding="utf-8")
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYTHONPATH=ROOT)
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", str(path)], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=600)
    row = json.loads(proc.stdout)["labs"][0]
    checks = {c["id"]: c for c in row["criteria"]}
    assert checks["sat_axes"]["status"] == "fail"
    assert checks["sat_axes"]["message"].startswith(f"line {first} (step 2) ")
    assert "edge normals yourself" in checks["sat_axes"]["message"]
    assert checks["handout_unchanged"]["status"] == "pass"
    assert {(f["line"], f["rule"]) for f in row["flags"]} == {(first, "library"), (first, "reach")}
    assert row["score"] < row["max_score"]


@pytest.mark.parametrize("added, steps", [
    ("from math import hypot as sat\n", {2, 3}),
    ("def sat(pa, pb):\n    return None\n", {2, 3}),
    ("from math import cos as apply_impulse\n", {6}),
    ("from lesson11.physics2d import sat as _ref\nsat = _ref\n", {2, 3, 4, 5, 6}),
    ("globals()['sat'] = None\n", {2, 3, 4, 5, 6}),
    ("import sys\nsys.modules[__name__].resolve = None\n", {2, 3, 4, 5, 6}),
    ("import checker.tape\n", {2, 3, 4, 5, 6}),                      # to rewrite what the child records
    ("import json\njson.dumps = str\n", {2, 3, 4, 5, 6}),            # to forge the child's report
    ("from lesson11.physics2d import sat as library_sat\n", {2, 3, 4, 5, 6}),
])
def test_code_outside_the_steps_that_can_replace_a_step_function_fails_those_steps(added, steps):
    """Delegation outside the steps: rebinding a step function (or anything that can) after the handout's def."""
    lab = lab_by_id("tumbling_crates")
    found = step_rules.scan_lab(read("solutions/tumbling_crates.py") + "\n" + added, lab.module)
    assert {b.step for b in found if b.rule == "outside"} == steps
    assert all("keep the handout's code around the steps" in b.message for b in found)


def test_an_added_import_of_a_harmless_module_is_not_flagged():
    lab = lab_by_id("tumbling_crates")
    for added in ("import numpy as np\n", "from math import hypot\n", "import random as rnd\n"):
        assert step_rules.scan_lab(added + read("solutions/tumbling_crates.py"), lab.module) == []


def test_the_main_guard_in_another_style_is_not_flagged():
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    assert solution.count('if __name__ == "__main__":') == 1
    source = solution.replace('if __name__ == "__main__":', "if __name__ == '__main__':")
    assert step_rules.scan_lab(source, lab.module) == []
