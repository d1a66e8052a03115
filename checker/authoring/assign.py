"""python -m checker assign: write each lab's starter from its solution, the one source of the lab.

A solution (solutions/LAB.py) is also the worked answer handed out, so its
annotations are comments a student can read past. Each step the student
writes sits between the step markers the checker reads (checker/reading/handout.py)
and opens with its prompt block:

    # --- step 2: the SAT loop ---
    # BEGIN PROMPT
    # Step 2 (lesson: "..."): what to write, in the lesson's words.
    # starter: return None  # placeholder: ...
    # END PROMPT
    ...the worked answer...
    # --- end of step 2 ---

The starter (starters/LAB_starter.py) is the solution with the inside of
every step region replaced by its prompt: the prompt's comment lines as they
are, and each `# starter: CODE` line as the line CODE (the placeholder that
keeps the starter running). Everything else, the step markers included, is
copied byte for byte, so the two files cannot drift apart outside the steps.

    python -m checker assign                 rewrite starters/ from solutions/ (only the *_starter.py files)
    python -m checker assign --check         exit 1, one line per starter that differs from what assign writes
    python -m checker assign --out DIR       write the starters into DIR (never over a file already there)

Bad annotations (a region or a prompt opened and not closed, a prompt
outside a step region or missing from one, code in a prompt, a `# starter:`
line outside a prompt) are one line naming the file and line; that lab's
starter is not written, the others are. A starter is written atomically and
keeps the permissions of the file it replaces.
"""
import argparse
import difflib
import os
import re
import sys
import tempfile

from checker.reading import source
from checker import labs
from checker.reading.handout import MarkerError, _comment_lines, step_regions
from checker.project import PROJECT_ROOT as ROOT

SOLUTIONS = os.path.join(ROOT, labs.SOLUTIONS)
STARTERS = os.path.join(ROOT, labs.STARTERS)
BEGIN = re.compile(r"^[ \t]*# BEGIN PROMPT[ \t]*$")
END = re.compile(r"^[ \t]*# END PROMPT[ \t]*$")
CODE = re.compile(r"^(?P<indent>[ \t]*)# starter: (?P<code>.*)$")
COMMENT = re.compile(r"^[ \t]*#")
LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+$")   # a line with its own end, as source.lines() splits


class AssignError(ValueError):
    """A solution whose annotations cannot make a starter (one line: the file, the line, what is wrong)."""


def _prompts(lines, regions, name):
    """{step: (first line index, last line index)} of each region's prompt block (BEGIN and END lines)."""
    comments = _comment_lines("".join(line + "\n" for line in lines)) or frozenset()
    step_at = {index: step for step, (start, end, _) in regions.items() for index in range(start + 1, end)}
    prompts, open_at = {}, None
    for index, line in enumerate(lines):
        begin, end = BEGIN.match(line), END.match(line)
        if (begin or end) and index + 1 not in comments:
            raise AssignError(f"{name}, line {index + 1}: a prompt marker inside a string, not a comment")
        if begin:
            if open_at is not None:
                raise AssignError(f"{name}, line {open_at + 1}: the prompt is not closed (`# END PROMPT`) "
                                  f"before the next one starts on line {index + 1}")
            if index not in step_at:
                raise AssignError(f"{name}, line {index + 1}: a prompt outside a step region (put it between "
                                  "`# --- step N: ... ---` and `# --- end of step N ---`)")
            if step_at[index] in prompts:
                raise AssignError(f"{name}, line {index + 1}: step {step_at[index]} has a second prompt")
            open_at = index
        elif end:
            if open_at is None:
                raise AssignError(f"{name}, line {index + 1}: `# END PROMPT` without a `# BEGIN PROMPT` before it")
            prompts[step_at[open_at]] = (open_at, index)
            open_at = None
        elif open_at is None:
            if CODE.match(line) and index + 1 in comments:
                raise AssignError(f"{name}, line {index + 1}: a `# starter:` line outside a prompt (it belongs "
                                  "between `# BEGIN PROMPT` and `# END PROMPT`)")
        else:
            if index not in step_at or step_at[index] != step_at[open_at]:
                raise AssignError(f"{name}, line {open_at + 1}: the prompt is not closed (`# END PROMPT`) "
                                  f"before step {step_at[open_at]}'s region ends")
            if not COMMENT.match(line):
                raise AssignError(f"{name}, line {index + 1}: code inside the prompt opened on line {open_at + 1} "
                                  "(a prompt holds only comments: close it with `# END PROMPT`, and write "
                                  "placeholder code as `# starter: CODE`)")
    if open_at is not None:
        raise AssignError(f"{name}, line {open_at + 1}: the prompt is not closed (`# END PROMPT`)")
    missing = sorted(set(regions) - set(prompts))
    if missing:
        raise AssignError(f"{name}, line {regions[missing[0]][0] + 1}: step {missing[0]}'s region has no prompt "
                          "(`# BEGIN PROMPT` ... `# END PROMPT`)")
    return prompts


def _ending(line):
    """The line end of `line` ("" on a last line without one)."""
    return line[len(line.rstrip("\r\n")):]


def starter_text(text, name="the solution"):
    """The starter written from the solution's source `text` (str); AssignError naming the line if it cannot be."""
    lines = source.lines(text)
    kept = LINE.findall(text)     # the same lines, with their ends
    try:
        regions = step_regions(lines)
    except MarkerError as exc:
        raise AssignError(f"{name}, line {exc.line}: {exc}" if exc.line else f"{name}: {exc}") from None
    if not regions:
        raise AssignError(f"{name}: no step regions (`# --- step N: ... ---` ... `# --- end of step N ---`)")
    prompts = _prompts(lines, regions, name)
    dropped = set()
    replace = {}
    for step, (start, end, _) in regions.items():
        first, last = prompts[step]
        dropped.update(range(start + 1, end))
        replace[start] = [_placeholder(kept[index]) for index in range(first + 1, last)]
    out = []
    for index, line in enumerate(kept):
        if index not in dropped:
            out.append(line)
            out += replace.get(index, [])
    written = "".join(out)
    try:
        compile(written, name, "exec")
    except SyntaxError as exc:
        raise AssignError(f"{name}: the starter it makes is not Python ({exc.msg} on the starter's line "
                          f"{exc.lineno}): check the `# starter:` lines") from None
    return written


def _placeholder(line):
    """A prompt line as the starter has it: `# starter: CODE` becomes CODE at the comment's indent."""
    code = CODE.match(line.rstrip("\r\n"))
    return code["indent"] + code["code"] + _ending(line) if code else line


def solutions(folder=SOLUTIONS):
    """The lab solutions, solutions/*.py, sorted."""
    return sorted(os.path.join(folder, name) for name in os.listdir(folder)
                  if name.endswith(".py") and not name.startswith("_"))


def _read(path):
    with open(path, "rb") as handle:
        return handle.read()


def _summary(committed, wanted):
    """One line: where the committed starter first differs from the written one."""
    have, want = committed.splitlines(), wanted.splitlines()
    changed = sum(max(i2 - i1, j2 - j1) for tag, i1, i2, j1, j2
                  in difflib.SequenceMatcher(None, have, want, autojunk=False).get_opcodes() if tag != "equal")
    first = next((i for i, (a, b) in enumerate(zip(have, want)) if a != b), min(len(have), len(want)))
    return f"{changed} line(s) differ, the first at line {first + 1}"


def _mode(path):
    """The permission bits `path` has, or those a new file gets (0o666 less the umask): mkstemp's are 0o600."""
    try:
        return os.stat(path).st_mode & 0o777
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def _write(path, data):
    """Write bytes atomically (a temporary file beside it, then a rename): never half a starter."""
    mode = _mode(path)
    handle, temporary = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".assign-", suffix=".tmp")
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(data)
        os.chmod(temporary, mode)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def run(paths, out=None, check=False, stdout=None, stderr=None):
    """Write (or with check, compare) the starter of each solution in `paths`; returns the exit status.

    out: the folder to write to (default starters/, where the starters are rewritten; anywhere else an
    existing file is never replaced). Each solution is its own row: one bad file does not stop the others.
    """
    stdout, stderr = stdout or sys.stdout, stderr or sys.stderr
    folder = os.path.abspath(out or STARTERS)
    own = os.path.realpath(folder) == os.path.realpath(STARTERS)
    if not check and not os.path.isdir(folder):
        print(f"checker assign: error: --out {out}: no such folder", file=stderr)
        return 2
    status = 0
    for path in paths:
        name = os.path.relpath(path, ROOT) if path.startswith(ROOT) else path
        target = os.path.join(folder, labs.Lab.of_solution(path).starter_file)
        shown = os.path.relpath(target, ROOT) if target.startswith(ROOT) else target
        try:
            wanted = starter_text(source.read(path, name), name).encode("utf-8")
        except OSError as exc:
            print(f"checker assign: error: {name}: cannot read it ({exc.strerror or exc})", file=stderr)
            status = 1
            continue
        except (source.SourceError, AssignError) as exc:
            print(f"checker assign: error: {exc}", file=stderr)
            status = 1
            continue
        committed = _read(target) if os.path.exists(target) else None
        if check:
            if committed is None:
                print(f"{shown} is missing (python -m checker assign writes it from {name})", file=stdout)
                status = 1
            elif committed != wanted:
                what = _summary(committed.decode("utf-8", "replace"), wanted.decode("utf-8"))
                print(f"{shown} differs from what python -m checker assign writes from {name}: {what}",
                      file=stdout)
                status = 1
        elif committed == wanted:
            print(f"{shown}: unchanged", file=stdout)
        elif committed is not None and not own:
            print(f"checker assign: error: {shown} exists: not replaced (remove it, or choose another --out)",
                  file=stderr)
            status = 1
        else:
            _write(target, wanted)
            print(f"{shown}: written from {name}", file=stdout)
    return status


def main(argv):
    """python -m checker assign [--check] [--out DIR] [SOLUTION ...]; returns the exit status."""
    parser = argparse.ArgumentParser(prog="python -m checker assign",
                                     description="Write each lab's starter from its annotated solution.")
    parser.add_argument("solutions", nargs="*", metavar="SOLUTION",
                        help="solution files (default: every solutions/*.py)")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 if a committed starter differs from what assign writes")
    parser.add_argument("--out", metavar="DIR", help="write the starters into DIR (default starters/)")
    args = parser.parse_args(argv)
    return run(args.solutions or solutions(), args.out, args.check)
