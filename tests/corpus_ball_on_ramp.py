"""The Ball on the Ramp mistake corpus: plausible student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter
(starters/ball_on_ramp_starter.py): the lines strictly between a step's start
marker (`# --- step N: ... ---`) and its end marker (`# --- end of step N ---`)
are replaced by the student's code for that step; a step the entry does not
give gets the solution's code, read from the same regions of
solutions/ball_on_ramp.py, so the corpus follows the lab when the lab changes.
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
from corpus_files import CorpusFiles, with_says  # noqa: E402  (tests/corpus_files.py: starter + steps + edits)
from corpus_entries import makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)
from wrong_kinds import AS_TEXT, HIT, MOTION, NUMBER, PLACES, VECTOR, after_solution, returns, substituted, wrapped  # noqa: E402  (tests/wrong_kinds.py)


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "ball_on_ramp_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "ball_on_ramp.py")
STEPS = (2, 3, 4, 5, 6, 7)

# the checker's checks and the lesson step each one's hint names
CHECK_STEP = {
    "loads": None, "handout_unchanged": None, "runtime_lines": None,
    "closest_point": 2, "inside_case": 3, "push_out_split": 4, "ball_inertia": 5, "contact_on_surface": 6,
    "friction_rolls": 7,
    "runs": None, "rolls_without_slipping": None, "slides_without_friction": None, "knocks_crate_over": None,
    "pushed_out_of_crate": None,
}
FUNCTION_CHECKS = ("closest_point", "inside_case", "push_out_split", "ball_inertia", "contact_on_surface",
                   "friction_rolls")


wrong, correct = makers(CHECK_STEP)


WRONG = [
    # ---- step 2: the closest point on one edge
    wrong("closest_not_clamped", "projects onto the edge's line but never clamps t", "closest_point", {2: """
        t = (p - a).dot(ab) / ab.dot(ab)
        return a + ab * t
    """}, why="a point beyond the edge's end b gets a point on the line past b"),
    wrong("closest_divides_by_length", "divides by |ab| instead of ab·ab", "closest_point", {2: """
        t = (p - a).dot(ab) / ab.length()
        t = max(0.0, min(1.0, t))
        return a + ab * t
    """}, why="t is |ab| times too big: a point above the middle of a 100 px edge maps to its end"),
    wrong("closest_p_minus_b", "measures from b instead of a", "closest_point", {2: """
        t = (p - b).dot(ab) / ab.dot(ab)
        t = max(0.0, min(1.0, t))
        return a + ab * t
    """}, why="t is 1 less than it should be: every point beside the edge maps to a"),
    wrong("closest_moves_the_corner", "`a += ab * t; return a`: the right point, but the caller's corner moves",
          "closest_point", {2: """
        t = (p - a).dot(ab) / ab.dot(ab)
        t = max(0.0, min(1.0, t))
        a += ab * t
        return a
    """}, why="every answer is right, but a (a corner of the caller's polygon) is moved in place: circle_polygon's "
              "later edges and inside() see a different polygon"),
    # ---- step 3: the center inside
    wrong("inside_not_flipped", "centre inside: keeps the normal towards the nearest edge", "inside_case", {3: """
        if inside(center, points):
            return offset / dist, radius + dist
    """}, why="a center 15 px inside a crate's left side gets a normal pointing left: the push drives it through"),
    wrong("inside_shallow_depth", "centre inside: flips the normal but keeps depth radius - dist", "inside_case", {3: """
        if inside(center, points):
            return -offset / dist, radius - dist
    """}, why="depth 15 px instead of 25 for a center 5 px inside the ramp's face"),
    # ---- step 4: the push-out
    wrong("push_not_split", "moves both bodies by the whole push", "push_out_split", {4: """
        a.pos -= normal * push
        b.pos += normal * push
    """}, why="a static ramp (A) moves by the push"),
    wrong("push_halved", "splits the push half and half", "push_out_split", {4: """
        a.pos -= normal * (push / 2)
        b.pos += normal * (push / 2)
    """}, why="a heavy crate moves as far as a light ball, and a static ramp moves"),
    wrong("push_shares_swapped", "gives each body the other's share", "push_out_split", {4: """
        a.pos -= normal * (push * b.inv_mass / total)
        b.pos += normal * (push * a.inv_mass / total)
    """}, why="against a static ramp the ball stays and the ramp moves"),
    wrong("push_missing_total", "each share is push × 1/m, never divided by the total", "push_out_split", {4: """
        a.pos -= normal * (push * a.inv_mass)
        b.pos += normal * (push * b.inv_mass)
    """}, why="a crate (1/m 0.21) and a ball (1/m 2.2): the ball moves 2.2 times the push, not 0.91 of it"),
    wrong("split_scales_the_normal", "`normal *= push / total`, then moves A and B by it", "push_out_split", {4: """
        normal *= push / total
        a.pos -= normal * a.inv_mass
        b.pos += normal * b.inv_mass
    """}, why="the positions are right, but the caller's normal is scaled in place: the impulses that follow use "
              "a normal that is no longer a unit vector"),
    # ---- step 5: the inertia
    wrong("inertia_ring", "I = m r² (a ring's)", "ball_inertia", {5: """
        return mass * radius ** 2
    """}, why="twice ½ m r² for every mass and radius"),
    wrong("inertia_ignores_mass", "I = ½ r²: the mass left out", "ball_inertia", {5: """
        return 0.5 * radius ** 2
    """}, why="right only for a mass of 1"),
    wrong("inertia_sphere", "I = 2/5 m r² (a solid sphere's)", "ball_inertia", {5: """
        return 2 / 5 * mass * radius ** 2
    """}, why="0.4 m r² instead of 0.5 m r²"),
    wrong("inertia_trailing_comma", "return 0.5 * mass * radius ** 2, (a trailing comma: a 1-tuple, not a number)",
          "ball_inertia", {5: """
        return 0.5 * mass * radius ** 2,
    """}, why="the right number inside a tuple: a wrong kind is a failure named with its value, never read as the "
              "number it holds"),
    # ---- step 6: the contact point
    wrong("contact_at_centre", "returns the ball's center as the contact point", "contact_on_surface", {6: """
        return center
    """}, why="the point should be radius px along the normal"),
    wrong("contact_halfway", "center + normal * (radius - depth / 2): halfway into the overlap, not on the surface",
          "contact_on_surface", {6: """
        return center + normal * (radius - depth / 2)
    """}, why="the point lies depth/2 px inside the ball; the step asks for the point on its surface"),
    wrong("contact_far_side", "center - normal * radius (the wrong side of the ball)", "contact_on_surface", {6: """
        return center - normal * radius
    """}, why="the normal points out of the ball, into the other body"),
    # ---- step 7: friction
    wrong("friction_sign_flipped", "jt = +rel·t / kt (pushes along the slip)", "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="every slipping contact slips faster after resolve()"),
    wrong("friction_not_clamped", "no Coulomb clamp", "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="a ball sliding fast onto the ramp, and any ball with mu = 0, is stopped dead"),
    wrong("friction_kt_no_spin", "kt = 1/mA + 1/mB, without the spin terms", "friction_rolls", {7: """
        kt = a.inv_mass + b.inv_mass
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="a ball slipping a little on the ramp gets 3x the impulse that stops the slip"),
    wrong("friction_at_centre", "applies the friction impulse at the centres", "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, pygame.Vector2(), pygame.Vector2())
    """}, why="the friction impulse changes no spin: the ball never starts to roll"),
    wrong("friction_velocity_only", "updates the velocities by hand and forgets the spins", "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        a.vel -= t * jt * a.inv_mass
        b.vel += t * jt * b.inv_mass
    """}, why="the same as at the centres: no spin change, so the ball slides"),
    wrong("friction_spin_vector", "updates the spins by hand without the cross product: omega += t * jt * "
          "inv_inertia, a Vector2 where a number belongs", "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        a.vel -= t * jt * a.inv_mass
        b.vel += t * jt * b.inv_mass
        a.omega -= t * jt * a.inv_inertia
        b.omega += t * jt * b.inv_inertia
    """}, status=("error",), why="float -= Vector2 raises in the student's own line on the first slipping contact: "
                                 "the error is the file's, shown at that line"),
    wrong("friction_crashes", "uses a name that does not exist (tangent_speed)", "friction_rolls", {7: """
        jt = -tangent_speed / kt
        apply_impulse(a, b, t * jt, ra, rb)
    """}, status=("error",), why="NameError on the first slipping contact"),
    # ---- issue 33: files whose first message once stated a cause they do not have
    wrong("closest_returns_t", "returns the clamped t itself instead of the point a + ab t", "closest_point", {2: """
        t = (p - a).dot(ab) / ab.dot(ab)
        return max(0.0, min(1.0, t))
    """}, why="a number is no point (it was shown as the point (t, t))"),
    wrong("closest_no_division", "t = (p - a)·ab, never divided by ab·ab", "closest_point", {2: """
        t = (p - a).dot(ab)
        t = max(0.0, min(1.0, t))
        return a + ab * t
    """}, why="t is |ab|² times too big; on long edges that clamps like t / |ab| would, a sub-pixel edge tells them "
              "apart (it was told 't is divided by |ab|')"),
    wrong("friction_kt_is_k", "divides by the normal's k instead of kt", "friction_rolls", {7: """
        jt = -rel.dot(t) / k
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="for a ball on a static surface k has no spin term, so kt = k looks like kt without its spin terms; "
              "a ball hitting a crate off its centre tells them apart"),
    wrong("friction_bodies_swapped", "apply_impulse(b, a, ...): the bodies swapped in the friction impulse",
          "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(b, a, t * jt, ra, rb)
    """}, why="the ball gets -t jt (it was told about the sign of jt), and at the other body's lever arm"),
    # issue 40: the step-7 mistakes that were only numbered, each told apart by the probe's cases
    wrong("friction_applied_twice", "applies the friction impulse twice (a second apply_impulse line)",
          "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="a ball slipping a little gets twice the impulse that stops its slip"),
    wrong("friction_clamped_to_mu", "clamps jt to [-mu, mu], not [-mu·j, mu·j]", "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu, min(mu, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="j is far above 1 in these contacts, so ±mu clamps every impulse that should stop the slip"),
    wrong("friction_whole_relative_speed", "jt from the whole relative speed |rel|, not the slip rel·t",
          "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.length() / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="after a bouncing impact rel still has a normal part: |rel| is more than the slip"),
    wrong("friction_kt_without_ball_spin", "kt with A's spin term only (B's, the ball's on the ramp, left out)",
          "friction_rolls", {7: """
        rat = cross(ra, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="on the ramp A is static, so kt loses the ball's spin term: 3x the impulse that stops the slip"),
    wrong("friction_kt_without_a_spin", "kt with B's spin term only (A's left out)", "friction_rolls", {7: """
        rbt = cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="only the ball hitting the spinning crate (A the ball) shows it: on the ramp A is static"),
    wrong("friction_if_clamp_loses_sign", "`if abs(jt) > mu * j: jt = mu * j`: the clamp drops jt's sign",
          "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        if abs(jt) > mu * j:
            jt = mu * j
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="jt < 0 here: where the clamp binds (the fast slide, the backspin) friction pushes along the slip; "
              "elsewhere it is right"),
    wrong("friction_bodies_and_arms_swapped", "apply_impulse(b, a, t * jt, rb, ra): bodies and lever arms swapped",
          "friction_rolls", {7: """
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(b, a, t * jt, rb, ra)
    """}, why="the same velocities as a flipped jt, but jt is right: the recorded call names the swap, not the sign"),
    wrong("friction_tangent_rotates_normal", "makes its own tangent by rotating the contact's normal in place",
          "friction_rolls", {7: """
        t = normal
        t.rotate_ip(90)
        if rel.dot(t) > 0:
            t = -t
        rat, rbt = cross(ra, t), cross(rb, t)
        kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
        jt = -rel.dot(t) / kt
        jt = max(-mu * j, min(mu * j, jt))
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="every impulse is right, but the caller's normal turns a quarter turn: the World's next contact "
              "point uses it (once caught only by the scenes, 'the function checks above all pass', step 8)"),
    # ---- outside the steps
    wrong("world_hook_removed", "drops circle_polygon=circle_polygon from the World (the library's test runs)",
          "handout_unchanged", edits=[("                 circle_polygon=circle_polygon, circle_point=contact_point)",
                                       "                 circle_point=contact_point)")],
          why="the World no longer uses the student's circle_polygon"),
    wrong("inertia_bypassed", "make_ball uses ½ m r² itself instead of calling disc_inertia()", "handout_unchanged",
          edits=[("    inertia = disc_inertia(mass, radius)\n", "    inertia = 0.5 * mass * radius ** 2\n")],
          why="code outside the steps changed"),
    wrong("slop_zeroed", "sets SLOP = 0 to make the ball sit deeper-free", "handout_unchanged",
          edits=[("SLOP = 0.5 ", "SLOP = 0.0 ")], why="a handed-out constant changed"),
]

CORRECT = [
    correct("correct_solution_steps", "the solution's own code in every step", {},
            why="the reference build is the solution, byte for byte"),
    correct("correct_unit_direction", "closest point by a unit direction and a distance along it; inertia as m r r / 2",
            {2: """
                length = ab.length()
                direction = ab / length
                along = min(max((p - a).dot(direction), 0.0), length)
                return a + direction * along
            """, 5: """
                return mass * radius * radius / 2
            """}, why="along = t |ab|, clamped to [0, |ab|]: the same point"),
    correct("correct_copy_moved_in_place", "copies a (a.copy()), then moves the copy with += (the caller's a is untouched)",
            {2: """
                t = max(0.0, min(1.0, (p - a).dot(ab) / ab.dot(ab)))
                point = a.copy()
                point += ab * t
                return point
            """}, why="an in-place += on a new Vector2 changes nothing the caller holds"),
    correct("correct_named_parts", "inside case with a named normal; push-out with named shares; a named offset",
            {3: """
                if inside(center, points):
                    way_out = (center - closest).normalize()
                    return way_out, radius + dist
            """, 4: """
                share_a = a.inv_mass / total
                share_b = b.inv_mass / total
                a.pos = a.pos - normal * push * share_a
                b.pos = b.pos + normal * push * share_b
            """, 6: """
                to_surface = normal * radius  # from the center out to the ball's surface
                return center + to_surface
            """}, why="(center - closest) / dist is -offset / dist; shares by inverse mass; the same surface point"),
    correct("correct_friction_if_clamp", "friction clamped with if/copysign, kt from named terms", {7: """
        spin_a = cross(ra, t) ** 2 * a.inv_inertia
        spin_b = cross(rb, t) ** 2 * b.inv_inertia
        kt = a.inv_mass + b.inv_mass + spin_a + spin_b
        jt = -rel.dot(t) / kt
        if abs(jt) > mu * j:
            jt = math.copysign(mu * j, jt)
        apply_impulse(a, b, t * jt, ra, rb)
    """}, why="the same Coulomb clamp written as an if"),
    correct("correct_reaction_on_b_first", "the same friction impulse written from B's side: "
            "apply_impulse(b, a, -(t * jt), rb, ra)", {7: """
                rat, rbt = cross(ra, t), cross(rb, t)
                kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
                jt = -rel.dot(t) / kt
                jt = max(-mu * j, min(mu * j, jt))
                apply_impulse(b, a, -(t * jt), rb, ra)
            """}, why="B first with its own lever arm and the impulse turned round is the same pair of impulses: the "
                      "recorded call order names a swap only when the outcome is wrong"),
    correct("correct_tangent_from_normal", "its own tangent: a turned copy of the normal (normal.rotate(90)), "
            "pointing against the slip", {7: """
                tangent = normal.rotate(90)
                if rel.dot(tangent) > 0:
                    tangent = -tangent
                rat, rbt = cross(ra, tangent), cross(rb, tangent)
                kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
                jt = -rel.dot(tangent) / kt
                jt = max(-mu * j, min(mu * j, jt))
                apply_impulse(a, b, tangent * jt, ra, rb)
            """}, why="rotate() makes a new vector; in 2D the unit tangent is ± the turned normal, either sign works "
                      "once jt's sign follows it"),
]

# the words each wrong entry's first message must contain: it names the mistake, not only the step (issue 33)
SAYS = {
    "closest_not_clamped": ("not clamped",),
    "closest_divides_by_length": ("divided by |ab|",),
    "closest_p_minus_b": ("from b",),
    "closest_moves_the_corner": ("in place",),
    "closest_returns_t": ("returned the number",),
    "closest_no_division": ("not divided",),
    "inside_not_flipped": ("towards the nearest edge",),
    "inside_shallow_depth": ("radius - dist",),
    "push_not_split": ("whole push",),
    "push_halved": ("halved",),
    "push_shares_swapped": ("swapped",),
    "push_missing_total": ("without dividing by the total",),
    "split_scales_the_normal": ("changed its argument normal",),
    "inertia_ring": ("ring",),
    "inertia_ignores_mass": ("mass is left out",),
    "inertia_sphere": ("sphere",),
    "inertia_trailing_comma": ("returned (", "expected the number"),
    "contact_at_centre": ("the ball's center",),
    "contact_halfway": ("halfway",),
    "contact_far_side": ("far side",),
    "friction_sign_flipped": ("along the slip",),
    "friction_not_clamped": ("never clamped",),
    "friction_kt_no_spin": ("lacks the spin terms",),
    "friction_at_centre": ("changes no spin",),
    "friction_velocity_only": ("changes no spin",),
    "friction_spin_vector": ("TypeError", "a.omega -= t * jt * a.inv_inertia", "the cross product forgotten"),
    "friction_crashes": ("NameError",),
    "friction_kt_is_k": ("kt = k",),
    "friction_bodies_swapped": ("apply_impulse(b, a",),
    "friction_tangent_rotates_normal": ("changed its argument normal",),
    "friction_applied_twice": ("applied twice",),
    "friction_clamped_to_mu": ("±mu, not ±mu·j",),
    "friction_whole_relative_speed": ("whole relative speed",),
    "friction_kt_without_ball_spin": ("lacks B's spin term",),
    "friction_kt_without_a_spin": ("lacks A's spin term",),
    "friction_if_clamp_loses_sign": ("where |jt| > mu·j", "loses jt's sign"),
    "friction_bodies_and_arms_swapped": ("apply_impulse(b, a, t * jt, rb, ra)", "lever arms swapped"),
    "world_hook_removed": ("circle_polygon=circle_polygon",),
    "inertia_bypassed": ("disc_inertia(mass, radius)",),
    "slop_zeroed": ("SLOP = 0.0",),
}
WRONG = with_says(WRONG, SAYS)

# What tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself (each key optional):
# short (its entries' name prefix), mechanisms (the issue-35 mechanisms that apply; tests/corpus_attacks.py
# says why), library_name / library_owner (the library's answer to the first step where it is not the first
# STEP_LIBRARY name), world_call, hidden, forger and side (the attacks' code where the default does not fit).
ATTACK = {
    "short": "br",
    "mechanisms": (1, 2, 3, 4, 5, 6, 7, 8, 9, 10),
    "world_call": "return World().circle_point and p",
    "forger": (7, ("closest_point", "push_out_split", "ball_inertia", "contact_on_surface")),
    "side": (5, "disc_inertia", "def found(mass, radius):\n    return 0.5 * mass * radius ** 2", "ball_inertia"),
}

# The wrong-kind values its step functions must fail on, never the checker (tests/test_wrong_kinds.py):
# [(function, step, [case, ...])], the cases written as tests/wrong_kinds.py says.
WRONG_KINDS = [("closest_on_segment", 2, returns(VECTOR) + wrapped(AS_TEXT + ["[answer]"])), ("circle_polygon", 3, returns(HIT)),
               ("separate", 4, after_solution(PLACES)), ("disc_inertia", 5, returns(NUMBER) + wrapped(AS_TEXT + ["[answer]"])),
               ("contact_point", 6, returns(VECTOR) + wrapped(AS_TEXT)), ("resolve", 7, after_solution(MOTION[:4]) + substituted(
                   "apply_impulse(a, b, t * jt, ra, rb)",
                   ["apply_impulse(a, b, (t * jt).x, ra, rb)", "apply_impulse(a, b, tuple(t * jt), ra, rb)",
                    "apply_impulse(a, b, t * jt, tuple(ra), rb)", "apply_impulse(a, b, t * jt, ra, 'rb')"]))]

# The wrong entry `python -m checker FILE --show` is tried on (tests/test_checker_show.py): one wrong step
# whose scene differs visibly from the solution's, and the kind of failing case --show draws for it.
SHOW_ENTRY, SHOW_CASE = 'inertia_ring', 'PolygonCase'

# the mistake id each entry's failing check must carry (issue 40: --json's "mistake"); an entry not listed may
# carry none
MISTAKE_IDS = {
    "friction_sign_flipped": "friction_sign", "friction_not_clamped": "friction_unclamped",
    "friction_kt_no_spin": "kt_no_spin", "friction_kt_is_k": "kt_is_k", "friction_at_centre": "friction_at_centre",
    "friction_bodies_swapped": "friction_bodies_swapped", "friction_applied_twice": "friction_twice",
    "friction_clamped_to_mu": "friction_bound_mu", "friction_whole_relative_speed": "friction_whole_rel",
    "friction_kt_without_ball_spin": "kt_missing_b_spin", "friction_kt_without_a_spin": "kt_missing_a_spin",
    "friction_if_clamp_loses_sign": "friction_clamp_loses_sign",
    "friction_bodies_and_arms_swapped": "friction_bodies_arms_swapped",
}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}

# ================================================================ building the files (tests/corpus_files.py)

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_ball_on_ramp.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
