"""One reading of a lab file, the compiler's (checker/reading/source.py), and what it closes (issue 35, items 1 and 4).

  - lines(): the lines Python counts (\\n, \\r\\n, \\r), checked against the compiler's own line numbers on
    text full of the characters str.splitlines() also breaks at (\\x0b \\x0c \\x1c-\\x1e \\x85 U+2028 U+2029);
  - decode(): UTF-8 (with or without a BOM, `# coding: utf8` too) is read; any other declared coding, an
    unknown one and bytes that are not UTF-8 are refused with one line naming the file;
  - the guard: a syntax tree reaching past the checker's lines refuses the file;
  - graded by the command line: each attack of these mechanisms scores no more than the honest work it
    contains, and honest files (CRLF, a BOM, a form feed in a string, cmath and itertools in the steps)
    get full marks.
"""
import ast
import json
import os
import subprocess
import sys

import pytest

from checker.reading import handout, source, step_rules
from checker.judging import probing
from checker.isolation import users
from checker.labs import LABS

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ODD_BREAKS = "\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"   # str.splitlines() breaks at these; Python does not


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


def lab(lab_id):
    return next(entry for entry in LABS if entry.id == lab_id)


def region(text, step):
    """(index of step's start marker line, index of its end marker line) in the lines of `text`."""
    lines = text.split("\n")
    return (next(i for i, line in enumerate(lines) if f"# --- step {step}:" in line),
            next(i for i, line in enumerate(lines) if f"# --- end of step {step} ---" in line))


def with_step(text, step, body_from):
    """`text` with the inside of step `step` taken from `body_from` (another version of the same lab)."""
    lines, other = text.split("\n"), body_from.split("\n")
    (start, end), (their_start, their_end) = region(text, step), region(body_from, step)
    return "\n".join(lines[:start + 1] + other[their_start + 1:their_end] + lines[end:])


def in_step(text, step, code):
    """`text` with the inside of step `step` replaced by `code` (written at the marker's indent)."""
    lines = text.split("\n")
    start, end = region(text, step)
    indent = lines[start][:len(lines[start]) - len(lines[start].lstrip())]
    return "\n".join(lines[:start + 1] + [indent + line for line in code.split("\n")] + lines[end:])


# ---------------------------------------------------------------- lines(): as the compiler counts them

@pytest.mark.parametrize("ending", ["\n", "\r\n", "\r"])
def test_lines_are_the_compiler_s_lines(ending):
    """Every name the compiler puts on line L is on lines()[L - 1], whatever odd characters the comments hold."""
    statements = [f"name_{i} = {i}  # {ODD_BREAKS * (i % 3)} comment" for i in range(40)]
    statements += ["text = '''a" + ODD_BREAKS + "b'''", "\x0c", "last = 1"]
    text = ending.join(statements) + ending
    lines = source.lines(text)
    names = [node for node in ast.walk(ast.parse(text)) if isinstance(node, ast.Name)]
    assert len(names) == 42
    for node in names:
        line = lines[node.lineno - 1].encode("utf-8")
        assert line[node.col_offset:].startswith(node.id.encode()), (node.id, node.lineno)
    assert len(lines) == len(statements) and len(text.splitlines()) > len(statements)   # splitlines disagrees


def test_lines_keeps_splitlines_conventions():
    assert source.lines("") == [] and source.lines("a") == ["a"] and source.lines("a\n") == ["a"]
    assert source.lines("a\r\n\rb\n\n") == ["a", "", "b", ""] == "a\r\n\rb\n\n".splitlines()


# ---------------------------------------------------------------- decode(): the file's declared text, UTF-8 only

@pytest.mark.parametrize("raw", [b"x = 1\n", b"\xef\xbb\xbfx = 1\n", b"# -*- coding: utf-8 -*-\nx = 1\n",
                                 b"# coding: utf8\nx = 1\n", b"# vim: set fileencoding=UTF_8 :\nx = 1\n",
                                 "# caf\u00e9 \u2028\nx = 1\n".encode("utf-8")])
def test_utf8_in_every_spelling_is_read_as_python_reads_it(raw):
    text = source.decode(raw, "lab.py")
    assert not text.startswith("\ufeff")
    namespace = {}
    exec(compile(text, "lab.py", "exec"), namespace)
    assert namespace["x"] == 1


@pytest.mark.parametrize("raw, words", [
    (b"# -*- coding: unicode_escape -*-\nx = 1\n", "lab.py declares `# coding: unicode_escape`; save it as UTF-8 "
                                                  "and remove the line"),
    (b"# coding: latin-1\nx = '\xe9'\n", "lab.py declares `# coding: iso-8859-1`"),
    (b"# coding: utf-16\nx = 1\n", "declares `# coding: utf-16`"),
    (b"# coding: no-such-coding\nx = 1\n", "lab.py: unknown encoding"),
    (b"x = 1\n# caf\xe9\n", "lab.py is not UTF-8 text: byte 0xe9 on line 2 cannot be read"),
    (b"# caf\xe9\nx = 1\n", "lab.py is not UTF-8 text: byte 0xe9 on line 1 cannot be read"),   # detect_encoding's
    (b"\xef\xbb\xbf# coding: latin-1\nx = 1\n", "lab.py: encoding problem"),
])
def test_any_other_coding_or_bytes_are_refused_in_one_line(raw, words):
    with pytest.raises(source.SourceError) as caught:
        source.decode(raw, "lab.py")
    assert words in str(caught.value) and "\n" not in str(caught.value)


def test_the_guard_refuses_a_tree_past_the_checker_s_lines(monkeypatch):
    """A checker-side split that counts fewer lines than Python (here: one that ignores \\r) refuses the file."""
    text = "a = 1\rb = 2\rc = 3\r"
    assert source.check(text) is not None
    monkeypatch.setattr(source, "lines", lambda text: text.split("\n")[:-1] or [text])
    with pytest.raises(source.SourceError, match="the file has line breaks Python does not count"):
        source.check(text, "the file")


def test_a_file_that_does_not_parse_passes_the_guard():
    assert source.check("def (:\n") is None


def test_the_child_compiles_the_text_the_grader_read(tmp_path, monkeypatch):
    """checker/isolation/child.py load_lab: a BOM and \r line ends read as the grader reads them; another coding never runs."""
    from checker.isolation import child
    monkeypatch.setitem(sys.modules, child.MODULE_NAME, None)   # load_lab's module is gone after the test
    path, copy = tmp_path / "lab.py", tmp_path / "copy.py"    # the child reads the copy in its work folder
    copy.write_bytes(b"\xef\xbb\xbfa = 1\rb = '\x0c'\r\nc = 3  # \xe2\x80\xa8 \x1c\n")
    module = child.load_lab(str(path), str(copy))
    assert (module.a, module.b, module.c) == (1, "\x0c", 3)
    copy.write_bytes(b"# -*- coding: unicode_escape -*-\n# \\nran = True\n")
    with pytest.raises(source.SourceError, match="unicode_escape"):
        child.load_lab(str(path), str(copy))


def test_the_grader_refuses_another_coding_before_anything_runs(tmp_path):
    """Grader.grade (the path every output takes, also without the command line's entries) refuses the file."""
    from checker.grade import Grader
    path = tmp_path / "tumbling_crates.py"
    path.write_bytes(b"# -*- coding: unicode_escape -*-\n" + read("solutions/tumbling_crates.py").encode())
    report = Grader().grade(str(path), lab("tumbling_crates"))
    assert report.status == "error" and report.score == 0
    assert report.results[0].message == ("tumbling_crates.py declares `# coding: unicode_escape`; save it as UTF-8 "
                                         "and remove the line.")


# ---------------------------------------------------------------- the checker's modules read the same lines

def shifted(text, before, count=100):
    """`text` with a comment of `count` × ODD_BREAKS on its own line before the line starting `before`."""
    at = text.index(before)
    return text[:at] + "# " + ODD_BREAKS * count + "\n" + text[at:]


def test_odd_line_breaks_shift_no_region():
    """Mechanism 1: a comment full of \\x0c, \\x1c, U+2028 ... moves no step region away from its code."""
    crates = lab("tumbling_crates")
    attack = shifted(in_step(read("solutions/tumbling_crates.py"), 2, "return World().sat(pa, pb)"), "def sat(")
    code_line = next(node.lineno for node in ast.walk(ast.parse(attack))
                     if isinstance(node, ast.Attribute) and node.attr == "sat")
    assert {(b.line, b.rule) for b in step_rules.scan_lab(attack, crates)} == {(code_line, "library"),
                                                                                       (code_line, "reach")}
    regions = handout.step_regions(source.lines(attack))
    assert regions[2][0] + 1 < code_line < regions[2][1] + 1     # the compiler's line is inside step 2's markers
    assert probing.regions_by_function(attack) == probing.regions_by_function(read("solutions/tumbling_crates.py"))


def test_odd_line_breaks_cannot_hide_an_edit_outside_the_steps():
    """blank_steps rebuilds with the compiler's lines: the World's settings changed after the comment are seen."""
    starter = read("starters/tumbling_crates_starter.py")
    edited = shifted(read("solutions/tumbling_crates.py"), "def make_world(").replace(
        "sat=sat, resolve=resolve)", "sat=sat, resolve=resolve, iterations=1)")
    assert "iterations=1" in edited
    comparison = handout.compare(edited, starter)
    assert not comparison.same and any("iterations=1" in problem for problem in comparison.problems)


def test_splices_are_cut_at_the_compiler_s_lines():
    """probing.splice_source: the spliced function compiles at the lab's own line numbers."""
    mine = shifted(read("starters/tumbling_crates_starter.py"), "def resolve(")
    splice = probing.splice_source(mine, read("solutions/tumbling_crates.py"), "resolve", [4])
    first = source.lines(mine).index(next(line for line in source.lines(mine) if line.startswith("def resolve(")))
    assert splice["first"] == first
    tree = ast.parse("\n" * splice["first"] + splice["text"])
    assert tree.body[0].name == "resolve" and tree.body[0].lineno == first + 1


# ---------------------------------------------------------------- graded by the command line

SIDE_MODULE = '''"""Helpers for my crates."""
import sys

from solutions.tumbling_crates import apply_impulse

sys.modules["lab_under_test"].apply_impulse = apply_impulse
'''


def files():
    """{name: (lab id, text or bytes, {side file: text})}: the attacks, their honest work, and honest files."""
    crates, starter = read("solutions/tumbling_crates.py"), read("starters/tumbling_crates_starter.py")
    shapes = read("solutions/more_shapes.py")
    no_step_2 = with_step(crates, 2, starter)
    no_step_6 = with_step(crates, 6, starter)
    guard = 'if __name__ == "__main__":'
    escaped = "# " + "\\n" + "from lesson11.physics2d import sat  # noqa\n"

    def before_guard(text, line):
        return text.replace(guard, line + "\n\n" + guard)

    honest_cmath = in_step(shapes, 2, "corners = [radius * cmath.exp(2j * cmath.pi * k / sides)\n"
                                      "           for k in range(sides)]\n"
                                      "return [Vector2(z.real, z.imag) for z in corners]")
    honest_cmath = honest_cmath.replace("import math\n", "import cmath\nimport math\n", 1)
    honest_itertools = in_step(in_step(shapes, 3, "import itertools\ntotal = Vector2()\n"
                                                  "for a, b in itertools.pairwise(points + points[:1]):\n"
                                                  "    total += (a + b) * cross(a, b)\nreturn total / (6 * area)"),
                               4, "from itertools import pairwise\nnum = den = 0.0\n"
                                  "for a, b in pairwise([*points, points[0]]):\n"
                                  "    area2 = abs(cross(a, b))\n"
                                  "    num += area2 * (a.dot(a) + a.dot(b) + b.dot(b))\n"
                                  "    den += area2\nreturn mass * num / (6 * den)")
    formfeed = in_step(crates, 2, "label = 'page\x0cbreak \u2028'  # a form feed \x0c in a comment\n"
                                  + "\n".join(line[4:] for line in crates.split("\n")[region(crates, 2)[0] + 1:
                                                                                     region(crates, 2)[1]]))
    return {
        # attacks: (lab, text, side files), graded against the honest work they contain
        "linebreaks": ("tumbling_crates", shifted(in_step(crates, 2, "return World().sat(pa, pb)"), "def sat("), {}),
        "unicode_escape": ("tumbling_crates", ("# -*- coding: unicode_escape -*-\n" + before_guard(no_step_2, escaped))
                           .encode("utf-8"), {}),
        "star_solutions": ("tumbling_crates", before_guard(no_step_6, "from solutions.tumbling_crates import *"), {}),
        "star_library": ("tumbling_crates", before_guard(no_step_2, "from lesson11.physics2d import *"), {}),
        "side_module": ("tumbling_crates", before_guard(no_step_6, "import crate_utils  # noqa"),
                        {"crate_utils.py": SIDE_MODULE}),
        "format_frame": ("tumbling_crates", in_step(crates, 6, "a.omega -= cross(ra, impulse) * a.inv_inertia\n"
                                                               "b.omega += cross(rb, impulse) * b.inv_inertia\n"
                                                               "where = '{0.gi_frame.f_lineno}'.format(\n"
                                                               "    (lambda: (yield))())"), {}),
        "stray_marker": ("tumbling_crates", in_step(crates, 2, "return World().sat(pa, pb)").replace(
            "def main():", "# --- end of step 2 ---\ndef main():"), {}),
        "marker_in_string": ("tumbling_crates", in_step(crates, 2, 's = """\n    # --- end of step 2 ---\n"""\n'
                                                               'return World().sat(pa, pb)').replace(
            "    # --- end of step 2 ---\n    # --- step 3", "    # --- step 3"), {}),
        "no_step_2": ("tumbling_crates", no_step_2, {}),
        "no_step_6": ("tumbling_crates", no_step_6, {}),
        # honest files: full marks
        "crlf": ("tumbling_crates", crates.replace("\n", "\r\n").encode("utf-8"), {}),
        "bom": ("tumbling_crates", b"\xef\xbb\xbf" + crates.encode("utf-8"), {}),
        "formfeed": ("tumbling_crates", formfeed, {}),
        "cmath": ("more_shapes", honest_cmath, {}),
        "itertools": ("more_shapes", honest_itertools, {}),
    }


ATTACKS = {"linebreaks": "no_step_2", "unicode_escape": "no_step_2", "star_solutions": "no_step_6",
           "star_library": "no_step_2", "side_module": "no_step_6", "format_frame": "no_step_6",
           "stray_marker": "no_step_2", "marker_in_string": "no_step_2"}
HONEST = ("crlf", "bom", "formfeed", "cmath", "itertools")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """{name: the checker's JSON row}, every file in its own folder, graded by one command-line run."""
    base = tmp_path_factory.mktemp("reading")
    paths = {}
    for name, (lab_id, text, side) in files().items():
        folder = base / name
        folder.mkdir()
        for file, content in side.items():
            (folder / file).write_text(content, encoding="utf-8")
        path = folder / f"{lab_id}.py"
        path.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8"))
        paths[name] = str(path)
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--jobs", "2", *paths.values()],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=1800)
    assert proc.returncode in (0, 1), proc.stderr[-3000:]
    by_path = {os.path.abspath(p): name for name, p in paths.items()}
    return {by_path[os.path.abspath(row["path"])]: row for row in json.loads(proc.stdout)["labs"]}


def show(row):
    return f"{row['score']}/{row['max_score']} " + "; ".join(
        f"{c['id']}: {c['status']} {c['message'][:160]}" for c in row.get("criteria", []) if c["status"] != "pass")


@pytest.mark.parametrize("attack", sorted(ATTACKS))
def test_an_attack_scores_no_more_than_the_honest_work_it_holds(attack, graded):
    row, honest = graded[attack], graded[ATTACKS[attack]]
    assert row["score"] <= honest["score"] < honest["max_score"], (show(row), show(honest))


def test_the_unicode_escape_file_is_refused_with_one_clear_line(graded):
    row = graded["unicode_escape"]
    assert row["status"] == "error" and row["score"] == 0
    assert "declares `# coding: unicode_escape`; save it as UTF-8 and remove the line" in json.dumps(row)


@pytest.mark.parametrize("attack, check, words", [
    ("linebreaks", "sat_axes", "calls the library's sat()"),
    ("star_solutions", "apply_impulse_spin", "imports every name of solutions.tumbling_crates"),
    ("star_library", "sat_axes", "imports every name of lesson11.physics2d"),
    ("side_module", "apply_impulse_spin", "imports crate_utils from the submission's own folder"),
    ("format_frame", "apply_impulse_spin", "formats the field {0.gi_frame.f_lineno}"),
    ("stray_marker", "sat_axes", "breaks the step markers"),
    ("marker_in_string", "sat_axes", "looks like a step marker but is inside a string"),
])
def test_each_attack_fails_its_step_naming_the_line(attack, check, words, graded):
    """The flag is listed with its line; the step's check fails with it (where the file loads at all: the side
    module is not beside the child's copy, so that file fails `loads` first, and a grader running as root keeps
    the answers from the child's user, so the star import of the solutions stops at the file's own
    ModuleNotFoundError, wherever the project sits: issue 44)."""
    row = graded[attack]
    assert any(words in flag["what"] and flag["line"] for flag in row["flags"]), show(row)
    checks = {c["id"]: c for c in row["criteria"]}
    if attack == "side_module" and checks["loads"]["status"] != "pass":
        return
    if attack == "star_solutions" and users.is_root():
        assert checks["loads"]["status"] == "error", show(row)
        assert "ModuleNotFoundError: No module named 'solutions'" in checks["loads"]["message"], show(row)
        return
    assert checks[check]["status"] == "fail" and words in checks[check]["message"], show(row)
    assert checks[check]["message"].startswith("line ")


@pytest.mark.parametrize("name", HONEST)
def test_honest_files_get_full_marks(name, graded):
    row = graded[name]
    assert row["score"] == row["max_score"] and not row.get("flags"), show(row)
