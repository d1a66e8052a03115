"""The lab's rules for the code inside the step regions, checked in the grader from the source.

A step is the student's own work: it may use the names the handout gives,
`math`, and the functions the student writes. The grader reads each step's
syntax tree (never running it) and flags what reaches around the exercise:

  import    an import inside a step, or a name the file imported itself (other than from math)
  dunder    a dunder name or attribute (__import__, __globals__, __class__, ...)
  builtin   exec, eval, compile, open, getattr, setattr, delattr, globals, vars, locals,
            __import__, breakpoint, input
  frame     a frame or traceback attribute (f_back, f_locals, gi_frame, tb_frame, ...)
  reach     World, the lab runtime (`lab`) or the panel (`LabPanel`)
  module    an attribute of a module other than math (pygame.Vector2 aside)
  library   a call of the library function the step asks the student to write (the lab's
            STEP_LIBRARY: {step: names}), by its name or as an attribute (`world.sat(...)`)

Outside the steps the code must be the handout's (handout_unchanged), but an
edit there could replace a step's function after the fact, so two things are
flagged under every step of the function they touch (rule "outside"): a
second top-level binding of a step function's name (`sat = other_sat`,
another `def sat`, an import as `sat`), and a line the handout does not have
that uses exec, eval, compile, globals, vars, setattr, getattr, __import__,
a dunder name or `sys.modules` (which can rebind any name).

These forbid reaching around the exercise, not ways of writing it: every
correct completion in the corpora passes (tests/test_step_rules.py).
"""
import ast
from dataclasses import dataclass

from .handout import MarkerError, step_regions

BUILTINS = frozenset({"exec", "eval", "compile", "open", "getattr", "setattr", "delattr", "globals", "vars",
                      "locals", "__import__", "breakpoint", "input"})
FRAME_ATTRIBUTES = frozenset({"f_back", "f_globals", "f_locals", "f_builtins", "f_code", "gi_frame", "gi_code",
                              "cr_frame", "ag_frame", "tb_frame", "tb_next", "func_globals"})
REACH = ("World", "lab", "LabPanel", "runtime", "panel")
FREE_MODULES = frozenset({"math"})                # a step may use any attribute of these
# modules a file may not import outside the steps either: they reach the checker, the library's answers,
# the interpreter's own machinery, files or other processes
CLOSED_MODULES = frozenset({"checker", "lesson11", "sys", "importlib", "inspect", "gc", "ctypes", "builtins",
                            "types", "json", "pickle", "marshal", "os", "subprocess", "io", "runpy", "threading",
                            "signal", "shutil", "pathlib", "socket", "traceback", "faulthandler", "atexit"})
FREE_ATTRIBUTES = {"pygame": frozenset({"Vector2", "math"})}   # and these attributes of these


@dataclass(frozen=True)
class Breach:
    """One construct inside a step region that the rules forbid."""
    step: int        # the step region it is in
    line: int        # 1-based line in the file
    rule: str        # import, dunder, builtin, frame, reach, module, library
    what: str        # what it does, for a student: "calls the library's sat()"
    text: str        # the line, stripped
    message: str = ""   # the whole sentence the step's check shows (scan_lab fills it in)


def _is_dunder(name):
    return len(name) > 4 and name.startswith("__") and name.endswith("__")


def _imports(tree):
    """{bound name: (module it comes from, is it a module itself)} for the top-level imports of a tree."""
    bound = {}
    for node in tree.body:
        if isinstance(node, ast.Import):
            for alias in node.names:
                name = alias.asname or alias.name.split(".")[0]
                bound[name] = (alias.name if alias.asname else alias.name.split(".")[0], True)
        elif isinstance(node, ast.ImportFrom) and node.module:
            for alias in node.names:
                # `from lesson11 import runtime as lab`: a module; `from x.y import name`: a module if x.y is a
                # package whose attribute is lower case and known to be one (runtime, panel, draw, physics2d)
                is_module = alias.name in ("runtime", "panel", "draw", "physics2d", "math", "collision", "world")
                bound[alias.asname or alias.name] = (f"{node.module}.{alias.name}", is_module)
    return bound


def _bound_by_code(tree):
    """Names the file binds itself other than by import: defs, classes, assignments, parameters, loop targets."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        elif isinstance(node, ast.arg):
            names.add(node.arg)
    return names


def scan(source, library=None, starter=None, reach=REACH):
    """Every Breach inside the step regions of `source` (a lab file's text), in line order.

    library: {step: names of library functions the step asks the student to write}.
    starter: the handout's source; a name the file imports that the handout does not is the
    file's own import (rule "import" when a step uses it). [] when the file does not parse or
    its markers are broken (other checks say so).
    """
    library = library or {}
    try:
        regions = step_regions(source.splitlines())
        tree = ast.parse(source)
    except (MarkerError, SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    lines = source.splitlines()
    spans = [(step, start + 1, end + 1) for step, (start, end, _) in regions.items()]

    def step_of(line):
        return next((step for step, first, last in spans if first < line < last), None)

    imported = _imports(tree)
    handed = set(_imports(ast.parse(starter))) if starter else set(imported)
    own = _bound_by_code(tree)
    found = {}

    def flag(node, rule, what):
        line = node.lineno
        step = step_of(line)
        if step is not None and (line, rule, step) not in found:
            found[(line, rule, step)] = Breach(step, line, rule, what, lines[line - 1].strip())

    for node in ast.walk(tree):
        if getattr(node, "lineno", None) is None or step_of(node.lineno) is None:
            continue
        step = step_of(node.lineno)
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names = ", ".join(alias.name for alias in node.names)
            flag(node, "import", f"imports {names}" + (f" from {node.module}" if getattr(node, "module", None)
                                                       else ""))
        elif isinstance(node, ast.Name):
            if _is_dunder(node.id):
                flag(node, "dunder", f"uses the dunder name {node.id}")
            elif node.id in BUILTINS and node.id not in own:
                flag(node, "builtin", f"uses {node.id}()")
            elif node.id in reach:
                flag(node, "reach", f"reaches {node.id}")
            elif node.id in imported and node.id not in handed and imported[node.id][0].split(".")[0] \
                    not in FREE_MODULES and node.id not in own:
                flag(node, "import", f"uses {node.id}, which the file imports itself")
        elif isinstance(node, ast.Attribute):
            if _is_dunder(node.attr):
                flag(node, "dunder", f"uses the dunder attribute .{node.attr}")
            elif node.attr in FRAME_ATTRIBUTES:
                flag(node, "frame", f"reaches into a frame (.{node.attr})")
            elif isinstance(node.value, ast.Name) and node.value.id in imported and imported[node.value.id][1] \
                    and node.value.id not in own:
                module = imported[node.value.id][0].split(".")[0]
                if module not in FREE_MODULES and node.attr not in FREE_ATTRIBUTES.get(module, ()):
                    flag(node, "module", f"reaches into the module {node.value.id} (.{node.attr})")
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and _is_dunder(node.name):
            flag(node, "dunder", f"defines the dunder name {node.name}")
        if isinstance(node, ast.Call):
            names = library.get(step, ())
            func = node.func
            if isinstance(func, ast.Name) and func.id in names and (func.id not in own or func.id in imported):
                flag(node, "library", f"calls the library's {func.id}()")
            elif isinstance(func, ast.Attribute) and func.attr in names:
                flag(node, "library", f"calls the library's {func.attr}() (as .{func.attr})")
    _outside(tree, lines, spans, starter, found, step_of)
    return sorted(found.values(), key=lambda breach: (breach.line, breach.rule, breach.step))


def _outside(tree, lines, spans, starter, found, step_of):
    """Flag edits outside the steps that can replace a step function (see the module docstring)."""
    steps_of = {}   # step function name -> its steps
    for index, node in enumerate(tree.body):
        if isinstance(node, ast.FunctionDef):
            end = tree.body[index + 1].lineno - 1 if index + 1 < len(tree.body) else len(lines)
            inside = [step for step, first, last in spans if node.lineno <= first <= end]
            if inside:
                steps_of.setdefault(node.name, []).extend(inside)
    if not steps_of:
        return
    every = sorted({step for steps in steps_of.values() for step in steps})
    handed = {line.strip() for line in (starter or "").splitlines()}

    def flag_all(node, steps, what):
        for step in steps:
            if (node.lineno, "outside", step) not in found:
                found[(node.lineno, "outside", step)] = Breach(step, node.lineno, "outside", what,
                                                               lines[node.lineno - 1].strip())

    handed_imports = set(_imports(ast.parse(starter))) if starter else set()
    imported = _imports(tree)
    seen_defs = set()
    for node in tree.body:
        if step_of(node.lineno) is not None:
            continue
        names = []
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            if node.name in steps_of and node.name not in seen_defs and isinstance(node, ast.FunctionDef) and \
                    any(node.lineno <= first for _, first, _ in spans):
                seen_defs.add(node.name)   # the handout's own def holding the step
                continue
            names = [node.name]
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names = [(alias.asname or alias.name).split(".")[0] for alias in node.names]
            module = (node.module or "") if isinstance(node, ast.ImportFrom) else node.names[0].name
            if lines[node.lineno - 1].strip() not in handed and module.split(".")[0] in CLOSED_MODULES and \
                    not set(names) <= handed_imports:
                flag_all(node, every, f"imports {module} outside the steps (it reaches the checker, the library "
                                      "or the interpreter)")
        elif isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign, ast.For, ast.With)):
            names = [n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)]
            targets = node.targets if isinstance(node, ast.Assign) else [getattr(node, "target", None)]
            for target in targets:
                base = target
                while isinstance(base, (ast.Attribute, ast.Subscript)):
                    base = base.value
                if target is not base and isinstance(base, ast.Name) and base.id in imported and \
                        lines[node.lineno - 1].strip() not in handed:
                    flag_all(node, every, f"changes the module {base.id} outside the steps")
        for name in names:
            if name in steps_of:
                flag_all(node, steps_of[name], f"binds {name} again outside the steps, in place of the one you "
                                                "write")
    for node in ast.walk(tree):
        line = getattr(node, "lineno", None)
        if line is None or step_of(line) is not None or lines[line - 1].strip() in handed:
            continue
        what = None
        if isinstance(node, ast.Name) and (node.id in BUILTINS or _is_dunder(node.id)) and node.id != "__name__":
            what = f"uses {node.id} outside the steps"
        elif isinstance(node, ast.Attribute) and (_is_dunder(node.attr) or node.attr in FRAME_ATTRIBUTES
                                                  or node.attr == "modules"):
            what = f"uses .{node.attr} outside the steps"
        if what:
            flag_all(node, every, what + " (code that can replace your functions)")


def describe(breach, advice=""):
    """The one-line message a step's check shows: "line 57 (step 2) calls the library's sat(): write ... yourself"."""
    tail = advice or f"write step {breach.step} with the lesson's own tools (the handout's names, math, your functions)"
    if breach.rule == "outside":
        return (f"line {breach.line} {breach.what} (`{breach.text}`): step {breach.step} is graded only as you "
                "write it inside its markers; keep the handout's code around the steps as it was.")
    return f"line {breach.line} (step {breach.step}) {breach.what} (`{breach.text}`): {tail}."


def scan_lab(source, lab_module):
    """scan() with the lab's own rules (its STEP_LIBRARY, STARTER and STEP_ADVICE), messages filled in."""
    starter = None
    path = getattr(lab_module, "STARTER", None)
    if path:
        try:
            with open(path, encoding="utf-8") as handle:
                starter = handle.read()
        except OSError:
            starter = None
    advice = getattr(lab_module, "STEP_ADVICE", {})
    return [Breach(b.step, b.line, b.rule, b.what, b.text, describe(b, advice.get(b.step, "")))
            for b in scan(source, getattr(lab_module, "STEP_LIBRARY", {}), starter)]
