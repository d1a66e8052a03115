"""python -m checker new-lab ID --title "...": write a new one-step lab that grades at once (lab_template.py).

    python -m checker new-lab air_hockey --title "Air Hockey"

writes solutions/ID.py, checker/labs/ID/ (checks, probes, scenes, show), starters/ID_starter.py (as `assign` writes
it) and tests/corpus_ID.py (tests/test_corpus_labs.py finds it). At once the solution passes, the starter fails step 2, and
`python -m checker lint-lab ID` passes; then make the lab yours, one file at a time, with lint-lab and the
corpus test after each change. Nothing is ever written over: if any of those paths exists, or the ID is not a
Python name or is a lab already, it is one line naming that and nothing is written (exit 2).
"""
import argparse
import keyword
import os
import re
import sys
from string import Template

from checker import labs
from checker.authoring import assign, lab_template
from checker.project import PROJECT_ROOT

USAGE = 2
ID = re.compile(r"^[a-z][a-z0-9_]*$")


def planned(lab_id, title):
    """{path under the project: text} of every file the new lab gets, the starter included."""
    values = {"lab_id": lab_id, "title": title}
    files = {Template(path).substitute(values): Template(text).substitute(values)
             for path, text in lab_template.FILES.items()}
    solution = f"solutions/{lab_id}.py"
    files[f"starters/{lab_id}_starter.py"] = assign.starter_text(files[solution], solution)
    return files


def problem(lab_id, title, root=PROJECT_ROOT):
    """The one-line reason new-lab refuses, or None."""
    if not ID.match(lab_id) or keyword.iskeyword(lab_id):
        return f"{lab_id!r} is not a lab id: use lower-case letters, digits and _, starting with a letter"
    if not title.strip() or '"' in title or "\\" in title or "\n" in title or "$" in title:
        return f"--title {title!r}: give a name on one line, without \" \\ or $"
    for path in planned(lab_id, title):
        for shown in (os.path.dirname(path), path) if path.startswith("checker/labs/") else (path,):
            if os.path.lexists(os.path.join(root, shown)):
                return f"{shown} exists: new-lab writes over nothing (choose another ID, or remove it)"
    if any(lab.title.lower() == title.lower() for lab in labs.LABS):
        return f"--title {title!r}: a lab has that title already (files are recognised by it)"
    return None


def write(lab_id, title, root=PROJECT_ROOT):
    """Write the new lab's files under `root`; returns their paths. Refuses (FileExistsError) to replace one."""
    written = []
    for path, text in planned(lab_id, title).items():
        target = os.path.join(root, path)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "x", encoding="utf-8", newline="\n") as handle:   # "x": never over a file
            handle.write(text)
        written.append(path)
    return written


def main(argv, stdout=None, stderr=None, root=PROJECT_ROOT):
    """python -m checker new-lab ID --title "..."; returns the exit status."""
    stdout, stderr = stdout or sys.stdout, stderr or sys.stderr
    parser = argparse.ArgumentParser(prog="python -m checker new-lab",
                                     description="Write a new one-step lab (solution, checks, probes, scene, "
                                                 "starter, corpus) that grades at once.")
    parser.add_argument("id", metavar="ID", help="the lab's id: lower-case letters, digits and _")
    parser.add_argument("--title", required=True, help="the lab's name, as students see it")
    args = parser.parse_args(argv)
    why = problem(args.id, args.title, root)
    if why:
        print(f"checker new-lab: error: {why}", file=stderr)
        return USAGE
    for path in write(args.id, args.title, root):
        print(f"{path}: written", file=stdout)
    print(f"next: python -m checker solutions/{args.id}.py (passes), python -m checker lint-lab {args.id}, "
          f"python -m pytest -n 0 tests/test_corpus_labs.py -k {args.id}", file=stdout)
    return 0
