"""What the window shows for each mistake a student makes in each lab's steps, and which step to look at.

One row per mistake: the lab, a key, the step it belongs to, the mistake in a few words, what the window
shows (measured: tests/test_symptoms.py applies each mistake to solutions/<lab>.py, runs the scene the row
names headless and asserts the symptom with a bound), and the symptom's kind. The lesson's Hint section
(lesson11/README.md) renders the Tumbling Crates rows with `markdown(lab)`, and each Going Further lab's page
(lesson11/labs/<lab>.md) its own; the checker's hints
(checker/labs/*/checks.py) may only name a symptom whose kind a row of their lab has (tests/test_symptoms.py
reads every hint with `kinds_named`).

Numbers are from the runs the test makes (seed 11, 60 frames a second, physics steps of 1/120 s); px, s, rad.
"""
import re
from typing import NamedTuple


class Symptom(NamedTuple):
    lab: str        # the lab's id (its folder in checker/labs/)
    key: str        # the mistake's key (tests/test_symptoms.py has its edit and its measurement)
    step: int       # the step whose code holds the mistake
    mistake: str    # what the student wrote, in a few words
    shows: str      # what the window shows
    kind: str       # one of KINDS


# Each kind of symptom and the words that name it in a hint or in the text (a regular expression, case-blind).
# Kinds no row has (explode, never_tip) are there so that a hint using the old, wrong diagnosis fails the test.
KINDS = {
    "fall_through": r"fall(s|ing)? (straight )?through the floor",
    "sink": r"\bsinks?\b|\bsinking\b",
    "fly_off": r"\bfl(y|ies) off\b",
    "thrown_out": r"thrown out of the window",
    "freeze_corner": r"freeze on (their|its) corners?",
    "stop_dead": r"stops? dead",
    "hardly_turn": r"hardly (turns?|tips?)",
    "hang": r"\bmid-air\b|hangs? in the air",
    "vanish": r"\bvanish(es)?\b",
    "crash": r"window never opens",
    "stays_inside": r"stays? inside the crate",
    "shoved": r"\bshov(e|es|ed)\b",
    "rolls_slower": r"rolls? .*slower",
    "no_turn": r"without turning|never turns",
    "spin_wrong_way": r"spins? the wrong way",
    "tunnel": r"tunnel",
    "looks_right": r"looks right",
    "never_settle": r"never settles?",
    "thin_air": r"thin air",
    "zero_division": r"ZeroDivisionError",
    "explode": r"explode|shot (apart|away)",
    "never_tip": r"never tip",
}

TABLE = (
    # ---------------------------------------------------------------- Tumbling Crates (its own scene, 3 s; clicked pile)
    Symptom("tumbling_crates", "sat_none", 2, "`sat()` still returns None (the placeholder left below the loop)",
            "all four crates fall through the floor; the HUD counts 0 contacts", "fall_through"),
    Symptom("tumbling_crates", "gap_continue", 2, "`continue` instead of `return None` on a gap",
            "crates hit thin air: the first crate is struck about 40 px above the ramp (the HUD counts a "
            "contact there), knocked sideways to the ramp's high end, and stays there", "thin_air"),
    Symptom("tumbling_crates", "normal_not_flipped", 3, "no flip: the normal is left as the edge gave it",
            "all four crates fall through the floor as if it were not there (2940 px/s after 3 s), though the "
            "HUD counts contacts while they pass; pause (P) and step (O): the red normals point down into "
            "the floor", "fall_through"),
    Symptom("tumbling_crates", "flip_reversed", 3, "the flip test reversed (`> 0`)",
            "the two crates that land on the floor sink into it (about 40 and 55 px) and stop there; the two "
            "on the ramp stop stuck through it", "sink"),
    Symptom("tumbling_crates", "flip_by_owner", 3, "the axis turned round when it is one of A's edge normals",
            "the four crates land and tip much as in the finished lab; click a pile of a dozen and some keep "
            "rocking on a corner: the pile never settles (`fast movers now: 3`)", "never_settle"),
    Symptom("tumbling_crates", "k_no_spin", 4, "`k` without the two spin terms",
            "corner landings kick far too hard: crates bounce about, spin at up to 20 rad/s, and one is "
            "thrown out of the window", "thrown_out"),
    Symptom("tumbling_crates", "k_divides", 4, "the spin terms divided by `inv_inertia`",
            "the window pauses as the first crate lands, naming ZeroDivisionError in resolve(): the floor's and "
            "the ramp's inv_inertia are 0", "zero_division"),
    Symptom("tumbling_crates", "friction_unclamped", 5, "no clamp: `jt` left as it is",
            "looks right here: the crates land, tip flat and rest; `python -m checker FILE --show` shows the "
            "checker's scene, where a crate thrown along the floor at 400 px/s stops dead", "looks_right"),
    Symptom("tumbling_crates", "friction_flipped", 5, "the clamped `jt` with its sign flipped",
            "friction drives the slide instead of braking it: crates spin up to 47 rad/s and are thrown out of "
            "the window", "thrown_out"),
    Symptom("tumbling_crates", "clamp_swapped", 5, "the clamp's bounds swapped: `max(mu * j, min(-mu * j, jt))`",
            "friction at full strength drives every slide: crates spin at hundreds of rad/s and all four are "
            "thrown out of the window", "thrown_out"),
    Symptom("tumbling_crates", "spin_missing", 6, "no spin lines in `apply_impulse`",
            "crates freeze on their corners: each one stays at the angle it landed, balanced on a corner, and "
            "never turns", "freeze_corner"),
    Symptom("tumbling_crates", "spin_swapped", 6, "the spin lines' signs swapped (A `+=`, B `-=`)",
            "crates fly off: every touch spins them faster, and within 3 s they are more than 19 000 px "
            "away", "fly_off"),
    Symptom("tumbling_crates", "spin_a_only", 6, "only A's spin line with the wrong sign (A `+=`)",
            "looks right with the four crates (they touch only the floor and the ramp, which never turn); "
            "click a pile of a dozen: crates landing on crates spin up and most are thrown out of the window",
            "thrown_out"),
    # ---------------------------------------------------------------- More Shapes (one or two shapes, 1.5 s)
    Symptom("more_shapes", "degrees", 2, "angles in degrees: `cos(360 k / sides)`",
            "the window never opens: the corners go round more than once, and the lab stops with 'a polygon "
            "must be convex (no dents)'", "crash"),
    Symptom("more_shapes", "centroid_sum", 3, "the centroid's sum not divided by 6 A",
            "a house vanishes: its corners are placed thousands of px from its centre, far outside the window",
            "vanish"),
    Symptom("more_shapes", "centroid_average", 3, "the average of the corners",
            "looks right: for a house the average is 1.4 px from the centroid and it lands as it should; the "
            "checker's centroid check finds it", "looks_right"),
    Symptom("more_shapes", "inertia_no_six", 4, "the triangle-fan sum without the 6",
            "shapes are six times too hard to turn: a hexagon pushed along the floor at 420 px/s hardly tips "
            "(it turns about 36° in all, rocking, against about 205° as it rolls over its corners)", "hardly_turn"),
    Symptom("more_shapes", "axes_of_a_only", 5, "only the first shape's edge directions",
            "a triangle falling past a box's corner stops in mid-air beside it, about 60 px above the floor",
            "hang"),
    # ---------------------------------------------------------------- Ball on the Ramp (the checker's scenes)
    Symptom("ball_on_ramp", "no_clamp", 2, "`t` not clamped to [0, 1]",
            "a ball rolling off the ramp's low end stops in mid-air there, leaning on the edge's line beyond "
            "the corner", "hang"),
    Symptom("ball_on_ramp", "inside_unflipped", 3, "the normal not flipped when the centre is inside",
            "a ball started inside a crate stays inside the crate: the push drives it on instead of out",
            "stays_inside"),
    Symptom("ball_on_ramp", "split_swapped", 4, "each body's share uses the other's inverse mass",
            "a ball started inside a crate comes out, but the heavy crate is shoved about 27 px and the light "
            "ball about 7 px: the other way round", "shoved"),
    Symptom("ball_on_ramp", "ring", 5, "I = m r² (a ring's) instead of ½ m r²",
            "the ball rolls down the ramp a quarter slower: a = ½ g sin θ = 184 px/s², not ⅔ g sin θ = 245",
            "rolls_slower"),
    Symptom("ball_on_ramp", "contact_at_centre", 6, "the contact point at the ball's centre",
            "the ball never turns: friction has no lever arm, so it holds the ball where it lands on the ramp",
            "no_turn"),
    Symptom("ball_on_ramp", "contact_behind", 6, "the contact point on the far side, `center - normal * radius`",
            "the ball rolls down at the right speed but spins the wrong way", "spin_wrong_way"),
    Symptom("ball_on_ramp", "no_friction", 7, "no friction impulse",
            "the ball slides down like an ice cube, without turning, at g sin θ (367 px/s²)", "no_turn"),
    Symptom("ball_on_ramp", "jt_flipped", 7, "`jt` with its sign flipped",
            "the ball spins the wrong way, faster and faster (over 50 rad/s), and shoots down the ramp",
            "spin_wrong_way"),
    # ---------------------------------------------------------------- Sleeping Crates (the checker's scene, 1.5 s)
    Symptom("sleeping_crates", "timer_never_reset", 2, "the timer never starts again from 0",
            "a crate thrown up hangs in the air: it falls asleep at the top of its throw, about 80 px above "
            "the floor", "hang"),
    Symptom("sleeping_crates", "timer_or", 2, "`or` instead of `and` between the two thresholds",
            "a crate thrown up hangs in the air: it does not spin, so with `or` it counts as calm all through "
            "its throw and falls asleep in flight", "hang"),
    Symptom("sleeping_crates", "moves_ignores_sleep", 3, "`moves()` ignores `asleep`",
            "looks right: the sleeping crates still look asleep and stay put, but they are simulated all the "
            "same, so the pile never gets cheaper; the checker counts the contact tests", "looks_right"),
    Symptom("sleeping_crates", "never_wakes", 4, "`wake_on_contact()` wakes nobody",
            "a crate dropped on the sleeping pile shoves its crates down: they sink about 35 px into the floor",
            "sink"),
    # ---------------------------------------------------------------- Bullets (CCD, 12 shots at 12000 px/s)
    Symptom("bullets", "no_touching_case", 2, "no `0.0` when the circles already touch",
            "under CCD (key 5) every bullet tunnels through the wall: once a bullet is inside the wall's "
            "bounding circle the earlier root is negative and the broad test says 'no hit'", "tunnel"),
    Symptom("bullets", "later_root", 2, "the later root `(-b + √disc) / 2a`",
            "looks right at the wall: the later root still lies within the step, so the exact test runs and "
            "finds the hit; the checker's circle-against-circle cases find it", "looks_right"),
    Symptom("bullets", "radius_half_width", 3, "the bounding radius as half the width",
            "under CCD every bullet tunnels through the 4 px wall: its bounding circle is 2 px in radius",
            "tunnel"),
    Symptom("bullets", "broad_inverted", 4, "the broad test's `is None` inverted",
            "under CCD every bullet tunnels: the exact test is skipped exactly when the bullet can reach",
            "tunnel"),
    Symptom("bullets", "no_resolve", 5, "no `resolve()` at the time of impact",
            "under CCD every bullet tunnels: it is moved to the wall and on through it with its old velocity",
            "tunnel"),
    Symptom("bullets", "whole_step_first", 5, "the whole step moved before resolving",
            "under CCD bullets tunnel: the bullet is already past the wall when it is resolved", "tunnel"),
)

# the labs of the lesson, which have a table (a lab an instructor adds has none until its rows are written)
LABS = tuple(dict.fromkeys(row.lab for row in TABLE))


def rows(lab):
    """The table's rows of one lab, in step order."""
    return [row for row in TABLE if row.lab == lab]


def kinds_named(text):
    """The kinds of symptom a text names (by KINDS' words)."""
    return {kind for kind, words in KINDS.items() if re.search(words, text, re.IGNORECASE)}


def markdown(lab):
    """The lab's rows as a Markdown table: what you see, what you wrote, the step to look at."""
    lines = ["| what the window shows | what was written | look at |", "|---|---|---|"]
    for row in rows(lab):
        shows = row.shows[0].upper() + row.shows[1:]
        lines.append(f"| {shows} | {row.mistake} | step {row.step} |")
    return "\n".join(lines)

