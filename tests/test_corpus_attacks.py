"""The checker owes every attack of tests/corpus_attacks.py a failed step, and every control its points.

All entries are written into a temporary folder, each in its own submission
folder as `<entry name>/<lab>.py` (with any side file the entry brings), and
graded in ONE run of `python -m checker --json` over their lab files. Then, per
entry:

  attack:  no check in its `target` has status "pass", and the file scores below
           the lab's maximum;
  control: loads, handout_unchanged, runtime_lines and every function check of
           its lab pass, and the step rules flag nothing. (The scenes are not
           constrained: a debug print in a step called every frame may flood
           the output, which is the print's doing, not a false fail.)

An entry marked needs_random_inputs (a table of the fixed inputs' answers) is
caught only by the inputs the checker draws per run; the checker draws them
today, so those entries are expected to fail like the others (no xfail).
Grading: about 80 files, most stopping after their probe; a few minutes of CPU.
"""
import json
import os
import subprocess
import sys

import pytest

import corpus_attacks as corpus
from checker import handout

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NON_FUNCTION = ("loads", "handout_unchanged", "runtime_lines")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """{entry name: the checker's JSON row for its file}, from one run over the whole corpus."""
    paths = corpus.write(tmp_path_factory.mktemp("attacks"))
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    # the lab files themselves, not their folders: a side file (lab_notes.py) is no entry to grade
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--jobs", "2", "--timeout", "60",
                           "--total-timeout", "3000", *paths.values()],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=3600)
    assert proc.returncode in (0, 1), f"the checker exited {proc.returncode}: {proc.stderr[-3000:]}"
    names = {os.path.abspath(path): name for name, path in paths.items()}
    rows = {names[os.path.abspath(row["path"])]: row for row in json.loads(proc.stdout)["labs"]}
    assert set(rows) == set(paths), set(rows) ^ set(paths)
    return rows


def _show(row):
    lines = [f"  score {row['score']}/{row['max_score']}, flags: "
             + ("; ".join(f"step {f['step']} {f['rule']}: {f['what']}" for f in row.get("flags") or []) or "none")]
    lines += [f"  {c['id']}: {c['status']}: {c['message'][:300]}" for c in row["criteria"]]
    return "\n".join(lines)


# ---------------------------------------------------------------- the corpus itself (no grading)

def test_every_lab_has_every_listed_kind_and_two_controls():
    for lab, entries in corpus.BY_LAB.items():
        kinds = {entry.kind for entry in entries}
        assert set(corpus.LISTED_KINDS) <= kinds, (lab, set(corpus.LISTED_KINDS) - kinds)
        assert sum(entry.kind == "control" for entry in entries) >= 2, lab
        assert any(entry.kind == "control" and "print(" in "".join(entry.steps.values()) for entry in entries), lab
        assert all(entry.needs_random_inputs == (entry.kind == "table") for entry in entries), lab


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_is_well_formed_and_keeps_the_handout(entry):
    lab = corpus.LABS[entry.lab]
    assert entry.why and "\n" not in entry.why
    assert entry.kind in corpus.LISTED_KINDS + corpus.EVASIONS + ("control",)
    assert set(entry.steps) <= set(lab.STEPS), (entry.name, set(entry.steps) - set(lab.STEPS))
    if entry.target is None:
        assert entry.kind == "control" and entry.steps and not entry.edits and not entry.extra_files
    else:
        assert entry.target and set(entry.target) <= set(lab.FUNCTION_CHECKS), entry.target
        assert entry.steps or entry.extra_files
    source = corpus.build(entry)
    compile(source, entry.name + ".py", "exec")
    assert corpus.TITLES[entry.lab] in source.split('"""')[1], "the checker recognises the lab by its title"
    with open(lab.STARTER, encoding="utf-8") as handle:
        comparison = handout.compare(source, handle.read())
    assert comparison.same, (entry.name, comparison.problems)   # only the steps (and an allowed import) changed
    if entry.edits:
        assert comparison.added_imports, entry.name
    with open(lab.SOLUTION, encoding="utf-8") as handle:
        solution = handle.read()
    if entry.target is not None:
        assert source != solution


@pytest.mark.parametrize("lab", sorted(corpus.TABLES))
def test_every_table_holds_the_fixed_inputs_of_its_probe(lab):
    """An empty table means the probe modules moved: the table attack would test nothing."""
    assert len(corpus.TABLES[lab]) >= 5, f"no fixed inputs found for {lab}'s table (checker/labs/{lab}/probes.py)"


# ---------------------------------------------------------------- the checker's verdicts

# Known holes, open (strict: the test fails once one is closed, so its mark must go):
KNOWN_HOLES = {
    "tc_early_return_friction": "resolve_friction skips a contact where no impulse was recorded, so a resolve() that "
                                "returns before step 4 passes it vacuously",
}


def _entries_with_holes():
    return [pytest.param(e, marks=pytest.mark.xfail(strict=True, reason=KNOWN_HOLES[e.name]))
            if e.name in KNOWN_HOLES else e for e in corpus.ENTRIES]


@pytest.mark.parametrize("entry", _entries_with_holes(), ids=lambda e: e.name)
def test_each_entry_gets_its_verdict(entry, graded):
    row = graded[entry.name]
    assert row["lab"] == entry.lab, f"{entry.name} was graded as {row['lab']}"
    checks = {c["id"]: c for c in row["criteria"]}
    lab = corpus.LABS[entry.lab]
    assert set(lab.FUNCTION_CHECKS) <= set(checks), f"{entry.name}: missing checks\n{_show(row)}"
    if entry.target is None:
        wanted = NON_FUNCTION + tuple(lab.FUNCTION_CHECKS)
        failing = [cid for cid in wanted if checks[cid]["status"] != "pass"]
        assert not failing and not row.get("flags"), (
            f"{entry.name} is an honest completion ({entry.why}) but {failing or 'the step rules flag it'}:\n"
            f"{_show(row)}")
        return
    passed = [cid for cid in entry.target if checks[cid]["status"] == "pass"]
    assert not passed, (f"{entry.name} ({entry.kind}) gets {', '.join(passed)} without doing the step: {entry.why}"
                        f"\n{_show(row)}")
    assert row["score"] < row["max_score"], f"{entry.name} scores full marks\n{_show(row)}"
