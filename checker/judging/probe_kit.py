"""Probe helpers that several labs share: placing shapes, the SAT cases and answers, spliced steps.

Tumbling Crates and More Shapes both probe a sat(); Ball on the Ramp and Bullets
place boxes and polygons. Units: px, degrees for the angles given here
(clockwise on screen), rad inside the bodies.

A probe runs twice: in the child (the student's code runs there) it only calls the
student's functions on its inputs; in the grader it replays the child's tape and adds
the lesson's answers. So every reference value is computed under `if judging(module):`
by a helper marked `@reference` (which raises if the child ever calls it), from inputs
or from a `twin` of a body taken before the student's function could change it.
"""
import copy
import math

from pygame import Vector2

from lesson11.physics2d import box_points, centre_of, cross, edge_normals, project, regular_polygon
from lesson11.physics2d import apply_impulse as lesson_apply_impulse, relative_velocity

from checker.judging.common import real, value_text
from checker.judging.tape import judging, reference, splice_name   # noqa: F401 (the labs' probes import them from here)


def twin(body):
    """A separate copy of `body` (its own pos and vel vectors; the shape is shared, it is never changed).

    Taken before a student's function gets the body, so a reference computed from the twin
    reads the body as it was given, whatever the function did to it.
    """
    copied = copy.copy(body)
    copied.pos, copied.vel = Vector2(body.pos), Vector2(body.vel)
    return copied


def changed_vectors(given, **originals):
    """{name: [x, y]} of the vectors in `given` {name: the copy handed to a step function} that no longer equal
    `originals[name]`: a step that changes a contact's normal or point in place, which its caller goes on using."""
    return {name: [vector.x, vector.y] for name, vector in given.items() if vector != originals[name]}


def with_reference_steps(module, lab_path, function, steps):
    """The lab's `function` with the inside of each step in `steps` taken from the solution, or None.

    Grading step 2 with the solution's step 3 (and so on) tells a mistake in one step from a
    mistake in the next: e.g. a step 3 that negates the depth instead of the axis. The grading
    parent builds the spliced source (checker/judging/probing.py, from the probe module's SPLICES, so
    the child never opens the solution); `module` (a tape.Recorder or tape.Replayer) compiles and
    records it in the child, or replays it in the parent. None when the markers cannot be found.
    """
    return module.spliced(splice_name(function, steps), function)


def _placed(points, centre, angle_deg=0.0):
    """Local points turned by angle_deg (clockwise on screen) and moved to centre: world points (px)."""
    return [Vector2(centre) + Vector2(p).rotate(angle_deg) for p in points]


def box(w, h, centre, angle_deg=0.0):
    """A w × h box's world points (px)."""
    return _placed(box_points(w, h), centre, angle_deg)


def ngon(sides, radius, centre, angle_deg=0.0):
    """A regular polygon's world points (px)."""
    return _placed(regular_polygon(sides, radius), centre, angle_deg)


def stop_over_bound(a, b, normal, point, resting, spin=True):
    """|the impulse that stops the slip| / (mu j) after the lesson's normal impulse (e above `resting` px/s; with
    spin=False, k without the spin terms, as a friction step written before Tumbling Crates' step 4 sees it), or
    None when the contact does not close or hardly slides (< 2 px/s): only to keep the contacts drawn for a run
    clear of Coulomb's clamp's edge (the grader computes the answers)."""
    a, b = twin(a), twin(b)
    ra, rb = point - a.pos, point - b.pos
    vn = relative_velocity(a, b, ra, rb).dot(normal)
    if vn >= -1.0:
        return None
    e = min(a.restitution, b.restitution) if vn < -resting else 0.0
    ran, rbn = cross(ra, normal), cross(rb, normal)
    j = -(1 + e) * vn / (a.inv_mass + b.inv_mass + spin * (ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia))
    lesson_apply_impulse(a, b, normal * j, ra, rb)
    rel = relative_velocity(a, b, ra, rb)
    tangent = rel - normal * rel.dot(normal)
    if tangent.length() < 2.0:
        return None
    t = tangent.normalize()
    rat, rbt = cross(ra, t), cross(rb, t)
    kt = a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia
    bound = math.sqrt(a.friction * b.friction) * j
    return abs(rel.dot(t)) / kt / bound if bound > 0 else None


# ---------------------------------------------------------------- sat (steps 2 and 3)

def sat_pairs():
    """(name, A's points, B's points): each pair is also probed with A and B swapped."""
    square = box(40, 40, (0, 0))
    return [
        ("side by side, 10 px overlap", square, box(40, 40, (30, 5))),
        ("a diamond near a corner (bounding boxes overlap, shapes apart)", square, box(40, 40, (45, 45), 45)),
        ("a diamond pushed closer", square, box(40, 40, (30, 30), 45)),
        ("two turned crates", box(60, 40, (100, 100), 30), box(50, 34, (146, 122), -20)),
        ("a turned crate and a pentagon", box(70, 30, (0, 0), 15), ngon(5, 30, (44, 28), 10)),
        ("a triangle and a hexagon, apart", ngon(3, 40, (0, 0), 12), ngon(6, 24, (48, -30), 5)),
        ("a small crate deep inside a big one", box(200, 120, (0, 0), 10), box(30, 20, (24, 12), 35)),
        ("a hexagon resting into a wide crate", box(160, 30, (0, 0), 0), ngon(6, 25, (22, -36), 17)),
        ("a small crate inside a big one, near its top-left corner", box(200, 120, (0, 0), 10),
         box(30, 20, (-60, -30), -25)),
        ("two triangles", ngon(3, 37, (0, 0), 345), ngon(3, 34, (46, -32), 224)),
        ("a pentagon and a small hexagon", ngon(5, 40.7, (0, 0), 265), ngon(6, 16.3, (-33, -29), 179)),
        ("a pentagon and a triangle, apart", ngon(5, 29, (0, 0), 76), ngon(3, 34.6, (47, 23), 179)),
        ("two crates exactly touching edge to edge", box(40, 40, (0, 0)), box(40, 40, (40, 7))),
        ("two crates far apart", box(40, 40, (0, 0)), box(30, 60, (300, -50), 25)),
    ]


DRAWN_PAIRS = 4   # pairs drawn at random per grading run, beside the fixed ones


def random_shape(rng, centre):
    """A box or a regular polygon of a random size and angle around `centre` (world points, px)."""
    angle = rng.uniform(0, 360)
    if rng.random() < 0.5:
        return box(rng.uniform(24, 90), rng.uniform(24, 90), centre, angle)
    return ngon(rng.randint(3, 7), rng.uniform(15, 45), centre, angle)


def _clear_winner(pa, pb, margin=0.5):
    """True when no overlap is within `margin` px of 0 and the smallest overlap (both rules) has no rival
    along another direction within `margin` px: a pair with one right answer."""
    overlaps = axis_overlaps(pa, pb)
    if any(abs(lesson) < margin for _, lesson, _ in overlaps):
        return False
    for rule in (1, 2):
        ranked = sorted(overlaps, key=lambda item: item[rule])
        best = ranked[0]
        if any(item[rule] - best[rule] < margin and abs(cross(item[0], best[0])) > 1e-6 for item in ranked[1:]):
            return False
    return True


def drawn_sat_pairs(rng, count=DRAWN_PAIRS):
    """`count` pairs drawn for this grading run, each with one right answer: overlapping and apart in turn (the
    first overlaps), so a table of the fixed pairs' answers with one default for the rest (None, say) is wrong on
    one of them at every seed.

    An apart pair shows a gap on some axes only, like the fixed apart pairs: on a pair apart on every axis a
    loop that keeps no axis (`continue` on a gap) raises, and its report would depend on the run's seed.
    """
    pairs = []
    while len(pairs) < count:
        overlapping = len(pairs) % 2 == 0
        pa = random_shape(rng, (0, 0))
        pb = random_shape(rng, Vector2(rng.uniform(10, 80), 0).rotate(rng.uniform(0, 360)))
        overlaps = [lesson for _, lesson, _ in axis_overlaps(pa, pb)]
        if any(lesson > 0 for lesson in overlaps) and all(lesson > 0 for lesson in overlaps) == overlapping \
                and _clear_winner(pa, pb):
            pairs.append((f"a pair drawn for this run, {'overlapping' if overlapping else 'apart'} "
                          f"({len(pairs) + 1} of {count})", pa, pb))
    return pairs


def axis_overlaps(pa, pb):
    """Per edge normal of A then B: (axis, the lesson's overlap, the shorter way out) in px.

    lesson: min(max_a, max_b) - max(min_a, min_b)
    shorter way out: min(max_a - min_b, max_b - min_a); the two differ only when one
    shadow contains the other (a deep hit).
    """
    out = []
    for axis in edge_normals(pa) + edge_normals(pb):
        min_a, max_a = project(pa, axis)
        min_b, max_b = project(pb, axis)
        out.append((axis, min(max_a, max_b) - max(min_a, min_b), min(max_a - min_b, max_b - min_a)))
    return out


@reference
def reference_sat(pa, pb, rule="lesson"):
    """The lesson's sat (or, with rule="short", the shorter-way-out depth): None or (normal A→B, depth)."""
    best_axis, best_depth = None, math.inf
    for axis, lesson, short in axis_overlaps(pa, pb):
        if lesson <= 0:
            return None
        depth = lesson if rule == "lesson" else short
        if depth < best_depth:
            best_axis, best_depth = axis, depth
    if (centre_of(pb) - centre_of(pa)).dot(best_axis) < 0:
        best_axis = -best_axis
    return best_axis, best_depth


def _plain(hit):
    return None if hit is None else {"normal": [hit[0].x, hit[0].y], "depth": hit[1]}


def sat_answer(hit):
    """The student's sat() answer as plain data.

    None, {"normal": [x, y], "depth": d}, or {"bad": what is wrong with its shape}
    (e.g. "(depth, normal)" when the two are returned the other way round).
    """
    if hit is None:
        return None
    try:
        first, second = hit
    except (TypeError, ValueError):
        return {"bad": f"a {type(hit).__name__} ({_short_repr(hit)})"}
    if isinstance(first, (int, float)) and not isinstance(second, (int, float)):
        return {"bad": "(depth, normal)"}
    try:
        normal, depth = Vector2(first), real(second)
    except (TypeError, ValueError):
        return {"bad": f"({_short_repr(first)}, {_short_repr(second)})"}
    if not (math.isfinite(normal.x) and math.isfinite(normal.y) and math.isfinite(depth)):
        return {"bad": f"a normal or depth that is not a finite number: ({_short_repr(first)}, {depth!r})"}
    return {"normal": [normal.x, normal.y], "depth": depth}


_short_repr = value_text   # repr cut to 60 characters; safe for a 5000-digit int


