"""The step rules (checker/reading/step_rules.py): they flag reaching around the exercise, never a way of writing it.

  - every corpus entry of every lab (correct completions in many styles and honest mistakes),
    every solution and every starter: no flag at all (a false flag fails a step that is right);
  - every name of every lab's STEP_LIBRARY, called in its step: flagged there (the labs are those in
    checker/labs/, tests/labs_found.py; the library is the lab's own, never a copy kept here);
  - each attack, written into a real step: flagged with its step, line and rule;
  - a flagged step fails its check through the command line, with the line and the lab's advice.
"""
import ast
import json
import os
import subprocess
import sys

import pytest

from checker.reading import handout, step_rules

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import labs_found  # noqa: E402  (tests/labs_found.py: every lab in checker/labs/)


lab_by_id = labs_found.by_id


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


@pytest.mark.parametrize("lab", labs_found.params())
def test_no_corpus_entry_solution_or_starter_is_flagged(lab):
    """Every lab (checker/labs/): its corpus's files (tests/corpus_<id>.py), its solution and its starter."""
    corpus = labs_found.need_corpus(lab)
    sources = {e.name: corpus.build(e.name) for e in corpus.ENTRIES}
    sources["solution"] = read(lab.solution)
    sources["starter"] = read(lab.starter)
    flagged = {name: [(b.line, b.rule, b.text) for b in step_rules.scan_lab(text, lab)]
               for name, text in sources.items()}
    assert len(sources) >= 10
    assert {name: found for name, found in flagged.items() if found} == {}


@pytest.mark.parametrize("lab", labs_found.params())
def test_the_solution_and_starter_of_every_lab_are_not_flagged(lab):
    """Without a corpus too: a lab's own two files break no rule (a false flag fails a step that is right)."""
    assert step_rules.scan_lab(read(lab.solution), lab) == []
    assert step_rules.scan_lab(read(lab.starter), lab) == []


@pytest.mark.parametrize("lab", labs_found.params())
def test_each_steps_library_names_are_flagged_in_that_step(lab):
    """Every lab's STEP_LIBRARY, read from the lab: each name it lists, called as an attribute in its step of the
    solution (on the step's function's own arguments), is flagged there as "library"; its steps are the solution's
    step regions. (Its own name called bare is the student's own function, which the rules leave alone.)"""
    library = lab.module.STEP_LIBRARY
    assert library, f"{lab.id}: its checks.py's STEP_LIBRARY names no library function a step asks for"
    assert set(library) <= set(labs_found.steps(lab)), "STEP_LIBRARY names a step the solution does not mark"
    functions = labs_found.step_functions(lab)
    for step, names in library.items():
        args = ", ".join(a for a in functions.get(step, ("", ()))[1] if a != "self")
        for name in names:
            code = f"helper = None\nreturn helper.{name}({args})"
            source, first = in_step(read(lab.solution), step, code)
            found = step_rules.scan_lab(source, lab)
            assert (step, first + 1, "library") in [(b.step, b.line, b.rule) for b in found], (lab.id, step, name)


def in_step(source, step, code):
    """`source` with the inside of step `step` replaced by `code` (lines at the region's indent); and its first line."""
    lines = source.splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if line.strip().startswith(f"# --- step {step}:"))
    end = next(i for i, line in enumerate(lines) if line.strip().startswith(f"# --- end of step {step} ---"))
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
    # the brief's list, as written
    ("tumbling_crates", 2, "m = __import__('json')", "dunder"),
    ("tumbling_crates", 2, "x = getattr(lab, 'x')", "builtin"),
    ("tumbling_crates", 2, "x = getattr(lab, 'x')", "reach"),
    ("tumbling_crates", 2, "x = lab.something", "reach"),
    ("tumbling_crates", 2, "text = open(__file__).read()", "builtin"),
    ("tumbling_crates", 2, "text = open(__file__).read()", "dunder"),
    ("tumbling_crates", 2, "c = self.__class__", "dunder"),
    ("tumbling_crates", 2, "m = type(pa).__mro__", "dunder"),
    # a name is the student's own only where Python finds the student's binding
    ("tumbling_crates", 2, "def f(getattr=getattr):\n    return getattr(edge_normals, 'x')\nreturn f()", "builtin"),
    ("tumbling_crates", 2, "class K:\n    g = getattr\nreturn K.g(pa, 'x')", "builtin"),
    ("tumbling_crates", 2, "names = [getattr for getattr in [1]]\nreturn getattr(pa, 'x')", "builtin"),
    ("tumbling_crates", 2, "@getattr\ndef f(x):\n    return x\nreturn None", "builtin"),
    ("tumbling_crates", 2, "def f():\n    global getattr\n    return getattr(pa, 'x')\nreturn f()", "builtin"),
    ("tumbling_crates", 2, "def f(pygame=pygame):\n    return pygame.display\nreturn f()", "module"),
    ("tumbling_crates", 2, "def f(r=random):\n    return r.random()\nreturn f()", "module"),
    ("tumbling_crates", 2, "m = memoryview(b'')", "builtin"),
    ("tumbling_crates", 2, "K = type('K', (), {})", "builtin"),
    # the library's function taken as a value, not only called
    ("ball_on_ramp", 5, "inertia_of = Circle(radius).inertia\nreturn inertia_of(mass)", "library"),
    ("ball_on_ramp", 5, "return Body(Circle(radius), mass=mass).inertia", "library"),
    ("more_shapes", 4, "return Body(points, mass=mass).inertia", "library"),
    ("bullets", 5, "move = world.swept_move\nmove(bullet, dt)", "library"),
    # attributes read by name through a match class pattern
    ("tumbling_crates", 2, "match edge_normals:\n    case object(__globals__=library):\n"
                           "        return library['sat'](pa, pb)", "dunder"),
    ("bullets", 5, "match super(type(world), world):\n    case object(swept_move=library):\n"
                   "        library(bullet, dt)", "library"),
    ("tumbling_crates", 2, "def f(__x__=0):\n    return dict(__y__=1)\nreturn f()", "dunder"),
    # World without naming it
    ("ball_on_ramp", 6, "hooks = type(make_world(rng))()", "reach"),
    ("bullets", 2, "hooks = BulletWorld()", "reach"),
]


@pytest.mark.parametrize("lab_id, step, code, rule", ATTACKS)
def test_an_attack_is_flagged_with_its_step_line_and_rule(lab_id, step, code, rule):
    lab = lab_by_id(lab_id)
    source, first = in_step(read(f"solutions/{lab_id}.py"), step, code)
    found = step_rules.scan_lab(source, lab)
    assert any(b.rule == rule and b.step == step and first <= b.line < first + len(code.splitlines())
               for b in found), [(b.line, b.rule) for b in found]
    breach = next(b for b in found if b.rule == rule)
    assert breach.message.startswith(f"line {breach.line} (step {step}) ")


LIBRARY_ATTACKS = [   # a handed class or World hook that runs the library's answer: flagged by the lab's STEP_LIBRARY
    ("more_shapes", 3, "return Body.from_world_points(points).pos"),
    ("more_shapes", 3, "return Vector2(points[0]) - Polygon(points).points[0]"),
    ("more_shapes", 3, "return Vector2(points[0]) - Body(points).shape.points[0]"),
    ("more_shapes", 4, "return 1 / Body(points, mass=mass).inv_inertia"),
    ("ball_on_ramp", 5, "return 1 / Body(Circle(radius), mass=mass).inv_inertia"),
    ("ball_on_ramp", 6, "return hooks.circle_point(center, radius, normal, depth)"),
    ("sleeping_crates", 4, "hooks.wake_pair(a, b)"),
]


@pytest.mark.parametrize("lab_id, step, code", LIBRARY_ATTACKS)
def test_a_handed_class_that_runs_the_library_s_answer_is_flagged_as_library(lab_id, step, code):
    lab = lab_by_id(lab_id)
    source, first = in_step(read(lab.solution), step, code)
    found = step_rules.scan(source, lab.module.STEP_LIBRARY, read(lab.starter))
    assert [(b.step, b.line, b.rule) for b in found] == [(step, first, "library")]


@pytest.mark.parametrize("code", [
    "def f(open, vars=0):\n    return open + vars\nbest = f(1)",     # the student's own names
    "input = [1, 2]\ntype_of = type(pa)\nbest = input[0]",
    "best = [eval for eval in range(3)]",
    "def helper(x):\n    return x._private\nbest = None",
    "print('axis', len(pa), math.hypot(1, 2), pygame.Vector2(1, 0), pygame.math.Vector2(0, 1))",
])
def test_ways_of_writing_a_step_are_not_flagged(code):
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, _ = in_step(solution, 2, code + "\n" + step_code(solution, 2))
    assert step_rules.scan_lab(source, lab) == []


def test_no_nesting_that_python_compiles_hides_a_breach():
    """The scan keeps its own stack: a long expression (deeper than the recursion limit) hides nothing."""
    lab = lab_by_id("tumbling_crates")
    code = "x = " + " + ".join(["1"] * 2500) + "\nreturn World().sat(pa, pb)"
    source, first = in_step(read("solutions/tumbling_crates.py"), 2, code)
    compile(source, "deep.py", "exec")
    assert {(b.line, b.rule) for b in step_rules.scan_lab(source, lab)} == {(first + 1, "library"),
                                                                                   (first + 1, "reach")}


def test_an_allowed_attribute_is_not_flagged():
    source, first = in_step(read("solutions/bullets.py"), 5, "world.swept_move(bullet, dt)")
    starter = read("starters/bullets_starter.py")
    assert [(b.line, b.rule) for b in step_rules.scan(source, {5: ("swept_move",)}, starter)] == [(first, "library")]
    assert step_rules.scan(source, {5: ("swept_move",)}, starter, allowed={5: ("swept_move",)}) == []


def test_describe_names_the_line_the_step_and_the_lab_s_hint():
    breach = step_rules.Breach(2, 57, "library", "calls the library's sat()", "return sat(pa, pb)")
    message = step_rules.describe(breach, "write the loop over the edge normals yourself")
    assert message == ("line 57 (step 2) calls the library's sat() (`return sat(pa, pb)`): "
                       "write the loop over the edge normals yourself.")


def test_a_file_that_does_not_parse_or_has_broken_markers_has_no_breach():
    solution = read("solutions/tumbling_crates.py")
    library = lab_by_id("tumbling_crates").module.STEP_LIBRARY
    assert step_rules.scan(solution + "\ndef (:\n", library) == []
    assert step_rules.scan(solution.replace("# --- end of step 2 ---", ""), library) == []


def test_an_import_added_outside_the_steps_and_used_inside_is_flagged_but_math_is_free():
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, first = in_step("from lesson11.physics2d import sat as ref\n" + solution, 2, "return ref(pa, pb)")
    found = step_rules.scan_lab(source, lab)
    assert (first, "import") in [(b.line, b.rule) for b in found]                  # used in step 2
    assert {b.step for b in found if b.line == 1 and b.rule == "outside"} == {2, 3, 4, 5, 6}   # and imported
    source, _ = in_step("from math import hypot\n" + solution, 2,
                        "d = hypot(1, 2) + math.sqrt(4)\nv = pygame.Vector2(1, 0)\n" + step_code(solution, 2))
    assert step_rules.scan_lab(source, lab) == []


def step_code(source, step):
    lines = source.splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip().startswith(f"# --- step {step}:"))
    end = next(i for i, line in enumerate(lines) if line.strip().startswith(f"# --- end of step {step} ---"))
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
    ("import checker.judging.tape\n", {2, 3, 4, 5, 6}),                      # to rewrite what the child records
    ("import json\njson.dumps = str\n", {2, 3, 4, 5, 6}),            # to forge the child's report
    ("from lesson11.physics2d import sat as library_sat\n", {2, 3, 4, 5, 6}),
])
def test_code_outside_the_steps_that_can_replace_a_step_function_fails_those_steps(added, steps):
    """Delegation outside the steps: rebinding a step function (or anything that can) after the handout's def."""
    lab = lab_by_id("tumbling_crates")
    found = step_rules.scan_lab(read("solutions/tumbling_crates.py") + "\n" + added, lab)
    assert {b.step for b in found if b.rule == "outside"} == steps
    assert all("keep the handout's code around the steps" in b.message for b in found)


def test_an_added_import_of_a_harmless_module_is_not_flagged():
    lab = lab_by_id("tumbling_crates")
    for added in ("import numpy as np\n", "from math import hypot\n", "import random as rnd\n"):
        assert step_rules.scan_lab(added + read("solutions/tumbling_crates.py"), lab) == []


def test_the_main_guard_in_another_style_is_not_flagged():
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    assert solution.count('if __name__ == "__main__":') == 1
    source = solution.replace('if __name__ == "__main__":', "if __name__ == '__main__':")
    assert step_rules.scan_lab(source, lab) == []


# ---------------------------------------------------------------- issue 35: star imports, closed and side modules,
# the pure standard-library modules, format strings

@pytest.mark.parametrize("added", [
    "from solutions.tumbling_crates import *\n",
    "from lesson11.physics2d import *\n",
    "from math import *\n",                       # harmless names, but `*` can rebind any name a step reads
    "from starters.tumbling_crates_starter import *\n",
])
def test_a_star_import_anywhere_fails_every_step_naming_its_line(added):
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    line = solution.count("\n") + 2
    found = step_rules.scan_lab(solution + "\n" + added, lab)
    assert {(b.step, b.line, b.rule) for b in found} == {(step, line, "outside") for step in (2, 3, 4, 5, 6)}
    assert found[0].message.startswith(f"line {line} imports every name of ")


@pytest.mark.parametrize("added", ["import solutions.tumbling_crates as answers\n",
                                   "from solutions import tumbling_crates\n",
                                   "from starters.tumbling_crates_starter import main as handout_main\n",
                                   "from pkgutil import resolve_name\n",          # imports by a string
                                   "import lab_under_test\n",                      # the lab's own module in the child
                                   "import timeit\n"])                             # runs code from a string
def test_solutions_starters_and_import_by_string_are_closed_modules(added):
    lab = lab_by_id("tumbling_crates")
    found = step_rules.scan_lab(added + read("solutions/tumbling_crates.py"), lab)
    assert {(b.step, b.line, b.rule) for b in found} == {(step, 1, "outside") for step in (2, 3, 4, 5, 6)}


@pytest.mark.parametrize("side, added", [
    ("crate_utils.py", "import crate_utils\n"),
    ("crate_utils.py", "from crate_utils import helper\n"),
    ("helpers/__init__.py", "import helpers.more\n"),
    ("cmath.py", "import cmath\n"),             # a free module's name, shadowed by a file beside the lab
    ("notes.cpython-311-x86_64-linux-gnu.so", "import notes\n"),
])
def test_an_import_of_a_module_beside_the_submission_fails_every_step(tmp_path, side, added):
    lab = lab_by_id("tumbling_crates")
    (tmp_path / side).parent.mkdir(parents=True, exist_ok=True)
    (tmp_path / side).write_text("x = 1\n")
    path = str(tmp_path / "tumbling_crates.py")
    source = added + read("solutions/tumbling_crates.py")
    found = step_rules.scan_lab(source, lab, path)
    assert {(b.step, b.line, b.rule) for b in found} == {(step, 1, "outside") for step in (2, 3, 4, 5, 6)}
    assert "from the submission's own folder" in found[0].message
    assert [b for b in step_rules.scan_lab(source, lab) if "own folder" in b.what] == []   # no folder given


def test_the_handout_s_own_imports_are_no_side_module(tmp_path):
    """A lab file at the project's top sits beside lesson11/: the handout's own `from lesson11 import ...` is fine."""
    lab = lab_by_id("tumbling_crates")
    (tmp_path / "lesson11").mkdir()
    (tmp_path / "pygame.py").write_text("")
    (tmp_path / "unused.py").write_text("")
    assert step_rules.scan_lab(read("solutions/tumbling_crates.py"), lab, str(tmp_path / "lab.py")) == []


FREE_STEPS = [   # honest uses of the pure standard-library modules (tumbling crates step 2, before the real code)
    "import cmath\nz = cmath.exp(1j * cmath.pi / 4)\nangle = cmath.phase(z)",
    "import itertools\nfor u, v in itertools.pairwise(edge_normals(pa)):\n    pass",
    "from itertools import chain, pairwise\nboth = list(chain(edge_normals(pa), edge_normals(pb)))",
    "import functools\nimport operator\ntotal = functools.reduce(operator.add, [1, 2, 3])",
    "from fractions import Fraction\nhalf = Fraction(1, 2)",
    "import statistics as st\nmiddle = st.mean([1.0, 2.0])",
    "import math\nd = math.dist((0, 0), (3, 4))",                  # import math inside a step, too
    "import itertools as it\npick = it.islice\ntools = [it, math]",  # itertools and math may be passed around
    "label = f'{pa!r:>10}' + '{:.2f} {}'.format(1.5, 'x') + '%(a)s' % {'a': 1}",
]


@pytest.mark.parametrize("code", FREE_STEPS)
def test_the_pure_standard_library_is_allowed_in_a_step(code):
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, _ = in_step(solution, 2, code + "\n" + step_code(solution, 2))
    assert step_rules.scan_lab(source, lab) == []


def test_a_free_module_imported_at_the_top_is_allowed_in_a_step():
    lab = lab_by_id("more_shapes")
    solution = read("solutions/more_shapes.py").replace("import math\n", "import cmath\nimport math\n", 1)
    source, _ = in_step(solution, 2, "return [Vector2(radius * cmath.exp(2j * cmath.pi * k / sides).real,\n"
                                     "                radius * cmath.exp(2j * cmath.pi * k / sides).imag)\n"
                                     "        for k in range(sides)]")
    assert step_rules.scan_lab(source, lab) == []


@pytest.mark.parametrize("code, rule", [
    ("import statistics\nm = statistics.sys.modules", "module"),          # a module among a free module's names
    ("import fractions as f\nm = f.sys", "module"),
    ("from statistics import sys", "import"),
    ("import operator\nget = operator.attrgetter('gi_frame')", "module"),   # getattr by a string
    ("from operator import methodcaller", "import"),
    ("import functools\nfunctools.update_wrapper(pa, pb, ('gi_frame',), ())", "module"),
    ("import statistics\nkeep = [statistics]", "module"),                  # passed on, its attributes reach further
    ("import operator\nf = (lambda m: m)(operator)", "module"),
    ("import os", "import"),
    ("from lesson11 import physics2d", "import"),
    ("text = '{0.gi_frame.f_back.f_locals}'.format((lambda: (yield))())", "format"),
    ("text = '{0[sat]}'.format({'sat': 1})", "format"),
    ("text = '{0:{1.x}}'.format(1, pa)", "format"),                        # a nested field
    ("text = '{g.gi_frame}'.format_map({'g': pa})", "format"),
    ("template = '{0.' + 'gi_frame}'\ntext = template.format(pa)", "format"),   # a template built at run time
    ("show = str.format\ntext = show('{}', pa)", "format"),
    ("match '{0.gi_frame}':\n    case str(format=f):\n        text = f(pa)", "format"),
])
def test_what_reaches_further_than_a_pure_module_or_through_a_format_string_is_flagged(code, rule):
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, first = in_step(solution, 2, code + "\n" + step_code(solution, 2))
    found = step_rules.scan_lab(source, lab)
    assert any(b.rule == rule and b.step == 2 and first <= b.line < first + len(code.splitlines()) for b in found), \
        [(b.line, b.rule, b.what) for b in found]


def test_a_debug_print_outside_the_steps_may_not_format_an_attribute():
    """handout.is_debug_print: '{0.x}'.format(v) reads an attribute by a string; the f-string does not."""
    assert handout.is_debug_print(ast.parse("print('{:.1f} {}'.format(1.0, a.b), f'{a.b}')").body[0])
    assert not handout.is_debug_print(ast.parse("print('{0.gi_frame}'.format(g))").body[0])
    assert handout.reaching_fields("{0.x} {1[k]} {{0.y}} {:>{w.z}}") == ["0.x", "1[k]", "w.z"]
    assert handout.reaching_fields("{") == []


def test_broken_or_missing_markers_leave_no_step_unchecked():
    """A stray end marker (all regions unknown) or a step's markers removed: the code the rules cannot find as the
    step fails that step, naming the markers (the library call below would pass its check otherwise)."""
    lab = lab_by_id("tumbling_crates")
    delegating, first = in_step(read("solutions/tumbling_crates.py"), 2, "return World().sat(pa, pb)")
    stray = delegating.replace("def main():", "# --- end of step 2 ---\ndef main():")
    line = stray.splitlines().index("# --- end of step 2 ---") + 1
    found = step_rules.scan_lab(stray, lab)
    assert {(b.step, b.line) for b in found} == {(step, line) for step in (2, 3, 4, 5, 6)}
    assert found[0].message.startswith(f"line {line} breaks the step markers (line {line} ends step 2")
    lines = delegating.splitlines(keepends=True)
    unmarked = "".join(text for text in lines if "step 2:" not in text and "end of step 2 " not in text)
    found = step_rules.scan_lab(unmarked, lab)
    assert [(b.step, b.rule) for b in found] == [(2, "outside")]
    assert found[0].message.startswith("the file has no markers for step 2 (keep `# --- step 2: ... ---`")


@pytest.mark.parametrize("added, flagged", [
    ("spy = '{0.gi_frame.f_back.f_locals}'.format\n", True),     # a frame read through a format field
    ("spy = '{0.__globals__}'\n", True),
    ("template = 'x'\nshow = template.format\n", True),            # a template built at run time
    ("label = '{0.x} {1[2]}'.format\n", False),                     # fields, but nothing that reaches further
])
def test_a_format_string_outside_the_steps_that_reaches_a_frame_fails_every_step(added, flagged):
    lab = lab_by_id("tumbling_crates")
    found = step_rules.scan_lab(read("solutions/tumbling_crates.py") + "\n" + added, lab)
    assert ({b.step for b in found} == {2, 3, 4, 5, 6}) == flagged and (found == []) != flagged


def test_a_marker_inside_a_string_is_no_marker():
    """An end marker inside a string literal (the real one removed) would end the region before the step's code:
    the markers are read as the comments they must be, so every step fails naming the line."""
    lab = lab_by_id("tumbling_crates")
    source, first = in_step(read("solutions/tumbling_crates.py"), 2,
                            's = """\n    # --- end of step 2 ---\n"""\nreturn World().sat(pa, pb)')
    real = source.rindex("    # --- end of step 2 ---\n")
    source = source[:real] + source[real + len("    # --- end of step 2 ---\n"):]
    found = step_rules.scan_lab(source, lab)
    assert {(b.step, b.line) for b in found} == {(step, first + 1) for step in (2, 3, 4, 5, 6)}
    assert "looks like a step marker but is inside a string" in found[0].message
    with pytest.raises(handout.MarkerError, match="inside a string"):
        handout.compare(source, read("starters/tumbling_crates_starter.py"))


# ---------------------------------------------------------------- attack round 2: a handed name rebound (hole A1),
# code a region dedents to module level (A2), a local named like the lab runtime (F1)

def outside_and_step(added, step, code):
    """The solution with `added` after its last def (before the main guard) and step `step` replaced by `code`;
    its text and the step's first line."""
    solution = read("solutions/tumbling_crates.py")
    guard = '\n\nif __name__ == "__main__":'
    assert solution.count(guard) == 1
    return in_step(solution.replace(guard, "\n\n" + added + guard), step, code)


REBOUND = [   # (added outside the steps, step 2's code, the rule flagging step 2): the library under a name a step reads
    ("from lesson11.physics2d import sat as project, effective_mass_inverse as edge_normals",
     "return project(pa, pb)", "import"),                                 # the attacker's PoC: a handed name
    ("project = World().sat", "return project(pa, pb)", "import"),        # assigned, not imported
    ("from random import Random as project", "return project(pa, pb)", "import"),   # an open module: still rebound
    ("def _bind():\n    global project\n    project = World().sat\n\n\n_bind()", "return project(pa, pb)", "import"),
    ("def _bind():\n    global project\n    from lesson11.physics2d import sat as project\n\n\n_bind()",
     "return project(pa, pb)", "import"),
    ("lesson_sat = World().sat", "return lesson_sat(pa, pb)", "reach"),  # a new name (the PoC's variant)
    ("engine = World\nlesson_sat = engine().sat", "return lesson_sat(pa, pb)", "reach"),   # through another name
    ("lesson_sat = lab", "return lesson_sat.something(pa, pb)", "reach"),
    ("def helper(pa, pb):\n    return World().manifolds()", "return helper(pa, pb)", "reach"),   # a helper def
    ("def helper(pa, pb):\n    return solver(pa, pb)\n\n\nsolver = Body.sat", "return helper(pa, pb)", "library"),
    ("if True:\n    from statistics import sys as system", "return system.modules['x']", "import"),
    ("shortcut = random._os", "return shortcut.sys.modules", "module"),
]


@pytest.mark.parametrize("added, code, rule", REBOUND)
def test_a_name_bound_outside_the_steps_to_the_library_is_flagged_where_a_step_reads_it(added, code, rule):
    """A handout-imported name is exempt only while every binding of it is the handout's import; a module-level
    name the file binds outside the steps to code that reaches World, the runtime, the library or a module is
    flagged in the step that reads it (attack report A1: 6/17 with no step written, 17/17 with --allow-edits)."""
    lab = lab_by_id("tumbling_crates")
    source, first = outside_and_step(added, 2, code)
    found = step_rules.scan_lab(source, lab)
    assert (2, first, rule) in [(b.step, b.line, b.rule) for b in found], [(b.step, b.line, b.rule) for b in found]
    breach = next(b for b in found if (b.step, b.line) == (2, first))
    assert breach.message.startswith(f"line {first} (step 2) uses ") and len(breach.message) < 300


@pytest.mark.parametrize("lab_id, added, step, code", [
    ("more_shapes", "from lesson11.physics2d import regular_polygon as draw_body", 2,
     "return draw_body(sides, radius)"),
    ("ball_on_ramp", "from lesson11.physics2d import circle_polygon as inside", 3,
     "return inside(center, radius, points)"),
])
def test_a_library_import_under_a_handed_name_fails_every_step_in_every_lab(lab_id, added, step, code):
    """README: an added import of the library fails every step (it was let through when it bound only names the
    handout imports: `from lesson11.physics2d import circle_polygon as inside`)."""
    lab = lab_by_id(lab_id)
    solution = read(lab.solution)
    source, first = in_step(solution + "\n" + added + "\n", step, code)
    found = step_rules.scan_lab(source, lab)
    line = len(source.splitlines())
    assert {b.step for b in found if (b.line, b.rule) == (line, "outside")} == set(labs_found.steps(lab))
    assert (step, first, "import") in [(b.step, b.line, b.rule) for b in found]


@pytest.mark.parametrize("added, code", [
    ("from lesson11.physics2d import project", "return project(pa, pb) if False else None"),   # as the handout binds it
    ("import math\nimport random", None),
    ("from lesson11.physics2d import Body, World, box_points, centre_of, cross, edge_normals, project, "
     "spin_velocity", None),                                      # the handout's import line again
    ("TAU = 2 * math.pi\nHALF = TAU / 4", "best_depth = min(best_depth, TAU * 1e9)"),     # a new name, plain numbers
    ("def span(points, axis):\n    return project(points, axis)", "lo_hi = span(pa, pa[1] - pa[0])"),  # a helper
])
def test_a_name_bound_outside_the_steps_to_plain_code_is_not_flagged(added, code):
    """Controls: a handed name bound again exactly as the handout binds it, or a new name bound to the file's own
    arithmetic or to the handed functions, used in a step (handout_unchanged judges the edit, not the rules)."""
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, _ = outside_and_step(added, 2, (code + "\n" if code else "") + step_code(solution, 2))
    assert step_rules.scan_lab(source, lab) == []


def test_the_attackers_step5only_file_no_longer_gets_full_marks_with_allow_edits(tmp_path):
    """Attack report A1 through the command line: steps 2, 4 and 6 call the library under handed names bound by an
    added import, only step 5 written; with --allow-edits (the platforms' option) it got 17/17."""
    starter = read("starters/tumbling_crates_starter.py")
    solution = read("solutions/tumbling_crates.py")
    source, _ = in_step(starter, 2, "return project(pa, pb)")
    source, _ = in_step(source, 4, "k = edge_normals(a, b, ra, rb, normal)")
    source, _ = in_step(source, 5, step_code(solution, 5))
    source, _ = in_step(source, 6, "a.omega += 0\ncentre_of(a, b, impulse * 0, ra, rb)")
    guard = '\n\nif __name__ == "__main__":'
    source = source.replace(guard, "\n\nfrom lesson11.physics2d import sat as project, effective_mass_inverse as "
                                   "edge_normals, apply_impulse as centre_of  # noqa: E402" + guard)
    path = tmp_path / "tumbling_crates.py"
    path.write_text(source, encoding="utf-8")
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYTHONPATH=ROOT)
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--allow-edits", "--seed", "7",
                           str(path)], cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    row = json.loads(proc.stdout)["labs"][0]
    checks = {c["id"]: c["status"] for c in row["criteria"]}
    assert all(checks[c] == "fail" for c in ("sat_axes", "resolve_k", "apply_impulse_spin")), checks
    assert row["score"] <= 4 < row["max_score"], row["score"]   # the starter and step 5: loads, handout, runtime, 5


def dedented(step, code):
    """The solution with `code` at column 0 just above step `step`'s end marker (it runs at module level)."""
    solution = read("solutions/tumbling_crates.py")
    end = f"    # --- end of step {step} ---\n"
    assert solution.count(end) == 1
    source = solution.replace(end, code + "\n" + end)
    return source, solution[:solution.index(end)].count("\n") + 1


def test_a_handout_constant_changed_at_column_0_inside_a_step_region_fails_handout_unchanged():
    """Attack report A2: `MAX_CRATES = 4` written at column 0 just above `# --- end of step 6 ---` runs at module
    level; it was blanked with the region, so handout_unchanged passed with the handout's constant changed."""
    source, line = dedented(6, "MAX_CRATES = 4\nRESTING_SPEED = 30")
    starter = read("starters/tumbling_crates_starter.py")
    comparison = handout.compare(source, starter)
    assert not comparison.same
    assert comparison.problems[0].startswith(f"line {line} `MAX_CRATES = 4`"), comparison.problems
    assert handout.constant_edits(source, starter) is None          # no warning that puts the handout's line back
    assert step_rules.scan_lab(source, lab_by_id("tumbling_crates")) == []   # handout_unchanged's, not a rule's


@pytest.mark.parametrize("code, rule, steps", [
    ("def sat(pa, pb):\n    return None", "outside", {2, 3}),              # a step function bound again
    ("lesson_sat = World().sat", "reach", {6}),                             # the step rules still read it
    ("import json", "outside", {2, 3, 4, 5, 6}),                            # a closed import at module level
])
def test_module_level_code_inside_a_step_region_is_code_outside_the_steps(code, rule, steps):
    """What a region dedents to module level is judged as code outside the steps (and still as the step's)."""
    lab = lab_by_id("tumbling_crates")
    source, line = dedented(6, code)
    found = step_rules.scan_lab(source, lab)
    assert {b.step for b in found if (b.line, b.rule) == (line, rule)} == steps, [(b.line, b.rule, b.step)
                                                                                   for b in found]
    comparison = handout.compare(source, read("starters/tumbling_crates_starter.py"))
    if code.startswith("import"):    # an added import binding a new name is allowed by the comparison, and listed
        assert comparison.added_imports == [f"line {line}: {code}"]
    else:
        assert not comparison.same and f"line {line} " in comparison.problems[0], comparison.problems


@pytest.mark.parametrize("code", [
    '    note = """\nmulti-line text\nat column 0\n"""',                    # a string's lines at column 0
    "    total = (1 +\n2)",                                                 # a bracket continued at column 0
    "# a comment at column 0",
    "def helper(x):\n    return x\nhelper(0)",                              # a def at the region's own indent
])
def test_a_step_s_own_lines_at_column_0_that_are_not_module_level_code_are_still_the_step(code):
    """Controls: only a statement that starts at module level leaves the step; text at column 0 inside a string,
    a bracket or a comment, or a def at the region's indent, stays the step's code."""
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    if code.startswith("def "):
        source, _ = in_step(solution, 6, code + "\n" + step_code(solution, 6))
    else:
        end = "    # --- end of step 6 ---\n"
        source = solution.replace(end, code + "\n" + end)
    compile(source, "lab.py", "exec")
    assert handout.compare(source, read("starters/tumbling_crates_starter.py")).same
    assert step_rules.scan_lab(source, lab) == []


@pytest.mark.parametrize("code", [
    "for lab in range(2):\n    panel = [lab]\nruntime = [w for w in panel]\nWorld = None",
    "def helper(runtime, lab=2):\n    return runtime * lab\nkept = (lambda panel: panel)(1)\n"
    "LabPanel = [make_world for make_world in (1, 2)]\n(runtime := 3)",
])
def test_a_local_named_like_the_lab_runtime_is_the_step_s_own(code):
    """Attack report F1: a local named lab, panel, runtime or World (assigned, a parameter, a loop or comprehension
    target) is the step's own; the rule "reach" is about the module's names."""
    lab = lab_by_id("tumbling_crates")
    solution = read(lab.solution)
    source, _ = in_step(solution, 2, code + "\n" + step_code(solution, 2))
    assert [(b.line, b.rule, b.what) for b in step_rules.scan_lab(source, lab)] == []


def test_the_bullets_solution_with_a_local_runtime_is_not_flagged():
    """The attacker's file (its step 5's last line through a local `runtime`): 7/15 before, "reaches runtime"."""
    lab = lab_by_id("bullets")
    solution = read(lab.solution)
    lines = step_code(solution, 5).splitlines()
    assert lines[-1] == "bullet.pos += bullet.vel * (dt - t)"
    code = "\n".join(lines[:-1] + ["runtime = dt - t  # the part of the step still to run",
                                   "bullet.pos += bullet.vel * runtime"])
    source, _ = in_step(solution, 5, code)
    assert step_rules.scan_lab(source, lab) == []


@pytest.mark.parametrize("code", ["x = runtime", "def f(r=lab):\n    return r", "global panel\npanel = 1",
                                  "class K:\n    def f(self):\n        return lab"])
def test_the_module_s_runtime_or_panel_is_still_flagged(code):
    """The module's `lab` read in a step (also as a default or in a method), or a name bound at module level."""
    lab = lab_by_id("tumbling_crates")
    source, first = in_step(read("solutions/tumbling_crates.py"), 2, code + "\nreturn None")
    found = step_rules.scan_lab(source, lab)
    assert any(b.rule == "reach" and b.step == 2 and first <= b.line for b in found), found


def test_a_constant_changed_at_column_0_in_a_step_region_fails_handout_unchanged_through_the_command_line(tmp_path):
    """Attack report A2 as graded: the solution with `MAX_CRATES = 4` at column 0 above step 6's end marker passed
    handout_unchanged (15/17, the scenes run with 4 crates); the check now names the line, and the scenes wait."""
    source, line = dedented(6, "MAX_CRATES = 4")
    path = tmp_path / "tumbling_crates.py"
    path.write_text(source, encoding="utf-8")
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYTHONPATH=ROOT)
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--seed", "7", str(path)], cwd=ROOT,
                          env=env, capture_output=True, text=True, timeout=600)
    row = json.loads(proc.stdout)["labs"][0]
    checks = {c["id"]: c for c in row["criteria"]}
    assert checks["handout_unchanged"]["status"] == "fail"
    assert f"line {line} `MAX_CRATES = 4` was added" in checks["handout_unchanged"]["message"]
    assert checks["runs"]["status"] == "skip" and row["flags"] == []


def test_a_name_bound_to_a_library_function_is_flagged_only_in_the_steps_that_ask_for_it():
    """What a module-level name reaches is judged per step, as in the step itself: the library's sat under a new
    name fails step 2 (which asks for sat), not step 6 (which asks for apply_impulse)."""
    lab = lab_by_id("tumbling_crates")
    solution = read("solutions/tumbling_crates.py")
    source, first = outside_and_step("overlap_of = Body.sat", 2, "return overlap_of(pa, pb)")
    assert [(b.step, b.line, b.rule) for b in step_rules.scan_lab(source, lab)] == [(2, first, "library")]
    source, _ = outside_and_step("overlap_of = Body.sat", 6, "unused = overlap_of\n" + step_code(solution, 6))
    assert step_rules.scan_lab(source, lab) == []


def test_an_expression_too_deep_to_compare_outside_the_steps_does_not_stop_the_scan():
    """A line outside the steps that compiles but is too deep for the handout comparison's syntax-tree dump: the
    rules still read the file (every top-level statement counts as changed) and find the step's breach."""
    lab = lab_by_id("tumbling_crates")
    source, first = outside_and_step("x = " + " + ".join(["1"] * 2500), 2, "return World().sat(pa, pb)")
    compile(source, "deep.py", "exec")
    assert (2, first, "reach") in [(b.step, b.line, b.rule) for b in step_rules.scan_lab(source, lab)]
