"""What a lab's mistake corpus (tests/corpus_<id>.py) is made of: its entries, and the two ways to write one.

A corpus sets CHECK_STEP (check id -> the lesson step its hint names) and takes `wrong, correct = makers(CHECK_STEP)`;
tests/corpus_verdicts.py says what the tests hold each entry to.
"""
import textwrap
from typing import NamedTuple


class Entry(NamedTuple):
    name: str
    what: str            # what the student did, one line
    steps: dict          # {step: code} (dedented; "" leaves the step empty)
    edits: tuple         # ((old, new), ...) outside the steps, applied after the steps are filled
    check: str           # "pass" for a correct completion, else the id of the check that must fail
    step: object         # the lesson step the failing check's hint names (None for a correct entry)
    status: tuple        # accepted statuses of that check
    also: tuple          # other checks this mistake may fail too
    why: str             # the input that shows the mistake, or why a correct variant is correct
    says: tuple = ()     # wrong entries: the words the first message must contain (it names the mistake)


def code(text):
    """A step's code as written in the corpus, dedented, without its first and last blank lines."""
    return textwrap.dedent(text).strip("\n")


def makers(check_step):
    """(wrong, correct): the two ways a corpus writes an entry, for its CHECK_STEP."""
    def wrong(name, what, check, steps=None, edits=(), status=("fail",), also=(), why=""):
        return Entry(name, what, {k: code(v) for k, v in (steps or {}).items()}, tuple(edits), check,
                     check_step[check], tuple(status), tuple(also), why)

    def correct(name, what, steps=None, edits=(), why=""):
        return Entry(name, what, {k: code(v) for k, v in (steps or {}).items()}, tuple(edits), "pass", None,
                     ("pass",), (), why)
    return wrong, correct
