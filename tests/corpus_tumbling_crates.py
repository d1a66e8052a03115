"""The Tumbling Crates mistake corpus: realistic student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter
(starters/tumbling_crates_starter.py): the lines strictly between a step's
start marker (`# --- step N: ... ---`) and its end marker
(`# --- end of step N ---`) are replaced by the student's code for that step;
a step the entry does not give gets the solution's code for it, read from the
same regions of solutions/tumbling_crates.py, so the corpus follows the lab
when the lab changes. An entry that also changes code OUTSIDE the steps lists
exact (old, new) edits, applied after the steps are filled; each old must
occur exactly once, else building raises AssertionError naming the entry (the
style of tests/mutants.py).

Verdicts (the ids are the checker's function checks of issue 9):
  CORRECT entries: every check passes.
  WRONG entries: `check` fails (or errors, for a crash; `status` lists what is
  accepted) and its JSON `step` is `step`. A mistake inside step N fails the
  check for step N and no other function check: sat_normal is skipped when
  sat_axes fails (it depends on it), and for a crash the other check of the same
  function (resolve_k / resolve_friction) may be skipped or error too, but never
  fail. A mistake outside the steps fails handout_unchanged (step None) and
  every function check passes, except those in the entry's `also`: an edit to
  the handout's part of resolve() (RESTING_SPEED, the `vn >= 0` test, the jt
  line) changes what resolve() does, so the resolve checks may fail as well.
  Checks that need every function check (runs and the four criteria) are not
  constrained for a wrong entry.

Each entry's `why` says which input shows the mistake (for a wrong entry) or
why the code is behaviourally the same as the lesson's (for a correct one).

    build(name) -> source text
    write_corpus(directory, names=None) -> {name: path}
"""
import os
import re
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutants  # noqa: E402  (tests/mutants.py: exact edits that must fit once)
from corpus_files import second_mistake, with_says  # noqa: E402
from corpus_entries import makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)
from wrong_kinds import HIT, MOTION, V, after_solution, returns  # noqa: E402  (tests/wrong_kinds.py)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "tumbling_crates_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")

STEPS = (2, 3, 4, 5, 6)
PER_STEP = 3   # wrong entries each step needs at least (tests/corpus_verdicts.py)
START = re.compile(r"^(?P<indent>[ \t]*)# --- step (?P<step>\d+): .*---[ \t]*$")
END = re.compile(r"^[ \t]*# --- end of step (?P<step>\d+) ---[ \t]*$")

# the checker's checks (issue 9) and the lesson step each one's hint names
CHECK_STEP = {
    "loads": None, "handout_unchanged": None, "runtime_lines": None,
    "sat_axes": 2, "sat_normal": 3, "resolve_k": 4, "resolve_friction": 5, "apply_impulse_spin": 6,
    "runs": None, "corner_tips": None, "ramp_holds": None, "pile_stable": None, "fast_movers_zero": None,
}
FUNCTION_CHECKS = ("sat_axes", "sat_normal", "resolve_k", "resolve_friction", "apply_impulse_spin")
DEPENDS = {"sat_normal": ("sat_axes",)}  # among the function checks
SAME_FUNCTION = {"sat_axes": "sat_normal", "sat_normal": "sat_axes",
                 "resolve_k": "resolve_friction", "resolve_friction": "resolve_k"}


wrong, correct = makers(CHECK_STEP)


# ================================================================ step 2: the SAT loop (sat_axes)


STEP2_WRONG = [
    wrong("sat_placeholder_left", "wrote the loop but left the starter's `return None` after it", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
        return None  # until you write step 2, nothing ever collides
    """}, why="every overlapping pair comes back None"),
    wrong("sat_only_a_axes", "tests only pa's edge normals", "sat_axes", {2: """
        for axis in edge_normals(pa):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="the lesson's diamond near a corner (apart only along the diamond's own normal) is called a hit"),
    wrong("sat_a_axes_twice", "copy-paste slip: edge_normals(pa) + edge_normals(pa)", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pa):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="same axes as sat_only_a_axes: the diamond near a corner is a hit; with B first it is right"),
    wrong("sat_gap_continue", "on a gap it skips the axis (`continue`) instead of returning None", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                continue  # no overlap on this axis, try the next one
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, status=("fail", "error"), why="pairs apart on one axis but overlapping on the others (the diamond near a corner) are hits"),
    wrong("sat_gap_break", "on a gap it leaves the loop (`break`) and returns whatever it kept so far", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                break  # found a gap
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, status=("fail", "error"),
        why="an apart pair whose gap is on a later axis is a hit; a gap on the first axis leaves best_axis None and "
            "step 3's dot product raises TypeError (so fail or error, always step 2)"),
    wrong("sat_largest_overlap", "keeps the LARGEST overlap (best_depth started at 0, compared with >)", "sat_axes", {2: """
        best_depth = 0
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap > best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="side by side, 10 px overlap: it reports the 35 px vertical overlap along (0, 1)"),
    wrong("sat_one_sided_overlap", "overlap written max_a - min_b (assumes B is on A's positive side)", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = max_a - min_b
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="with A and B swapped, the axes where B lies on A's negative side show no gap and a huge depth"),
    wrong("sat_union_extent", "overlap as the extent of both shadows together", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = max(max_a, max_b) - min(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="never a gap (apart pairs are hits) and the depth is the union's length (70 px, not 10)"),
    wrong("sat_projects_pa_twice", "projects pa onto the axis twice (min_b, max_b from pa)", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pa, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="every pair is a hit with A's own width as the depth"),
    wrong("sat_axis_never_kept", "updates best_depth but never best_axis", "sat_axes", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_depth = overlap
    """}, status=("error",),
        why="any overlapping pair: best_axis stays None and step 3's dot product raises TypeError (the line is in "
            "step 3, the mistake in step 2)"),
    wrong("sat_unnormalised_axes", "builds the axes from the edges by hand and forgets to normalise them", "sat_axes", {2: """
        axes = []
        for points in (pa, pb):
            for i in range(len(points)):
                edge = points[(i + 1) % len(points)] - points[i]
                axes.append(pygame.Vector2(-edge.y, edge.x))
        for axis in axes:
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="depths come out multiplied by the edge length (400 px for the 10 px pair) and the axis is not unit"),
    wrong("sat_skips_closing_edge", "hand-built normals with range(len(points) - 1): the closing edge is never tested",
          "sat_axes", {2: """
        axes = []
        for points in (pa, pb):
            for i in range(len(points) - 1):
                edge = points[i + 1] - points[i]
                axes.append(pygame.Vector2(-edge.y, edge.x).normalize())
        for axis in axes:
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="the same answer as the lesson for every box (a box's closing edge is parallel to its second edge), "
              "wrong for a triangle or pentagon whose separating or shallowest axis is the closing edge's normal: "
              "only the non-box polygons catch it"),
]

# ================================================================ step 3: the normal from A to B (sat_normal)

STEP3_WRONG = [
    wrong("normal_not_flipped", "left step 3 empty: the axis points whichever way edge_normals gave it", "sat_normal",
          {3: ""}, why="about half the pairs, and every pair with A and B swapped, get a normal from B to A"),
    wrong("normal_flip_reversed", "flips when the dot product is positive (> 0 instead of < 0)", "sat_normal", {3: """
        if (centre_of(pb) - centre_of(pa)).dot(best_axis) > 0:
            best_axis = -best_axis
    """}, why="every normal ends up pointing from B to A"),
    wrong("normal_centres_reversed", "compares with centre_of(pa) - centre_of(pb) but keeps the < 0 test",
          "sat_normal", {3: """
        if (centre_of(pa) - centre_of(pb)).dot(best_axis) < 0:
            best_axis = -best_axis
    """}, why="every normal points from B to A; (centre_a - centre_b)·n < 0 is normal_flip_reversed's test "
              "(centre_b - centre_a)·n > 0, even at 0, so no probe tells the two apart: the message names both forms"),
    wrong("normal_first_vertices", "orients with the first corners pb[0] - pa[0] instead of the centres", "sat_normal",
          {3: """
        if (pb[0] - pa[0]).dot(best_axis) < 0:
            best_axis = -best_axis
    """}, why="right for equal boxes turned alike (pb[0] - pa[0] is then the centre offset); wrong when the boxes "
              "differ in size or angle, e.g. a small box overlapping a big one's right side"),
    wrong("normal_always_flipped", "turns the axis round every time, without the test", "sat_normal", {3: """
        best_axis = -best_axis
    """}, why="half the pairs: whenever edge_normals already gave the A-to-B direction"),
    wrong("normal_negates_depth", "negates the depth instead of the axis when the axis points from B to A",
          "sat_normal", {3: """
        if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:
            best_depth = -best_depth
    """}, why="the normal still points from B to A half the time and the depth turns negative there: the depth is "
              "wrong only because of step 3, so a checker grading sat() as a whole must not blame step 2 (sat_axes)"),
    wrong("normal_flips_x_only", "'turns round' the axis by negating only its x", "sat_normal", {3: """
        if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:
            best_axis = pygame.Vector2(-best_axis.x, best_axis.y)
    """}, why="right for a horizontal axis, wrong for a vertical one (not flipped) and for a diagonal one (mirrored, "
              "so not even the same axis up to sign: the axis is wrong only because of step 3)"),
]

# ================================================================ step 4: the spin terms of k (resolve_k)

STEP4_WRONG = [
    wrong("k_missing", "left step 4 empty: k has only the inverse masses", "resolve_k", {4: ""},
          why="any off-centre contact: the impulse is too big (a corner landing bounces back)"),
    wrong("k_only_a", "adds only A's spin term", "resolve_k", {4: """
        k += ran * ran * a.inv_inertia
    """}, why="zero extra when A is static (the floor): wrong whenever B is dynamic and rbn != 0"),
    wrong("k_only_b", "adds only B's spin term (passed the old checker: with a static floor A's term is 0)",
          "resolve_k", {4: """
        k += rbn * rbn * b.inv_inertia
    """}, why="right whenever A is static; wrong with two dynamic bodies or a static B"),
    wrong("k_not_squared", "uses ran and rbn without squaring them", "resolve_k", {4: """
        k += ran * a.inv_inertia + rbn * b.inv_inertia
    """}, why="any off-centre contact with ran or rbn != 1 (and negative lever arms make k smaller)"),
    wrong("k_inv_mass", "uses inv_mass instead of inv_inertia in the spin terms", "resolve_k", {4: """
        k += ran * ran * a.inv_mass + rbn * rbn * b.inv_mass
    """}, why="any off-centre contact (1/m is not 1/I)"),
    wrong("k_assigned", "`k = ...` instead of `k += ...`: the inverse masses are dropped", "resolve_k", {4: """
        k = ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia
    """}, why="any contact with a dynamic body (a central hit even gives k = 0)"),
    wrong("k_a_term_with_b_inertia", "A's spin term uses B's inverse inertia", "resolve_k", {4: """
        k += ran * ran * b.inv_inertia + rbn * rbn * b.inv_inertia
    """}, why="a static A still gets a spin term; unequal inertias differ too"),
    wrong("k_minus", "subtracts B's spin term", "resolve_k", {4: """
        k += ran * ran * a.inv_inertia - rbn * rbn * b.inv_inertia
    """}, why="any off-centre contact on B: k too small, even negative"),
    wrong("k_lever_length", "uses |r|² (like I = m r²) instead of (r × n)²", "resolve_k", {4: """
        k += ra.length_squared() * a.inv_inertia + rb.length_squared() * b.inv_inertia
    """}, why="right only when r is perpendicular to n; a corner contact has r partly along n"),
    wrong("k_divides_inertia", "divides by inertia instead of multiplying by inv_inertia", "resolve_k", {4: """
        k += ran * ran / a.inertia + rbn * rbn / b.inertia
    """}, status=("error",),
        why="the same number for two dynamic bodies; a static body has inertia 0, so ZeroDivisionError (the floor "
            "is A in every floor contact)"),
]

# ================================================================ step 5: Coulomb's clamp (resolve_friction)

STEP5_WRONG = [
    wrong("friction_missing", "left step 5 empty: friction is never clamped", "resolve_friction", {5: ""},
          why="a glancing touch: jt stops the slide dead, far more than mu * j"),
    wrong("friction_bound_normal_speed", "clamps to mu times the normal speed |vn| instead of mu * j",
          "resolve_friction", {5: """
        jt = max(-mu * abs(vn), min(mu * abs(vn), jt))
    """}, why="a speed is not an impulse: j = (1 + e)|vn| / k, so the bound is off whenever (1 + e) / k != 1 and the "
              "clamp is active"),
    wrong("friction_bound_slip_speed", "clamps to mu times the slip speed rel.length()", "resolve_friction", {5: """
        jt = max(-mu * rel.length(), min(mu * rel.length(), jt))
    """}, why="a fast slide gets a huge bound (no clamp), a slow one too small a bound"),
    wrong("friction_bound_k", "clamps to mu * k", "resolve_friction", {5: """
        jt = max(-mu * k, min(mu * k, jt))
    """}, why="k is an inverse mass, tiny next to j: friction almost vanishes"),
    wrong("friction_bound_mu", "clamps to mu alone", "resolve_friction", {5: """
        jt = max(-mu, min(mu, jt))
    """}, why="any clamp-active contact with j != 1, and clamp-inactive ones whose jt is below -mu"),
    wrong("friction_half_bound", "clamps to mu * j / 2", "resolve_friction", {5: """
        jt = max(-mu * j / 2, min(mu * j / 2, jt))
    """}, why="clamp active: half the Coulomb friction"),
    wrong("friction_always_full", "always applies full sliding friction jt = -mu * j", "resolve_friction", {5: """
        jt = -mu * j
    """}, why="clamp inactive (a slow slide): more friction than stops it, the slip reverses"),
    wrong("friction_upper_only", "clamps only from above: jt = min(mu * j, jt)", "resolve_friction", {5: """
        jt = min(mu * j, jt)
    """}, why="jt = -rel·t / kt is never positive (t points along the slip), so this clamps nothing: clamp active"),
    wrong("friction_bound_signed_vn", "clamps to mu * vn, the closing speed with its sign (vn < 0)",
          "resolve_friction", {5: """
        jt = max(-mu * vn, min(mu * vn, jt))
    """}, why="vn < 0, so the clamp always gives +mu|vn|: friction pushes along the slide (it was told 'the clamp "
              "must keep its sign', which is another mistake)"),
    wrong("friction_abs_loses_sign", "jt = min(abs(jt), mu * j): the size is clamped, the sign lost", "resolve_friction",
          {5: """
        jt = min(abs(jt), mu * j)
    """}, why="every slide: friction pushes along the slip instead of against it"),
    # issue 40: the clamp written as an if that drops jt's sign where it binds (named with that condition)
    wrong("friction_if_clamp_loses_sign", "`if abs(jt) > mu * j: jt = mu * j`: the clamp drops jt's sign",
          "resolve_friction", {5: """
        if abs(jt) > mu * j:
            jt = mu * j
    """}, why="jt <= 0 here: where the clamp binds friction pushes along the slip; where it does not, jt is right"),
]

# ================================================================ step 6: the spin updates (apply_impulse_spin)

STEP6_WRONG = [
    wrong("spin_missing", "left step 6 empty: no spin updates", "apply_impulse_spin", {6: ""},
          why="any off-centre impulse leaves both spins unchanged"),
    wrong("spin_swapped", "swapped signs: A +=, B -=", "apply_impulse_spin", {6: """
        a.omega += cross(ra, impulse) * a.inv_inertia
        b.omega -= cross(rb, impulse) * b.inv_inertia
    """}, why="both spin changes have the wrong sign"),
    wrong("spin_only_a", "updates only A's spin", "apply_impulse_spin", {6: """
        a.omega -= cross(ra, impulse) * a.inv_inertia
    """}, why="B dynamic with an off-centre impulse: B does not turn"),
    wrong("spin_only_b", "updates only B's spin", "apply_impulse_spin", {6: """
        b.omega += cross(rb, impulse) * b.inv_inertia
    """}, why="right while A is static (the floor); two dynamic crates: A does not turn"),
    wrong("spin_reversed_cross", "cross(impulse, r) instead of cross(r, impulse)", "apply_impulse_spin", {6: """
        a.omega -= cross(impulse, ra) * a.inv_inertia
        b.omega += cross(impulse, rb) * b.inv_inertia
    """}, why="the cross product is antisymmetric: the same as spin_swapped"),
    wrong("spin_inv_mass", "uses inv_mass instead of inv_inertia", "apply_impulse_spin", {6: """
        a.omega -= cross(ra, impulse) * a.inv_mass
        b.omega += cross(rb, impulse) * b.inv_mass
    """}, why="any off-centre impulse on a dynamic body (1/m is not 1/I)"),
    wrong("spin_rb_for_a", "uses rb in A's update too", "apply_impulse_spin", {6: """
        a.omega -= cross(rb, impulse) * a.inv_inertia
        b.omega += cross(rb, impulse) * b.inv_inertia
    """}, why="A dynamic with ra != rb"),
    wrong("spin_assigned", "`=` instead of -= / +=: the spin is replaced, not changed", "apply_impulse_spin", {6: """
        a.omega = -cross(ra, impulse) * a.inv_inertia
        b.omega = cross(rb, impulse) * b.inv_inertia
    """}, why="the same as the lesson when both bodies start with omega = 0: only a probe with a body already "
              "spinning shows it"),
    wrong("spin_both_plus", "+= for both bodies", "apply_impulse_spin", {6: """
        a.omega += cross(ra, impulse) * a.inv_inertia
        b.omega += cross(rb, impulse) * b.inv_inertia
    """}, why="A dynamic, off-centre: A turns the wrong way"),
    wrong("spin_divides_inertia", "divides by inertia instead of multiplying by inv_inertia", "apply_impulse_spin",
          {6: """
        a.omega -= cross(ra, impulse) / a.inertia
        b.omega += cross(rb, impulse) / b.inertia
    """}, status=("error",),
        why="the same for two dynamic bodies; a static body has inertia 0: ZeroDivisionError"),
    wrong("spin_vector_assigned", "forgot the cross product and assigned: b.omega = impulse * b.inv_inertia, a "
          "Vector2 where a number belongs", "apply_impulse_spin", {6: """
        a.omega -= cross(ra, impulse) * a.inv_inertia
        b.omega = impulse * b.inv_inertia
    """}, status=("error",),
        why="B's omega becomes a Vector2: the replay names it (it was the checker's own TypeError, 'a bug in the "
            "checker', until the tape checked a body's motion)"),
    wrong("spin_rotates_levers_in_place", "turns ra and rb a quarter turn in place to write r × P as a dot product",
          "apply_impulse_spin", {6: """
        ra.rotate_ip(90)   # (-ra.y, ra.x) · P = ra × P
        rb.rotate_ip(90)
        a.omega -= ra.dot(impulse) * a.inv_inertia
        b.omega += rb.dot(impulse) * b.inv_inertia
    """}, why="both spins change rightly, but the caller's lever arms turn: resolve()'s friction impulse after the "
              "normal one acts at the wrong points"),
]

# ================================================================ outside the steps (handout_unchanged)

_WORLD_LINE = "    return World(lab.scene(make_scene(rng)), sat=sat, resolve=resolve)  # lab runtime: scene()\n"


def _world(extra):
    return (_WORLD_LINE, _WORLD_LINE.replace("resolve=resolve)", f"resolve=resolve, {extra})"))


OUTSIDE_WRONG = [
    wrong("outside_gravity_world", "passes a weaker gravity to World", "handout_unchanged",
          edits=[_world("gravity=(0, 500)")], why="crates fall and hit slower; code outside the steps changed"),
    wrong("outside_gravity_set", "sets world.gravity lower in main()", "handout_unchanged", edits=[
        ("    world = make_world(rng)\n    debug = True\n",
         "    world = make_world(rng)\n    world.gravity = pygame.Vector2(0, 300)\n    debug = True\n")],
        why="a line added outside the steps"),
    wrong("outside_max_crates", "MAX_CRATES lowered to 4 so clicks drop nothing", "handout_unchanged",
          edits=[("MAX_CRATES = 14\n", "MAX_CRATES = 4\n")], why="a constant outside the steps changed"),
    wrong("outside_ramp_angle", "the ramp made shallower (12° instead of 22°)", "handout_unchanged",
          edits=[("angle=math.radians(22)", "angle=math.radians(12)")], why="the scene changed"),
    wrong("outside_iterations", "more solver iterations passed to World", "handout_unchanged",
          edits=[_world("iterations=20")], why="the World changed"),
    wrong("outside_clock_tick", "the `# lab runtime` tick replaced by clock.tick(60)", "handout_unchanged", edits=[
        ("        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)\n",
         "        dt = clock.tick(60) / 1000  # lab runtime: clock.tick(60)\n")], also=("runtime_lines",),
        why="a lab-runtime call replaced (runtime_lines may fail too: lab.tick is gone, though a call named tick stays)"),
    wrong("outside_print_zero", "the final count hard-coded to 0 fast movers", "handout_unchanged", edits=[
        ("    moving = sum(1 for body in world.bodies if body.inv_mass > 0 and body.vel.length() > FAST_MOVER)\n",
         "    moving = 0\n")], why="the printed line no longer counts anything"),
    wrong("outside_fast_mover", "FAST_MOVER raised to 1000 px/s so nothing counts as fast", "handout_unchanged",
          edits=[("FAST_MOVER = 30 ", "FAST_MOVER = 1000 ")], why="a constant outside the steps changed"),
    wrong("outside_resting_speed", "RESTING_SPEED raised to 300 px/s (nothing bounces)", "handout_unchanged",
          edits=[("RESTING_SPEED = 30 ", "RESTING_SPEED = 300 ")], also=("resolve_k", "resolve_friction"),
          why="a constant outside the steps changed; resolve() now differs from the lesson's for impacts between 30 "
              "and 300 px/s, so the resolve checks may fail too"),
    wrong("outside_separating_test_removed", "deleted the handout's `if vn >= 0: return`", "handout_unchanged", edits=[
        ("    if vn >= 0:\n        return  # the contact points are already separating\n", "")],
        also=("resolve_k", "resolve_friction"),
        why="separating contacts get pulled together (j < 0): resolve() differs, so the resolve checks may fail too"),
    wrong("outside_no_push_out", "World given a separate() that does nothing", "handout_unchanged",
          edits=[_world("separate=lambda *a: None")], why="the pile sinks; the World changed"),
    wrong("outside_friction_sign", "the handout's jt line with its sign flipped (jt = rel·t / kt)", "handout_unchanged",
          edits=[("        jt = -rel.dot(t) / kt  # the impulse", "        jt = rel.dot(t) / kt  # the impulse")],
          also=("resolve_k", "resolve_friction"),
          why="friction pushes along the slip; the line is outside step 5, so resolve_friction may fail too"),
    wrong("outside_crate_friction", "crates given friction 1.5 so they grip the ramp", "handout_unchanged", edits=[
        ("angle=rng.uniform(0, math.pi), color=color)", "angle=rng.uniform(0, math.pi), color=color, friction=1.5)")],
        why="make_crate changed"),
]

# ================================================================ correct completions in other styles

CORRECT = [
    correct("correct_solution_steps", "the solution's code in every step (the reference build)",
            why="it is the solution, byte for byte (test_the_reference_build_is_the_solution)"),
    correct("correct_lever_turned_copy", "r × P written as a turned copy of r dotted with P (ra.rotate(90))", {6: """
        a.omega -= ra.rotate(90).dot(impulse) * a.inv_inertia
        b.omega += rb.rotate(90).dot(impulse) * b.inv_inertia
    """}, why="rotate() makes a new vector: (-r.y, r.x) · P = r × P, the caller's ra and rb stay"),
    correct("correct_styles_a", "gap test on the ends; flip by * -1; k with ** 2, B first; min(max()) clamp; "
            "a.omega = a.omega - ...", {
                2: """
                for axis in edge_normals(pa) + edge_normals(pb):
                    min_a, max_a = project(pa, axis)
                    min_b, max_b = project(pb, axis)
                    if max_a <= min_b or max_b <= min_a:
                        return None  # a gap
                    overlap = min(max_a, max_b) - max(min_a, min_b)
                    if overlap < best_depth:
                        best_depth = overlap
                        best_axis = axis
                """,
                3: """
                if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:
                    best_axis = best_axis * -1
                """,
                4: """
                k += b.inv_inertia * rbn ** 2 + a.inv_inertia * ran ** 2
                """,
                5: """
                jt = min(max(jt, -mu * j), mu * j)
                """,
                6: """
                a.omega = a.omega - cross(ra, impulse) * a.inv_inertia
                b.omega = b.omega + cross(rb, impulse) * b.inv_inertia
                """},
            why="(max_a <= min_b or max_b <= min_a) is exactly overlap <= 0 for shadows with min <= max"),
    correct("correct_shorter_way_out", "overlap as min(max_a - min_b, max_b - min_a); flip by -1 * axis", {
        2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a - min_b, max_b - min_a)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
        """,
        3: """
        if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:
            best_axis = -1 * best_axis
        """},
        why="equal to the lesson's overlap unless one shadow contains the other; then it is the distance B must move "
            "to get out (the library's own sat() uses it), which the checker accepts for containment; the gap test "
            "is the same (the smaller way out is <= 0 exactly when there is a gap)"),
    correct("correct_while_loop", "index-based while loop; Vector2(-x, -y); copysign clamp; cross spelled out", {
        2: """
        axes = edge_normals(pa) + edge_normals(pb)
        i = 0
        while i < len(axes):
            lo_a, hi_a = project(pa, axes[i])
            lo_b, hi_b = project(pb, axes[i])
            depth = min(hi_a, hi_b) - max(lo_a, lo_b)
            if depth <= 0:
                return None
            if depth < best_depth:
                best_depth = depth
                best_axis = axes[i]
            i += 1
        """,
        3: """
        direction = centre_of(pb) - centre_of(pa)
        if direction.dot(best_axis) < 0:
            best_axis = pygame.Vector2(-best_axis.x, -best_axis.y)
        """,
        5: """
        limit = mu * j
        if abs(jt) > limit:
            jt = math.copysign(limit, jt)
        """,
        6: """
        a.omega -= (ra.x * impulse.y - ra.y * impulse.x) * a.inv_inertia
        b.omega += (rb.x * impulse.y - rb.y * impulse.x) * b.inv_inertia
        """},
        why="cross(a, b) = a.x * b.y - a.y * b.x; copysign keeps jt's sign at the bound"),
    correct("correct_min_key", "all overlaps in a list, best by min(key=...); flip with *= -1; if/elif clamp", {
        2: """
        found = []
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            found.append((axis, overlap))
        best_axis, best_depth = min(found, key=lambda pair: pair[1])
        """,
        3: """
        if best_axis.dot(centre_of(pb)) < best_axis.dot(centre_of(pa)):
            best_axis *= -1
        """,
        5: """
        if jt > mu * j:
            jt = mu * j
        elif jt < -mu * j:
            jt = -mu * j
        """},
        why="min() keeps the first of equal overlaps, like `<`; c_b·n < c_a·n is (c_b - c_a)·n < 0; *= -1 turns "
            "round a fresh vector (edge_normals builds new ones on every call)"),
    correct("correct_one_sided_clamp", "clamps only from below: jt = max(-mu * j, jt)", {5: """
        jt = max(-mu * j, jt)
    """}, why="behaviourally the lesson's clamp: the handout makes t the unit slip direction, so jt = -rel·t / kt "
              "= -|slip| / kt <= 0 and j > 0, so min(mu * j, jt) is always jt"),
    correct("correct_k_cross_operands_swapped", "k's terms from cross(normal, r) ** 2 recomputed, order swapped", {4: """
        k += cross(normal, ra) ** 2 * a.inv_inertia
        k += cross(normal, rb) ** 2 * b.inv_inertia
    """}, why="cross(n, r) = -cross(r, n): the sign is lost in the square"),
    correct("correct_spin_vector_cross", "spin updates with pygame's Vector2.cross, written B first", {6: """
        b.omega += rb.cross(impulse) * b.inv_inertia
        a.omega -= ra.cross(impulse) * a.inv_inertia
    """}, why="Vector2.cross is the same 2D cross product (physics2d says so); the two lines are independent"),
    correct("correct_ties_keep_later_axis", "best test written `overlap <= best_depth`", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap <= best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="differs from `<` only when two axes tie for the smallest overlap (e.g. two equal boxes overlapping "
              "10 px in x and 10 px in y): then it keeps the later axis, which is an equally short way out, so a "
              "checker must accept any axis whose overlap is the smallest"),
    correct("correct_flip_on_zero", "flip test written `<= 0`", {3: """
        if (centre_of(pb) - centre_of(pa)).dot(best_axis) <= 0:
            best_axis = -best_axis
    """}, why="differs only when the centres are level along the axis (dot exactly 0, e.g. concentric shapes): "
              "then neither direction points 'from A to B', so a checker must accept both there"),
    correct("correct_reformatted", "re-formatted outside the steps: blank lines, comments, quotes, parentheses",
            edits=[
                ("import math\nimport random\n", "import math   # for radians and sqrt\nimport random\n\n"),
                ("WIDTH, HEIGHT = 900, 600\n", "WIDTH, HEIGHT = (900, 600)   # the window, px\n"),
                ("BACKGROUND = (24, 26, 34)\n", "\nBACKGROUND = (24, 26, 34)  # dark blue-grey\n"),
                ('    pygame.display.set_caption("Tumbling Crates")\n',
                 "    pygame.display.set_caption('Tumbling Crates')\n"),
                ("    ra, rb = point - a.pos, point - b.pos\n",
                 "    # offsets from each centre to the contact point\n    ra, rb = (point - a.pos,\n"
                 "              point - b.pos)\n\n"),
                ("    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)\n",
                 "    floor = Body(\n        box_points(WIDTH, 40),\n        (WIDTH / 2, HEIGHT - 20),\n"
                 "        0,\n        color=GREY,\n    )\n"),
                ("    running = True\n", "    running = True  # until the window is closed\n\n"),
                ('if __name__ == "__main__":\n', "\nif __name__ == '__main__':\n"),
            ],
            why="comments, blank lines, quote style, redundant parentheses, a trailing comma and line breaks inside "
                "brackets leave the syntax tree unchanged"),
    # A decision, not an oversight: the lesson's `overlap <= 0` calls exactly touching shapes apart; `< 0`
    # reports them as a hit of depth 0. Both are accepted (checker/README.md says so): at exactly zero overlap
    # the push-out moves nothing and an impulse only stops an approach that is about to start, so the
    # physics is the same; failing it would fail a student on the boundary of floating-point equality.
    correct("correct_touching_is_hit", "gap test `overlap < 0`: shapes that exactly touch count as a hit of depth 0",
            {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap < 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, why="differs from the lesson only for an exactly-touching pair (two 40 px boxes 40 px apart), where it "
              "returns depth 0 instead of None; a depth-0 contact is pushed by nothing, so the scenes behave the same"),
]

ENTRIES = CORRECT + STEP2_WRONG + STEP3_WRONG + STEP4_WRONG + STEP5_WRONG + STEP6_WRONG + OUTSIDE_WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"

# the words each wrong entry's first message must contain: it names the mistake, not only the step (issue 33)
SAYS = {
    "sat_placeholder_left": ("placeholder",),
    "sat_only_a_axes": ("B's edge normals",),
    "sat_a_axes_twice": ("B's edge normals",),
    "sat_gap_continue": ("shows a gap", "goes on to the next axis"),
    "sat_gap_break": ("TypeError",),
    "sat_largest_overlap": ("LARGEST overlap",),
    "sat_one_sided_overlap": ("overlap = max_a - min_b",),
    "sat_union_extent": ("both shadows together",),
    "sat_projects_pa_twice": ("project(pa, axis)",),
    "sat_axis_never_kept": ("TypeError",),
    "sat_unnormalised_axes": ("not divided by their length",),
    "sat_skips_closing_edge": ("closing edge",),
    "normal_not_flipped": ("from B to A",),
    "normal_flip_reversed": ("from B to A", "flip test is the wrong way round"),
    "normal_centres_reversed": ("from B to A", "flip test is the wrong way round"),
    "normal_first_vertices": ("from B to A", "pb[0] - pa[0], the first corners"),
    "normal_always_flipped": ("from B to A", "turned round every time, without the test"),
    "normal_negates_depth": ("not the depth",),
    "normal_flips_x_only": ("more than the normal's direction",),
    "k_missing": ("no spin terms",),
    "k_only_a": ("lacks B's spin term",),
    "k_only_b": ("lacks A's spin term",),
    "k_not_squared": ("not squared",),
    "k_inv_mass": ("inv_mass where inv_inertia belongs",),
    "k_assigned": ("use k +=",),
    "k_a_term_with_b_inertia": ("A's spin term uses B's inv_inertia",),
    "k_minus": ("B's spin term is subtracted",),
    "k_lever_length": ("|r|²",),
    "k_divides_inertia": ("ZeroDivisionError",),
    "friction_missing": ("never clamped",),
    "friction_bound_normal_speed": ("closing speed |vn|",),
    "friction_bound_slip_speed": ("relative speed |rel|",),
    "friction_bound_k": ("mu × k",),
    "friction_bound_mu": ("±mu, not ±mu·j",),
    "friction_half_bound": ("mu·j / 2",),
    "friction_always_full": ("full mu·j",),
    "friction_upper_only": ("min(mu·j, jt) alone clamps nothing",),
    "friction_bound_signed_vn": ("closing speed with its sign",),
    "friction_abs_loses_sign": ("along the slip", "min(|jt|, mu·j)"),
    "friction_if_clamp_loses_sign": ("where |jt| > mu·j", "loses jt's sign"),
    "spin_missing": ("spin update is missing",),
    "spin_swapped": ("changed the wrong way",),
    "spin_only_a": ("B's spin did not change",),
    "spin_only_b": ("A's spin did not change",),
    "spin_reversed_cross": ("changed the wrong way",),
    "spin_inv_mass": ("inv_mass where inv_inertia belongs",),
    "spin_rb_for_a": ("uses rb where ra belongs",),
    "spin_assigned": ("set to the change",),
    "spin_both_plus": ("changed the wrong way",),
    "spin_divides_inertia": ("ZeroDivisionError",),
    "spin_vector_assigned": ("left a body's omega as Vector2(", "not a number (rad/s)"),
    "spin_rotates_levers_in_place": ("changed its argument ra in place",),
    "outside_gravity_world": ("gravity=(0, 500)",),
    "outside_gravity_set": ("world.gravity = pygame.Vector2(0, 300)",),
    "outside_max_crates": ("MAX_CRATES = 4",),
    "outside_ramp_angle": ("math.radians(12)",),
    "outside_iterations": ("iterations=20",),
    "outside_clock_tick": ("clock.tick(60) / 1000",),
    "outside_print_zero": ("moving = 0",),
    "outside_fast_mover": ("FAST_MOVER = 1000",),
    "outside_resting_speed": ("RESTING_SPEED = 300",),
    "outside_separating_test_removed": ("if vn >= 0:",),
    "outside_no_push_out": ("separate=lambda",),
    "outside_friction_sign": ("jt = rel.dot(t) / kt",),
    "outside_crate_friction": ("friction=1.5",),
}
ENTRIES = with_says(ENTRIES, SAYS)
BY_NAME = {entry.name: entry for entry in ENTRIES}
WRONG = [entry for entry in ENTRIES if entry.check != "pass"]

# What tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself (each key optional):
# short (its entries' name prefix), mechanisms (the issue-35 mechanisms that apply; tests/corpus_attacks.py
# says why), library_name / library_owner (the library's answer to the first step where it is not the first
# STEP_LIBRARY name), world_call, hidden, forger and side (the attacks' code where the default does not fit).
ATTACK = {
    "short": "tc",
    "mechanisms": (1, 2, 3, 4, 5, 6, 7, 8, 9, 10),
    # a step function no probe splices, hidden under `coding: unicode_escape` (mechanism 2)
    "hidden": (6, "from lesson11.physics2d import apply_impulse", "apply_impulse_spin"),
    "forger": (4, ("sat_axes", "apply_impulse_spin")),   # resolve() forges; the other functions' checks
}

# The wrong-kind values its step functions must fail on, never the checker (tests/test_wrong_kinds.py):
# [(function, step, [case, ...])], the cases written as tests/wrong_kinds.py says.
WRONG_KINDS = [("sat", 2, returns(HIT)), ("apply_impulse", 6, after_solution(MOTION)),
               ("resolve", 4, after_solution(MOTION[:3] + ["a.pos = 'x'", f"k += {V}(1, 0)", "k = float('nan')",
                                                           "k = '1'"])),
               ("resolve", 5, after_solution([f"jt = {V}(1, 0)", "jt = (1.0, 0.0)", "jt = float('inf')",
                                              "jt = 10 ** 400", "jt = None"]))]

# The wrong entry `python -m checker FILE --show` is tried on (tests/test_checker_show.py): one wrong step
# whose scene differs visibly from the solution's, and the kind of failing case --show draws for it.
SHOW_ENTRY, SHOW_CASE = 'spin_missing', 'ImpulseCase'

# the mistake id each entry's failing check must carry (issue 40: --json's "mistake"); the friction ones are
# Ball on the Ramp's (the same mistake, the same id and words: checker/causes.SHARED)
MISTAKE_IDS = {
    "sat_gap_continue": "sat_gap_continue", "sat_one_sided_overlap": "sat_one_sided", "sat_union_extent": "sat_union",
    "sat_projects_pa_twice": "sat_a_twice", "sat_unnormalised_axes": "sat_unnormalised",
    "sat_largest_overlap": "sat_largest", "sat_skips_closing_edge": "sat_closing_edge",
    "normal_not_flipped": "normal_not_flipped", "normal_flip_reversed": "normal_reversed",
    "normal_always_flipped": "normal_always_flipped", "normal_first_vertices": "normal_first_vertices",
    "normal_negates_depth": "normal_depth_negated", "k_missing": "k_no_spin", "k_only_a": "k_no_b_spin",
    "k_only_b": "k_no_a_spin", "friction_missing": "friction_unclamped", "friction_bound_mu": "friction_bound_mu",
    "friction_always_full": "friction_always_full", "friction_abs_loses_sign": "friction_sign",
    "friction_if_clamp_loses_sign": "friction_clamp_loses_sign", "spin_missing": "spin_missing",
    "spin_assigned": "spin_assigned",
}


# Two known mistakes of one step at once (tests/test_named_causes.py): neither formula alone gives the file's
# answers, so the first message names the step and the values and neither cause (a cause the file does not have
# alone is a false lead). {name: (the check that fails first, {step: code}, the causes' words it must not say)}
COMBINED = {
    "union_on_unnormalised_axes": (   # unnormalised axes and both shadows together
        "sat_axes", second_mistake(ENTRIES, "sat_unnormalised_axes", 2, "min(max_a, max_b) - max(min_a, min_b)",
                                   "max(max_a, max_b) - min(min_a, min_b)"),
        ("both shadows together", "not divided by their length")),
    "reversed_test_on_first_corners": (   # the first corners and the test reversed
        "sat_normal", second_mistake(ENTRIES, "normal_first_vertices", 3, "< 0", "> 0"),
        ("wrong way round", "first corners", "every time", "never turned round")),
}


# ================================================================ building the files

def regions(source, where="file"):
    """{step: (start marker line index, end marker line index, indent)} for steps 2-6; each marker exactly once."""
    lines = source.split("\n")
    starts, ends = {}, {}
    for index, line in enumerate(lines):
        match = START.match(line)
        if match:
            step = int(match.group("step"))
            if step in starts:
                raise AssertionError(f"{where}: the start marker of step {step} occurs twice")
            starts[step] = (index, match.group("indent"))
        match = END.match(line)
        if match:
            step = int(match.group("step"))
            if step in ends:
                raise AssertionError(f"{where}: the end marker of step {step} occurs twice")
            ends[step] = index
    found = {}
    for step in STEPS:
        if step not in starts or step not in ends or ends[step] <= starts[step][0]:
            raise AssertionError(f"{where}: step {step} has no `# --- step {step}: ... ---` ... "
                                 f"`# --- end of step {step} ---` region")
        found[step] = (starts[step][0], ends[step], starts[step][1])
    return found


def step_code(source, where="file"):
    """{step: the dedented code strictly between the step's markers}."""
    lines = source.split("\n")
    return {step: textwrap.dedent("\n".join(lines[start + 1:end])).strip("\n")
            for step, (start, end, _) in regions(source, where).items()}


def fill(source, codes, where="file"):
    """source with the interior of each step in codes replaced by that code, indented like the step's marker."""
    lines = source.split("\n")
    found = regions(source, where)
    for step in sorted(codes, key=lambda s: -found[s][0]):  # bottom up, so earlier indices stay valid
        start, end, indent = found[step]
        body = [indent + line if line.strip() else "" for line in codes[step].split("\n")] if codes[step] else []
        lines[start + 1:end] = body
    return "\n".join(lines)


def apply_edits(source, edits, name):
    """source with each (old, new) replacement made in turn; each old must occur exactly once (tests/mutants.py)."""
    return mutants.apply_edits(source, edits, name, "the built file", "tests/corpus_tumbling_crates.py")


def _read(path):
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def build(name, starter=None, solution=None):
    """The source of entry `name`: the starter, its steps filled (the entry's code, else the solution's), then edits."""
    entry = BY_NAME[name]
    starter = _read(STARTER) if starter is None else starter
    solution = _read(SOLUTION) if solution is None else solution
    codes = step_code(solution, "solutions/tumbling_crates.py")
    unknown = set(entry.steps) - set(STEPS)
    if unknown:
        raise AssertionError(f"{name}: no step {sorted(unknown)} in the lab (steps are {STEPS})")
    codes.update(entry.steps)
    return apply_edits(fill(starter, codes, "starters/tumbling_crates_starter.py"), entry.edits, name)


def write_corpus(directory, names=None):
    """Write NAME.py into directory for each entry (all by default); returns {name: path}."""
    starter, solution = _read(STARTER), _read(SOLUTION)
    paths = {}
    for name in (BY_NAME if names is None else names):
        path = os.path.join(str(directory), name + ".py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(build(name, starter, solution))
        paths[name] = path
    return paths
