"""The checker owes every attack of tests/corpus_attacks.py a failed step, and every control its points.

All entries are written into a temporary folder, each in its own submission
folder as `<entry name>/<lab>.py` (with any side file the entry brings), beside
the HONEST file of every issue-35 entry (the same file with the attack removed,
corpus_attacks.honest), and graded in ONE run of `python -m checker --json` per
grading mode (GRADING_MODES) over their lab files. Then, per entry:

  attack:  no check in its `target` has status "pass", the file scores below the
           lab's maximum, and an issue-35 entry (mechanism 1-10) scores no more than
           its honest file got in the same run; `message`, if set, is in the first
           target check's message; mechanism 7 (a forged document on the grader's
           stdout): the grader's stdout holds exactly one JSON document, its own;
  control: loads, handout_unchanged, runtime_lines and every function check of
           its lab pass, and the step rules flag nothing; an all_checks control
           (tests/attack_corpus.py's, issue 35's stdlib steps) gets every check,
           the scenes included: full marks. (Other controls leave the scenes
           unconstrained: a debug print in a step called every frame may flood
           the output, which is the print's doing, not a false fail.)

An entry marked needs_random_inputs (a table of the fixed inputs' answers) is
caught only by the inputs the checker draws per run; the checker draws them
today, so those entries are expected to fail like the others (no xfail).
A last test turns the step rules off (in-process) and grades the tables and
forgeries: the grader's own replay and drawn inputs still fail them.
Grading (-n 0, root mode): 224 files (199 entries, 25 distinct honest files), most stopping after their probe.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import pytest

import corpus_attacks as corpus
import labs_found
from checker.reading import handout

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NON_FUNCTION = ("loads", "handout_unchanged", "runtime_lines")

# how the corpus is graded: the CLI as root as the README's class example shows it (no option), and with
# --child-user nobody (root only). The Gradescope package's own procedure is tests/platform_acceptance.py's
# (slow, opt-in); it grades Tumbling Crates' issue-35 attacks there too.
GRADING_MODES = {"root": [], "child_user": ["--child-user", "nobody"]}


def _documents(text):
    """The JSON documents printed one after another in `text` (the grader prints one)."""
    decoder, found, at = json.JSONDecoder(), [], 0
    while True:
        while at < len(text) and text[at].isspace():
            at += 1
        if at >= len(text):
            return found
        try:
            document, at = decoder.raw_decode(text, at)
        except json.JSONDecodeError:
            return found + [{"not json": text[at:at + 200]}]
        found.append(document)


def _grade(folder, mode, env_extra=None):
    """{"rows": {name: row}, "documents": how many JSON documents the grader's stdout held} for `mode`
    (env_extra: more environment for the checker, e.g. CHECKER_PORTABLE=1 in tests/test_checker_portable.py)."""
    entries = [entry for entry in corpus.ENTRIES if mode in entry.modes]
    same = {}   # an honest file's text -> the first honest entry with it (44 honest entries, 20 distinct files)
    for entry in entries:
        if entry.name in corpus.HONEST:
            same.setdefault(corpus.build(corpus.HONEST[entry.name]), corpus.HONEST[entry.name])
    paths = corpus.write(folder, entries + list(same.values()))
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", **(env_extra or {}))
    # the lab files themselves, not their folders: a side file (lab_notes.py) is no entry to grade
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--jobs", "2", "--timeout", "60",
                           "--total-timeout", "3000", *GRADING_MODES[mode], *paths.values()],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=3600)
    assert proc.returncode in (0, 1), f"the checker exited {proc.returncode}: {proc.stderr[-3000:]}"
    documents = _documents(proc.stdout)
    names = {os.path.abspath(path): name for name, path in paths.items()}
    # the grader's own document is the last: a forged one (mechanism 7) can only come before it
    rows = {names[os.path.abspath(row["path"])]: row for row in documents[-1]["labs"]
            if os.path.abspath(row.get("path", "")) in names}
    assert set(rows) == set(paths), set(rows) ^ set(paths)
    for entry in entries:   # every honest entry gets its file's row
        if entry.name in corpus.HONEST:
            rows[corpus.HONEST[entry.name].name] = rows[same[corpus.build(corpus.HONEST[entry.name])].name]
    return {"rows": rows, "documents": len(documents)}


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """graded(mode) -> that mode's grading (one CLI run per mode, made when first asked for)."""
    runs = {}

    def run(mode):
        if mode == "child_user" and (getattr(os, "geteuid", lambda: 1)() != 0 or not _user_exists("nobody")):
            pytest.skip("--child-user needs root and the user nobody")
        if mode not in runs:
            folder = tmp_path_factory.mktemp(f"attacks-{mode}")
            if mode == "child_user":   # pytest's folders are root's alone (700): the class folder must be readable
                folder = tempfile.mkdtemp(prefix="l11-attacks-", dir="/var/tmp")
                made.append(folder)
                os.chmod(folder, 0o755)
            runs[mode] = _grade(folder, mode)
        return runs[mode]

    made = []
    yield run
    for folder in made:
        shutil.rmtree(folder, ignore_errors=True)


def _user_exists(name):
    import pwd
    try:
        pwd.getpwnam(name)
        return True
    except KeyError:
        return False


def _show(row):
    lines = [f"  score {row['score']}/{row['max_score']}, flags: "
             + ("; ".join(f"step {f['step']} {f['rule']}: {f['what']}" for f in row.get("flags") or []) or "none")]
    lines += [f"  {c['id']}: {c['status']}: {c['message'][:300]}" for c in row["criteria"]]
    return "\n".join(lines)


# ---------------------------------------------------------------- the corpus itself (no grading)

@pytest.mark.parametrize("lab", labs_found.params(labs_found.with_corpus()))
def test_every_lab_has_every_listed_kind_and_two_controls(lab):
    """Every lab in checker/labs/ (with a mistake corpus; one without fails tests/test_corpus_labs.py). Also: it
    has an entry of each issue-35 mechanism that applies to it (MECHANISMS_BY_LAB). The first round's seven kinds
    and mechanisms 1, 2, 5, 6, 7 are built for any lab from the lab itself; a "table" attack and the controls are
    written for it (by its corpus: ATTACK["entries"])."""
    entries = corpus.BY_LAB[lab.id]
    where = (f"write them in tests/corpus_{lab.id}.py's ATTACK[\"entries\"] (corpus_attacks.own_entries; new-lab's "
             "corpus has an example)")
    mechanisms = set(corpus.MECHANISMS_BY_LAB[lab.id]) - {entry.mechanism for entry in entries}
    assert not mechanisms, f"{lab.id}: no entry of issue-35 mechanisms {sorted(mechanisms)}: {where}"
    kinds = set(corpus.LISTED_KINDS) - {entry.kind for entry in entries}
    assert not kinds, f"{lab.id}: no attack of kinds {sorted(kinds)}: {where}"
    assert sum(entry.kind == "control" for entry in entries) >= 2, f"{lab.id}: fewer than two controls: {where}"
    assert any(entry.kind == "control" and "print(" in "".join(entry.steps.values()) for entry in entries), \
        f"{lab.id}: no control with a debug print in a step: {where}"
    assert all(entry.needs_random_inputs == (entry.kind == "table") for entry in entries), lab.id


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_is_well_formed_and_keeps_the_handout(entry):
    lab = corpus.LABS[entry.lab]
    assert entry.why and "\n" not in entry.why
    assert entry.kind in corpus.LISTED_KINDS + corpus.EVASIONS + corpus.MECHANISM_KINDS + ("control",)
    assert set(entry.modes) <= set(GRADING_MODES) and "root" in entry.modes
    assert set(entry.steps) <= set(lab.STEPS), (entry.name, set(entry.steps) - set(lab.STEPS))
    if entry.target is None:
        assert entry.kind == "control" and entry.steps and not entry.edits and not entry.extra_files
    else:
        assert entry.target and set(entry.target) <= set(lab.FUNCTION_CHECKS), entry.target
        assert entry.steps or entry.extra_files
    source = corpus.build(entry)
    compile(source.encode("utf-8"), entry.name + ".py", "exec")   # bytes: as Python reads the file (its coding)
    assert corpus.TITLES[entry.lab] in source.split('"""')[1], "the checker recognises the lab by its title"
    if entry.mechanism in (1, 2):
        return   # the checker's own reading of the file is what these attack: its comparison proves nothing here
    with open(lab.STARTER, encoding="utf-8") as handle:
        comparison = handout.compare(source, handle.read())
    if not entry.keeps_handout:   # code added outside the steps: handout_unchanged fails it
        assert not comparison.same, entry.name
        return
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

# Holes open, each a strict xfail naming its mechanism of issue 35 and the branch expected to close it (strict: the
# test fails once the hole is closed, so its mark must go). None is open now: i35-probes, i35-safe and i35-reading
# closed mechanisms 1-10.
OPEN = {}
# with --child-user nobody: no open hole (branch i35-safe made the zygote import what a scene needs).
OPEN_AS_CHILD_USER = {}


def _cases():
    out = []
    for mode in GRADING_MODES:
        holes = OPEN if mode == "root" else OPEN_AS_CHILD_USER
        for entry in corpus.ENTRIES:
            if mode in entry.modes:
                marks = [pytest.mark.xfail(strict=True, reason=holes[entry.name])] if entry.name in holes else []
                out.append(pytest.param(mode, entry, marks=marks, id=f"{mode}-{entry.name}"))
    return out


@pytest.mark.parametrize("mode, entry", _cases())
def test_each_entry_gets_its_verdict(mode, entry, graded):
    run = graded(mode)
    row = run["rows"][entry.name]
    assert row["lab"] == entry.lab, f"{entry.name} was graded as {row['lab']}"
    checks = {c["id"]: c for c in row["criteria"]}
    lab = corpus.LABS[entry.lab]
    if entry.kind == "coding":   # refused before any check: the file is not the UTF-8 text Python would compile
        assert row["status"] == "error" and row["score"] == 0 and not row["criteria"], _show(row)
        assert "save it as UTF-8 and remove the line" in row["message"], row["message"]
        return
    assert set(lab.FUNCTION_CHECKS) <= set(checks), f"{entry.name}: missing checks\n{_show(row)}"
    if entry.target is None:
        wanted = tuple(checks) if entry.all_checks else NON_FUNCTION + tuple(lab.FUNCTION_CHECKS)
        failing = [cid for cid in wanted if checks[cid]["status"] != "pass"]
        assert not failing and not row.get("flags"), (
            f"{entry.name} is an honest completion ({entry.why}) but {failing or 'the step rules flag it'}:\n"
            f"{_show(row)}")
        return
    if entry.mechanism == 7:   # the grader's stdout is its own: one document, no forged one before it
        assert run["documents"] == 1, f"the grader's stdout held {run['documents']} JSON documents (a forged one)"
        honest = run["rows"][corpus.HONEST[entry.name].name]   # and the child did run: no pass by running nothing
        assert [c["status"] for c in honest["criteria"] if c["id"] == "loads"] == ["pass"], _show(honest)
    passed = [cid for cid in entry.target if checks[cid]["status"] == "pass"]
    assert not passed, (f"{entry.name} ({entry.kind}) gets {', '.join(passed)} without doing the step: {entry.why}"
                        f"\n{_show(row)}")
    assert row["score"] < row["max_score"], f"{entry.name} scores full marks\n{_show(row)}"
    if entry.message:
        assert entry.message in checks[entry.target[0]]["message"], f"{entry.name}: {entry.why}\n{_show(row)}"
    if entry.mechanism:
        honest = run["rows"][corpus.HONEST[entry.name].name]
        assert row["score"] <= honest["score"], (
            f"{entry.name} scores {row['score']}, more than the {honest['score']} its honest work earns "
            f"(the same file without the attack)\n{_show(row)}")


# 102, 251: every pair Tumbling Crates drew was apart; 4, 7: every path Bullets drew missed (the report's seeds)
TABLE_SEEDS = (1, 2, 3, 4, 5, 7, 102, 251)


@pytest.mark.parametrize("entry", [entry for entry in corpus.ENTRIES if entry.kind == "table"], ids=lambda e: e.name)
def test_a_table_of_the_fixed_answers_fails_its_step_at_every_seed(entry, tmp_path):
    """The table attacks, a default right for one kind of answer included (None for a pair apart, the placeholder
    where it happens to be right), fail their target checks at each of TABLE_SEEDS: the inputs each run draws hold
    every kind of answer. In-process, as tests/test_probe_tape.py records and replays a probe (no step rules, no
    scenes); the CLI run above grades each entry once, at a fresh seed."""
    from test_probe_tape import function_results, lab_by_id, recorded
    lab = lab_by_id(entry.lab)
    path = corpus.write(tmp_path / "files", [entry])[entry.name]
    passed = []
    for seed in TABLE_SEEDS:
        settings, result, source = recorded(lab, path, seed, tmp_path)
        statuses, _ = function_results(lab, path, source, settings, result)
        passed += [(seed, cid) for cid in entry.target if statuses.get(cid, ("missing",))[0] == "pass"]
    assert not passed, f"{entry.name} ({entry.why}) passes (seed, check): {passed}"


def test_without_the_step_rules_the_replay_still_fails_tables_and_forgery(tmp_path, monkeypatch, capsys):
    """(Was tests/test_attack_corpus.py's.) In-process, the step rules turned off: the attacks that need no
    forbidden construct in a step (the tables) or that work on the child (the forgeries) still fail on the
    grader's own replay and drawn inputs. The real procedure has the rules on; this shows the replay holds alone."""
    from checker import cli
    from checker.reading import step_rules
    monkeypatch.setattr(step_rules, "scan_lab", lambda source, module, path=None: [])
    chosen = [e for e in corpus.ENTRIES if e.kind in ("table", "forge")]
    paths = corpus.write(tmp_path, chosen)
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    monkeypatch.setenv("SDL_AUDIODRIVER", "dummy")
    cli.main([*paths.values(), "--json", "--quiet"])
    names = {os.path.abspath(path): name for name, path in paths.items()}
    rows = {names[os.path.abspath(r["path"])]: r for r in json.loads(capsys.readouterr().out)["labs"]}
    for entry in chosen:
        checks = {c["id"]: c for c in rows[entry.name]["criteria"]}
        assert rows[entry.name]["flags"] == []
        assert set(entry.target) <= set(checks), f"{entry.name} was not graded:\n{_show(rows[entry.name])}"
        assert all(checks[t]["status"] != "pass" for t in entry.target), (entry.name, checks[entry.target[0]])
