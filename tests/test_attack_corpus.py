"""The checker owes every attack of tests/attack_corpus.py a failed step, and every control a pass.

All entries are graded in ONE run of `python -m checker DIR --json` (each in
its own folder under its lab's file name, as a class folder would hold them),
then per entry:
  attack: no check in its target passes and the file scores below the lab's maximum;
  control: every check passes (all of them, the scenes included).
A second test turns the step rules off (in-process, monkeypatched) and grades the
attacks that need no forbidden construct in a step (the tables) or that work on
the child (forge): they still fail, on the grader's own replay and drawn inputs.
The real procedure has the rules on; this only shows the replay holds by itself.
"""
import json
import os
import subprocess
import sys

import pytest

import attack_corpus as corpus

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write(entries, folder):
    for entry in entries:
        path = folder / entry.name / f"{entry.lab}.py"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(corpus.build(entry), encoding="utf-8")


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    folder = tmp_path_factory.mktemp("attacks")
    write(corpus.ENTRIES, folder)
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    proc = subprocess.run([sys.executable, "-m", "checker", str(folder), "--json", "--quiet"], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=1800)
    rows = json.loads(proc.stdout)["labs"]
    return {os.path.basename(os.path.dirname(row["path"])): row for row in rows}


def test_the_corpus_covers_every_kind_for_every_lab():
    kinds = {(e.lab, e.kind) for e in corpus.ENTRIES}
    for lab in corpus.TARGETS:
        assert {k for l, k in kinds if l == lab} >= {"import", "world", "dunder", "forge", "rebind", "solution",
                                                   "detect"}
    assert sum(e.kind == "table" for e in corpus.ENTRIES) >= 2
    assert sum(e.kind == "control" for e in corpus.ENTRIES) >= 4


@pytest.mark.parametrize("entry", corpus.ENTRIES, ids=lambda e: e.name)
def test_each_entry_gets_its_verdict(entry, graded):
    row = graded[entry.name]
    assert row["lab"] == entry.lab
    checks = {c["id"]: c for c in row["criteria"]}
    if entry.target:
        assert all(checks[t]["status"] != "pass" for t in entry.target), checks[entry.target[0]]
        assert row["score"] < row["max_score"]
    else:
        assert [c["id"] for c in row["criteria"] if c["status"] != "pass"] == [], row


def test_without_the_step_rules_the_replay_still_fails_tables_and_forgery(tmp_path, monkeypatch, capsys):
    from checker import cli, step_rules
    monkeypatch.setattr(step_rules, "scan_lab", lambda source, module, path=None: [])
    chosen = [e for e in corpus.ENTRIES if e.kind in ("table", "forge")]
    write(chosen, tmp_path)
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    monkeypatch.setenv("SDL_AUDIODRIVER", "dummy")
    cli.main([str(tmp_path), "--json", "--quiet"])
    rows = {os.path.basename(os.path.dirname(r["path"])): r for r in json.loads(capsys.readouterr().out)["labs"]}
    for entry in chosen:
        checks = {c["id"]: c for c in rows[entry.name]["criteria"]}
        assert rows[entry.name]["flags"] == []
        assert all(checks[t]["status"] != "pass" for t in entry.target), (entry.name, checks[entry.target[0]])
