"""Issue 39's attacks on the grader's judging (items 2, 3 and 4), entries of tests/corpus_attacks.py.

Each is graded there in every mode (the CLI as root, --child-user nobody, CHECKER_PORTABLE=1 in
tests/test_checker_portable.py) beside its honest file, the same file without the attack (its
`honest_keeps` steps keep their honest code, the solution's, the others go back to the starter's
placeholder), and must score no more. Mechanism numbers: 392, 393, 394 (issue 39, items 2, 3, 4).

  run_time_constant (392)  step 2 sets a handout constant a later probe reads (`global PERCENT; PERCENT = 0`),
                           so the grader's reference for step 4 pushed 0 px: the grader now reads the
                           handout's constants, the child puts them back before each probe, and the step
                           that changed one fails, named
  judge_budget      (393)  step 5 sets BULLET_RADIUS = 1e9 during the last CCD shot: the grader's replay took
                           about 2e7 World steps a shot and the batch never ended; now a named fail (and the
                           replay has a budget: tests/test_judge_budget.py)
  kept_splice       (394)  step 2 keeps the function it runs in on a handout class; run as the grader's splice
                           (the solution's step 3 in it) it keeps that splice, and step 3 returns its answer:
                           the spliced probe now runs after every graded call (checker/labs/*/probes.py
                           PROBES), and the step rules flag the store (rule "keep") where they can see it
"""
import textwrap

KINDS = ("run_time_constant", "judge_budget", "kept_splice")


def code(*parts):
    """One step's code from parts each indented its own way."""
    return "\n".join(textwrap.dedent(part).strip("\n") for part in parts)


# the solution's code of the steps these attacks keep, written out (the prompts left out)
CLOSEST = """
t = (p - a).dot(ab) / ab.dot(ab)
t = max(0.0, min(1.0, t))
return a + ab * t
"""
SWEPT = """
bullet.pos += bullet.vel * t
world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)
bullet.pos += bullet.vel * (dt - t)
"""
SAT_LOOP = """
for axis in edge_normals(pa) + edge_normals(pb):
    min_a, max_a = project(pa, axis)
    min_b, max_b = project(pb, axis)
    overlap = min(max_a, max_b) - max(min_a, min_b)
    if overlap <= 0:
        return None
    if overlap < best_depth:
        best_axis, best_depth = axis, overlap
"""


def entries(attack):
    """The entries, made with tests/corpus_attacks.py's attack()."""
    both = ("root", "child_user")
    return [
        attack("br_m392_percent_first_case", "ball_on_ramp", "run_time_constant", {2: code("""
            global PERCENT
            if p == pygame.Vector2(30, -20) and b == pygame.Vector2(100, 0):  # the probes' first case only
                PERCENT = 0  # separate()'s probe then read 0; the scenes never see this input
        """, CLOSEST), 4: """
            a.pos -= normal * (push / 2)  # wrong: not split by inverse mass
            b.pos += normal * (push / 2)
        """}, ["closest_point", "push_out_split"], "step 2 sets PERCENT = 0 on the probes' first case only, so a "
                                                   "wrong step 4 matched a 0 px push-out and the scenes ran with "
                                                   "0.4: 18/18 (issue 39)", mechanism=392, modes=both,
            message="PERCENT", honest_keeps=(2,)),
        attack("br_m392_percent_from_step2", "ball_on_ramp", "run_time_constant", {2: code("""
            global PERCENT
            PERCENT = 0  # set by step 2, which the probes run first: separate()'s probe then reads 0
        """, CLOSEST), 4: """
            pass  # (no push-out)
        """}, ["closest_point", "push_out_split"], "step 2 is right but sets PERCENT = 0 for the probes that "
                                                   "follow, so an empty step 4 matched a 0 px push-out",
            mechanism=392, modes=both, message="PERCENT", honest_keeps=(2,)),
        attack("bu_m393_radius_last_shot", "bullets", "judge_budget", {5: code("""
            global BULLET_RADIUS
            if bullet.vel.x > 11999 and bullet.pos.x < 370:  # the last shot at 12000 px/s with CCD
                BULLET_RADIUS = 1e9  # the x8 shots' replay then took 2e7 World steps each
        """, SWEPT)}, ["swept_move_resolves"],
            "step 5 is right but sets BULLET_RADIUS = 1e9 during the last CCD shot: the grader's replay never ended "
            "(no report); it must fail, named, and the batch end", mechanism=393, modes=both,
            message="BULLET_RADIUS", honest_keeps=(5,)),
        attack("tc_m394_kept_splice", "tumbling_crates", "kept_splice", {2: code(SAT_LOOP, """
            if not hasattr(Body, "kept"):
                Body.kept = sat  # in the grader's splice, sat is the spliced copy: the solution's step 3
        """), 3: """
            if hasattr(Body, "kept") and Body.kept is not sat:
                return Body.kept(pa, pb)
        """}, ["sat_axes", "sat_normal"], "step 2 keeps the function it runs in on Body; run as the spliced probe "
                                          "it keeps the solution's step 3, which step 3 then calls: 9/17 with step 3 "
                                          "skipped (issue 39)", mechanism=394, modes=both, message=".kept",
            honest_keeps=(2,)),
        attack("tc_m394_kept_by_alias", "tumbling_crates", "kept_splice", {2: code(SAT_LOOP, """
            holder = Body
            if not hasattr(holder, "kept"):
                holder.kept = sat  # through a local name: no rule sees a store on Body
        """), 3: """
            holder = Body
            if hasattr(holder, "kept") and holder.kept is not sat:
                return holder.kept(pa, pb)
        """}, ["sat_normal"], "as tc_m394_kept_splice, the store made through a local name the step rules cannot "
                              "follow: only the order of the probes (the splice last) stands between it and step "
                              "3's points", mechanism=394, modes=both, honest_keeps=(2,)),
    ]


# what still fails each entry with the step rules turned off (tests/test_corpus_attacks_judge.py): the grader's
# own mechanisms alone, the handout's constants and the probes' order (the rules flag `global` and `Body.kept =`)
WITHOUT_RULES = {
    "br_m392_percent_first_case": ("closest_point", "push_out_split"),
    "br_m392_percent_from_step2": ("closest_point", "push_out_split"),
    "bu_m393_radius_last_shot": ("swept_move_resolves", "ccd_never_tunnels", "substeps_still_tunnel"),
    "tc_m394_kept_splice": ("sat_normal",),
    "tc_m394_kept_by_alias": ("sat_normal",),
}
