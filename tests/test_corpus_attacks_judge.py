"""Issue 39's attacks on the judging (tests/corpus_attacks_judge.py) fail without the step rules too.

tests/test_corpus_attacks.py grades them as the checker runs (rules on) in every mode. Here the rules are
turned off in a checker process of its own (as that file's last test turns them off in-process): the
`global PERCENT` and `Body.kept = sat` the rules flag are then left to the grader's own mechanisms (the
handout's constants, the child putting them back before each probe, the spliced probe run last), which must still fail each entry's
WITHOUT_RULES checks, naming the constant where one was changed, and score no more than its honest file.
"""
import json
import os
import subprocess
import sys

import corpus_attacks as corpus
import corpus_attacks_judge as judge_corpus

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def test_without_the_step_rules_the_judging_still_fails_them(tmp_path):
    chosen = list(corpus.ISSUE39_JUDGE)
    paths = corpus.write(tmp_path, chosen + [corpus.HONEST[e.name] for e in chosen])
    # the checker in a process of its own (no state of earlier tests in this one), its step rules turned off
    without_rules = ("import sys; from checker import cli; from checker.reading import step_rules; "
                     "step_rules.scan_lab = lambda source, module, path=None: []; sys.exit(cli.main(sys.argv[1:]))")
    # at seed 1: the CCD shots start at a drawn phase, and bu_m393's trigger fires only at some (1, not 6)
    done = subprocess.run([sys.executable, "-c", without_rules, *paths.values(), "--json", "--quiet", "--jobs", "2",
                           "--seed", "1"],
                          cwd=ROOT, capture_output=True, text=True, timeout=900,
                          env=dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYTHONPATH=ROOT))
    assert done.returncode in (0, 1), done.stderr[-2000:]
    names = {os.path.abspath(path): name for name, path in paths.items()}
    rows = {names[os.path.abspath(r["path"])]: r for r in json.loads(done.stdout)["labs"]}
    assert set(judge_corpus.WITHOUT_RULES) == {e.name for e in chosen}
    for entry in chosen:
        row, honest = rows[entry.name], rows[corpus.HONEST[entry.name].name]
        checks = {c["id"]: c for c in row["criteria"]}
        assert set(judge_corpus.WITHOUT_RULES[entry.name]) <= set(checks), (entry.name, "not graded", row)
        assert row["flags"] == []
        passing = [t for t in judge_corpus.WITHOUT_RULES[entry.name] if checks[t]["status"] == "pass"]
        assert not passing, (entry.name, passing, [(c["id"], c["status"], c["message"]) for c in row["criteria"]])
        assert row["score"] <= honest["score"], (entry.name, row["score"], honest["score"])
        if entry.kind != "kept_splice":   # the check of the step that changed it names the constant
            first = checks[judge_corpus.WITHOUT_RULES[entry.name][0]]["message"]
            assert entry.message in first and "while it runs" in first, (entry.name, first)


def test_on_gradescopes_procedure_the_judging_attacks_gain_nothing(tmp_path):
    """Each judging attack and its honest file, each submitted alone to the lab's Gradescope package run as
    Gradescope runs it (tests/gradescope_procedure.py says what differs from the real one): the attack scores no
    more than the honest file. Needs root and a user `nobody`, as the package's grading does."""
    import pytest

    import gradescope_procedure as gradescope
    from checker.isolation import users
    if not users.is_root() or users.choose(None)[0] is None:
        pytest.skip("needs a grader running as root and a user nobody")
    chosen = list(corpus.ISSUE39_JUDGE)
    labs = sorted({entry.lab for entry in chosen})
    bundle = tmp_path / "autograder.zip"
    gradescope.build(bundle, labs)
    scores = {}
    for entry in chosen + [corpus.HONEST[e.name] for e in chosen]:
        if entry.name in scores:
            continue
        text = open(corpus.write(tmp_path / "files", [entry])[entry.name], encoding="utf-8").read()
        done, results = gradescope.run(bundle, tmp_path / "runs" / entry.name, f"{entry.lab}.py", text)
        assert done.returncode == 0 and results is not None, (entry.name, done.stderr[-2000:])
        scores[entry.name] = results["score"]
    for entry in chosen:
        honest = corpus.HONEST[entry.name].name
        assert scores[honest] > 0, (honest, "the honest file was not graded")   # so the comparison can fail
        assert scores[entry.name] <= scores[honest], (entry.name, scores[entry.name], honest, scores[honest])
