"""How every lab's mistake corpus turns its entries into student files (shared by tests/corpus_<lab>.py).

An entry's file is the lab's current starter with each step region filled:
with the entry's own code for the steps it names (entry.steps {step: code}),
else with the solution's code; then the entry's exact edits outside the steps
(entry.edits, applied by tests/mutants.py, each must fit exactly once). Step
regions are found by the checker's own marker parser (checker/reading/handout.py).
"""
import os
import textwrap

import mutants
from checker.reading.handout import step_regions


def _read(path):
    with open(path, encoding="utf-8") as handle:
        return handle.read()


class CorpusFiles:
    """Builds the files of one lab's corpus: starter and solution paths, the student's STEPS, entries by name."""

    def __init__(self, starter, solution, steps, by_name, corpus_name):
        self.starter, self.solution, self.steps = starter, solution, tuple(steps)
        self.by_name, self.corpus_name = by_name, corpus_name

    def regions(self, source, where="file"):
        """{step: (start marker index, end marker index, indent)}; AssertionError naming `where` if a step is missing."""
        found = step_regions(source.split("\n"))
        missing = [step for step in self.steps if step not in found]
        if missing:
            raise AssertionError(f"{where}: step {missing[0]} has no `# --- step {missing[0]}: ... ---` region")
        return found

    def step_code(self, source, where="file"):
        """{step: the dedented code strictly between the step's markers}."""
        lines = source.split("\n")
        return {step: textwrap.dedent("\n".join(lines[start + 1:end])).strip("\n")
                for step, (start, end, _) in self.regions(source, where).items()}

    def fill(self, source, codes, where="file"):
        """source with the inside of each step in codes replaced by that code, indented like the step's marker."""
        lines = source.split("\n")
        found = self.regions(source, where)
        for step in sorted(codes, key=lambda s: -found[s][0]):
            start, end, indent = found[step]
            body = [indent + line if line.strip() else "" for line in codes[step].split("\n")] if codes[step] else []
            lines[start + 1:end] = body
        return "\n".join(lines)

    def build(self, name, starter=None, solution=None):
        """The source of entry `name`: the starter, its steps filled (the entry's code, else the solution's), then edits."""
        entry = self.by_name[name]
        starter = _read(self.starter) if starter is None else starter
        solution = _read(self.solution) if solution is None else solution
        codes = self.step_code(solution, os.path.relpath(self.solution))
        codes.update(entry.steps)
        source = self.fill(starter, codes, os.path.relpath(self.starter))
        return mutants.apply_edits(source, entry.edits, name, "the built file", self.corpus_name)

    def write(self, directory, names=None):
        """Write NAME.py into directory for each entry (all by default); returns {name: path}."""
        starter, solution = _read(self.starter), _read(self.solution)
        paths = {}
        for name in (self.by_name if names is None else names):
            path = os.path.join(str(directory), name + ".py")
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(self.build(name, starter, solution))
            paths[name] = path
        return paths


def with_says(entries, says):
    """`entries` with each wrong one's `says` (the words its first message must contain) from the dict `says`.

    Every wrong entry must be in `says` and every name in `says` must be an entry (a renamed entry shows).
    """
    names = {entry.name for entry in entries if entry.check != "pass"}
    assert names == set(says), f"SAYS and the wrong entries differ: {sorted(names ^ set(says))}"
    return [entry._replace(says=tuple(says[entry.name])) if entry.name in says else entry for entry in entries]
