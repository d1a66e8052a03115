"""A message names a mistake only when that one known wrong formula fits every probe case (issue 33, item 6).

Each file here makes TWO of a step's known mistakes at once (checker/causes.consistent_mistake): neither
formula alone gives the file's answers, so the first message must give the step and the values but name
neither cause (a cause the file does not have is a false lead). The single mistakes are corpus entries
(tests/corpus_tumbling_crates.py, tests/corpus_bullets.py), whose messages name them.
One checker run per lab, four files.
"""
import os
import textwrap

import pytest

import corpus_bullets
import corpus_tumbling_crates
import corpus_verdicts as verdicts

def plus(corpus, entry, step, old, new):
    """{step: code}: corpus entry `entry`'s step (one known mistake) with `old` changed to `new` (a second one)."""
    code = next(e for e in corpus.ENTRIES if e.name == entry).steps[step]
    assert code.count(old) == 1, (entry, old)
    return {step: code.replace(old, new)}


# (lab, name, corpus, {step: code}, the check that must fail first, the causes' words it must not contain)
COMBINED = [
    ("tumbling_crates", "union_on_unnormalised_axes",   # unnormalised axes and both shadows together
     corpus_tumbling_crates, plus(corpus_tumbling_crates, "sat_unnormalised_axes", 2,
                                  "min(max_a, max_b) - max(min_a, min_b)", "max(max_a, max_b) - min(min_a, min_b)"),
     "sat_axes", ("both shadows together", "not divided by their length")),
    ("tumbling_crates", "reversed_test_on_first_corners",   # the first corners and the test reversed
     corpus_tumbling_crates, plus(corpus_tumbling_crates, "normal_first_vertices", 3, "< 0", "> 0"),
     "sat_normal", ("wrong way round", "first corners", "every time", "never turned round")),
    ("bullets", "b_sign_without_the_two",   # b = -2 dp·dv and a for 2a
     corpus_bullets, plus(corpus_bullets, "toi_b_sign", 2, "/ (2 * a)", "/ a"),
     "toi_matches_root", ("b = -2 dp·dv", "the 2 of 2a")),
    ("bullets", "falsy_zero_with_a_point_bullet", corpus_bullets, {4: """
        if not circle_toi(bullet.pos, bullet.vel, 0, other.pos, Vector2(), bounding_radius(points, other.pos), dt):
            return None
    """}, "broad_test", ("t = 0.0 as no contact", "as a point", "wrong way round")),
]


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """{lab: {name: {check id: JSON}}}: one checker run per lab over its combined-mistake files."""
    out = {}
    for lab in ("tumbling_crates", "bullets"):
        directory = tmp_path_factory.mktemp(lab + "_combined")
        built = {}
        for lab_id, name, corpus, codes, _, _ in COMBINED:
            if lab_id == lab:
                source = corpus.fill(corpus.build("correct_solution_steps"),
                                     {step: textwrap.dedent(code).strip("\n") for step, code in codes.items()})
                built[name] = os.path.join(directory, f"{lab}_{name}.py")
                with open(built[name], "w", encoding="utf-8") as handle:
                    handle.write(source)
        out[lab] = verdicts.grade(built, lab)
    return out


@pytest.mark.parametrize("lab, name, corpus, codes, check, causes", COMBINED, ids=[c[1] for c in COMBINED])
def test_two_mistakes_at_once_fail_at_their_step_naming_neither(lab, name, corpus, codes, check, causes, graded):
    checks = graded[lab][name]
    first = next(c for c in checks.values() if c["status"] != "pass")
    assert first["id"] == check and first["status"] == "fail", verdicts.show(checks)
    stated = [words for words in causes if words.lower() in first["message"].lower()]
    assert not stated, f"{name}: the message names {stated}, a cause the file does not have alone: {first['message']}"
