"""Checker test files made from the solution: each is solutions/tumbling_crates.py with a few exact edits.

A mutant carries one of the bugs the lesson's Hint diagnoses; a hostile copy
misbehaves under the checker (a loop, a faked printed line). Instead of
keeping full copies of the solution that would drift from it, each entry
lists (old, new) text replacements; write_variants() applies them to the
current solution and writes NAME.py files into a directory (the checker
recognises them as Tumbling Crates labs by the docstring's title).

Every `old` must occur exactly once in the text it is applied to: when the
solution changes so that an edit no longer fits, building the file raises
AssertionError naming the file and the edit, instead of silently testing the
unmodified solution.
"""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLUTION = os.path.join(ROOT, "solutions", "tumbling_crates.py")

TITLE = '"""Tumbling Crates: the Lesson 11 practice exercise'   # the solution's first line begins so

# name -> (what is wrong, [(old, new), ...]); each old is whole lines of the solution, indentation and
# newlines included
MUTANTS = {
    "mutant_sat_never_overlaps": ("step 2 starts with return None, so sat always returns None", [
        ("    # --- step 2: the SAT loop ---\n",
         "    # --- step 2: the SAT loop ---\n    return None\n"),
    ]),
    "mutant_normal_not_flipped": ("step 3 removed, the normal is not turned to point from A to B", [
        ("    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:\n        best_axis = -best_axis\n", ""),
    ]),
    "mutant_spin_terms_missing": ("step 4 removed, k has no spin terms", [
        ("    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n", ""),
    ]),
    "mutant_friction_unclamped": ("step 5 removed, the friction impulse is not clamped", [
        ("        jt = max(-mu * j, min(mu * j, jt))\n", ""),
    ]),
    "mutant_friction_flipped": ("a flipped sign in the clamped friction impulse", [
        ("        jt = max(-mu * j, min(mu * j, jt))\n", "        jt = -max(-mu * j, min(mu * j, jt))\n"),
    ]),
    "mutant_spin_missing": ("step 6 removed, apply_impulse has no spin updates", [
        ("    a.omega -= cross(ra, impulse) * a.inv_inertia\n    b.omega += cross(rb, impulse) * b.inv_inertia\n", ""),
    ]),
    "mutant_spin_swapped": ("step 6 with swapped signs, A uses += and B uses -=", [
        ("    a.omega -= cross(ra, impulse) * a.inv_inertia\n    b.omega += cross(rb, impulse) * b.inv_inertia\n",
         "    a.omega += cross(ra, impulse) * a.inv_inertia\n    b.omega -= cross(rb, impulse) * b.inv_inertia\n"),
    ]),
}

# edits outside the steps: handout_unchanged fails them; graded with --allow-edits their behaviour shows
EDITED = {
    # an edit outside the steps: handout_unchanged fails; graded with --allow-edits the pile sinks
    "mutant_no_push_out": ("no positional correction: World gets a separate() that does nothing", [
        ("    return World(lab.scene(make_scene(rng)), sat=sat, resolve=resolve)  # lab runtime: scene()\n",
         "    return World(lab.scene(make_scene(rng)), sat=sat, resolve=resolve, separate=lambda *args: None)"
         "  # lab runtime: scene()\n"),
    ]),
}

# hostile copies of the solution; the other hostile_*.py files in tests/fixtures/checker are short and stay files
HOSTILE_COPIES = {
    "hostile_loop_in_main": ("the lab-runtime frame_budget() removed from the loop, so it never ends under the checker", [
        ("    while running and lab.frame_budget():  # lab runtime: frame_budget()\n",
         "    while running:  # lab runtime: frame_budget()\n"),
    ]),
    # test_checker.py works out the endless loop's two line numbers from this variant's text and looks for them
    "hostile_loop_inside_frame": ("an endless loop inside the main loop, every runtime line kept", [
        ("        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)\n",
         "        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)\n"
         "        while dt > 0:  # an endless loop inside the main loop (the runtime lines are all kept)\n"
         "            dt = dt * 1.0\n"),
    ]),
    "hostile_fake_line": ("prints the final line without simulating", [
        ("def main():\n    pygame.init()\n",
         "def main():\n    print('Simulated 10.0 s with 8 crates; fast movers now: 0')\n    return\n    pygame.init()\n"),
    ]),
}

VARIANTS = {**MUTANTS, **EDITED, **HOSTILE_COPIES}


def apply_edits(source, edits, name="file", where="solutions/tumbling_crates.py", owner="tests/mutants.py"):
    """source with each (old, new) replacement made in turn; each old must occur exactly once.

    Otherwise AssertionError naming the file (`name`), the text it was applied to (`where`) and the
    module whose edits must be updated (`owner`).
    """
    for old, new in edits:
        count = source.count(old)
        if count != 1:
            raise AssertionError(f"{name}: the text to replace occurs {count} times (expected once) in "
                                 f"{where}; update {owner}. Text: {old!r}")
        source = source.replace(old, new)
    return source


def variant_source(name, solution=None):
    """The text of one variant: the solution with its edits, its docstring's first line naming the bug."""
    if solution is None:
        with open(SOLUTION, encoding="utf-8") as handle:
            solution = handle.read()
    what, edits = VARIANTS[name]
    label = "hostile checker test file" if name.startswith("hostile_") else "checker test mutant"
    header = (TITLE, f"{TITLE} ({label}: {what})")
    return apply_edits(solution, [header] + edits, name)


def write_variants(directory, names):
    """Write NAME.py into directory for each name; returns {name: path}."""
    paths = {}
    for name in names:
        path = os.path.join(str(directory), name + ".py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(variant_source(name))
        paths[name] = path
    return paths
