"""The symptom table (lesson11/symptoms.py) is what the window shows: each mistake applied to the solution, run.

For every row, the row's mistake is made in solutions/<lab>.py by exact (old, new) edits (each old must fit
once: tests/mutants.py), the file runs headless through the lab runtime (tests/lab_run.py, as the checker
runs it) on the scene named here, and the symptom the row states is asserted with a measured bound. Scenes:
  Tumbling Crates  the lab's own scene (seed 11, four crates, 3 s); a dozen crates clicked into a pile (the
                   student's window with clicks, 7.7 s); the checker's crate thrown along the floor (1.5 s),
                   which `python -m checker FILE --show` shows
  More Shapes      one or two shapes (1.5 s): a house dropped flat, a hexagon pushed at 420 px/s, a
                   triangle falling past a box's corner
  Ball on the Ramp the checker's ramp, knock and inside scenes (checker/labs/ball_on_ramp/scenes.py)
  Sleeping Crates  the checker's scene (checker/labs/sleeping_crates/scenes.py, 1.5 s)
  Bullets          the lab's own scene, key 5 (CCD), twelve shots at 12000 px/s at the wall (1 s)
The text, the hints and the table agree: lesson11/README.md's Hint section and each lab page's (lesson11/labs/)
are the table's rendering, and no
checker hint names a symptom its lab's table does not have at the hint's step.
"""
import math
import os
import tempfile

import pytest

import mutants
from checker.reading.handout import step_regions
from lab_run import ROOT, run_lab
from lesson11 import symptoms

FLOOR_TOP = 560.0   # px
SEED = {"fps": 60, "seed": 11, "record_every": 1}


def settings(frames, **extra):
    return dict(SEED, frames=frames, **extra)


# ---------------------------------------------------------------- scenes
OWN_SCENE = settings(180)
PILE = None   # filled in below from lab_run.pile_settings (a dozen clicks over the floor, then settling)
THROWN_CRATE = settings(90, scenario=[{"w": 60, "h": 40, "pos": [300, FLOOR_TOP - 20.25], "vel": [400, 0]}])
HOUSE = settings(90, scenario=[{"kind": "house", "w": 56, "h": 44, "pos": [450, 490]}])
PUSHED_HEXAGON = settings(90, scenario=[{"kind": "hexagon", "size": 28, "angle": math.pi / 3, "vel": [420, 0],
                                         "pos": [470, FLOOR_TOP - 28 * math.cos(math.pi / 6) - 0.25]}])
PAST_A_CORNER = settings(90, scenario=[{"kind": "box", "w": 60, "h": 60, "pos": [450, FLOOR_TOP - 30.25]},
                                       {"kind": "triangle", "size": 30, "pos": [492, 300], "angle": -math.pi / 2}])
BULLETS = settings(60, script=[{"frame": 1, "type": "key", "key": "5"}] +
                   [{"frame": 3 + 4 * k, "type": "click", "pos": [700, 120 + 25 * k]} for k in range(12)])


def pile_scene():
    from lab_run import FPS, pile_settings
    return dict(pile_settings(settle_frames=8 * FPS - 250), record_every=5)


PILE = pile_scene()
RAMP_CENTRE, RAMP_ANGLE, RAMP_HALF_THICKNESS = (230, 380), math.radians(22), 12   # px, rad, px


def below_ramp_top(body):
    """How far (px) the body's deepest corner lies below the ramp's top face (negative: above it)."""
    up = (math.sin(RAMP_ANGLE), -math.cos(RAMP_ANGLE))           # the top face's outward normal
    top = (RAMP_CENTRE[0] + RAMP_HALF_THICKNESS * up[0], RAMP_CENTRE[1] + RAMP_HALF_THICKNESS * up[1])
    return max(-((p[0] - top[0]) * up[0] + (p[1] - top[1]) * up[1]) for p in body["points"])


def ball_scene(name):
    from checker.labs.ball_on_ramp import scenes
    return scenes.SCENARIOS[name]()


def sleep_scene():
    from checker.labs.sleeping_crates import scenes
    return scenes.scenario()


# ---------------------------------------------------------------- measurements of a record
def dynamic(frame):
    return [body for body in frame["bodies"] if not body["static"]]


def lowest(body):
    """y (px) of the body's lowest point."""
    if body.get("points"):
        return max(p[1] for p in body["points"])
    return body["pos"][1] + body.get("radius", 0.0)


def max_spin(frames):
    return max((abs(body["omega"]) for frame in frames for body in dynamic(frame)), default=0.0)


def out_of_window(body):
    x, y = body["pos"]
    return not (0 <= x <= 900 and y <= 600)


def flat_degrees(body):
    off = math.degrees(body["angle"]) % 90
    return min(off, 90 - off)


def tunnelled(frames):
    """Bullet positions recorded beyond the wall (x > 472 px) at the wall's height."""
    return [b["pos"] for f in frames for b in f["bodies"] if "radius" in b and b["pos"][0] > 472
            and 40 <= b["pos"][1] <= 440]


def inside_box(point, corners):
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    return min(xs) < point[0] < max(xs) and min(ys) < point[1] < max(ys)


_solution_runs = {}


def solution_run(lab, scene_settings):
    key = (lab, repr(scene_settings))
    if key not in _solution_runs:
        _solution_runs[key] = run(lab, [], scene_settings)
    return _solution_runs[key]


# ---------------------------------------------------------------- the checks, one per row
def tc_fall_through_no_contacts(r):
    last = dynamic(r.frames[-1])
    assert all(c["pos"][1] > 600 for c in last) and not any(f["contacts"] for f in r.frames)


def tc_fall_through_with_contacts(r):
    last = dynamic(r.frames[-1])
    assert all(c["pos"][1] > 600 and math.hypot(*c["vel"]) > 2500 for c in last)   # measured 2940 px/s
    assert any(f["contacts"] for f in r.frames)
    touching = [c for f in r.frames for c in f["touching"]]
    assert touching and all(c["normal"][1] > 0.9 for c in touching)          # down, into the floor


def tc_sink(r):
    last = dynamic(r.frames[-1])
    floor = [c for c in last if c["pos"][1] > 450]                     # the two that land on the floor
    sunk = sorted(lowest(c) - FLOOR_TOP for c in floor)
    assert len(floor) == 2 and 30 < sunk[0] < 50 and 45 < sunk[1] < 65   # measured 39 and 55 px
    assert all(math.hypot(*c["vel"]) < 10 for c in floor)
    ramp = [c for c in last if c["pos"][1] <= 450]                     # the two on the ramp: through it
    assert len(ramp) == 2 and all(below_ramp_top(c) > 2 * RAMP_HALF_THICKNESS for c in ramp)   # 60, 46 px


def lying_flat(body):
    """Whether the body lies flat (within 2°) on the floor or on the 22° ramp."""
    on_ramp = (math.degrees(body["angle"]) - 22) % 90
    return min(flat_degrees(body), on_ramp, 90 - on_ramp) < 2


def settled_like_the_solution(r):
    """The own scene's end: every crate in the window, lying flat, at rest; the printed line says 0."""
    last = dynamic(r.frames[-1])
    assert not any(out_of_window(c) for c in last) and all(lying_flat(c) for c in last)
    assert r.stdout.strip().endswith("fast movers now: 0")


def tc_hang_in_thin_air(r):
    first = [dynamic(f)[0] for f in r.frames]
    struck = [k for k, c in enumerate(first) if -60 < below_ramp_top(c) < -30 and r.frames[k]["contacts"]]
    assert struck                                           # a contact while 30-60 px above the ramp (43 px)
    assert first[-1]["pos"][0] < 120 and below_ramp_top(first[-1]) < 2   # on the ramp near its high end (x 85)
    assert math.hypot(*first[-1]["vel"]) < 5


def tc_never_settles(r):
    assert r.line is not None and r.line[2] >= 2                        # measured: fast movers now: 3
    assert solution_run("tumbling_crates", PILE).line[2] == 0
    own = run("tumbling_crates", CASES["flip_by_owner"][0], OWN_SCENE)
    last = dynamic(own.frames[-1])
    assert not any(out_of_window(c) for c in last) and all(lying_flat(c) for c in last)


def tc_zero_division(r):
    assert isinstance(r, str) and "ZeroDivisionError" in r


def tc_looks_right_but_stops_dead_in_the_checkers_scene(r):
    settled_like_the_solution(r)
    tc_stop_dead(run("tumbling_crates", CASES["friction_unclamped"][0], THROWN_CRATE))


def tc_spin_out(r):
    assert max_spin(r.frames) > 200 and all(out_of_window(c) for c in dynamic(r.frames[-1]))   # 508 rad/s


def tc_looks_right_but_a_pile_flies_apart(r):
    settled_like_the_solution(r)
    pile = run("tumbling_crates", CASES["spin_a_only"][0], PILE)
    assert sum(out_of_window(c) for c in dynamic(pile.frames[-1])) >= 6   # measured 8 of 12
    assert not any(out_of_window(c) for c in dynamic(solution_run("tumbling_crates", PILE).frames[-1]))


def tc_thrown_out(r):
    assert max_spin(r.frames) > 15                                           # measured 21.7, 47 rad/s
    assert any(out_of_window(c) for c in dynamic(r.frames[-1]))


def tc_stop_dead(r):
    start = dynamic(r.frames[0])[0]["pos"][0]
    end = dynamic(r.frames[-1])[0]["pos"][0]
    sol = dynamic(solution_run("tumbling_crates", THROWN_CRATE).frames[-1])[0]["pos"][0]
    assert end - start < 40 and sol - start > 100                           # measured about 2 and 129 px
    print(f"thrown crate: {end - start:.1f} px with the mistake, {sol - start:.1f} px in the finished lab")


def tc_freeze_corner(r):
    assert max_spin(r.frames) == 0.0
    last = dynamic(r.frames[-1])
    assert all(math.hypot(*c["vel"]) < 5 for c in last)
    assert all(flat_degrees(c) > 5 for c in last)                            # 26, 20, 16, 6 degrees off flat


def tc_fly_off(r):
    assert max(math.hypot(*c["pos"]) for c in dynamic(r.frames[-1])) > 19000


def ms_crash(r):
    assert isinstance(r, str) and "convex" in r


def ms_vanish(r):
    assert lowest(dynamic(r.frames[0])[0]) - FLOOR_TOP > 1000


def ms_looks_right(r):
    mine, sol = dynamic(r.frames[-1])[0], dynamic(solution_run("more_shapes", HOUSE).frames[-1])[0]
    assert math.dist(mine["pos"], sol["pos"]) < 3 and flat_degrees(mine) < 1


def turned_in_all(frames):
    """Degrees the first body turned over the run, every frame's turn added (rocking back and forth counts)."""
    angles = [dynamic(frame)[0]["angle"] for frame in frames]
    return math.degrees(sum(abs(b - a) for a, b in zip(angles, angles[1:])))


def ms_hardly_turn(r):
    mine, sol = turned_in_all(r.frames), turned_in_all(solution_run("more_shapes", PUSHED_HEXAGON).frames)
    assert 25 < mine < 50 and 180 < sol < 230                               # measured 35.9° and 205.2°


def ms_hang(r):
    triangle = dynamic(r.frames[-1])[1]
    assert FLOOR_TOP - lowest(triangle) > 40 and math.hypot(*triangle["vel"]) < 5   # 59 px up, at rest


def br_hang(r):
    ball = dynamic(r.frames[-1])[0]
    assert FLOOR_TOP - lowest(ball) > 100 and math.hypot(*ball["vel"]) < 5   # stopped at the ramp's end


def br_stays_inside(r):
    crate, ball = dynamic(r.frames[-1])
    assert inside_box(ball["pos"], crate["points"])


def br_shoved(r):
    from checker.labs.ball_on_ramp.scenes import INSIDE_BALL, INSIDE_CRATE   # where the two start
    crate, ball = dynamic(r.frames[-1])
    assert math.dist(crate["pos"], INSIDE_CRATE["pos"]) > 20 and math.dist(ball["pos"], INSIDE_BALL["pos"]) < 12


def br_rolls_slower(r):
    from checker.labs.ball_on_ramp.scenes import ROLLING, measure_roll
    accel = measure_roll(r.record, 0)["accel"]
    assert abs(accel - ROLLING * 3 / 4) < 0.03 * ROLLING                      # ½ g sin θ = ¾ of ⅔ g sin θ


def br_held(r):
    ball = dynamic(r.frames[-1])[0]
    assert max_spin(r.frames) < 0.1 and math.hypot(*ball["vel"]) < 5


def br_spins_backwards(r):
    ball = dynamic(r.frames[-1])[0]
    sol = dynamic(solution_run("ball_on_ramp", ball_scene("ramp")).frames[-1])[0]
    assert ball["omega"] * sol["omega"] < 0 and abs(abs(ball["omega"]) - abs(sol["omega"])) < 0.05 * abs(sol["omega"])
    assert abs(math.hypot(*ball["vel"]) - math.hypot(*sol["vel"])) < 0.02 * math.hypot(*sol["vel"])


def br_slides(r):
    from checker.labs.ball_on_ramp.scenes import SLIDING, measure_roll
    assert max(abs(b["omega"]) for f in r.frames for b in dynamic(f)[:1]) < 0.1
    assert abs(measure_roll(r.record, 0)["accel"] - SLIDING) < 0.02 * SLIDING


def br_spin_wrong_way(r):
    ball = dynamic(r.frames[-1])[0]
    sol = dynamic(solution_run("ball_on_ramp", ball_scene("ramp")).frames[-1])[0]
    assert ball["omega"] * sol["omega"] < 0 and abs(ball["omega"]) > 50
    assert math.hypot(*ball["vel"]) > 2 * math.hypot(*sol["vel"])


def sc_hang(r):
    thrown = dynamic(r.frames[-1])[-1]
    assert thrown["asleep"] and FLOOR_TOP - lowest(thrown) > 50                # 78 px up, asleep


def sc_looks_right(r):
    sol = dynamic(solution_run("sleeping_crates", sleep_scene()).frames[-1])
    mine = dynamic(r.frames[-1])
    assert all(math.dist(a["pos"], b["pos"]) < 2 for a, b in zip(mine, sol)) and all(b["asleep"] for b in mine)


def sc_sink(r):
    assert max(lowest(b) for b in dynamic(r.frames[-1])) - FLOOR_TOP > 30      # 35 px


def b_tunnel(r):
    assert len(tunnelled(r.frames)) >= 10                                      # 13-24 records past the wall


def b_looks_right(r):
    assert tunnelled(r.frames) == []


CASES = {
    "sat_none": ([("    # --- step 2: the SAT loop ---\n", "    # --- step 2: the SAT loop ---\n    return None\n")],
                 OWN_SCENE, tc_fall_through_no_contacts),
    "gap_continue": ([("            return None  # found a gap: not touching\n",
                       "            continue  # found a gap: not touching\n")], OWN_SCENE, tc_hang_in_thin_air),
    "flip_by_owner": ([("    for axis in edge_normals(pa) + edge_normals(pb):\n",
                        "    for i, axis in enumerate(edge_normals(pa) + edge_normals(pb)):\n"),
                       ("            best_axis, best_depth = axis, overlap\n",
                        "            best_axis, best_depth, from_a = axis, overlap, i < len(pa)\n"),
                       ("    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:\n", "    if from_a:\n")],
                      PILE, tc_never_settles),
    "k_divides": ([("    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n",
                    "    k += ran * ran / a.inv_inertia + rbn * rbn / b.inv_inertia\n")], OWN_SCENE, tc_zero_division),
    "clamp_swapped": ([("        jt = max(-mu * j, min(mu * j, jt))\n", "        jt = max(mu * j, min(-mu * j, jt))\n")],
                      OWN_SCENE, tc_spin_out),
    "spin_a_only": ([("    a.omega -= cross(ra, impulse) * a.inv_inertia\n", "    a.omega += cross(ra, impulse) * a.inv_inertia\n")],
                    OWN_SCENE, tc_looks_right_but_a_pile_flies_apart),
    "normal_not_flipped": ([("    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:\n        best_axis = -best_axis\n",
                             "")], OWN_SCENE, tc_fall_through_with_contacts),
    "flip_reversed": ([("    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:\n",
                        "    if (centre_of(pb) - centre_of(pa)).dot(best_axis) > 0:\n")], OWN_SCENE, tc_sink),
    "k_no_spin": ([("    k += ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia\n", "")], OWN_SCENE, tc_thrown_out),
    "friction_unclamped": ([("        jt = max(-mu * j, min(mu * j, jt))\n", "")], OWN_SCENE,
                           tc_looks_right_but_stops_dead_in_the_checkers_scene),
    "friction_flipped": ([("        jt = max(-mu * j, min(mu * j, jt))\n", "        jt = -max(-mu * j, min(mu * j, jt))\n")],
                         OWN_SCENE, tc_thrown_out),
    "spin_missing": ([("    a.omega -= cross(ra, impulse) * a.inv_inertia\n    b.omega += cross(rb, impulse) * b.inv_inertia\n",
                       "")], OWN_SCENE, tc_freeze_corner),
    "spin_swapped": ([("    a.omega -= cross(ra, impulse) * a.inv_inertia\n    b.omega += cross(rb, impulse) * b.inv_inertia\n",
                       "    a.omega += cross(ra, impulse) * a.inv_inertia\n    b.omega -= cross(rb, impulse) * b.inv_inertia\n")],
                     OWN_SCENE, tc_fly_off),
    "degrees": ([("    return [Vector2(radius * math.cos(2 * math.pi * k / sides), radius * math.sin(2 * math.pi * k / sides))\n",
                  "    return [Vector2(radius * math.cos(360 * k / sides), radius * math.sin(360 * k / sides))\n")],
                settings(10), ms_crash),
    "centroid_sum": ([("    return total / (6 * area)\n", "    return total\n")], HOUSE, ms_vanish),
    "centroid_average": ([("    return total / (6 * area)\n", "    return sum(points, Vector2()) / len(points)\n")],
                         HOUSE, ms_looks_right),
    "inertia_no_six": ([("    return mass * num / (6 * den)\n    # --- end of step 4 ---\n",
                         "    return mass * num / den\n    # --- end of step 4 ---\n")], PUSHED_HEXAGON, ms_hardly_turn),
    "axes_of_a_only": ([("    for axis in edge_normals(pa) + edge_normals(pb):\n        if all(",
                         "    for axis in edge_normals(pa):\n        if all(")], PAST_A_CORNER, ms_hang),
    "no_clamp": ([("    t = max(0.0, min(1.0, t))\n", "")], "knock", br_hang),
    "inside_unflipped": ([("        return -offset / dist, radius + dist\n", "        return offset / dist, radius + dist\n")],
                         "inside", br_stays_inside),
    "split_swapped": ([("    a.pos -= normal * (push * a.inv_mass / total)\n    b.pos += normal * (push * b.inv_mass / total)\n",
                        "    a.pos -= normal * (push * b.inv_mass / total)\n    b.pos += normal * (push * a.inv_mass / total)\n")],
                      "inside", br_shoved),
    "ring": ([("    return 0.5 * mass * radius ** 2\n", "    return mass * radius ** 2\n")], "ramp", br_rolls_slower),
    "contact_at_centre": ([("    return center + normal * radius\n", "    return center\n")], "ramp", br_held),
    "contact_behind": ([("    return center + normal * radius\n", "    return center - normal * radius\n")], "ramp",
                       br_spins_backwards),
    "no_friction": ([("    jt = max(-mu * j, min(mu * j, jt))  # Coulomb: |friction| <= mu * normal impulse\n"
                      "    apply_impulse(a, b, t * jt, ra, rb)\n", "")], "ramp", br_slides),
    "jt_flipped": ([("    jt = -rel.dot(t) / kt  # the impulse that would stop the slip\n",
                                "    jt = rel.dot(t) / kt\n")], "ramp", br_spin_wrong_way),
    "timer_never_reset": ([("        return timer + dt\n    return 0.0\n", "        return timer + dt\n    return timer + dt\n")],
                          "sleep", sc_hang),
    "timer_or": ([("    if speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN:\n", "    if speed < SLEEP_SPEED or abs(spin) < SLEEP_SPIN:\n")],
                 "sleep", sc_hang),
    "moves_ignores_sleep": ([("    return body.inv_mass != 0 and not body.asleep\n", "    return body.inv_mass != 0\n")],
                            "sleep", sc_looks_right),
    "never_wakes": ([("        if sleeper.asleep and other.inv_mass != 0 and not other.asleep:\n", "        if False:\n")],
                    "sleep", sc_sink),
    "no_touching_case": ([("    if c <= 0:\n        return 0.0  # already touching\n", "")], BULLETS, b_tunnel),
    "later_root": ([("    t = (-b - math.sqrt(disc)) / (2 * a)  # the earlier root: first contact\n",
                     "    t = (-b + math.sqrt(disc)) / (2 * a)\n")], BULLETS, b_looks_right),
    "radius_half_width": ([("    return max(centre.distance_to(p) for p in points)\n",
                            "    return min(abs(p.x - centre.x) for p in points)\n")], BULLETS, b_tunnel),
    "broad_inverted": ([("                  dt) is None:\n", "                  dt) is not None:\n")], BULLETS, b_tunnel),
    "no_resolve": ([("    world.resolve(bullet, other, normal, bullet.pos + normal * bullet.radius)\n", "")], BULLETS, b_tunnel),
    "whole_step_first": ([("    bullet.pos += bullet.vel * t\n    world.resolve(", "    bullet.pos += bullet.vel * dt\n    world.resolve(")],
                         BULLETS, b_tunnel),
}


def scene_settings(scene):
    if isinstance(scene, dict):
        return scene
    return sleep_scene() if scene == "sleep" else ball_scene(scene)


def run(lab, edits, scene):
    """solutions/<lab>.py with the edits, run headless on the scene: a LabRun, or the child's error text."""
    with open(os.path.join(ROOT, "solutions", lab + ".py"), encoding="utf-8") as handle:
        source = handle.read()
    if edits:
        source = mutants.apply_edits(source, edits, lab, f"solutions/{lab}.py", "tests/test_symptoms.py")
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, lab + ".py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(source)
        try:
            return run_lab(path, scene_settings(scene), work)
        except AssertionError as error:   # the lab stopped with an error: its stderr is the symptom
            return str(error)


def case_of(row):
    return CASES[row.key]


@pytest.mark.parametrize("row", symptoms.TABLE, ids=lambda row: f"{row.lab}-{row.key}")
def test_the_window_shows_what_the_table_says(row):
    edits, scene, check = case_of(row)
    result = run(row.lab, edits, scene)
    if check not in (ms_crash, tc_zero_division):
        assert not isinstance(result, str), f"{row.lab} {row.key}: the lab stopped:\n{result}"
    check(result)


def test_every_case_has_a_row_and_every_lab_step_a_row():
    keys = [row.key for row in symptoms.TABLE]
    assert len(keys) == len(set(keys)) and set(keys) == set(CASES)
    from checker import labs
    # the student's steps of each lab with a table: its solution's step regions
    steps = {lab.id: set(step_regions(open(lab.solution, encoding="utf-8").read().split("\n")))
             for lab in labs.LABS if lab.id in symptoms.LABS}
    assert set(steps) == set(symptoms.LABS)
    assert {lab: {row.step for row in symptoms.rows(lab)} for lab in steps} == steps
    assert all(row.kind in symptoms.KINDS for row in symptoms.TABLE)
    assert all(symptoms.kinds_named(row.shows) >= {row.kind} for row in symptoms.TABLE)


def test_the_lessons_and_the_lab_pages_hint_tables_are_the_table():
    """The lesson's Hint section is the Tumbling Crates table; each Going Further lab's page has its own."""
    with open(os.path.join(ROOT, "lesson11", "README.md"), encoding="utf-8") as handle:
        assert symptoms.markdown("tumbling_crates") in handle.read()
    for lab in symptoms.LABS:
        if lab != "tumbling_crates":
            with open(os.path.join(ROOT, "lesson11", "labs", lab + ".md"), encoding="utf-8") as handle:
                assert symptoms.markdown(lab) in handle.read(), lab


def hints():
    from checker import labs
    return [(lab.id, key, hint) for lab in labs.LABS for key, hint in lab.module.HINTS.items()]


@pytest.mark.parametrize("lab,key,hint", hints(), ids=lambda v: v if isinstance(v, str) else "")
def test_no_hint_names_a_symptom_its_labs_table_does_not(lab, key, hint):
    rows = symptoms.rows(lab)
    at_step = [row for row in rows if row.step == hint.step] or rows   # a hint of no student step: any row
    named = symptoms.kinds_named(f"{hint.title} {hint.text}")
    shown = set().union(*(symptoms.kinds_named(row.shows) for row in at_step))
    assert named <= shown, (f"{lab} hint {key!r} (step {hint.step}) names {sorted(named - shown)}, "
                            f"which its table has not at that step")


def test_the_hint_rule_catches_the_old_diagnoses():
    assert symptoms.kinds_named("If crates explode apart on contact") == {"explode"}
    assert symptoms.kinds_named("crates land but never tip over") == {"never_tip"}
    assert symptoms.kinds_named("Crates are shot apart") == {"explode"}
    assert "explode" not in {row.kind for row in symptoms.TABLE}
