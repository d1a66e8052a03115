"""lesson11/README.md stands on its own: it cites no document the student does not have, its links and the
World methods it names exist, and the seed's false claims it corrected do not come back.

(What the text says the windows show is held by tests/test_step_promises.py and tests/test_symptoms.py.)
"""
import os
import re

import pytest

from lesson11.physics2d import World

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LESSON = os.path.join(ROOT, "lesson11", "README.md")


def text():
    with open(LESSON, encoding="utf-8") as handle:
        return handle.read()


@pytest.mark.parametrize("phrase", [
    "the lesson's own listing", "the lesson says", "lesson text's order", "the lesson's listing",  # finding 9
    "roughly every second contact", "about half",                                                # finding 1
    "nothing changes on screen",                                                                 # finding 2
    "shorter than the target",                                                                   # finding 3
    "kg·px",                                                                                     # finding 13
])
def test_no_reference_to_what_the_student_lacks_nor_a_corrected_claim(phrase):
    student_part = text().split("## Instructor notes")[0]   # the notes quote the corrected claims
    assert "## Instructor notes" in text() and phrase.lower() not in student_part.lower()


def test_every_local_link_exists():
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", text())
    local = [link for link in links if not re.match(r"[a-z]+://", link)]
    assert local, "no links found"
    missing = [link for link in local if not os.path.exists(os.path.join(ROOT, "lesson11", link))]
    assert missing == []


def test_the_bench_section_it_links_to_exists():
    assert "(bench/README.md#the-lesson-texts-measurements)" in text()
    with open(os.path.join(ROOT, "lesson11", "bench", "README.md"), encoding="utf-8") as handle:
        assert "\n## The lesson text's measurements\n" in handle.read()


def test_every_world_method_it_names_exists():
    named = set(re.findall(r"World\.([a-z_]+)", text()))
    assert named and {name for name in named if not hasattr(World, name)} == set()


def test_the_whole_engine_in_one_file_is_linked():
    assert "The whole engine in one file, [`bench/listing.py`](bench/listing.py)" in text()
