"""Attempts to get a step's points without doing the work, for every lab, and honest files in odd styles.

Every entry is a whole file built from the lab's CURRENT solution: the attacked
step's inside is replaced (the attacker did not write it: the starter's
placeholder, or code that hands the step to someone else), and some attacks add
code outside the steps too. Kinds of attack, each aimed at one step's check:

  import      the step imports the library's version of its function and returns its answer
  world       the step asks World (which runs on the library's functions) for the answer
  dunder      the step reaches the library through __import__
  forge       the step is left undone; code added outside the steps patches the checker's probe
              module in the child so the child's own reference agrees with whatever it returns
  rebind      the step is left undone; code outside the steps rebinds the function to the library's
  solution    the step is left undone; code outside the steps reads the shipped solution file and
              runs it over the module (the packages keep it unreadable; here the rules stop it first)
  detect      the step answers with the library's function only when it sees it is graded
              (`__name__` is "lab_under_test" under the checker)
  table       the step answers from a table of the answers to the checker's fixed inputs, copied
              from a run: no forbidden construct at all, but the inputs drawn per run are not in
              the table

Controls are correct completions in other styles that must pass every function
check (a false fail is as bad as a false pass): a while loop, a comprehension,
a print inside a step, a debug print in main() outside the steps (a warning).

    ENTRIES: [Entry]; build(entry) -> source text
"""
import math
import os
import sys
from typing import NamedTuple

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)


class Entry(NamedTuple):
    name: str
    lab: str
    kind: str
    step: int
    code: str           # the step's new inside ("" keeps the starter's placeholder)
    outside: str = ""   # code appended to the file (outside every step)
    target: tuple = ()  # check ids that must not pass; () for a control: every function check passes
    why: str = ""


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as handle:
        return handle.read()


def region(source, step):
    """(first line index inside, end marker index, indent) of step `step`'s region."""
    lines = source.splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if f"# --- step {step}:" in line)
    end = next(i for i, line in enumerate(lines) if f"# --- end of step {step} ---" in line)
    return start + 1, end, lines[start][:len(lines[start]) - len(lines[start].lstrip())]


def build(entry):
    """The entry's file: the solution with the step's inside replaced and `outside` appended."""
    solution = read(f"solutions/{entry.lab}.py")
    lines = solution.splitlines(keepends=True)
    first, end, indent = region(solution, entry.step)
    if entry.code:
        body = "".join(indent + line + "\n" if line else "\n" for line in entry.code.splitlines())
    else:   # the starter's placeholder: the step not done
        starter = read(f"starters/{entry.lab}_starter.py")
        s_first, s_end, _ = region(starter, entry.step)
        body = "".join(starter.splitlines(keepends=True)[s_first:s_end])
    text = "".join(lines[:first]) + body + "".join(lines[end:])
    return text + ("\n" + entry.outside if entry.outside else "")


# the step attacked in each lab: (step, the function's call with its own arguments, the library's name for it,
# the check of that step, the probe module)
TARGETS = {
    "tumbling_crates": (2, "sat(pa, pb)", "sat", "sat_axes"),
    "more_shapes": (2, "regular_polygon(sides, radius)", "regular_polygon", "polygon_corners"),
    "ball_on_ramp": (2, "closest_on_segment(p, a, b)", "closest_on_segment", "closest_point"),
    "bullets": (2, "circle_toi(p1, v1, r1, p2, v2, r2, dt)", "circle_toi", "toi_matches_root"),
    "sleeping_crates": (2, "sleep_timer(timer, speed, spin, dt)", "sleep_timer_of_world", "timer_rule"),
}
WORLD_CALLS = {   # the World method doing each attacked step's job, where there is one
    "tumbling_crates": "return World().sat(pa, pb)",
    "sleeping_crates": "return World().sleep_timer_of_world(timer, speed, spin, dt)",
    "ball_on_ramp": "return World().circle_point and p",
    "more_shapes": "return [p for p in World().bodies] or Polygon(box_points(2 * radius, radius)).points",
    "bullets": "return World().swept_move and None",
}


def _library_call(lab):
    step, call, name, _ = TARGETS[lab]
    args = call[call.index("("):]
    if lab == "sleeping_crates":
        return f"World().sleep_timer_of_world{args}"
    return f"_library{args}"


def attacks(lab):
    step, call, name, check = TARGETS[lab]
    args = call[call.index("("):]
    imported = "sleep_timer_of_world" if lab == "sleeping_crates" else name
    library_import = (f"from lesson11.physics2d import World as _W\nreturn _W().sleep_timer_of_world{args}"
                      if lab == "sleeping_crates" else
                      f"from lesson11.physics2d import {name} as _library\nreturn _library{args}")
    function = call[:call.index("(")]
    probes = f"checker.labs.{lab}.probes"
    out = [
        Entry(f"{lab}_import", lab, "import", step, library_import, target=(check,),
              why="the step imports the library's answer"),
        Entry(f"{lab}_world", lab, "world", step, WORLD_CALLS[lab], target=(check,),
              why="the step asks World, which runs on the library's functions"),
        Entry(f"{lab}_dunder", lab, "dunder", step,
              f"return __import__('lesson11.physics2d', fromlist=['x']).{'World().' if lab == 'sleeping_crates' else ''}"
              f"{imported}{args}", target=(check,), why="the step reaches the library through __import__"),
        Entry(f"{lab}_forge", lab, "forge", step, "",
              outside=f"import sys as _sys\nfor _name in dir(_sys.modules.get('{probes}')):\n"
                      f"    if _name.startswith('reference'):\n"
                      f"        setattr(_sys.modules['{probes}'], _name, lambda *a, **k: None)\n",
              target=(check,), why="the child's references are patched to agree with an undone step"),
        Entry(f"{lab}_rebind", lab, "rebind", step, "",
              outside=(f"from lesson11.physics2d import World as _W\n{function} = lambda *a: _W().sleep_timer_of_world(*a)\n"
                       if lab == "sleeping_crates" else
                       f"from lesson11.physics2d import {name} as _library\n{function} = _library\n"),
              target=(check,), why="the undone step's function is rebound to the library's after the handout's def"),
        Entry(f"{lab}_solution", lab, "solution", step, "",
              outside=f"exec(open({os.path.join(ROOT, 'solutions', lab + '.py')!r}).read().split('def main')[0], "
                      "globals())\n",
              target=(check,), why="the shipped solution is read and run over the module"),
        Entry(f"{lab}_detect", lab, "detect", step,
              f"if __name__ == 'lab_under_test':\n    {library_import.replace(chr(10), chr(10) + '    ')}",
              target=(check,), why="the library's answer only when graded"),
    ]
    return out


def sat_table():
    """Tumbling Crates' step 2 and 3 answered from a table of the checker's fixed pairs (as a student could copy)."""
    from pygame import Vector2  # noqa: F401 (the table holds plain numbers)

    from checker.probe_kit import reference_sat, sat_pairs
    table = {}
    for _, pa, pb in sat_pairs():
        for first, second in ((pa, pb), (pb, pa)):
            hit = reference_sat(first, second)
            key = (round(first[0].x, 3), round(first[0].y, 3), round(second[0].x, 3), round(second[0].y, 3))
            table[key] = None if hit is None else (round(hit[0].x, 12), round(hit[0].y, 12), hit[1])
    return ("table = " + repr(table) + "\n"
            "hit = table.get((round(pa[0].x, 3), round(pa[0].y, 3), round(pb[0].x, 3), round(pb[0].y, 3)))\n"
            "if hit is None:\n    return None\nreturn pygame.Vector2(hit[0], hit[1]), hit[2]")


def timer_table():
    """Sleeping Crates' step 2 answered for the checker's fixed cases only."""
    from checker.labs.sleeping_crates.probes import DT, TIMER_CASES, reference_timer
    table = {}
    for _, timer, speed, spin in TIMER_CASES:
        for dt in (DT, 1 / 60):
            table[(timer, speed, spin, round(dt, 9))] = reference_timer(timer, speed, spin, dt)
    return ("table = " + repr(table) + "\n"
            "return table.get((timer, speed, spin, round(dt, 9)), 0.0)")


def entries():
    out = []
    for lab in TARGETS:
        out += attacks(lab)
    # tables of the fixed inputs: they pass every fixed case, so only the inputs drawn per run fail them
    sat_step2 = read("solutions/tumbling_crates.py")
    first, end, _ = region(sat_step2, 2)
    out.append(Entry("tumbling_crates_table", "tumbling_crates", "table", 2, sat_table(),
                     outside="", target=("sat_axes",), why="answers copied for the fixed pairs only"))
    out.append(Entry("sleeping_crates_table", "sleeping_crates", "table", 2, timer_table(),
                     target=("timer_rule",), why="answers copied for the fixed timer cases only"))
    # controls: correct, in other styles
    out += [
        Entry("tumbling_crates_while_loop", "tumbling_crates", "control", 2,
              "axes = edge_normals(pa) + edge_normals(pb)\nk = 0\nwhile k < len(axes):\n"
              "    axis = axes[k]\n    k += 1\n    lo_a, hi_a = project(pa, axis)\n    lo_b, hi_b = project(pb, axis)\n"
              "    overlap = min(hi_a, hi_b) - max(lo_a, lo_b)\n    if overlap <= 0:\n        return None\n"
              "    if overlap < best_depth:\n        best_depth = overlap\n        best_axis = axis",
              why="a while loop and other names"),
        Entry("more_shapes_comprehension", "more_shapes", "control", 2,
              "return [pygame.Vector2(radius * math.cos(2 * math.pi * k / sides),\n"
              "                       radius * math.sin(2 * math.pi * k / sides)) for k in range(sides)]",
              why="a comprehension with math.cos / math.sin and pygame.Vector2"),
        Entry("sleeping_crates_print_in_step", "sleeping_crates", "control", 2,
              "calm = speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN\nprint('timer', timer, calm)\n"
              "return timer + dt if calm else 0.0", why="a debug print inside the step"),
        Entry("ball_on_ramp_hypot", "ball_on_ramp", "control", 2,
              "ab = b - a\nlength_squared = math.hypot(ab.x, ab.y) ** 2\n"
              "t = min(1.0, max(0.0, (p - a).dot(ab) / length_squared))\nreturn a + ab * t",
              why="math.hypot for |ab|, the clamp written min(max())"),
    ]
    return out


ENTRIES = entries()
