"""The documents stand on their own and stay short and true.

lesson11/README.md (the student's lesson) is at most 5,800 words, cites no document the student does not have,
and the false claims once corrected do not come back; the root README is at most 250 lines and names no issue;
every local link in the documents a reader meets resolves, anchors included; the pass count the lesson gives is
what the World runs; the World methods the documents name exist.

(What the text says the windows show is held by tests/test_step_promises.py and tests/test_symptoms.py, the flip
by tests/test_flip_truth.py, the worked k and j by tests/test_worked_impulse.py.)
"""
import os
import re

import pytest
from pygame import Vector2

from lesson11.physics2d import Body, World, box_points
from lesson11.physics2d.response import resolve

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LESSON = os.path.join(ROOT, "lesson11", "README.md")
MAX_WORDS, MAX_README_LINES = 5800, 250
DOCUMENTS = ["README.md", "lesson11/README.md", "lesson11/INSTRUCTORS.md", "lesson11/physics2d/README.md",
             "lesson11/labs/more_shapes.md", "lesson11/labs/ball_on_ramp.md", "lesson11/labs/sleeping_crates.md",
             "lesson11/labs/bullets.md", "lesson11/examples/README.md"]


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


def text():
    return read("lesson11/README.md")


def test_the_lesson_is_no_longer_than_the_original():
    words = len(text().split())
    print(f"lesson11/README.md: {words} words (at most {MAX_WORDS})")
    assert words <= MAX_WORDS


def test_the_root_readme_is_one_screenful_of_commands_and_names_no_issue():
    readme = read("README.md")
    lines = readme.count("\n")
    print(f"README.md: {lines} lines (at most {MAX_README_LINES})")
    assert lines <= MAX_README_LINES
    assert not re.search(r"\bissues?\s*#?\d+|#\d{1,4}\b", readme, re.IGNORECASE)


@pytest.mark.parametrize("phrase", [
    "the lesson's own listing", "the lesson says", "lesson text's order", "the lesson's listing",  # cites the seed
    "roughly every second contact", "wrong, every time", "wrong exactly when",                   # the flip
    "nothing changes on screen",                                                                 # step 4
    "shorter than the target", "size of the target",                                             # sub-stepping
    "kg·px", "Press D to", "give the same intervals", "solid ball", "Box2D-Lite and Gaul",
    "I pressed Left twice", "7 passes", "crates on the ramp stay where they are",
])
def test_no_reference_to_what_the_student_lacks_nor_a_corrected_claim(phrase):
    for rel in ["lesson11/README.md"] + [d for d in DOCUMENTS if d.startswith("lesson11/labs/")]:
        assert phrase.lower() not in read(rel).lower(), (rel, phrase)


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    heading = re.sub(r"[`*]", "", heading.strip().lower())
    return re.sub(r"\s", "-", re.sub(r"[^\w\s-]", "", heading))


def anchors(rel):
    return {slug(line.lstrip("#")) for line in read(rel).splitlines() if re.match(r"#{1,6} ", line)}


@pytest.mark.parametrize("rel", DOCUMENTS)
def test_every_local_link_and_anchor_resolves(rel):
    folder = os.path.dirname(os.path.join(ROOT, rel))
    links = re.findall(r"\]\(([^)\s]+)\)", read(rel))
    assert links
    for link in links:
        if re.match(r"[a-z]+://", link):
            continue
        target, _, anchor = link.partition("#")
        path = os.path.normpath(os.path.join(folder, target)) if target else os.path.join(ROOT, rel)
        assert os.path.exists(path), f"{rel} links to missing {target}"
        if anchor:
            assert path.endswith(".md"), f"{rel}: an anchor into {target}"
            assert anchor in anchors(os.path.relpath(path, ROOT)), f"{rel} links to missing #{anchor} in {target}"


def test_the_bench_section_instructors_are_sent_to_exists():
    assert "(bench/README.md#the-lesson-texts-measurements)" in read("lesson11/INSTRUCTORS.md")
    assert "\n## The lesson text's measurements\n" in read("lesson11/bench/README.md")


@pytest.mark.parametrize("rel", DOCUMENTS)
def test_every_world_method_it_names_exists(rel):
    named = set(re.findall(r"World\.([a-z_]+)", read(rel)))
    world = World()
    assert {name for name in named if not hasattr(world, name)} == set()


def test_the_whole_engine_in_one_file_is_linked():
    assert "The whole engine in one file, [`bench/listing.py`](../bench/listing.py)" in read("lesson11/physics2d/README.md")


def test_resolve_runs_28_times_per_contact_point_per_step_as_the_lesson_says():
    """4 sub-steps × (1 impact pass + 6 passes): a box resting flat on a floor, two contact points."""
    calls = []

    def counting(a, b, normal, point):
        calls.append(point)
        resolve(a, b, normal, point)

    floor = Body(box_points(400, 40), (200, 420), 0)
    crate = Body(box_points(60, 40), (200, 380.2), 2.4)
    world = World([floor, crate], resolve=counting)
    world.step()
    assert world.substeps == 4 and world.iterations == 6
    assert len(calls) == 4 * (1 + 6) * 2
    assert "4 × (1 + 6) = 28" in " ".join(text().split())
    assert "4 × (1 + 6) = 28" in " ".join(read("lesson11/physics2d/README.md").split())
