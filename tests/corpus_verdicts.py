"""What every lab's mistake-corpus test shares: one checker run over the whole corpus, and the verdict rules.

A corpus module (tests/corpus_<lab>.py) builds plausible student files from
the lab's current starter. It has ENTRIES (= CORRECT + WRONG; each entry has
name, what, why, check, step, steps, edits, status, says and, optionally, also),
STEPS, CHECK_STEP {check id: step}, FUNCTION_CHECKS, SOLUTION, build(name) and
write_corpus(directory) -> {name: path}; optionally NEEDS_STEPS_2_TO_4, the
checks that need several steps and so may be skipped when one step is wrong;
DEPENDS {check: (checks it depends on)}, so a check may be skipped when one it
depends on fails; SAME_FUNCTION {check: the other check of the same function},
which a crash may take with it (skip or error, never fail); PER_STEP, how many
wrong entries each step needs at least (1 if not given); and the lab-specific
entries the generic tests read: SHOW_ENTRY (the wrong entry --show opens,
tests/test_checker_show.py) and COMBINED (two mistakes at once,
tests/test_named_causes.py).

Every lab in checker/labs/ gets these tests by being there (tests/test_corpus_labs.py); a lab
without its corpus file fails a test naming the file to write (tests/labs_found.py).

The rules, one test per entry (tests/test_corpus_labs.py calls these for every lab):
  correct entry: every check passes;
  wrong entry: the named check has one of the entry's statuses ("fail", or
  "error" for a crash), its JSON step is the entry's step and its hint names
  that step; loads passes; a mistake inside the steps leaves handout_unchanged
  and runtime_lines passing; every other function check passes (those in
  NEEDS_STEPS_2_TO_4 or depending on the named check may be skipped, the named
  check's SAME_FUNCTION twin may skip or error on a crash); the entry's `also` checks are free; the
  named check's message (the file's first message) contains every word of the
  entry's `says` (issue 33: it names the mistake, not only its step), and the check carries the mistake id the
  corpus's MISTAKE_IDS gives the entry, and the message is two short lines and the hint short (issue 40,
  message_problem). The
  scenes need every function check, so they are not constrained for a wrong
  entry (a wrong file stops after its probe run).
"""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NON_FUNCTION = ("loads", "handout_unchanged", "runtime_lines")


def grade(built, lab_id):
    """{entry name: {check id: the check's JSON}} from ONE `python -m checker --json` run over `built` {name: path}.

    Every file must be graded as `lab_id`.
    """
    env = dict(os.environ, PYTHONPATH=ROOT, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    # long limits: on a busy machine a scene can take longer than the default 20 s, and no entry loops;
    # a corpus whose files all run their scenes (Tumbling Crates: about 12 s of CPU each) gets 100 s a file
    total = max(1500, 100 * len(built))
    proc = subprocess.run([sys.executable, "-m", "checker", "--json", "--quiet", "--timeout", "180",
                           "--total-timeout", str(total), *built.values()],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=total + 300)
    assert proc.returncode in (0, 1), f"the checker exited {proc.returncode}: {proc.stderr[-2000:]}"
    names = {os.path.abspath(path): name for name, path in built.items()}
    result = {}
    for lab in json.loads(proc.stdout)["labs"]:
        assert lab["lab"] == lab_id, f"{lab['path']} was graded as {lab['lab']}, not {lab_id}"
        result[names[os.path.abspath(lab["path"])]] = {check["id"]: check for check in lab["criteria"]}
    assert set(result) == set(built)
    return result


def show(checks):
    """Every check of one file on a line: id, status, step and message."""
    return "\n".join(f"  {cid}: {c['status']} (step {c['step']}): {c['message']}" for cid, c in checks.items())


def assert_big_enough(corpus, per_step=None):
    """At least 10 wrong and 3 correct entries, `per_step` (else the corpus's PER_STEP, else 1) wrong ones in every
    step, one outside the steps."""
    per_step = getattr(corpus, "PER_STEP", 1) if per_step is None else per_step
    assert len(corpus.WRONG) >= 10 and len(corpus.CORRECT) >= 3
    for step in corpus.STEPS:
        assert len([e for e in corpus.WRONG if e.step == step]) >= per_step, f"too few mistakes in step {step}"
    assert [e for e in corpus.WRONG if e.check == "handout_unchanged"], "no mistake outside the steps"


def assert_builds(entry, corpus, title):
    """The entry is described, builds a file that compiles and names the lab, and changes only what it says."""
    assert entry.what and "\n" not in entry.what and entry.why
    source = corpus.build(entry.name)
    compile(source, entry.name + ".py", "exec")
    assert title in source.split('"""')[1], "the checker recognises the lab by its docstring's title"
    assert_says_words(entry)
    if entry.check == "pass":   # a correct file may also differ outside the steps where the handout allows it
        assert entry.step is None
    elif entry.check == "handout_unchanged":
        assert entry.edits and not entry.steps
    else:
        assert list(entry.steps) == [entry.step] and not entry.edits
        assert corpus.CHECK_STEP[entry.check] == entry.step
        assert source != corpus.build("correct_solution_steps")


def assert_reference_build_is_the_solution(corpus):
    with open(corpus.SOLUTION, encoding="utf-8") as handle:
        assert corpus.build("correct_solution_steps") == handle.read()


def assert_verdict(entry, checks, corpus):
    """The checker's verdict on one entry's file (`checks`: {check id: JSON}) follows the module docstring's rules."""
    assert set(corpus.CHECK_STEP) <= set(checks), show(checks)
    if entry.check == "pass":
        failing = {cid: c for cid, c in checks.items() if c["status"] != "pass"}
        assert not failing, f"{entry.name} is correct ({entry.what}) but:\n{show(failing)}\nwhy: {entry.why}"
        return
    named = checks[entry.check]
    assert named["status"] in entry.status and named["step"] == entry.step, (
        f"{entry.name} ({entry.what}): expected {entry.check} {'/'.join(entry.status)} naming step {entry.step}; "
        f"got {named['status']} naming step {named['step']}: {named['message']}\nwhy: {entry.why}\n{show(checks)}")
    assert_first_message(entry, named, corpus)
    if entry.step is not None:
        assert named["hint"].startswith(f"[step {entry.step}: "), named["hint"]
    may_skip = tuple(getattr(corpus, "NEEDS_STEPS_2_TO_4", ()))
    depends, twin = getattr(corpus, "DEPENDS", {}), getattr(corpus, "SAME_FUNCTION", {}).get(entry.check)
    crash = "error" in entry.status
    for cid in NON_FUNCTION + tuple(corpus.FUNCTION_CHECKS) + may_skip:
        if cid == entry.check or cid in getattr(entry, "also", ()):
            continue
        if cid in may_skip or entry.check in depends.get(cid, ()):
            allowed = ("pass", "skip")
        elif crash and cid == twin:
            allowed = ("pass", "skip", "error")
        else:
            allowed = ("pass",)
        assert checks[cid]["status"] in allowed, (f"{entry.name} ({entry.what}) is a mistake for {entry.check}, but "
                                                  f"{cid} is {checks[cid]['status']} (allowed: {', '.join(allowed)}):"
                                                  f"\n{show(checks)}")


def assert_first_message(entry, named, corpus):
    """A wrong entry's failing check (its first message): it names the mistake (entry.says), is two short lines
    with a short hint (message_problem), and carries the mistake id corpus.MISTAKE_IDS gives the entry."""
    assert_names_the_mistake(entry, named)
    assert_short(named, entry.name)
    expected = getattr(corpus, "MISTAKE_IDS", {}).get(entry.name)
    if expected is not None:
        assert (named.get("mistake") or {}).get("id") == expected, (
            f"{entry.name} ({entry.what}): its check must carry the mistake {expected!r}; it carries "
            f"{named.get('mistake')!r}: {named['message']}")


FIRST_LINE, EVIDENCE_LINE, HINT = 160, 200, 250   # characters (issue 40): a message is two short lines


def message_problem(check):
    """Why a failing check's message or hint is too long, or "": at most two lines, the first (what is wrong)
    <= FIRST_LINE characters, the second (the evidence) <= EVIDENCE_LINE, the hint as shown <= HINT."""
    lines = check["message"].split("\n")
    if len(lines) > 2:
        return f"{len(lines)} lines (two at most)"
    if len(lines[0]) > FIRST_LINE:
        return f"its first line has {len(lines[0])} characters (at most {FIRST_LINE}): {lines[0]}"
    if len(lines) == 2 and len(lines[1]) > EVIDENCE_LINE:
        return f"its second line has {len(lines[1])} characters (at most {EVIDENCE_LINE}): {lines[1]}"
    if len(check["hint"]) > HINT:
        return f"its hint has {len(check['hint'])} characters (at most {HINT}): {check['hint']}"
    return ""


def assert_short(check, name):
    """The failing check's message is two short lines and its hint short (message_problem)."""
    problem = message_problem(check)
    assert not problem, f"{name}: the message of {check['id']} is too long: {problem}"


def assert_says_words(entry):
    """A wrong entry lists the words its first message must contain (`says`); a correct one lists none."""
    if entry.check == "pass":
        assert not entry.says
    else:
        assert entry.says and all(isinstance(word, str) and word for word in entry.says), \
            f"{entry.name}: give the words its first message must contain (SAYS)"


def assert_names_the_mistake(entry, named):
    """The wrong entry's first message (its named check's) contains every word of entry.says, case aside."""
    message = named["message"].lower()
    missing = [word for word in entry.says if word.lower() not in message]
    assert not missing, (f"{entry.name} ({entry.what}): its first message does not say {missing}; it says: "
                         f"{named['message']}")
