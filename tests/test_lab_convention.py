"""Labs by convention: a lab is its id, and every file of it is found from that id by one function.

checker/labs/__init__.py's Lab finds a lab's checks, probes and scenes (checker/labs/<id>/), its
starter (starters/<id>_starter.py) and its solution (solutions/<id>.py); the registry is every folder
of checker/labs holding a checks.py. No lab spells a path of its own.
"""
import ast
import glob
import importlib
import os

from checker import labs

ROOT = labs.PROJECT_ROOT
LAB_FILES = ("__init__.py", "checks.py", "probes.py", "scenes.py")
OPTIONAL_FILES = ("show.py",)   # what --show and --pictures draw for its checks (Lab.replay)


def test_every_folder_holding_checks_is_a_registered_lab_in_the_lessons_order():
    folders = sorted(os.path.basename(os.path.dirname(path))
                     for path in glob.glob(os.path.join(labs.HERE, "*", "checks.py"))
                     if not os.path.basename(os.path.dirname(path)).startswith("_"))
    assert sorted(lab.id for lab in labs.LABS) == folders and len(folders) >= 5
    assert [lab.id for lab in labs.LABS][:len(labs.ORDER)] == list(labs.ORDER)


def test_a_lab_folder_not_in_the_lessons_order_is_found_after_the_others(tmp_path):
    for lab_id in ("zeta", "alpha", "bullets", "tumbling_crates"):
        (tmp_path / lab_id).mkdir()
        (tmp_path / lab_id / "checks.py").write_text("")
    (tmp_path / "_toy").mkdir()
    (tmp_path / "_toy" / "checks.py").write_text("")     # a leading _ is never a lab
    (tmp_path / "notes").mkdir()                        # a folder without checks.py is not one either
    assert labs.found(str(tmp_path)) == ["tumbling_crates", "bullets", "alpha", "zeta"]


def test_every_lab_has_the_same_files_found_from_its_id():
    for lab in labs.LABS:
        folder = os.path.join(labs.HERE, lab.id)
        present = {name for name in os.listdir(folder) if name.endswith(".py")}
        assert set(LAB_FILES) <= present <= set(LAB_FILES + OPTIONAL_FILES), lab.id
        assert lab.starter == os.path.join(ROOT, "starters", f"{lab.id}_starter.py") and os.path.isfile(lab.starter)
        assert lab.solution == os.path.join(ROOT, "solutions", f"{lab.id}.py") and os.path.isfile(lab.solution)
        assert lab.probes == f"checker.labs.{lab.id}.probes"
        assert lab.module.__name__ == f"checker.labs.{lab.id}.checks"
        assert lab.scenes.__name__ == f"checker.labs.{lab.id}.scenes" and lab.scenarios()
        assert set(lab.scenarios()) == set(lab.scenes.SCENARIOS), lab.id
        assert lab.replay is None if "show.py" not in present else lab.replay.__name__ == f"checker.labs.{lab.id}.show"


def test_no_lab_spells_a_path_of_its_own():
    """No ROOT, STARTER, SOLUTION or PROBES in a lab's modules, and no path built from their own __file__."""
    for path in sorted(glob.glob(os.path.join(labs.HERE, "*", "*.py"))):
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
        assigned = {target.id for node in ast.walk(ast.parse(text)) if isinstance(node, ast.Assign)
                    for target in node.targets if isinstance(target, ast.Name)}
        assert not assigned & {"ROOT", "STARTER", "SOLUTION"}, path
        assert "PROBES" not in assigned or path.endswith("probes.py"), path   # probes.py's PROBES is its table
        assert "__file__" not in text and "os.path.dirname(os.path.dirname(os.path.dirname" not in text, path


def test_a_lab_under_another_root_finds_its_starter_and_solution_there(tmp_path):
    lab = labs.Lab("tumbling_crates", root=str(tmp_path))
    assert lab.starter == str(tmp_path / "starters" / "tumbling_crates_starter.py")
    assert lab.solution == str(tmp_path / "solutions" / "tumbling_crates.py")
    assert lab.module is labs.LABS[0].module      # its modules are still checker/labs/<id>/


def test_assign_names_a_starter_as_the_lab_does():
    lab = labs.Lab.of_solution(os.path.join(ROOT, "solutions", "bullets.py"))
    assert lab == labs.Lab("bullets") and lab.starter_file == "bullets_starter.py"
    assert lab.starter == os.path.join(ROOT, "starters", lab.starter_file)


SHARED_CHECKS = ("loads", "handout_unchanged", "runtime_lines")


def test_every_lab_starts_with_the_shared_checks_listing_the_functions_its_probe_requires():
    for lab in labs.LABS:
        first = lab.checks.checks[:3]
        assert tuple(c.id for c in first) == SHARED_CHECKS, lab.id
        assert [c.max_score for c in first] == [1.0] * 3 and [c.after for c in first] == [(), ("loads",), ("loads",)]
        listed = first[0].description.split(" defines ", 1)[1].rstrip(".").replace(" and ", ", ").split(", ")
        required = importlib.import_module(lab.probes).REQUIRED
        assert sorted(listed) == sorted(required), lab.id   # the description names what a missing name fails


def test_no_lab_writes_the_shared_checks_again():
    for path in sorted(glob.glob(os.path.join(labs.HERE, "*", "checks.py"))):
        with open(path, encoding="utf-8") as handle:
            defined = {node.name for node in ast.walk(ast.parse(handle.read())) if isinstance(node, ast.FunctionDef)}
        assert not defined & set(SHARED_CHECKS), path   # lab_checks.register_common registers them


def _imported_modules(path):
    """The modules a Python file imports (absolute names; relative imports as written, with their dots)."""
    with open(path, encoding="utf-8") as handle:
        tree = ast.parse(handle.read())
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            names.add("." * node.level + (node.module or ""))
    return names


def test_nothing_in_lesson11_imports_the_checker():
    """The checker may import lesson11 (the scenes it shares with the bench: lesson11/crate_scenes.py, records.py),
    never the other way round: the bench measures the checker's scenes without importing the checker."""
    paths = glob.glob(os.path.join(ROOT, "lesson11", "**", "*.py"), recursive=True)
    assert any(path.endswith(os.path.join("bench", "default_probe.py")) for path in paths)
    importing = {os.path.relpath(path, ROOT): sorted(name for name in _imported_modules(path)
                                                     if name == "checker" or name.startswith("checker."))
                 for path in paths}
    assert {path: names for path, names in importing.items() if names} == {}


def test_the_import_finder_sees_a_checker_import():
    assert "checker" in _imported_modules(__file__)   # this file's `from checker import labs`


def test_nothing_in_lesson11_reaches_into_the_tests():
    """The bench takes the scenes it shares with the tests from lesson11 (crate_scenes.pile_settings, clicks,
    ramp_crate): no lesson11 module imports tests/lab_run.py or puts tests/ on sys.path."""
    paths = glob.glob(os.path.join(ROOT, "lesson11", "**", "*.py"), recursive=True)
    reaching = []
    for path in paths:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
        if "lab_run" in _imported_modules(path) or ("sys.path" in text and '"tests"' in text):
            reaching.append(os.path.relpath(path, ROOT))
    assert reaching == []


def test_a_lab_without_its_own_recognise_knows_its_files_by_id_or_title():
    for lab in labs.LABS:
        if hasattr(lab.module, "recognise"):   # Bullets: its own rule (the docstring's first line)
            continue
        assert labs.identify(os.path.join("class", "A", lab.id + "_v2.py"), "") == lab
        assert labs.identify(os.path.join("class", "A", "lab.py"), f'"""{lab.title.upper()}: my file"""') == lab
    assert labs.identify(os.path.join("class", "A", "lab.py"), "print('hello')") is None


def test_a_file_opening_with_one_labs_title_is_that_labs_though_it_names_another():
    """The strongest evidence wins: a file's name, then the title its docstring opens with, then a title anywhere.
    A renamed file that opens with one lab's title and mentions an earlier lab's in a comment is the first lab's
    (checked first in the lesson's order, the earlier lab used to take it); a file naming a lab only in passing
    is still that lab's."""
    convention = [lab for lab in labs.LABS if not hasattr(lab.module, "recognise")]
    assert len(convention) >= 2
    earlier, later = convention[0], convention[-1]
    text = f'"""{later.title}: my copy."""\n# this builds on {earlier.title}\n'
    assert labs.identify(os.path.join("class", "A", "lab.py"), text) == later
    assert labs.identify(os.path.join("class", "A", f"{earlier.id}.py"), text) == earlier   # the name is stronger
    assert labs.identify(os.path.join("class", "A", "lab.py"), f"# notes on {later.title}\n") == later
    assert later.evidence("lab.py", text) == 2 and earlier.evidence("lab.py", text) == 1
