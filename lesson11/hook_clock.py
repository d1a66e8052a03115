"""Timing a lab's own functions inside the World: which hooks are the lab's, a timing wrapper, its own cost.

Used by the solver panel (lesson11/panel.py, "where a frame goes", measured live)
and by the frame-share benchmark (lesson11/bench/frame_share.py). A World calls
a lab's functions through its hooks (world.sat, world.resolve, ...); the lab's
time is the time inside those calls, inclusive of everything they call
(apply_impulse, and the library's project, edge_normals, spin_velocity, cross).
"""
import statistics

HOOKS = ("sat", "circle_circle", "circle_polygon", "resolve", "separate", "circle_point")


def lab_hooks(world):
    """{name: function} of the World's hooks that are not the library's own (so: the lab's functions)."""
    from .physics2d import collision
    library = {"sat": collision.sat, "circle_circle": collision.circle_circle,
               "circle_polygon": collision.circle_polygon, "circle_point": collision.circle_contact_point,
               "resolve": getattr(world, "lesson_resolve", None), "separate": getattr(world, "lesson_separate", None)}
    found = {}
    for name in HOOKS:
        function = getattr(world, name, None)
        function = getattr(function, "timed_function", function)  # already wrapped: the lab's function inside
        if function is not None and function != library[name]:
            found[name] = function
    return found


def wrap(function, tally, clock):
    """function, timed: each call adds its clock() seconds to tally[0] and 1 to tally[1].

    The wrapper keeps the function as `timed_function`, so it can be taken off again.
    """
    def timed(*args):
        start = clock()
        result = function(*args)
        tally[0] += clock() - start
        tally[1] += 1
        return result
    timed.timed_function = function
    return timed


def calibrate(clock, calls=20_000, repeats=5):
    """The wrapper's own cost with this clock (s per call): (added to the caller's time, counted inside the call).

    A no-op called with four arguments, bare and wrapped, and an empty loop, medians of `repeats`:
    added = (wrapped loop - bare loop) / calls; inside = counted inside / calls - (bare loop - empty loop) / calls.
    """
    def noop(a, b, c, d):
        return None
    added, inside = [], []
    for _ in range(repeats):
        tally = [0.0, 0]
        timed = wrap(noop, tally, clock)
        start = clock()
        for _ in range(calls):
            pass
        empty = clock() - start
        start = clock()
        for _ in range(calls):
            noop(1, 2, 3, 4)
        bare = clock() - start
        start = clock()
        for _ in range(calls):
            timed(1, 2, 3, 4)
        wrapped = clock() - start
        added.append((wrapped - bare) / calls)
        inside.append(tally[0] / calls - (bare - empty) / calls)
    return max(statistics.median(added), 0.0), max(statistics.median(inside), 0.0)
