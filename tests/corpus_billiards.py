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
from corpus_files import CorpusFiles, second_mistake, with_says  # noqa: E402  (tests/corpus_files.py: starter + steps + edits)
from corpus_entries import makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "billiards_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "billiards.py")

STEPS = (2, 3, 4)
CHECK_STEP = {"loads": None, "handout_unchanged": None, "runtime_lines": None, "circle_circle_right": 2,
              "bounce_right": 3, "cloth_slowing_right": 4, "runs": None, "speeds_exchange": None,
              "momentum_kept": None, "no_overlap": None, "comes_to_rest": None}
FUNCTION_CHECKS = ("circle_circle_right", "bounce_right", "cloth_slowing_right")
SHOW_ENTRY = "bounce_b_only"
SHOW_CASE = "BallsCase"


wrong, correct = makers(CHECK_STEP)


CORRECT = [
    correct("correct_solution_steps", "the solution's own steps", why="the reference build"),
    correct("correct_squared_test", "tests |d|² against (ra + rb)² before taking a square root", {2: """
        offset = cb - ca
        reach = ra + rb
        if offset.length_squared() >= reach * reach:
            return None
        distance = offset.length()
        if distance == 0:
            return pygame.Vector2(1, 0), reach
        return offset.normalize(), reach - distance
    """}, why="the same None and, up to rounding, the same normal and depth"),
    correct("correct_by_components", "writes everything in x and y", {2: """
        import math
        dx, dy = cb.x - ca.x, cb.y - ca.y
        distance = math.hypot(dx, dy)
        if distance >= ra + rb:
            return None
        if distance == 0:
            return pygame.Vector2(1.0, 0.0), ra + rb
        return pygame.Vector2(dx / distance, dy / distance), ra + rb - distance
    """, 3: """
        nx, ny = normal.x, normal.y
        vn = (b.vel.x - a.vel.x) * nx + (b.vel.y - a.vel.y) * ny
        if vn < 0:
            j = -(1 + e) * vn / (a.inv_mass + b.inv_mass)
            a.vel = pygame.Vector2(a.vel.x - j * nx * a.inv_mass, a.vel.y - j * ny * a.inv_mass)
            b.vel = pygame.Vector2(b.vel.x + j * nx * b.inv_mass, b.vel.y + j * ny * b.inv_mass)
    """}, why="new Vector2s instead of in-place changes; math.hypot for the length"),
    correct("correct_impulse_vector_and_scale", "an impulse vector; scale_to_length for the speed", {3: """
        closing = (b.vel - a.vel) * normal
        if closing >= 0:
            return
        impulse = normal * (-(1 + e) * closing / (a.inv_mass + b.inv_mass))
        a.vel = a.vel - impulse * a.inv_mass
        b.vel = b.vel + impulse * b.inv_mass
    """, 4: """
        new = pygame.Vector2(vel)
        speed = new.length() - mu * G * dt
        if speed <= 0:
            return pygame.Vector2()
        new.scale_to_length(speed)
        return new
    """}, why="Vector2 * Vector2 is the dot product; scale_to_length keeps the direction"),
    correct("correct_cloth_in_place", "slows the given vector in place and returns it", {4: """
        speed = vel.length()
        if speed == 0 or speed <= mu * G * dt:
            return vel * 0
        vel -= vel / speed * (mu * G * dt)
        return vel
    """}, why="main() stores what it returns; the same speed up to rounding"),
]

WRONG = [
    wrong("contact_reversed", "normal from B to A", "circle_circle_right", {2: """
        offset = ca - cb
        distance = offset.length()
        if distance >= ra + rb:
            return None
        if distance == 0:
            return pygame.Vector2(1, 0), ra + rb
        return offset / distance, ra + rb - distance
    """}, why="overlapping along x gives (-1, 0)"),
    wrong("contact_gap", "depth = |d| - ra - rb", "circle_circle_right", {2: """
        offset = cb - ca
        distance = offset.length()
        if distance >= ra + rb:
            return None
        if distance == 0:
            return pygame.Vector2(1, 0), distance - ra - rb
        return offset / distance, distance - ra - rb
    """}, why="overlapping along x gives depth -8"),
    wrong("contact_unit", "the normal left as cb - ca", "circle_circle_right", {2: """
        offset = cb - ca
        depth = ra + rb - offset.length()
        if depth <= 0:
            return None
        if offset.length() == 0:
            return pygame.Vector2(1, 0), depth
        return offset, depth
    """}, why="overlapping along x gives (20, 0)"),
    wrong("contact_halved", "each ball's half of the overlap", "circle_circle_right", {2: """
        offset = cb - ca
        depth = (ra + rb - offset.length()) / 2
        if depth <= 0:
            return None
        if offset.length() == 0:
            return pygame.Vector2(1, 0), depth
        return offset.normalize(), depth
    """}, why="overlapping along x gives depth 4"),
    wrong("contact_squared", "compares |d|² with ra + rb", "circle_circle_right", {2: """
        offset = cb - ca
        if offset.length_squared() >= ra + rb:
            return None
        if offset.length() == 0:
            return pygame.Vector2(1, 0), ra + rb
        return offset.normalize(), ra + rb - offset.length()
    """}, why="overlapping along x (|d|² = 400 > 28) gives None"),
    wrong("contact_inverted", "None for overlapping balls, a contact for apart ones", "circle_circle_right", {2: """
        offset = cb - ca
        depth = ra + rb - offset.length()
        if depth > 0:
            return None
        return offset.normalize(), depth
    """}, why="overlapping along x gives None, apart along x a contact"),
    wrong("contact_coincident_crash", "no case for coincident centres", "circle_circle_right", {2: """
        offset = cb - ca
        if offset.length() >= ra + rb:
            return None
        return offset.normalize(), ra + rb - offset.length()
    """}, status=("error",), why="Vector2.normalize() of (0, 0) raises at coincident centres"),
    wrong("bounce_separating", "pushes even when the balls separate", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        j = -(1 + e) * vn / (a.inv_mass + b.inv_mass)
        a.vel -= normal * (j * a.inv_mass)
        b.vel += normal * (j * b.inv_mass)
    """}, why="separating pairs are pulled back together"),
    wrong("bounce_e_alone", "j = -e vn / k", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        if vn < 0:
            j = -e * vn / (a.inv_mass + b.inv_mass)
            a.vel -= normal * (j * a.inv_mass)
            b.vel += normal * (j * b.inv_mass)
    """}, why="e = 1 head-on: each ball keeps half the speed"),
    wrong("bounce_no_e", "j = -vn / k", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        if vn < 0:
            j = -vn / (a.inv_mass + b.inv_mass)
            a.vel -= normal * (j * a.inv_mass)
            b.vel += normal * (j * b.inv_mass)
    """}, why="the balls end moving together"),
    wrong("bounce_masses_summed", "divides by mA + mB", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        if vn < 0:
            j = -(1 + e) * vn / (a.mass + b.mass)
            a.vel -= normal * (j * a.inv_mass)
            b.vel += normal * (j * b.inv_mass)
    """}, why="B three times heavier: j is 3 times too small"),
    wrong("bounce_b_only", "changes B's velocity only", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        if vn < 0:
            j = -(1 + e) * vn / (a.inv_mass + b.inv_mass)
            b.vel += normal * (j * b.inv_mass)
    """}, why="A goes on at 400 px/s"),
    wrong("bounce_same_sign", "+j n to both balls", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        if vn < 0:
            j = -(1 + e) * vn / (a.inv_mass + b.inv_mass)
            a.vel += normal * (j * a.inv_mass)
            b.vel += normal * (j * b.inv_mass)
    """}, why="A speeds up through B"),
    wrong("bounce_signs_swapped", "+j n to A, -j n to B", "bounce_right", {3: """
        vn = (b.vel - a.vel).dot(normal)
        if vn < 0:
            j = -(1 + e) * vn / (a.inv_mass + b.inv_mass)
            a.vel += normal * (j * a.inv_mass)
            b.vel -= normal * (j * b.inv_mass)
    """}, why="the balls are pushed into each other"),
    wrong("cloth_reverses", "subtracts mu g dt along v without stopping at zero", "cloth_slowing_right", {4: """
        if vel.length() == 0:
            return vel
        return vel - vel.normalize() * (mu * G * dt)
    """}, why="a ball at (1, 1) px/s turns round"),
    wrong("cloth_drag", "slows in proportion to the speed", "cloth_slowing_right", {4: """
        return vel * (1 - mu * dt)
    """}, why="a ball never stops"),
    wrong("cloth_no_dt", "drops mu g each frame", "cloth_slowing_right", {4: """
        speed = vel.length()
        if speed <= mu * G:
            return pygame.Vector2(0, 0)
        return vel * ((speed - mu * G) / speed)
    """}, why="a ball at 120 px/s stops in one frame"),
    wrong("cloth_no_g", "drops mu dt", "cloth_slowing_right", {4: """
        speed = vel.length()
        if speed <= mu * dt:
            return pygame.Vector2(0, 0)
        return vel * ((speed - mu * dt) / speed)
    """}, why="a fast ball loses 0.0025 px/s a frame"),
    wrong("cloth_per_axis", "slows x and y apart", "cloth_slowing_right", {4: """
        drop = mu * G * dt
        x = max(abs(vel.x) - drop, 0) * (1 if vel.x > 0 else -1)
        y = max(abs(vel.y) - drop, 0) * (1 if vel.y > 0 else -1)
        return pygame.Vector2(x, y)
    """}, why="a slanted ball turns towards an axis"),
    wrong("cloth_at_rest_crash", "normalizes a ball at rest", "cloth_slowing_right", {4: """
        speed = vel.length()
        drop = mu * G * dt
        if speed <= drop:
            return vel.normalize() * 0
        return vel - vel.normalize() * drop
    """}, status=("error",), why="Vector2.normalize() of (0, 0) raises for the ball at rest"),
    wrong("attempt_answers_for_the_fixed_cases", "hard-codes the handout's cases", "circle_circle_right", {2: """
        known = {(100, 100, 120, 100): ((1, 0), 8), (200, 200, 200, 180): ((0, -1), 8),
                 (50, 60, 62, 76): ((0.6, 0.8), 5), (400, 100, 390, 100): ((-1, 0), 24),
                 (300, 300, 300, 300): ((1, 0), 28)}
        found = known.get((ca.x, ca.y, cb.x, cb.y))
        return None if found is None else (pygame.Vector2(found[0]), found[1])
    """}, why="the cases drawn for this run are not in the table"),
    wrong("attempt_swap_velocities", "swaps the two velocities", "bounce_right", {3: """
        a.vel, b.vel = b.vel, a.vel
    """}, why="right for equal balls head-on with e = 1 only"),
    wrong("attempt_stop_every_ball", "stops every ball at once", "cloth_slowing_right", {4: """
        return pygame.Vector2(0, 0)
    """}, why="every ball at rest at once would pass comes_to_rest: the step's cases must fail it"),
    wrong("outside_cloth_skipped", "main() no longer slows the balls", "handout_unchanged",
          edits=[("            ball.vel = cloth_slowing(ball.vel, ball.rolling, steps * world.step_seconds)\n",
                  "            pass\n")], why="code outside the steps differs from the handout"),
]

SAYS = {
    "contact_reversed": ("from B to A",), "contact_gap": ("the gap",), "contact_unit": ("not a unit vector",),
    "contact_halved": ("halved",), "contact_squared": ("|d|²",), "contact_inverted": ("wrong way round",),
    "contact_coincident_crash": ("circle_circle",),
    "bounce_separating": ("already separate",), "bounce_e_alone": ("e alone",), "bounce_no_e": ("leaves out e",),
    "bounce_masses_summed": ("mA + mB",), "bounce_b_only": ("only B",), "bounce_same_sign": ("both balls",),
    "bounce_signs_swapped": ("A gets +j n",), "cloth_reverses": ("turns round",), "cloth_drag": ("drag",),
    "cloth_no_dt": ("leaves out dt",), "cloth_no_g": ("leaves out g",), "cloth_per_axis": ("x and y",),
    "cloth_at_rest_crash": ("cloth_slowing",), "attempt_swap_velocities": ("e = 0.95",),
    "attempt_answers_for_the_fixed_cases": ("drawn for this run",), "attempt_stop_every_ball": ("fast along x",),
    "outside_cloth_skipped": ("pass",),
}
WRONG = with_says(WRONG, SAYS)

# the mistake id each entry's failing check must carry (--json's "mistake")
MISTAKE_IDS = {name: name for name in SAYS if name.split("_")[0] in ("contact", "bounce", "cloth")
               and not name.endswith("_crash")}

# two mistakes of one step at once (tests/test_named_causes.py): the step fails, naming neither
COMBINED = {
    "billiards_contact_reversed_and_halved": ("circle_circle_right", second_mistake(
        WRONG, "contact_halved", 2, "offset = cb - ca", "offset = ca - cb"), ("from B to A", "halved")),
    "billiards_bounce_e_alone_on_b_only": ("bounce_right", second_mistake(
        WRONG, "bounce_b_only", 3, "j = -(1 + e) * vn", "j = -e * vn"), ("e alone", "only B")),
    "billiards_cloth_no_dt_and_reverses": ("cloth_slowing_right", second_mistake(
        WRONG, "cloth_reverses", 4, "(mu * G * dt)", "(mu * G)"), ("leaves out dt", "turns round")),
}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"



def attack_entries(attack, control):
    """Billiards' entries of the attack corpus (tests/corpus_attacks.py builds the others from the lab itself):
    step 2 answered from a table of the probe's fixed pairs, and two honest controls in other styles."""
    import types
    from checker.labs.billiards.probes import contact_cases, reference_contact
    fixed = contact_cases(types.ModuleType("plain"))[:-2]   # the last two are drawn for each run
    hits = {(*case["ca"], case["ra"], *case["cb"], case["rb"]): reference_contact(case) for case in fixed}
    assert len(hits) >= 5, "the probe's fixed pairs moved: the table would test nothing"
    return [
        attack("billiards_table_contact", "billiards", "table", {2: f"""
            hits = {hits!r}
            hit = hits.get((ca.x, ca.y, ra, cb.x, cb.y, rb))
            if hit is None:
                return None  # not in the table (or apart): the placeholder
            return pygame.Vector2(hit[0], hit[1]), hit[2]
        """}, ["circle_circle_right"], "step 2 answers the probe's fixed pairs from a table; the pairs drawn for "
               "this run are not in it", needs_random_inputs=True),
        control("billiards_control_hypot", "billiards", {2: """
            import math
            dx, dy = cb.x - ca.x, cb.y - ca.y
            gap = math.hypot(dx, dy)
            if gap >= ra + rb:
                return None
            return (pygame.Vector2(dx / gap, dy / gap) if gap else pygame.Vector2(1, 0)), ra + rb - gap
        """}, "math.hypot and components instead of Vector2 arithmetic"),
        control("billiards_control_print", "billiards", {3: """
            vn = (b.vel - a.vel).dot(normal)
            print("closing speed", vn)
            if vn < 0:
                j = -(1 + e) * vn / (a.inv_mass + b.inv_mass)
                a.vel -= normal * (j * a.inv_mass)
                b.vel += normal * (j * b.inv_mass)
        """}, "a debug print inside the step"),
    ]


# what tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself
ATTACK = {"entries": attack_entries}

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_billiards.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
