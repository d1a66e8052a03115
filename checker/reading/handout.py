"""The handed-out parts stay handed out: compare a submission with its starter outside the step regions.

A lab's starter marks what the student writes with lines

    # --- step N: what to do ---
    ...the student's code...
    # --- end of step N ---

`compare(submission, starter)` replaces the inside of every step region with a
placeholder statement (but for lines a region dedents to module level: code
outside the steps), parses both files and compares their syntax trees, so
formatting, comments, blank lines and docstrings do not matter but any change
to the code the student was handed does (gravity, a constant, the scene, the
World's settings, the lab-runtime lines, the final print); an added print(...)
that calls nothing (a debug print) is a warning instead. Top-level imports
the student added that bind new names are allowed (they change nothing the
handout runs) and listed.

It returns a Comparison: `same` (bool), `problems` (one line each, naming the
submission's line and, where there is one, the handout's), `added_imports` and
`warnings` (the debug prints added).
"""
import ast
import difflib
import functools
import io
import re
import string
import tokenize
from dataclasses import dataclass, field

from checker.reading.source import lines as split_lines

START = re.compile(r"^(?P<indent>[ \t]*)# --- step (?P<step>\d+)\b.*---\s*$")
END = re.compile(r"^[ \t]*# --- end of step (?P<step>\d+) ---\s*$")
MAX_PROBLEMS = 4


class MarkerError(ValueError):
    """The step markers are missing, repeated or out of order; `line`: the 1-based line where it shows, if known."""

    def __init__(self, message, line=None):
        super().__init__(message)
        self.line = line


@dataclass
class Comparison:
    """The outcome of comparing a submission with its handout outside the steps."""
    same: bool
    problems: list = field(default_factory=list)
    added_imports: list = field(default_factory=list)
    warnings: list = field(default_factory=list)   # debug prints added outside the steps (allowed)


HARMLESS_CALLS = frozenset({"str", "repr", "format", "len", "round", "abs", "int", "float", "type"})
PRINT_KEYWORDS = frozenset({"sep", "end", "flush"})   # not file=: printing goes to the output, nowhere else


def reaching_fields(template):
    """The replacement fields of a str.format template that read an attribute or an item: ["0.gi_frame", "0[k]"].

    Such a field reads attributes named in a string, where no rule on the syntax tree sees them.
    A template str.format would reject is [] (it reads nothing).
    """
    try:
        parsed = list(string.Formatter().parse(template))
    except ValueError:
        return []
    found = []
    for _, name, spec, _ in parsed:
        if name and ("." in name or "[" in name):
            found.append(name)
        if spec:
            found += reaching_fields(spec)     # a nested field: "{0:{1.x}}"
    return found


def _harmless_call(call):
    """str(), repr(), format(), len(), round(), abs(), int(), float(), type(), or "...".format(...) whose
    fields read no attribute or item."""
    func = call.func
    if isinstance(func, ast.Name):
        return func.id in HARMLESS_CALLS
    return isinstance(func, ast.Attribute) and func.attr == "format" and isinstance(func.value, ast.Constant) \
        and isinstance(func.value.value, str) and not reaching_fields(func.value.value)


def is_debug_print(node):
    """True for a statement that only prints: print(...) whose arguments call nothing but the harmless
    calls above (f-strings are fine; reading attributes is fine) and whose keywords are sep, end or flush."""
    if not (isinstance(node, ast.Expr) and isinstance(node.value, ast.Call)
            and isinstance(node.value.func, ast.Name) and node.value.func.id == "print"):
        return False
    if any(keyword.arg not in PRINT_KEYWORDS for keyword in node.value.keywords):
        return False
    for part in ast.walk(node.value):
        if part is node.value:
            continue
        if isinstance(part, ast.Call) and not _harmless_call(part):
            return False
        if isinstance(part, (ast.NamedExpr, ast.Lambda, ast.Await, ast.Yield, ast.YieldFrom)):
            return False
    return True


@functools.lru_cache(maxsize=32)
def _comment_lines(text):
    """The 1-based lines of `text` on which a comment starts, as Python's tokenizer reads them; None when the
    text does not tokenize (the checks that compile it say so)."""
    try:
        return frozenset(token.start[0] for token in tokenize.generate_tokens(io.StringIO(text).readline)
                         if token.type == tokenize.COMMENT)
    except (tokenize.TokenError, SyntaxError, ValueError, RecursionError, MemoryError):
        return None


def step_regions(lines):
    """{step: (start line index, end line index, indent)} of the marked regions (0-based marker lines).

    `lines`: the file's lines as Python counts them (checker/reading/source.py lines()), never str.splitlines().
    A marker counts only as the comment it looks like: one inside a string literal is a MarkerError.
    """
    regions, open_step = {}, None
    comments = _comment_lines("".join(line.rstrip("\r\n") + "\n" for line in lines))   # lines may keep their ends
    for index, line in enumerate(lines):
        start, end = START.match(line), END.match(line)
        if (start or end) and comments is not None and index + 1 not in comments:
            raise MarkerError(f"line {index + 1} looks like a step marker but is inside a string, not a comment",
                              index + 1)
        if start:
            step = int(start.group("step"))
            if open_step is not None:
                raise MarkerError(f"step {open_step}'s region has no `# --- end of step {open_step} ---` line "
                                  f"before step {step} starts (line {index + 1})", index + 1)
            if step in regions:
                raise MarkerError(f"the `# --- step {step}` marker appears twice (line {index + 1})", index + 1)
            open_step = step
            regions[step] = [index, None, start.group("indent")]
        elif end:
            step = int(end.group("step"))
            if open_step != step:
                raise MarkerError(f"line {index + 1} ends step {step}, but step {step} was not started "
                                  "just before it", index + 1)
            regions[step][1] = index
            open_step = None
    if open_step is not None:
        raise MarkerError(f"step {open_step}'s region has no `# --- end of step {open_step} ---` line",
                          regions[open_step][0] + 1)
    return {step: tuple(region) for step, region in regions.items()}


def module_level_starts(source, regions):
    """{step: 1-based line} of the first top-level statement that begins inside an indented step region.

    A line dedented to column 0 in a region inside a function ends that function: it and every line after it
    up to the end marker run at module level, so they are code outside the steps, not the step. {} when the
    source does not parse (other checks say so).
    """
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return {}
    starts = [min([node.lineno] + [d.lineno for d in getattr(node, "decorator_list", [])]) for node in tree.body]
    found = {}
    for step, (start, end, indent) in regions.items():
        inside = [line for line in starts if start + 1 < line < end + 1]
        if indent and inside:
            found[step] = min(inside)
    return found


def blank_steps(source):
    """The source with each step region's inside replaced by one placeholder line `__step_N__`.

    Code a region dedents to module level (module_level_starts) is kept after the placeholder: it is
    code outside the steps. Line numbers outside the regions shift; returns (text, line map) where the
    map takes a line of the new text (1-based) to the line of `source`.
    """
    lines = split_lines(source)
    regions = step_regions(lines)
    outside = module_level_starts(source, regions)
    out, origin = [], []
    skip_until = -1
    starts = {start: (step, end, indent) for step, (start, end, indent) in regions.items()}
    for index, line in enumerate(lines):
        if index <= skip_until:
            continue
        out.append(line)
        origin.append(index + 1)
        if index in starts:
            step, end, indent = starts[index]
            out.append(f"{indent}__step_{step}__")
            origin.append(index + 2)
            for kept in range(outside.get(step, end + 1) - 1, end + 1):   # module-level lines, then the end marker
                out.append(lines[kept])
                origin.append(kept + 1)
            skip_until = end
    return "\n".join(out) + "\n", origin, sorted(regions)


def _is_string_statement(node):
    return isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str)


def _strip_docstrings(tree):
    """Drop docstrings and other bare string statements: like comments, they change nothing that runs."""
    for node in ast.walk(tree):
        for name in BODIES:
            body = getattr(node, name, None)
            if isinstance(body, list) and any(_is_string_statement(n) for n in body):
                setattr(node, name, [n for n in body if not _is_string_statement(n)] or [ast.Pass()])
    return tree


def _bound_names(node):
    return [(alias.asname or alias.name).split(".")[0] for alias in node.names]


def _top_level_names(tree):
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            names.update(_bound_names(node))
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
            for target in getattr(node, "targets", [getattr(node, "target", None)]):
                for name in ast.walk(target):
                    if isinstance(name, ast.Name):
                        names.add(name.id)
    return names


def _parse(source, what):
    try:
        text, origin, steps = blank_steps(source)
    except MarkerError as exc:
        raise MarkerError(f"{what}: {exc}") from None
    try:
        tree = ast.parse(text)
    except SyntaxError as exc:
        line = origin[exc.lineno - 1] if exc.lineno and 0 < exc.lineno <= len(origin) else exc.lineno
        raise MarkerError(f"{what}: cannot be read as Python outside the steps (line {line}: {exc.msg})") from None
    return _strip_docstrings(tree), origin, steps


def _dump(node):
    return ast.dump(node, annotate_fields=True, include_attributes=False)


def _text(lines, lineno, width=70):
    if lineno and 0 < lineno <= len(lines):
        text = lines[lineno - 1].strip()
        return text if width is None or len(text) <= width else text[:width - 3] + "..."
    return ""


def _around_difference(mine, theirs, width=70):
    """Both lines cut to `width` characters around where they first differ."""
    if len(mine) <= width and len(theirs) <= width:
        return mine, theirs
    same = 0
    while same < min(len(mine), len(theirs)) and mine[same] == theirs[same]:
        same += 1
    start = max(0, same - 25)

    def cut(text):
        piece = text[start:start + width]
        return ("..." if start else "") + piece + ("..." if start + width < len(text) else "")
    return cut(mine), cut(theirs)


BODIES = ("body", "orelse", "finalbody", "handlers")


def _diff(mine, theirs, out):
    """Append (submission node or None, handout node or None) for each differing statement, recursing
    into compound statements that match in kind."""
    a = [_dump(n) for n in mine]
    b = [_dump(n) for n in theirs]
    for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        if tag == "equal":
            continue
        if tag == "replace" and i2 - i1 == j2 - j1:
            for x, y in zip(mine[i1:i2], theirs[j1:j2]):
                if type(x) is type(y) and any(getattr(x, f, None) for f in BODIES) \
                        and _dump(_header(x)) == _dump(_header(y)):
                    for f in BODIES:
                        _diff(getattr(x, f, []) or [], getattr(y, f, []) or [], out)
                else:
                    out.append((x, y))
            continue
        for x in mine[i1:i2]:
            out.append((x, None))
        for y in theirs[j1:j2]:
            out.append((None, y))


def _code_part(text):
    """A line without its comment (roughly: from the first #) and its spaces, to tell a changed line from a
    changed comment or a reformatted one."""
    return "".join(text.split("#", 1)[0].split())


def _differing_lines(x, y, my_origin, their_origin, sub_lines, start_lines):
    """(submission line, handout line) of the first line where statements x and y (the submission's and the
    handout's, each spanning lines) differ, so a message quotes the edited line, not the statement's first.

    Lines are compared without their comments first, then as written; where no line differs (the same
    lines, re-wrapped), the statements' first lines. Only the lines before a step region inside the
    statement are compared (the step's code is the student's).
    """
    def span(node, origin, lines):
        found = []
        for i in range(node.lineno, min(node.end_lineno or node.lineno, len(origin)) + 1):
            if found and (origin[i - 1] != found[-1] + 1 or START.match(lines[found[-1] - 1])):
                break
            found.append(origin[i - 1])
        return found
    mine, theirs = span(x, my_origin, sub_lines), span(y, their_origin, start_lines)
    for key in (_code_part, str):
        for k in range(max(len(mine), len(theirs))):
            m, t = mine[min(k, len(mine) - 1)], theirs[min(k, len(theirs) - 1)]
            if key(_text(sub_lines, m, None)) != key(_text(start_lines, t, None)):
                return m, t
    return mine[0], theirs[0]


def _header(node):
    """The statement without its bodies (to tell an edited `if` line from an edit inside it)."""
    return type(node)(**{f: getattr(node, f) for f in node._fields if f not in BODIES})


def compare(submission, starter, submission_name="the file", starter_name="the handout"):
    """Compare `submission` (source text) with `starter` outside the step regions; returns a Comparison.

    Raises MarkerError (one line) when the submission's step markers are missing or broken or it
    cannot be parsed.
    """
    theirs, their_origin, their_steps = _parse(starter, starter_name)
    mine, my_origin, my_steps = _parse(submission, submission_name)
    if my_steps != their_steps:
        missing = [s for s in their_steps if s not in my_steps]
        if missing:
            raise MarkerError(f"{submission_name}: the marker lines of step {missing[0]} are missing: keep "
                              f"`# --- step {missing[0]}: ... ---` and `# --- end of step {missing[0]} ---` "
                              "from the handout and write your code between them")
        extra = [s for s in my_steps if s not in their_steps]
        raise MarkerError(f"{submission_name}: it marks a step {extra[0]} that the handout does not have")
    known = _top_level_names(theirs)
    added = []
    kept = []
    for node in mine.body:
        if isinstance(node, (ast.Import, ast.ImportFrom)) and not set(_bound_names(node)) & known \
                and _dump(node) not in {_dump(n) for n in theirs.body}:
            added.append(f"line {my_origin[node.lineno - 1]}: {ast.unparse(node)}")
        else:
            kept.append(node)
    mine.body = kept
    if _dump(mine) == _dump(theirs):
        return Comparison(True, [], added)
    sub_lines, start_lines = split_lines(submission), split_lines(starter)
    differences = []
    _diff(mine.body, theirs.body, differences)
    problems, warnings = [], []
    for x, y in differences:
        if x is not None and y is None and is_debug_print(x):
            line = my_origin[x.lineno - 1]
            warnings.append(f"line {line}: `{_text(sub_lines, line)}` added outside the steps (a debug print is "
                            "allowed; remove it before you hand in)")
            continue
        line = my_origin[x.lineno - 1] if x is not None else None
        hand = their_origin[y.lineno - 1] if y is not None else None
        if x is not None and y is not None:
            line, hand = _differing_lines(x, y, my_origin, their_origin, sub_lines, start_lines)
            mine_text, their_text = _around_difference(_text(sub_lines, line, None), _text(start_lines, hand, None))
            problems.append(f"line {line} `{mine_text}` (the handout has `{their_text}`)")
        elif x is not None:
            problems.append(f"line {line} `{_text(sub_lines, line)}` was added")
        else:
            problems.append(f"the handout's line `{_text(start_lines, hand)}` was removed")
    if not problems and warnings:
        return Comparison(True, [], added, warnings)
    if not problems:
        problems.append("the code outside the steps differs from the handout")
    return Comparison(False, problems, added, warnings)


def changed_statements(submission, starter):
    """The 1-based lines of `submission` where a top-level statement starts that is none of the handout's (the
    steps blanked, docstrings dropped): code added or edited outside the steps. None when either cannot be read."""
    try:
        theirs, _, _ = _parse(starter, "the handout")
        mine, origin, _ = _parse(submission, "the file")
    except MarkerError:
        return None
    known = {_dump(node) for node in theirs.body}
    return {origin[node.lineno - 1] for node in mine.body if _dump(node) not in known}


@dataclass
class ConstantEdit:
    """A top-level `NAME = value` the submission changed: its line, the handout's line, the names it binds."""
    line: int
    handout_line: int
    names: tuple
    problem: str


def _assigned_names(node):
    targets = node.targets if isinstance(node, ast.Assign) else [node.target]
    return tuple(sorted({n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}))


def constant_edits(submission, starter):
    """[ConstantEdit] when the only differences outside the steps are changed values of top-level constants (a
    one-line `NAME = value`, or `NAME: type = value`, in the handout's place, binding the same names, on one line
    in both files); None when there is any other difference, or none at all (compare() then says what it is)."""
    try:
        theirs, their_origin, their_steps = _parse(starter, "the handout")
        mine, my_origin, my_steps = _parse(submission, "the file")
    except MarkerError:
        return None
    known = _top_level_names(theirs)
    body = [node for node in mine.body if not (isinstance(node, (ast.Import, ast.ImportFrom))
                                               and not set(_bound_names(node)) & known)]
    if my_steps != their_steps or len(body) != len(theirs.body):
        return None
    sub_lines, start_lines = split_lines(submission), split_lines(starter)
    edits = []
    for x, y in zip(body, theirs.body):
        if _dump(x) == _dump(y):
            continue
        if not (type(x) is type(y) and isinstance(x, (ast.Assign, ast.AnnAssign)) and x.value is not None
                and y.value is not None and _assigned_names(x) == _assigned_names(y)
                and _dump(_header_of_assign(x)) == _dump(_header_of_assign(y))):
            return None
        line, hand = my_origin[x.lineno - 1], their_origin[y.lineno - 1]
        if my_origin[x.end_lineno - 1] != line or their_origin[y.end_lineno - 1] != hand:
            return None   # over several lines: not replaced line for line
        edits.append(ConstantEdit(line, hand, _assigned_names(x),
                                  f"line {line} `{_text(sub_lines, line)}` (the handout has "
                                  f"`{_text(start_lines, hand)}`)"))
    return edits or None


def _header_of_assign(node):
    """An assignment without its value (its targets, and its annotation): what must stay the handout's."""
    if isinstance(node, ast.Assign):
        return ast.Assign(targets=node.targets, value=ast.Constant(None))
    return ast.AnnAssign(target=node.target, annotation=node.annotation, value=None, simple=node.simple)


def with_handout_lines(submission, starter, edits):
    """The submission with each edited line put back to the handout's line: the same lines, numbered as in the
    submission (each edit is one line in both files), so a message naming a line names the student's."""
    lines, handout_lines = split_lines(submission), split_lines(starter)
    for edit in edits:
        lines[edit.line - 1] = handout_lines[edit.handout_line - 1]
    return "\n".join(lines) + "\n"


def names_read(text):
    """Every identifier in the step regions of `text` (the names a step's code reads or binds)."""
    lines = split_lines(text)
    try:
        regions = step_regions(lines)
    except MarkerError:
        return set()
    found = set()
    for start, end, _ in regions.values():
        for line in lines[start + 1:end]:
            found.update(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", line.split("#", 1)[0]))
    return found
