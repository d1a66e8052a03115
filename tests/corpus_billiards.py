"""The Billiards mistake corpus: plausible student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter (starters/billiards_starter.py): the
lines strictly between a step's markers are replaced by the student's code for that step; a step the
entry does not give gets the solution's code, so the corpus follows the lab when the lab changes. An
entry that changes code OUTSIDE the steps lists exact (old, new) edits (tests/mutants.py).

Verdicts (tests/corpus_verdicts.py): a CORRECT entry passes every check; a WRONG one fails `check`,
naming `step`, with a first message holding the words of `says` and the mistake id of MISTAKE_IDS.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_files import CorpusFiles, with_says  # noqa: E402  (tests/corpus_files.py: starter + steps + edits)
from corpus_entries import makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "billiards_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "billiards.py")

STEPS = (2,)
CHECK_STEP = {"loads": None, "handout_unchanged": None, "runtime_lines": None, "normal_speed_right": 2, "runs": None}
FUNCTION_CHECKS = ("normal_speed_right",)


wrong, correct = makers(CHECK_STEP)


CORRECT = [
    correct("correct_solution_steps", "the solution's own step", why="the reference build"),
    correct("correct_components", "writes the dot product out by components", {2: """
        return (vb.x - va.x) * normal.x + (vb.y - va.y) * normal.y
    """}, why="the same sums in the same order"),
    correct("correct_two_dots", "projects each velocity, then subtracts", {2: """
        return vb.dot(normal) - va.dot(normal)
    """}, why="equal up to rounding, within the check's 1e-9 relative tolerance"),
    correct("correct_vector_product", "Vector2 * Vector2, pygame's dot product", {2: """
        relative = vb - va
        return relative * normal
    """}, why="pygame's Vector2 * Vector2 is the dot product"),
]

WRONG = [
    wrong("sign_flipped", "takes vA - vB", "normal_speed_right", {2: "return (va - vb).dot(normal)"},
          why="head-on along x reads +480 instead of -480"),
    wrong("only_b", "projects vB only", "normal_speed_right", {2: "return vb.dot(normal)"},
          why="B catching up with A reads -200 instead of -150"),
    wrong("only_a", "projects vA only", "normal_speed_right", {2: "return va.dot(normal)"},
          why="B falling onto A at rest reads 0"),
    wrong("length", "the length of the relative velocity", "normal_speed_right", {2: "return (vb - va).length()"},
          why="sliding past each other reads 200 instead of 0"),
    wrong("sum", "projects vB + vA", "normal_speed_right", {2: "return (vb + va).dot(normal)"},
          why="head-on along x reads 0"),
    wrong("cross", "a cross product instead of the dot product", "normal_speed_right",
          {2: "return (vb - va).cross(normal)"}, why="head-on along x reads 0"),
    wrong("absolute", "abs() of the projection", "normal_speed_right", {2: "return abs((vb - va).dot(normal))"},
          why="an approaching pair reads positive"),
    wrong("halved", "half the projection", "normal_speed_right", {2: "return (vb - va).dot(normal) / 2"},
          why="head-on along x reads -240"),
    wrong("clamped", "keeps only approaching speeds", "normal_speed_right",
          {2: "return min(0.0, (vb - va).dot(normal))"}, why="separating along y reads 0 instead of 170"),
    wrong("x_only", "the x part of the relative velocity", "normal_speed_right", {2: "return vb.x - va.x"},
          why="B falling onto A reads 0"),
    wrong("returns_none", "computes the speed but returns nothing", "normal_speed_right", {2: """
        speed = (vb - va).dot(normal)
    """}, why="the function returns None: the checker must say it needs a number, not crash"),
    wrong("outside_scene_changed", "edits make_scene(): the first crate starts on the floor", "handout_unchanged",
          edits=[('"pos": [300, 240]})', '"pos": [300, 540]})')],
          why="code outside the steps differs from the handout"),
]

SAYS = {
    "sign_flipped": ("A's velocity relative to B's",), "only_b": ("only B's velocity",),
    "only_a": ("only A's velocity",), "length": ("the length of vB - vA",), "sum": ("vB + vA",),
    "cross": ("cross product",), "absolute": ("lost its sign",), "halved": ("halved",),
    "clamped": ("separating pair reads 0",), "x_only": ("only the x part",), "returns_none": ("a number",),
    "outside_scene_changed": ('"pos": [300, 540]',),
}
WRONG = with_says(WRONG, SAYS)

# the mistake id each entry's failing check must carry (--json's "mistake")
MISTAKE_IDS = {"sign_flipped": "normal_sign", "only_b": "normal_only_b", "only_a": "normal_only_a",
               "length": "normal_length", "sum": "normal_sum", "cross": "normal_cross", "absolute": "normal_abs",
               "halved": "normal_halved", "clamped": "normal_clamped", "x_only": "normal_x_only"}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_billiards.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
