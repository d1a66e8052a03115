"""Ball on the Ramp (Lesson 11, Going Further): the checks, their bounds and the hints.

Order of checks (stable), one per lesson step where a step is the student's:
  loads, handout_unchanged, runtime_lines,
  closest_point (step 2), inside_case (step 3), push_out_split (step 4), ball_inertia (step 5),
  contact_on_surface (step 6), friction_rolls (step 7),
  runs, then the four done-criteria: rolls_without_slipping, slides_without_friction,
  knocks_crate_over, pushed_out_of_crate.
Checks are worth 1 point, the four criteria 2 points each.

The function steps are declared in probes.py; the scenes (scenes.py) run only when every function check
passes, so a mistake is reported once, under its own step.

Every bound of the criteria comes from the issue (rolling within 2 % and 3 %,
sliding within 1 %, sinking at most 1 px) or was set from what
solutions/ball_on_ramp.py measures in the same scene, noted beside it.
"""
import math

from . import probes, scenes
from checker.judging import criteria, lab_checks
from checker.judging.criteria import Bound, Criterion
from checker.judging.checks import Hint, Registry

TITLE = "Ball on the Ramp"
# the library functions each step asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("closest_on_segment",), 3: ("circle_polygon",), 4: ("separate", "lesson_separate"),
                5: ("inertia", "inv_inertia", "Circle", "Body"), 6: ("circle_contact_point", "circle_point"),
                7: ("resolve", "lesson_resolve")}
STEP_ADVICE = {2: "clamp t to [0, 1] on the edge yourself",
               3: "handle the centre inside the polygon yourself",
               4: "split the push-out by inverse mass yourself",
               5: "write ½ m r² yourself",
               6: "put the contact point on the ball's surface yourself",
               7: "write the friction impulse at the contact point yourself"}

# ---------------------------------------------------------------- bounds of the criteria
ROLL_ACCEL = 0.03      # relative to ⅔ g sin θ = 244.74 px/s² (the issue); solution: 244.743, off by 0.0000 %
ROLL_SLIP = 0.02       # |ω r - v| / v (the issue); solution: 2e-15
SLIDE_ACCEL = 0.01     # relative to g sin θ = 367.11 px/s² (the issue); solution: 367.114, off by 0.0000 %
SLIDE_SPIN = 0.05      # rad/s (1 px/s at the rim of a 20 px ball); solution: 3e-14
SINK = 1.0             # px into the ramp, the floor or a crate (the issue); solution: ramp 0.010, knock 0.43 (a crate)
KNOCK_TURN = math.radians(60)   # the crate tips over; solution: 90.3° (it ends on its side)
KNOCK_MOVE = 20.0      # px the crate's centre moves; solution: 72.9
INSIDE_DEPTH = 1.0     # px of overlap left after 0.5 s; solution: 0.41 (the push-out's slop is 0.5)

# ---------------------------------------------------------------- the hints, in the lesson's terms
HINTS = {
    "clamp": Hint(2, "clamp t to the segment",
                  "A ball against a polygon: the closest point of an EDGE, not of its line: t = (p - a)·ab / (ab·ab), "
                  "kept within [0, 1] before the point a + ab t."),
    "closest": Hint(2, "the closest point on one edge",
                    "A ball against a polygon: t = (p - a)·ab / (ab·ab) runs from 0 at a to 1 at b; clamp it to "
                    "[0, 1]; the point is a + ab t."),
    "inside": Hint(3, "the center inside: push out the other way",
                   "A ball against a polygon: a ball's center inside leaves by the nearest edge: normal "
                   "-offset / dist (flipped), depth radius + dist."),
    "split": Hint(4, "split the push-out by inverse mass",
                  "Lesson §5, the push-out: each body's share is its 1/m over 1/m_A + 1/m_B, A back along the "
                  "normal, B forward; a static body (1/m = 0) never moves."),
    "inertia": Hint(5, "a solid disc's moment of inertia",
                    "Lesson §4: a solid disc has I = ½ m r², half a ring's m r²: mass near the center is easy to "
                    "spin."),
    "contact": Hint(6, "the contact point on the ball's surface",
                    "Lesson §3: the contact is on the ball's surface, center + normal * radius (the normal points "
                    "out of the ball), where friction has a lever arm."),
    "friction_missing": Hint(7, "friction makes it roll",
                             "Lesson §5: one friction impulse t * jt at the contact, jt = -rel·t / kt, kt with both "
                             "spin terms, clamped to [-mu j, mu j]."),
    "friction_sign": Hint(7, "the sign of the friction impulse",
                          "Lesson §5: friction opposes the slip, jt = -rel·t / kt, and the clamp keeps that sign."),
    "friction_clamp": Hint(7, "Coulomb's clamp on friction",
                           "Lesson §5: keep jt within [-mu j, mu j], j the normal impulse; leave a smaller jt, and "
                           "its sign, alone."),
    "friction_kt": Hint(7, "the spin terms of kt",
                        "Lesson §5: kt is k along t: 1/m_A + 1/m_B + (ra × t)²/I_A + (rb × t)²/I_B, both spin terms."),
    "friction_slip": Hint(7, "the slip along the tangent",
                          "Lesson §5: friction stops the slip, the part of rel along t: jt = -rel·t / kt, not the "
                          "whole relative speed."),
    "friction_centre": Hint(7, "friction acts at the contact point",
                            "Lesson §5: apply t * jt at the contact, with the normal impulse's lever arms ra and rb, "
                            "to a then b."),
    "friction_order": Hint(7, "the order of apply_impulse's arguments",
                           "Lesson §5: apply_impulse(a, b, impulse, ra, rb) takes A first with its lever arm ra: "
                           "the same order as the normal impulse."),
    "handout": lab_checks.handout_hint("the constants, the scene, make_ball, build, the World, the `# lab "
                                       "runtime` lines"),
    "runtime": lab_checks.RUNTIME_HINT,
    "settle": Hint(8, "watch it roll",
                   "The function checks pass, yet the ball misbehaves: press D and watch the contacts while it "
                   "rolls; compare your file with the handout around the steps."),
    "crash": Hint(1, "run the file",
                  "Run the file yourself (python ball_on_ramp.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("ramp", "knock", "inside"), "rolls_without_slipping": ("ramp",),
                  "slides_without_friction": ("ramp",), "knocks_crate_over": ("knock",), "pushed_out_of_crate": ("inside",)}

CHECKS = Registry()


# CPU s of the solution's run of each scene (measured 2026-11-23, one job on this 2-core machine): the
# grader starts the longest first, so a long scene does not start last and run alone.
SCENE_SECONDS = {"knock": 0.8, "ramp": 0.3, "inside": 0.3}


# ---------------------------------------------------------------- loading, the handout and the steps (probes.py)

lab_checks.register_common(CHECKS, HINTS, probes.REQUIRED)
for step in (probes.CLOSEST, probes.INSIDE, probes.SEPARATE, probes.INERTIA, probes.CONTACT, probes.FRICTION):
    step.register(CHECKS, HINTS)


# ---------------------------------------------------------------- the scenes and the lesson's criteria

lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, [check.id for check in CHECKS.checks],   # all the above
                         "main() runs each of the checker's three scenes to the end.",
                         more=lambda records: {name: run.record for name, run in records.items()})


def _roll(index, expected):
    def measure(records):
        roll = scenes.measure_roll(records["ramp"], index)
        return dict(roll, accel_off=abs(roll["accel"] - expected) / expected)
    return measure


def _inside(records):
    inside = scenes.measure_inside(records["inside"])
    return dict(inside, pushed_through=inside["side"] == "far", not_out=inside["side"] != "near")


LEFT, SANK = "the ball let go on the ramp did not stay on it", "the ball sank into the ramp"
INSIDE = "a ball started with its center inside a crate is not pushed out"
criteria.register(CHECKS, HINTS, (
    Criterion("rolls_without_slipping", "On the 22° ramp (mu 0.6) the ball rolls without slipping, |ω r - v| <= 2 % "
              "of v, at a = ⅔ g sin θ (criterion 1).", _roll(0, scenes.ROLLING), (
                  Bound("left_ramp", 0, LEFT, "settle"),
                  Bound("depth", SINK, SANK, "settle", "px", frame="depth_frame"),
                  Bound("accel_off", ROLL_ACCEL, "the ball does not roll down the ramp at ⅔ g sin θ", "settle"),
                  Bound("slip", ROLL_SLIP, "the ball slips on the ramp instead of rolling", "settle"))),
    Criterion("slides_without_friction", "On a frictionless ramp the ball slides at a = g sin θ (within 1 %) and "
              "does not spin (criterion 2).", _roll(1, scenes.SLIDING), (
                  Bound("left_ramp", 0, LEFT, "settle"),
                  Bound("depth", SINK, SANK, "settle", "px", frame="depth_frame"),
                  Bound("accel_off", SLIDE_ACCEL, "the frictionless ball does not slide at g sin θ", "friction_clamp"),
                  Bound("omega", SLIDE_SPIN, "the frictionless ball spins: with mu = 0 nothing can turn it",
                        "friction_clamp", "rad/s"))),
    Criterion("knocks_crate_over", "The ball rolls off the ramp and knocks a tall crate over, never sinking more "
              "than 1 px into anything (criterion 3).", lambda records: scenes.measure_knock(records["knock"]), (
                  Bound("depth", SINK, "the ball sank into {depth_into}", "settle", "px", frame="depth_frame"),
                  Bound("moved", KNOCK_MOVE, "the ball did not knock the tall crate over", "settle", "px", True),
                  Bound("turned", KNOCK_TURN, "the ball did not knock the tall crate over", "settle", "°", True,
                        180 / math.pi))),
    Criterion("pushed_out_of_crate", "A ball started with its center inside a crate is pushed out of the crate, not "
              "through it (criterion 4).", _inside, (
                  Bound("pushed_through", 0, "a ball with its center inside a crate was pushed through it", "inside"),
                  Bound("depth", INSIDE_DEPTH, INSIDE, "inside", "px"),
                  Bound("not_out", 0, INSIDE, "inside"))),
))
