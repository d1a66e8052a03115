"""The lab's rules for the code inside the step regions, checked in the grader from the source.

A step is the student's own work: it may use the names the handout gives,
the functions the student writes, and the pure standard-library modules of
FREE_MODULES (math, cmath, itertools, functools, operator, fractions,
statistics; imported at the top or inside the step), their public functions
and classes only (not `statistics.sys`, not operator.attrgetter or
functools.update_wrapper, which read attributes named by a string). The grader reads each step's
syntax tree (never running it) and flags what reaches around the exercise:

  import    an import inside a step, or a name the file imported itself (other than from FREE_MODULES), or a
            name the handout imports that the file binds again (`from lesson11.physics2d import sat as
            project`, `project = ...`, a `global project` in a function)
  dunder    a dunder name or attribute (__import__, __globals__, __class__, ...), also as a
            parameter, keyword or def name, or read by a match pattern (`case object(__globals__=g)`)
  builtin   exec, eval, compile, open, getattr, setattr, delattr, globals, vars, locals,
            __import__, breakpoint, input, memoryview, and type() with three arguments
  frame     a frame or traceback attribute (f_back, f_locals, gi_frame, tb_frame, ...)
  reach     World (or make_world and BulletWorld, which hand one out: `type(make_world(rng))`),
            the lab runtime (`lab`) or the panel (`LabPanel`), where the name is the module's (a step's
            own local `runtime` is not)
  module    a module other than FREE_MODULES, or an attribute of one (pygame.Vector2 aside); a free
            module's module-valued or string-named attribute; functools, operator, fractions or
            statistics as a value (their attributes reach further)
  format    a str.format / format_map template whose field reads an attribute or item (`"{0.gi_frame}"`,
            `"{0[k]}"`), or one that is not written out as a literal (it could be built to do so)
  keep      an attribute or item stored on (or deleted from) a module-level name (`Body.kept = sat`), or a
            module-level name declared `global`: state that outlives the call (a spliced function kept for
            the next step, a handout constant changed while the probes run)
  library   the library function the step asks the student to write (the lab's STEP_LIBRARY:
            {step: names}): called or taken by its imported name, or as an attribute
            (`world.sat(...)`, `f = Circle(r).inertia`, `case object(sat=f)`), unless the lab allows it
            (STEP_ALLOWED: {step: names})

A module-level name the file binds outside the steps to code that reaches what a
step may not (World, the runtime, the library, a module, a name the file imported or
rebound: `lesson_sat = World().sat`, a helper def calling one) is flagged, with that
rule, in the step that reads it.

A name counts as the file's own only where Python would find the file's own
binding (a parameter, a local, a module-level def or assignment): the scan
follows Python's scopes, so `def f(getattr=getattr)` still uses the builtin
(a default is read in the scope around the def) and a class attribute hides
nothing from the methods.

Outside the steps the code must be the handout's (handout_unchanged), but an
edit there could replace a step's function after the fact, so two things are
flagged under every step of the function they touch (rule "outside"): a
second top-level binding of a step function's name (`sat = other_sat`,
another `def sat`, an import as `sat`), and a line the handout does not have
that uses exec, eval, compile, globals, vars, setattr, getattr, __import__,
a dunder name or `sys.modules` (which can rebind any name). Under every step:
`from X import *` anywhere (it can rebind every name a step reads), an added
import of a closed module (the checker, the library, solutions, starters,
the interpreter's machinery; at the top or in a def; under a handout name too
unless it binds it exactly as the handout does) and an import of a module that
lies beside the submission (a .py file or package in its folder, which the
handout does not import). Lines a step region dedents to module level
(handout.module_level_starts) are read both as the step's code and as code
outside the steps.

These forbid reaching around the exercise, not ways of writing it: every
correct completion in the corpora passes (tests/test_step_rules.py).
"""
import ast
import importlib
import importlib.machinery
import inspect
import os
import re
from dataclasses import dataclass

from checker.reading.handout import (MarkerError, changed_statements, module_level_starts, reaching_fields,
                                     step_regions)
from checker.reading.source import SourceError, read as read_source, lines as split_lines

BUILTINS = frozenset({"exec", "eval", "compile", "open", "getattr", "setattr", "delattr", "globals", "vars",
                      "locals", "__import__", "breakpoint", "input", "memoryview"})
FRAME_ATTRIBUTES = frozenset({"f_back", "f_globals", "f_locals", "f_builtins", "f_code", "gi_frame", "gi_code",
                              "cr_frame", "ag_frame", "tb_frame", "tb_next", "func_globals"})
REACH = ("World", "lab", "LabPanel", "runtime", "panel", "make_world", "BulletWorld")
# pure standard-library modules a step may import and use (their public functions and classes: FREE_NAMES)
FREE_MODULES = frozenset({"math", "cmath", "itertools", "functools", "operator", "fractions", "statistics"})
BY_NAME = frozenset({"attrgetter", "methodcaller", "update_wrapper", "wraps"})   # getattr/setattr by a string
# modules a file may not import outside the steps either: they reach the checker, the library's answers,
# the interpreter's own machinery, files or other processes
# (and the lab's own module by its name in the child, and modules that import, run or read by a string or a path)
CLOSED_MODULES = frozenset({"checker", "lesson11", "solutions", "starters", "lab_under_test", "sys", "importlib",
                            "inspect", "gc", "ctypes", "builtins", "types", "json", "pickle", "marshal", "os",
                            "subprocess", "io", "runpy", "threading", "signal", "shutil", "pathlib", "socket",
                            "traceback", "faulthandler", "atexit", "pkgutil", "pydoc", "imp", "_imp", "zipimport",
                            "code", "codeop", "timeit", "cProfile", "profile", "pdb", "bdb", "trace", "doctest",
                            "unittest", "multiprocessing", "concurrent", "asyncio", "_thread", "linecache",
                            "tokenize", "codecs", "tempfile", "glob", "fileinput", "zipfile", "tarfile", "mmap",
                            "shelve", "dbm", "sqlite3", "copyreg", "platform", "pty", "site", "sysconfig", "posix",
                            "nt", "posixpath", "ntpath"})
FREE_ATTRIBUTES = {"pygame": frozenset({"Vector2", "math"})}   # and these attributes of these


def _public(name):
    """{attribute: value} of the free module `name` without its dunders."""
    return {k: v for k, v in vars(importlib.import_module(name)).items() if not _is_dunder(k)}


def _is_dunder(name):
    return len(name) > 4 and name.startswith("__") and name.endswith("__")


# a free module's attributes a step may use: public, not a module (statistics.sys), not reading by a string
FREE_NAMES = {name: frozenset(k for k, v in _public(name).items()
                              if not k.startswith("_") and not inspect.ismodule(v) and k not in BY_NAME)
              for name in FREE_MODULES}
# free modules that may be passed around as values: none of their attributes reaches further
VALUE_SAFE = frozenset(name for name in FREE_MODULES
                       if not any(inspect.ismodule(v) or k in BY_NAME for k, v in _public(name).items()))


def _free(dotted):
    """True for a free module (`cmath`) or one of its free names (`itertools.pairwise`), not `statistics.sys`."""
    module, _, attribute = dotted.partition(".")
    return module in FREE_MODULES and (not attribute or attribute in FREE_NAMES[module])


@dataclass(frozen=True)
class Breach:
    """One construct inside a step region that the rules forbid."""
    step: int        # the step region it is in
    line: int        # 1-based line in the file
    rule: str        # import, dunder, builtin, frame, reach, module, library
    what: str        # what it does, for a student: "calls the library's sat()"
    text: str        # the line, stripped
    message: str = ""   # the whole sentence the step's check shows (scan_lab fills it in)


def _binding(node, alias):
    """(name, (module it comes from, is it a module itself)) that one alias of an import binds; name None for `*`."""
    if isinstance(node, ast.Import):
        name = alias.asname or alias.name.split(".")[0]
        return name, (alias.name if alias.asname else alias.name.split(".")[0], True)
    if alias.name == "*":
        return None, ("", False)
    # `from lesson11 import runtime as lab`: a module; `from x.y import name`: a module if x.y is a
    # package whose attribute is lower case and known to be one (runtime, panel, draw, physics2d)
    is_module = alias.name in ("runtime", "panel", "draw", "physics2d", "math", "collision", "world")
    return alias.asname or alias.name, (f"{'.' * node.level}{node.module or ''}.{alias.name}", is_module)


def _imports(tree):
    """{bound name: (module it comes from, is it a module itself)} for the top-level imports of a tree."""
    return dict(_binding(node, alias) for node in tree.body if isinstance(node, (ast.Import, ast.ImportFrom))
                and (isinstance(node, ast.Import) or node.module) for alias in node.names if alias.name != "*")


def _module_imports(tree):
    """[(bound name, (module, is a module))] for every import that binds a module-level name: at the top, or
    inside a module-level if, try, with or loop (not in a def, lambda or class)."""
    found, todo = [], list(tree.body)
    while todo:
        node = todo.pop()
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            found += [b for b in (_binding(node, alias) for alias in node.names) if b[0] is not None]
        elif not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda, ast.expr)):
            todo += list(ast.iter_child_nodes(node))
    return found


class _Scope:
    """One Python scope while the file is read: its kind and the names bound or declared in it."""

    def __init__(self, kind, parent):
        self.kind, self.parent = kind, parent         # kind: module, function, class, comprehension
        self.bound, self.imported = set(), set()      # imported: names bound only by an import (module level)
        self.declared_global, self.declared_nonlocal = set(), set()


def _type_params(node):
    """A def's or class's type parameters (Python 3.12+), read here in the scope around it."""
    return list(getattr(node, "type_params", None) or [])


def _name_origins(tree):
    """({id(node): where}, the module-level names bound other than by an import).

    For every Name the file reads, where Python finds it: "local" (a parameter or local
    of an enclosing function, lambda or comprehension), "code" (a module-level def,
    class or assignment), "import" (a module-level import only) or "free" (bound
    nowhere in the file: a builtin). For every binding (a Name stored or deleted, a
    def, a class, an import alias in a function): "code" where it binds the module's
    name (at module level, or declared `global`), else "local". A class body's names
    hide nothing (its methods do not see them, and in the body itself a name may still
    be read before the class binds it). The walk keeps its own stack, so no depth of
    nesting that Python compiles can stop it.
    """
    module = _Scope("module", None)
    loads, binds = [], []              # (Name node read, its scope); (name bound, its scope, binding node or None)
    todo = [(statement, module) for statement in tree.body]

    def all_args(args):
        return [a for a in args.posonlyargs + args.args + args.kwonlyargs + [args.vararg, args.kwarg] if a]

    def outer_parts(node):
        """What a def, lambda or class reads in the scope around it: decorators, defaults, annotations, bases."""
        parts = list(getattr(node, "decorator_list", [])) + _type_params(node)
        if isinstance(node, ast.ClassDef):
            return parts + node.bases + node.keywords
        args = node.args
        parts += args.defaults + [d for d in args.kw_defaults if d is not None]
        parts += [a.annotation for a in all_args(args) if a.annotation is not None]
        return parts + ([node.returns] if getattr(node, "returns", None) else [])

    while todo:
        node, scope = todo.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            todo += [(part, scope) for part in outer_parts(node)]
            if not isinstance(node, ast.Lambda):
                binds.append((node.name, scope, node))
            inner = _Scope("class" if isinstance(node, ast.ClassDef) else "function", scope)
            if not isinstance(node, ast.ClassDef):
                inner.bound.update(a.arg for a in all_args(node.args))
            todo += [(part, inner) for part in (node.body if isinstance(node.body, list) else [node.body])]
        elif isinstance(node, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
            todo.append((node.generators[0].iter, scope))          # the first iterable is read outside
            inner = _Scope("comprehension", scope)
            for number, generator in enumerate(node.generators):
                todo += [(generator.target, inner)] + [(condition, inner) for condition in generator.ifs]
                if number:
                    todo.append((generator.iter, inner))
            parts = (node.key, node.value) if isinstance(node, ast.DictComp) else (node.elt,)
            todo += [(part, inner) for part in parts]
        elif isinstance(node, ast.NamedExpr):              # := binds outside a comprehension
            todo.append((node.value, scope))
            target = scope
            while target.kind == "comprehension":
                target = target.parent
            binds.append((node.target.id, target, node.target))
        elif isinstance(node, ast.Global):
            scope.declared_global.update(node.names)
        elif isinstance(node, ast.Nonlocal):
            scope.declared_nonlocal.update(node.names)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                name = (alias.asname or alias.name).split(".")[0]
                if scope is module:
                    scope.imported.add(name)
                else:                       # a `global` in the function makes it the module's
                    binds.append((name, scope, alias))
        elif isinstance(node, ast.Name):
            if isinstance(node.ctx, ast.Load):
                loads.append((node, scope))
            else:
                binds.append((node.id, scope, node))
        else:
            if isinstance(node, (ast.ExceptHandler, ast.MatchAs, ast.MatchStar)) and node.name:
                binds.append((node.name, scope, None))
            elif isinstance(node, ast.MatchMapping) and node.rest:
                binds.append((node.rest, scope, None))
            todo += [(child, scope) for child in ast.iter_child_nodes(node)]

    found = {}
    for name, scope, node in binds:     # after the walk: a `global x` anywhere in a function counts for all of it
        target = module if name in scope.declared_global else scope
        target.bound.add(name)
        if node is not None:
            found[id(node)] = "code" if target is module else "local"

    def origin(name, scope):
        while scope.kind != "module" and name not in scope.declared_global:
            if scope.kind != "class" and name in scope.bound and name not in scope.declared_nonlocal:
                return "local"
            scope = scope.parent
        if name in module.bound:
            return "code"
        return "import" if name in module.imported else "free"

    found.update({id(node): origin(node.id, scope) for node, scope in loads})
    return found, module.bound


def _free_aliases(tree):
    """{name: free module} for every `import M` / `import M as name` of a free module anywhere in the file."""
    return {alias.asname or alias.name: alias.name for node in ast.walk(tree) if isinstance(node, ast.Import)
            for alias in node.names if alias.name in FREE_MODULES}


def _step_import_is_free(node):
    """True for an import inside a step that brings only free modules or their free names."""
    if isinstance(node, ast.Import):
        return all(_free(alias.name) for alias in node.names)
    return not node.level and node.module in FREE_MODULES and all(_free(f"{node.module}.{alias.name}")
                                                                  for alias in node.names)


def _top_level_names(tree):
    """The names the file's top-level statements bind (defs, classes, assignments, imports): the handout's names."""
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names.update((alias.asname or alias.name).split(".")[0] for alias in node.names)
        elif isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names.update(n.id for target in targets for n in ast.walk(target) if isinstance(n, ast.Name))
    return names


def _bound_name(node):
    """The name a binding node binds: a Name's id, a def's or class's name, an import alias's name."""
    if isinstance(node, ast.alias):
        return (node.asname or node.name).split(".")[0]
    return getattr(node, "id", None) or node.name


def _kept(node, origins):
    """What an attribute or item store (or del) on a module-level name does (`Body.kept = sat`), or None.

    Such a store outlives the call: a step 2 that keeps the function it runs in on a handout class lets
    step 3 call the grader's spliced copy of it later.
    """
    if not isinstance(node, (ast.Attribute, ast.Subscript)) or isinstance(node.ctx, ast.Load):
        return None
    root = node.value
    while isinstance(root, (ast.Attribute, ast.Subscript)):
        root = root.value
    if not isinstance(root, ast.Name) or origins.get(id(root)) not in ("code", "import"):
        return None
    what = f".{node.attr}" if isinstance(node, ast.Attribute) else "an item"
    verb = "deletes" if isinstance(node.ctx, ast.Del) else "stores"
    return (f"{verb} {what} on the file's {root.id} (a step keeps nothing on the handout's names: it outlives the "
            "call)")


def _format_breach(node):
    """What a `.format` / `.format_map` attribute does wrong, or None (a literal template reading no attribute)."""
    template = node.value
    if not (isinstance(template, ast.Constant) and isinstance(template.value, str)):
        return (f"calls .{node.attr} on a template that is not written out (write the string itself, or use an "
                "f-string)")
    fields = reaching_fields(template.value)
    if fields:
        return (f"formats the field {{{fields[0]}}}, which reads an attribute or item named in a string (use an "
                "f-string)")
    return None


def scan(source, library=None, starter=None, reach=REACH, allowed=None, folder=None):
    """Every Breach inside the step regions of `source` (a lab file's text), in line order.

    library: {step: names of library functions the step asks the student to write}.
    starter: the handout's source; a name the file imports that the handout does not is the
    file's own import (rule "import" when a step uses it).
    allowed: {step: attribute names the step may use although they are in library[step]}.
    folder: the submission's folder; an import of a module that lies in it is flagged under every step.
    [] when the file does not parse (other checks say so); when its markers are broken or a step's are
    missing, a breach under every step they leave unmarked (the rules cannot find that step's code).
    """
    library, allowed = library or {}, allowed or {}
    try:
        tree = ast.parse(source)
        origins, module_bound = _name_origins(tree)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    lines = split_lines(source)
    try:
        regions = step_regions(lines)
    except MarkerError as exc:
        return _unmarked(starter, lines, {}, exc.line or 0, f"breaks the step markers ({exc})")
    unmarked = _unmarked(starter, lines, regions, 0, "")
    if unmarked:
        return unmarked
    spans = [(step, start + 1, end + 1) for step, (start, end, _) in regions.items()]

    def step_of(line):
        return next((step for step, first, last in spans if first < line < last), None)

    # a region's lines dedented to module level (and all after them up to its end marker) end the step's
    # function: the rules read them as step code and as code outside the steps
    module_lines = {line for step, first in module_level_starts(source, regions).items()
                    for line in range(first, regions[step][1] + 1)}

    def in_step(line):
        return step_of(line) is not None and line not in module_lines

    bindings = _module_imports(tree)
    imported = {}
    for name, binding in reversed(bindings):    # the last binding, or one that is not free
        if name not in imported or not _free(binding[0]):
            imported[name] = binding
    handout_imports, rebound = dict(imported), set()
    if starter:
        # a handout name is the handout's only while the file binds it only as the handout does
        handout_tree = ast.parse(starter)
        handout_imports, handout_bindings = _imports(handout_tree), set(_module_imports(handout_tree))
        handout_bound = _name_origins(handout_tree)[1]
        rebound = {name for name in handout_imports if name in module_bound - handout_bound
                   or any(n == name and (n, b) not in handout_bindings for n, b in bindings)}
    handed = set(handout_imports) - rebound
    aliases = _free_aliases(tree)
    found = {}
    called = {id(node.func) for node in ast.walk(tree) if isinstance(node, ast.Call)}
    attribute_bases = {id(node.value) for node in ast.walk(tree) if isinstance(node, ast.Attribute)}

    def flag(node, rule, what):
        line = node.lineno
        step = step_of(line)
        if step is not None and (line, rule, step) not in found:
            found[(line, rule, step)] = Breach(step, line, rule, what, lines[line - 1].strip())

    def reaching(node):
        """(rule, the library name or None, what) when `node`, outside the steps, reaches what a step may not
        (World, the lab runtime, the library, a module, a name imported by the file or rebound), else None."""
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
            where = origins.get(id(node), "free")
            binding = imported.get(node.id, ("", False))
            if node.id in reach and where != "local":
                return "reach", None, f"reaches {node.id}"
            if node.id in every_library and where in ("import", "free"):
                return "library", node.id, f"uses the library's {node.id}"
            if node.id in rebound and where in ("code", "import"):
                return "import", None, f"uses {node.id}, which the file binds again (the handout imports it)"
            if where == "import" and node.id not in handed and not _free(binding[0]):
                return "import", None, f"uses {node.id}, which the file imports itself"
            if where == "import" and binding[1] and id(node) not in attribute_bases \
                    and binding[0].split(".")[0] not in VALUE_SAFE:
                return "module", None, f"uses the module {node.id} itself"
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load):
            if node.attr in every_library:
                return "library", node.attr, f"uses the library's {node.attr} (as .{node.attr})"
            base = node.value.id if isinstance(node.value, ast.Name) else None
            if origins.get(id(node.value)) == "import" and imported.get(base, ("", False))[1]:
                module = imported[base][0]
                if module in FREE_MODULES and node.attr not in FREE_NAMES[module] or \
                        module not in FREE_MODULES and node.attr not in FREE_ATTRIBUTES.get(module.split(".")[0], ()):
                    return "module", None, f"reaches into the module {base} (.{node.attr})"
        elif isinstance(node, (ast.Import, ast.ImportFrom)) and not _step_import_is_free(node):
            return "import", None, f"imports {', '.join(alias.name for alias in node.names)}"
        return None

    # names the file binds at module level outside the steps to code that reaches what a step may not: a step
    # that reads one reaches it too (`lesson_sat = World().sat`, a helper def calling the library). Each
    # top-level statement once: what its own lines reach (if it is not the handout's, or where it reads a
    # rebound name), the names it binds, the module-level names it reads; then reaching spreads along reads.
    every_library = {name for names in library.values() for name in names}
    try:
        changed = changed_statements(source, starter) if starter else set()
    except (ValueError, RecursionError, MemoryError):   # too deep to compare: every statement counts as changed
        changed = None
    changed = {node.lineno for node in tree.body} if changed is None else changed
    statement_hits, binds_of, readers = [], [], {}
    for index, statement in enumerate(tree.body):
        hits = {}
        for node in ast.walk(statement):
            line = getattr(node, "lineno", None)
            if line is None or in_step(line):
                continue
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and origins.get(id(node)) == "code":
                readers.setdefault(node.id, set()).add(index)
            hit = reaching(node)
            if hit and (statement.lineno in changed or isinstance(node, ast.Name) and node.id in rebound):
                hits.setdefault(hit[:2], hit[2])          # one of each (rule, library name): a bounded set
        statement_hits.append(hits)
        binds_of.append({_bound_name(n) for n in ast.walk(statement) if origins.get(id(n)) == "code"} - rebound)
    tainted = {}    # name -> {(rule, library name): what}
    queue = [index for index, hits in enumerate(statement_hits) if hits]
    while queue:
        index = queue.pop()
        for name in binds_of[index]:
            new = {key: what for key, what in statement_hits[index].items() if key not in tainted.get(name, {})}
            if new:
                tainted.setdefault(name, {}).update(new)
                for reader in readers.get(name, ()):
                    if not new.keys() <= statement_hits[reader].keys():
                        statement_hits[reader] = {**new, **statement_hits[reader]}
                        queue.append(reader)

    def taint_in(name, step):
        """(rule, what) of what `name` reaches that step `step` may not use, or None."""
        order = {"reach": 0, "library": 1, "import": 2, "module": 3}
        for (rule, used), what in sorted(tainted.get(name, {}).items(), key=lambda item: order[item[0][0]]):
            if rule != "library" or used in library.get(step, ()) and used not in allowed.get(step, ()):
                return rule, what
        return None

    top = _top_level_names(tree)
    for node in ast.walk(tree):
        if getattr(node, "lineno", None) is None or step_of(node.lineno) is None:
            continue
        step = step_of(node.lineno)
        names = library.get(step, ())
        kept = _kept(node, origins)
        if kept:
            flag(node, "keep", kept)
        if isinstance(node, ast.Global) and set(node.names) & top:
            flag(node, "keep", f"declares the file's {sorted(set(node.names) & top)[0]} global (a step reads the "
                               "handout's names, it never rebinds them)")
        if isinstance(node, (ast.Import, ast.ImportFrom)) and not _step_import_is_free(node):
            listed = ", ".join(alias.name for alias in node.names)
            flag(node, "import", f"imports {listed}" + (f" from {node.module}" if getattr(node, "module", None)
                                                        else ""))
        elif isinstance(node, ast.Name):
            # where Python finds a name read here (one the walk missed counts as a builtin); None: bound here
            where = origins.get(id(node), "free") if isinstance(node.ctx, ast.Load) else None
            if _is_dunder(node.id):
                flag(node, "dunder", f"uses the dunder name {node.id}")
            elif node.id in reach and (where or origins.get(id(node), "code")) != "local":   # a local is the step's
                flag(node, "reach", f"reaches {node.id}")
            elif node.id in BUILTINS and where == "free":
                flag(node, "builtin", f"uses {node.id}()")
            elif node.id in names and where in ("import", "free") and (where == "import" or id(node) in called):
                flag(node, "library", f"calls the library's {node.id}()" if id(node) in called
                     else f"uses the library's {node.id}")
            elif where == "import" and imported.get(node.id, ("", False))[1] and id(node) not in attribute_bases \
                    and imported[node.id][0].split(".")[0] not in VALUE_SAFE:
                flag(node, "module", f"uses the module {node.id} itself")
            elif where == "local" and node.id in aliases and aliases[node.id] not in VALUE_SAFE \
                    and id(node) not in attribute_bases:
                flag(node, "module", f"uses the module {node.id} itself")
            elif node.id in rebound and where in ("code", "import"):
                flag(node, "import", f"uses {node.id}, which the file binds again (the handout imports it)")
            elif where == "code" and taint_in(node.id, step):
                rule, what = taint_in(node.id, step)
                flag(node, rule, f"uses {node.id}, bound outside the steps where it {what}")
            elif where == "import" and node.id in imported and node.id not in handed \
                    and not _free(imported[node.id][0]):
                flag(node, "import", f"uses {node.id}, which the file imports itself")
        elif isinstance(node, ast.Attribute):
            if _is_dunder(node.attr):
                flag(node, "dunder", f"uses the dunder attribute .{node.attr}")
            elif node.attr in FRAME_ATTRIBUTES:
                flag(node, "frame", f"reaches into a frame (.{node.attr})")
            elif node.attr in names and isinstance(node.ctx, ast.Load) and node.attr not in allowed.get(step, ()):
                flag(node, "library", f"calls the library's {node.attr}() (as .{node.attr})" if id(node) in called
                     else f"uses the library's {node.attr} (as .{node.attr})")
            if node.attr in ("format", "format_map") and _format_breach(node):
                flag(node, "format", _format_breach(node))
            base = node.value.id if isinstance(node.value, ast.Name) else None
            where = origins.get(id(node.value))
            if where == "import" and imported.get(base, ("", False))[1]:
                module = imported[base][0]
                top = module.split(".")[0]
                if module in FREE_MODULES and node.attr not in FREE_NAMES[module] or \
                        module not in FREE_MODULES and node.attr not in FREE_ATTRIBUTES.get(top, ()):
                    flag(node, "module", f"reaches into the module {base} (.{node.attr})")
            elif where == "local" and base in aliases and node.attr not in FREE_NAMES[aliases[base]]:
                flag(node, "module", f"reaches into the module {base} (.{node.attr})")
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and _is_dunder(node.name):
            flag(node, "dunder", f"defines the dunder name {node.name}")
        elif isinstance(node, (ast.arg, ast.keyword)) and node.arg and _is_dunder(node.arg):
            flag(node, "dunder", f"uses the dunder name {node.arg}")
        elif isinstance(node, ast.MatchClass):     # `case object(__globals__=g)` reads g = x.__globals__
            for attr in node.kwd_attrs:
                if _is_dunder(attr):
                    flag(node, "dunder", f"reads the dunder attribute .{attr} through a match pattern")
                elif attr in FRAME_ATTRIBUTES:
                    flag(node, "frame", f"reaches into a frame (.{attr}) through a match pattern")
                elif attr in names and attr not in allowed.get(step, ()):
                    flag(node, "library", f"uses the library's {attr} (as .{attr}, through a match pattern)")
                elif attr in ("format", "format_map"):
                    flag(node, "format", f"takes .{attr} through a match pattern (write the template itself)")
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "type" \
                and origins.get(id(node.func)) == "free" and len(node.args) + len(node.keywords) >= 3:
            flag(node, "builtin", "uses type() with three arguments (it makes a class)")
    _outside(tree, lines, spans, starter, found, in_step, folder)
    return sorted(found.values(), key=lambda breach: (breach.line, breach.rule, breach.step))


def _beside(folder):
    """Names a module beside the submission would be imported as: NAME.py (.pyc, .so, ...) and NAME/ in `folder`."""
    try:
        entries = os.listdir(folder)
    except (OSError, TypeError, ValueError):
        return set()
    suffixes = sorted(importlib.machinery.all_suffixes(), key=len, reverse=True)
    names = set()
    for entry in entries:
        if os.path.isdir(os.path.join(folder, entry)):
            names.add(entry)
        else:
            names.update(entry[:-len(suffix)] for suffix in suffixes if entry.endswith(suffix))
    return names


def _unmarked(starter, lines, regions, line, what):
    """A Breach (rule "outside") under each of the handout's steps that `regions` lacks: code the rules cannot
    find cannot be graded as the step. [] without a starter (no steps known) or when every step is marked."""
    try:
        wanted = sorted(step_regions(split_lines(starter))) if starter else []
    except MarkerError:
        return []
    text = lines[line - 1].strip() if 0 < line <= len(lines) else ""
    return [Breach(step, line, "outside", what or f"the file has no markers for step {step} (keep `# --- step "
                                                  f"{step}: ... ---` and `# --- end of step {step} ---` from the "
                                                  "handout)", text) for step in wanted if step not in regions]


def _outside(tree, lines, spans, starter, found, in_step, folder=None):
    """Flag edits outside the steps that can replace a step function (see the module docstring).

    in_step(line): True for a line of a step's own code (not one a region dedents to module level)."""
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
    handed = {line.strip() for line in split_lines(starter or "")}

    def flag_all(node, steps, what):
        for step in steps:
            if (node.lineno, "outside", step) not in found:
                found[(node.lineno, "outside", step)] = Breach(step, node.lineno, "outside", what,
                                                               lines[node.lineno - 1].strip())

    handout_imports = _imports(ast.parse(starter)) if starter else {}
    handed_modules = {module.split(".")[0] for module, _ in handout_imports.values()}
    imported = _imports(tree)
    beside = _beside(folder) if folder else set()
    for node in ast.walk(tree):   # anywhere in the file, inside a step too
        if not isinstance(node, (ast.Import, ast.ImportFrom)) or lines[node.lineno - 1].strip() in handed:
            continue
        modules = [alias.name for alias in node.names] if isinstance(node, ast.Import) else [node.module or ""]
        if isinstance(node, ast.ImportFrom) and any(alias.name == "*" for alias in node.names):
            flag_all(node, every, f"imports every name of {node.module} (`import *` can replace any name a step "
                                  "reads)")
        side = [m for m in modules if m.split(".")[0] in beside and m.split(".")[0] not in handed_modules]
        if side or folder and getattr(node, "level", 0):
            flag_all(node, every, f"imports {side[0] if side else 'a module'} from the submission's own folder (a "
                                  "module beside the lab file is not graded and may change what a step does)")
        # a closed module, at the top or in a def: only a name bound exactly as the handout's import binds it
        closed = [m for m in modules if m.split(".")[0] in CLOSED_MODULES]
        if closed and not in_step(node.lineno) and \
                any(handout_imports.get(name) != binding for name, binding in
                    (_binding(node, alias) for alias in node.names)):
            flag_all(node, every, f"imports {closed[0]} outside the steps (it reaches the checker, the library "
                                  "or the interpreter)")
    seen_defs = set()
    for node in tree.body:
        if in_step(node.lineno):
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
        if line is None or in_step(line) or lines[line - 1].strip() in handed:
            continue
        what = None
        if isinstance(node, ast.Name) and (node.id in BUILTINS or _is_dunder(node.id)) and node.id != "__name__":
            what = f"uses {node.id} outside the steps"
        elif isinstance(node, ast.Attribute) and (_is_dunder(node.attr) or node.attr in FRAME_ATTRIBUTES
                                                  or node.attr == "modules"):
            what = f"uses .{node.attr} outside the steps"
        elif isinstance(node, ast.MatchClass) and any(_is_dunder(attr) or attr in FRAME_ATTRIBUTES
                                                      or attr == "modules" for attr in node.kwd_attrs):
            what = "reads an attribute through a match pattern outside the steps"
        elif isinstance(node, ast.Attribute) and node.attr in ("format", "format_map") and _format_breach(node) \
                and not _format_breach(node).startswith("formats the field"):
            what = f"calls .{node.attr} on a template that is not written out, outside the steps"
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and any(
                _is_dunder(name) or name in FRAME_ATTRIBUTES or name == "modules"
                for field in reaching_fields(node.value) for name in re.findall(r"\.(\w+)", field)):
            what = "formats a field that reads a frame, dunder or module attribute outside the steps"
        if what:
            flag_all(node, every, what + " (code that can replace your functions)")


def describe(breach, advice=""):
    """The one-line message a step's check shows: "line 57 (step 2) calls the library's sat(): write ... yourself"."""
    tail = advice or f"write step {breach.step} with the lesson's own tools (the handout's names, math, your functions)"
    if breach.rule == "outside":   # line 0: no line to name (a step's markers are missing)
        where = (f"line {breach.line} " if breach.line else "") + breach.what + \
            (f" (`{breach.text}`)" if breach.text else "")
        return (f"{where}: step {breach.step} is graded only as you write it inside its markers; keep the "
                "handout's code around the steps as it was.")
    return f"line {breach.line} (step {breach.step}) {breach.what} (`{breach.text}`): {tail}."


def scan_lab(source, lab, path=None):
    """scan() with the lab's own rules (its module's STEP_LIBRARY, STEP_ALLOWED and STEP_ADVICE, its starter),
    messages filled in.

    lab: a checker.labs.Lab. path: the submission's own path (the modules beside it are flagged when imported),
    None when unknown.
    """
    lab_module = lab.module
    try:
        starter = read_source(lab.starter)
    except (OSError, SourceError):
        starter = None
    advice = getattr(lab_module, "STEP_ADVICE", {})
    return [Breach(b.step, b.line, b.rule, b.what, b.text, describe(b, advice.get(b.step, "")))
            for b in scan(source, getattr(lab_module, "STEP_LIBRARY", {}), starter,
                          allowed=getattr(lab_module, "STEP_ALLOWED", {}),
                          folder=os.path.dirname(os.path.abspath(path)) if path else None)]
