"""The Bullets mistake corpus: plausible student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter
(starters/bullets_starter.py): the lines strictly between a step's start
marker (`# --- step N: ... ---`) and its end marker (`# --- end of step N ---`)
are replaced by the student's code for that step; a step the entry does not
give gets the solution's code, read from the same regions of
solutions/bullets.py, so the corpus follows the lab when the lab changes.
An entry that changes code OUTSIDE the steps lists exact (old, new) edits,
applied after the steps are filled; each old must occur exactly once
(tests/mutants.py).

Verdicts:
  CORRECT entries: every check passes.
  WRONG entries: `check` fails (or errors, for a crash; `status` lists what is
  accepted) and its JSON `step` is `step`; every other function check passes,
  and so do loads, handout_unchanged and runtime_lines unless the mistake is
  outside the steps (then handout_unchanged is the check that fails). The scene
  checks need every function check, so they are not constrained for a wrong entry.

Each entry's `why` says which input shows the mistake (wrong) or why the code is
the lesson's formula in another style (correct).

    build(name) -> source text
    write_corpus(directory, names=None) -> {name: path}
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_files import CorpusFiles, second_mistake, with_says  # noqa: E402  (tests/corpus_files.py: starter + steps + edits)
from corpus_entries import code, makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)
from wrong_kinds import AS_TEXT, NUMBER, TOI, V, after_solution, before_solution, returns, substituted, wrapped  # noqa: E402  (tests/wrong_kinds.py)


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "bullets_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "bullets.py")
STEPS = (2, 3, 4, 5)

# the checker's checks and the lesson step each one's hint names
CHECK_STEP = {
    "loads": None, "handout_unchanged": None, "runtime_lines": None,
    "toi_matches_root": 2, "bounding_circle": 3, "broad_test": 4, "swept_move_resolves": 5,
    "runs": None, "ccd_never_tunnels": None, "substeps_still_tunnel": None, "crate_momentum": None,
}
FUNCTION_CHECKS = ("toi_matches_root", "bounding_circle", "broad_test", "swept_move_resolves")


wrong, correct = makers(CHECK_STEP)


# the first lines of step 2 as the lesson writes them, indented like the entries' code below
TOI_HEAD = """
        c = dp.dot(dp) - reach * reach
        if c <= 0:
            return 0.0
        a = dv.dot(dv)
        b = 2 * dp.dot(dv)
        disc = b * b - 4 * a * c"""

WRONG = [
    # ---- step 2: circle_toi
    wrong("toi_later_root", "takes the later root (-b + √disc) / 2a", "toi_matches_root", {2: TOI_HEAD + """
        if a == 0 or disc < 0:
            return None
        t = (-b + math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, why="head-on at 3000 px/s: 22.3 ms (when the circles would stop touching) instead of 17.7 ms"),
    wrong("toi_disc_sign_flipped", "returns None when the discriminant is POSITIVE", "toi_matches_root", {2: TOI_HEAD + """
        if a == 0 or disc > 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, status=("fail", "error"), why="every real hit (disc > 0) is reported as a miss"),
    wrong("toi_a_not_squared", "a = |dv| instead of dv·dv = |dv|²", "toi_matches_root", {2: """
        c = dp.dot(dp) - reach * reach
        if c <= 0:
            return 0.0
        a = dv.length()
        b = 2 * dp.dot(dv)
        disc = b * b - 4 * a * c
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, why="the head-on time comes out thousands of times too large (or no contact at all)"),
    wrong("toi_twice", "divides by a instead of 2a: the time comes out twice too long", "toi_matches_root",
          {2: TOI_HEAD + """
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / a
        return t if 0 <= t <= dt else None
    """}, why="head-on at 3000 px/s: 35.3 ms instead of 17.7 ms, past dt, so None"),
    wrong("toi_no_past_check", "no early-out for circles moving apart (negative t returned)", "toi_matches_root",
          {2: TOI_HEAD + """
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if t <= dt else None
    """}, why="two circles moving apart get a time in the past, -0.17 s"),
    wrong("toi_no_touching_case", "forgets the already-touching case (c <= 0)", "toi_matches_root", {2: """
        c = dp.dot(dp) - reach * reach
        a = dv.dot(dv)
        b = 2 * dp.dot(dv)
        disc = b * b - 4 * a * c
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, why="overlapping circles: the earlier root is -0.01 s, so None instead of 0.0"),
    wrong("toi_ignores_dt", "returns a root later than this step's dt", "toi_matches_root", {2: TOI_HEAD + """
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if t >= 0 else None
    """}, why="a circle 195 px away at 1200 px/s is hit after 0.16 s, not within 1/120 s"),
    wrong("toi_b_sign", "b = -2 dp·dv (the gap taken the other way round)", "toi_matches_root", {2: """
        c = dp.dot(dp) - reach * reach
        if c <= 0:
            return 0.0
        a = dv.dot(dv)
        b = -2 * dp.dot(dv)
        disc = b * b - 4 * a * c
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, why="approaching circles get negative roots: no contact"),
    wrong("toi_parallel_crash", "no a == 0 test: parallel paths at the same velocity divide by zero",
          "toi_matches_root", {2: TOI_HEAD + """
        if disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, status=("error", "fail"), why="ZeroDivisionError for two circles moving together"),
    # issue 40: b without its factor 2; the bound hard-coded to 1/120 s
    wrong("toi_b_without_two", "b = dp·dv, without its factor 2", "toi_matches_root", {2: """
        c = dp.dot(dp) - reach * reach
        if c <= 0:
            return 0.0
        a = dv.dot(dv)
        b = dp.dot(dv)
        disc = b * b - 4 * a * c
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= dt else None
    """}, why="head-on, b² - 4ac is negative: no contact where the circles do meet"),
    wrong("toi_bound_fixed_step", "keeps t only up to 1/120 s, the course's step, not the dt given",
          "toi_matches_root", {2: TOI_HEAD + """
        if a == 0 or disc < 0:
            return None
        t = (-b - math.sqrt(disc)) / (2 * a)
        return t if 0 <= t <= 1 / 120 else None
    """}, why="head-on at 3000 px/s with dt = 1/30 s: the contact at 17.7 ms is dropped"),
    # ---- step 3: bounding_radius
    # issue 33: values that name their formula
    wrong("bounding_squared", "the farthest corner's squared distance (no square root)", "bounding_circle", {3: """
        return max((p - centre).length_squared() for p in points)
    """}, why="a 40 x 40 crate gets 800 = 28.28² px"),
    wrong("bounding_from_origin", "the farthest corner's distance from (0, 0), not from the centre", "bounding_circle",
          {3: """
        return max(p.length() for p in points)
    """}, why="a crate at (380, 540) gets 680 px"),
    wrong("bounding_half_width", "half the width (largest |x - centre.x|)", "bounding_circle", {3: """
        return max(abs(p.x - centre.x) for p in points)
    """}, why="a 40 x 40 crate gets 20 px instead of 28.3: its corners stick out"),
    wrong("bounding_nearest_corner", "the NEAREST point's distance", "bounding_circle", {3: """
        return min(centre.distance_to(p) for p in points)
    """}, why="right for boxes around their centre; the uneven pentagon shows it"),
    wrong("bounding_average", "the average distance to the points", "bounding_circle", {3: """
        return sum(centre.distance_to(p) for p in points) / len(points)
    """}, why="the uneven pentagon's farthest corner is outside the average"),
    # ---- step 4: the broad test
    wrong("broad_test_missing", "no broad test: every crate goes to the exact swept test", "broad_test", {4: """
        pass
    """}, why="a crate the bullet cannot reach still costs a circle_polygon_toi() call"),
    wrong("broad_zero_is_falsy", "`if not circle_toi(...)`: t = 0.0 (inside the bounding circle) counts as a miss",
          "broad_test", {4: """
        if not circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(),
                          bounding_radius(points, other.pos), dt):
            return None
    """}, why="a bullet already inside a tall crate's bounding circle, 1 px from its side, never hits it"),
    wrong("broad_inverted", "returns None when the bounding circle IS reached", "broad_test", {4: """
        if circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(),
                      bounding_radius(points, other.pos), dt) is not None:
            return None
    """}, why="every crate that could be hit is skipped"),
    wrong("broad_without_bullet_radius", "the broad test treats the bullet as a point (radius 0)", "broad_test",
          {4: """
        if circle_toi(bullet.pos, bullet.vel, 0, other.pos, Vector2(), bounding_radius(points, other.pos),
                      dt) is None:
            return None
    """}, why="a bullet whose centre passes 1.2 px outside a turned crate's bounding circle grazes its corner: "
              "the solution finds the hit, this broad test lets it tunnel"),
    # ---- step 5: the swept move
    wrong("swept_contact_far_side", "resolves at the far side of the bullet, bullet.pos - normal * radius",
          "swept_move_resolves", {5: """
        bullet.pos += bullet.vel * t
        world.resolve(bullet, other, normal, bullet.pos - normal * bullet.radius)
        bullet.pos += bullet.vel * (dt - t)
    """}, why="an off-centre, slanted hit with friction: the impulse's lever arm is wrong, so the crate's spin and "
              "the bullet's bounce differ from the lesson's"),
    wrong("swept_stops_at_impact", "moves to the impact and resolves, but never spends the rest of the step",
          "swept_move_resolves", {5: """
        bullet.pos += bullet.vel * t
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
    """}, why="the bullet stays stuck at the wall's face for the rest of the step"),
    wrong("swept_normal_reversed", "resolves with the normal reversed, resolve(..., -normal, ...)",
          "swept_move_resolves", {5: """
        bullet.pos += bullet.vel * t
        world.resolve(bullet, other, -normal, bullet.pos + normal * bullet.radius)
        bullet.pos += bullet.vel * (dt - t)
    """}, why="resolve() sees the bodies moving apart and does nothing: the bullet goes on through (it was told it "
              "'kept its velocity from before the hit', which is another mistake)"),
    wrong("swept_old_velocity", "spends the rest of the step with the velocity from before the hit",
          "swept_move_resolves", {5: """
        velocity = Vector2(bullet.vel)
        bullet.pos += velocity * t
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        bullet.pos += velocity * (dt - t)
    """}, why="the bullet ends 40 px past the wall at 12000 px/s"),
    wrong("swept_whole_step_after", "moves a whole dt after the impact instead of dt - t", "swept_move_resolves", {5: """
        bullet.pos += bullet.vel * t
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        bullet.pos += bullet.vel * dt
    """}, why="the bounce goes back too far: the step lasted t + dt"),
    wrong("swept_resolve_before_move", "resolves at the start of the step, then moves the whole dt", "swept_move_resolves",
          {5: """
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
        bullet.pos += bullet.vel * dt
    """}, why="the bullet turns back before it reaches the wall: it never touches it"),
    # issue 40: the contact at the bullet's centre; the whole step, then resolve
    wrong("swept_contact_at_centre", "resolves at the bullet's centre, world.resolve(..., bullet.pos)",
          "swept_move_resolves", {5: """
        bullet.pos += bullet.vel * t
        world.resolve(bullet, other, normal, bullet.pos)
        bullet.pos += bullet.vel * (dt - t)
    """}, why="the off-centre, slanted hit: the lever arm ends 3 px short, so the crate spins differently"),
    wrong("swept_move_then_resolve", "moves the whole step, then resolves where it ended", "swept_move_resolves",
          {5: """
        bullet.pos += bullet.vel * dt
        world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
    """}, why="the bullet is already past the impact (through the wall at 12000 px/s) when it resolves"),
    # ---- outside the steps
    wrong("wall_thickened", "makes the wall 20 px thick so nothing tunnels", "handout_unchanged",
          edits=[("WALL_WIDTH = 4.0 ", "WALL_WIDTH = 20.0 ")], why="a handed-out constant changed"),
    wrong("world_not_hooked", "BulletWorld no longer uses this file's swept_move()", "handout_unchanged",
          edits=[("    def swept_move(self, bullet, dt):\n        swept_move(self, bullet, dt)\n",
                  "    pass\n")], why="the World's own swept move would run instead of the student's"),
]

CORRECT = [
    correct("correct_solution_steps", "the solution's own code in every step", {},
            why="the reference build is the solution, byte for byte"),
    correct("correct_half_b", "the quadratic with half of b (b' = dp·dv, t = (-b' - √(b'² - ac)) / a)", {2: """
        c = dp.dot(dp) - reach ** 2
        if c <= 0:
            return 0.0
        a = dv.dot(dv)
        half_b = dp.dot(dv)
        quarter_disc = half_b * half_b - a * c
        if a == 0 or quarter_disc < 0:
            return None
        t = (-half_b - math.sqrt(quarter_disc)) / a
        if t < 0 or t > dt:
            return None
        return t
    """}, why="dividing the quadratic by 2 changes no root"),
    correct("correct_stable_root", "the earlier root as 2c / (-b + √disc), squared distances, a named broad result",
            {2: TOI_HEAD + """
        if a == 0 or disc < 0:
            return None
        t = 2 * c / (-b + math.sqrt(disc))  # the same root, without cancellation
        return t if 0 <= t <= dt else None
    """, 3: """
        return math.sqrt(max((p - centre).length_squared() for p in points))
    """, 4: """
        reach_time = circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(),
                                bounding_radius(points, other.pos), dt)
        if reach_time is None:
            return None
    """}, why="(-b - √disc)/2a = 2c/(-b + √disc) when the earlier root is positive; the same radius squared first"),
    correct("correct_named_rest", "swept move with the remaining time named and the contact point named", {5: """
        remaining = dt - t
        bullet.pos = bullet.pos + bullet.vel * t
        contact = bullet.pos + normal * bullet.radius
        world.resolve(bullet, other, normal, contact)
        bullet.pos = bullet.pos + bullet.vel * remaining
    """}, why="the same three moves in other words"),
]

# the words each wrong entry's first message must contain: it names the mistake, not only the step (issue 33)
SAYS = {
    "toi_later_root": ("later root",),
    "toi_disc_sign_flipped": ("ValueError", "negative discriminant"),
    "toi_a_not_squared": ("a = |dv|",),
    "toi_twice": ("twice the first-contact time",),
    "toi_no_past_check": ("negative time",),
    "toi_no_touching_case": ("already overlap",),
    "toi_ignores_dt": ("later than this step's dt",),
    "toi_b_sign": ("b = -2 dp·dv",),
    "toi_parallel_crash": ("division by zero",),
    "bounding_squared": ("squared distance",),
    "bounding_from_origin": ("from (0, 0)",),
    "bounding_half_width": ("half the width",),
    "bounding_nearest_corner": ("nearest corner",),
    "bounding_average": ("average distance",),
    "broad_test_missing": ("broad test should have returned None",),
    "broad_zero_is_falsy": ("counts t = 0.0 as no contact",),
    "broad_inverted": ("broad test is the wrong way round",),
    "broad_without_bullet_radius": ("treats the bullet as a point",),
    "swept_contact_far_side": ("far side of the bullet",),
    "swept_stops_at_impact": ("stopped at the impact",),
    "swept_old_velocity": ("velocity from before the hit",),
    "swept_normal_reversed": ("normal reversed",),
    "swept_whole_step_after": ("whole dt more",),
    "swept_resolve_before_move": ("resolved where the bullet starts the step",),
    "swept_contact_at_centre": ("bullet's centre",),
    "swept_move_then_resolve": ("moved the whole step, then resolved",),
    "toi_b_without_two": ("without its factor 2",),
    "toi_bound_fixed_step": ("only up to 1/120 s",),
    "wall_thickened": ("WALL_WIDTH = 20.0",),
    "world_not_hooked": ("swept_move",),
}
WRONG = with_says(WRONG, SAYS)

# What tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself (each key optional):
# short (its entries' name prefix), mechanisms (the issue-35 mechanisms that apply; tests/corpus_attacks.py
# says why), library_name / library_owner (the library's answer to the first step where it is not the first
# STEP_LIBRARY name), world_call, hidden, forger and side (the attacks' code where the default does not fit).
ATTACK = {
    "short": "bu",
    "mechanisms": (1, 2, 5, 6, 7, 8),
    "world_call": "return World().swept_move and None",
    "side": (2, "circle_toi", "from lesson11.physics2d import circle_toi as found", "toi_matches_root"),
}

# The wrong-kind values its step functions must fail on, never the checker (tests/test_wrong_kinds.py):
# [(function, step, [case, ...])], the cases written as tests/wrong_kinds.py says.
WRONG_KINDS = [("circle_toi", 2, returns(NUMBER) + wrapped(["None if answer is None else str(answer)",
                                                            "None if answer is None else [answer]"])),
               ("bounding_radius", 3, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]"])),
               ("time_of_impact", 4, returns(TOI) + before_solution(["bullet.vel = (1.0, 2.0)", "other.omega = 'x'"])),
               ("swept_move", 5, after_solution(["bullet.pos = (1.0, 2.0)", "bullet.vel = 'fast'",
                                                 f"bullet.pos = {V}(float('nan'), 0)",
                                                 f"bullet.omega = {V}(1, 0)", "bullet.vel = None"])
                + substituted("normal, bullet.pos + normal * bullet.radius)",
                              ["normal, 'here')",
                               "normal, None)", "tuple(normal), bullet.pos + normal * bullet.radius)"]))]

# The wrong entry `python -m checker FILE --show` is tried on (tests/test_checker_show.py): one wrong step
# whose scene differs visibly from the solution's, and the kind of failing case --show draws for it.
SHOW_ENTRY, SHOW_CASE = 'swept_whole_step_after', 'SweptCase'

# the mistake id each entry's failing check must carry (issue 40: --json's "mistake")
MISTAKE_IDS = {
    "toi_twice": "toi_no_two", "toi_a_not_squared": "toi_a_unsquared", "toi_b_sign": "toi_b_sign",
    "toi_later_root": "toi_later_root", "toi_b_without_two": "toi_b_no_two", "toi_bound_fixed_step": "toi_fixed_dt",
    "swept_contact_far_side": "swept_far_side", "swept_stops_at_impact": "swept_stops",
    "swept_old_velocity": "swept_old_velocity", "swept_whole_step_after": "swept_whole_step",
    "swept_resolve_before_move": "swept_resolve_first", "swept_contact_at_centre": "swept_at_centre",
    "swept_move_then_resolve": "swept_move_then_resolve",
}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}

# Two known mistakes at once (tests/test_named_causes.py): the first message names the step and the values and
# neither cause. {name: (the check that fails first, {step: code}, the causes' words it must not say)}
COMBINED = {
    "b_sign_without_the_two": (   # b = -2 dp·dv and a for 2a
        "toi_matches_root", second_mistake(ENTRIES, "toi_b_sign", 2, "/ (2 * a)", "/ a"),
        ("b = -2 dp·dv", "the 2 of 2a")),
    "falsy_zero_with_a_point_bullet": ("broad_test", {4: code("""
        if not circle_toi(bullet.pos, bullet.vel, 0, other.pos, Vector2(), bounding_radius(points, other.pos), dt):
            return None
    """)}, ("t = 0.0 as no contact", "as a point", "wrong way round")),
}


# ================================================================ building the files (tests/corpus_files.py)

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_bullets.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
