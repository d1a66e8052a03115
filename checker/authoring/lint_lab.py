"""python -m checker lint-lab ID: the rules a lab must keep (checker/authoring/lab_rules.py), one line per rule broken.

    python -m checker lint-lab ID        one line per rule broken, "<file>: <what is wrong> — <how to fix it>",
                                         exit 1; else "lab ID keeps all N rules", exit 0
    python -m checker lint-lab --rules   every rule, in the guide's order (checker/README.md, "Writing a lab"),
                                         then those left to the tests

An unknown ID is one line naming it and the known labs (exit 2). A rule the lab's modules cannot even be imported
for is one line naming the exception; a rule whose prerequisite broke is not checked (its line would repeat it).
"""
import argparse
import sys

from checker import labs
from checker.authoring import lab_rules
from checker.project import PROJECT_ROOT

USAGE = 2


def line(rule, subject, found):
    """The one line of a broken rule: "<file>: <what> — <fix>"."""
    file = found.file or rule.file.format(id=subject.id)
    return f"{file}: {found.what} — {found.fix}"


def lint(subject, rules=None):
    """[(rule, Broken)] of the rules `subject` (a lab_rules.Subject) breaks, in the rules' order."""
    rules = lab_rules.RULES if rules is None else rules
    by_id = {r.id: r for r in lab_rules.RULES}
    results = {}

    def result(rule):   # None (kept), a Broken, or False (not checked: a prerequisite broke)
        if rule.id not in results:
            if any(result(by_id[need]) is not None for need in rule.needs):
                results[rule.id] = False
            else:
                try:
                    results[rule.id] = rule.function(subject)
                except Exception as exc:  # noqa: BLE001 - the lab's own module fails: that is the line
                    results[rule.id] = lab_rules.broken(
                        f"could not be checked ({type(exc).__name__}: {exc})".replace("\n", " "),
                        "fix that first (import the module, or run the rule's test, to see the traceback)")
        return results[rule.id]

    return [(r, result(r)) for r in rules if result(r)]


def rules_text():
    """Every rule on a line, numbered, in order; then the rules left to the tests."""
    out = [f"{n}. {rule.text}" for n, rule in enumerate(lab_rules.RULES, 1)]
    out += [f"{n}. {stated.text} (left to `{stated.test}`)"
            for n, stated in enumerate(lab_rules.STATED, len(lab_rules.RULES) + 1)]
    return "\n".join(out)


def main(argv, stdout=None, stderr=None, root=PROJECT_ROOT):
    """python -m checker lint-lab ID | --rules; returns the exit status."""
    stdout, stderr = stdout or sys.stdout, stderr or sys.stderr
    parser = argparse.ArgumentParser(prog="python -m checker lint-lab",
                                     description="Check that a lab keeps every rule of checker/README.md's "
                                                 "\"Writing a lab\"; one line per rule broken.")
    parser.add_argument("id", nargs="?", metavar="ID", help="the lab's id (its folder's name in checker/labs/)")
    parser.add_argument("--rules", action="store_true", help="print every rule and exit")
    args = parser.parse_args(argv)
    if args.rules:
        print(rules_text(), file=stdout)
        return 0
    known = labs.found()
    if args.id not in known:
        what = f"no lab {args.id!r}" if args.id else "give a lab's ID"
        print(f"checker lint-lab: error: {what} (checker/labs/{args.id or 'ID'}/checks.py); the labs are: "
              f"{', '.join(known)}", file=stderr)
        return USAGE
    subject = lab_rules.Subject(labs.Lab(args.id, root=root))
    found = lint(subject)
    for rule, problem in found:
        print(line(rule, subject, problem), file=stdout)
    if found:
        return 1
    print(f"lab {args.id} keeps all {len(lab_rules.RULES)} rules ({len(lab_rules.STATED)} more are left to the "
          "tests: --rules lists them)", file=stdout)
    return 0
