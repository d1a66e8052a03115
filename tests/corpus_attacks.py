"""The attack corpus: files that try to get a step's points without doing the step, for every lab.

Every entry is a whole student file built like the mistake corpora
(tests/corpus_files.py): the lab's CURRENT starter with each step region filled,
with the entry's code for the steps it names and the solution's code for the
others, so the code around the steps is the handout's and handout_unchanged has
nothing to say. A few entries go further, as a submission may: kind
"evade_own_import" adds one top-level import line (the handout comparison allows
it: "imports you add are fine"), and kinds "evade_side_module" and one
"forge_unflagged" also put a second file beside the lab file (`extra_files`,
as a submission folder may hold), imported by one line added at the file's end.

An attack names `target`, the check ids that must NOT pass, and the file must
score below the lab's maximum. A control (`target` None) is an honest, correct
completion in an unusual style: every function check must pass and the step
rules must flag nothing (a false fail is as bad as a false pass).

Kinds, every lab has each of the first seven and at least two controls:

  import      the step imports the library's function that does its job and returns its answer
  world       the step asks World (built on the library's functions) to do its job
  dunder      the step reaches the library through __import__ or importlib
  forge       the step is left undone and, at its first call, patches the child's view of the
              grading: the probe module's reference function (so the child's "lesson" answer equals
              the placeholder's), json.dumps (copying every "want" into "got"), or a forged result
              line written straight to the result pipe (fd 3) before the child kills itself
  solution    the step reads solutions/<lab>.py, runs it and returns the solution's answer
  detect      the step returns the library's answer only when it sees it is graded
              (checker in sys.modules, __name__ == "lab_under_test", the checker's SDL driver or
              its temporary working folder), the placeholder otherwise
  table       the step answers from a table of the answers for the probes' FIXED inputs (read from
              the probe modules' case lists, as a student copies them from a run) and guesses
              otherwise: no forbidden construct at all, so only inputs drawn per run can catch it
              (needs_random_inputs=True)
  control     a correct completion in another style: while loops, comprehensions, math.hypot,
              lambdas, a local named `result`, tuple unpacking; and one with a debug print in a step

Beyond the brief's list: attacks that reach the same answers around the step rules
(checker/reading/step_rules.py), each written against the rules as they stood when it was added
(the rules are being rewritten; the test says which still get through):

  evade_alias       `[random][0]._os.sys.modules[...]`: random is a handout import, the list hid
                    it from the "module" rule, random's private `_os` is the os module and its `sys`
                    gives every loaded module; a library function bound to a local name first was no
                    "library" call (only `x.sat(...)` and `sat(...)` were)
  evade_class       a handout class or World method computes the answer under a name no rule lists:
                    Body.from_world_points(points).pos (the library's centroid), 1 / Body(...).inv_inertia
                    (polygon and disc inertia), type(make_world(...))() (a World without naming World),
                    World.manifolds (sat), World().wake_pair, World.step (the sleep timer),
                    super(BulletWorld, world) (World.swept_move)
  evade_own_import  an added `from pkgutil import resolve_name` (allowed outside the steps, pkgutil
                    is not a closed module), used in the step through a parameter default, which the
                    "import" rule once took for a name the file binds itself
  evade_match       a match statement's class pattern, `case object(__globals__=g)`, reads an
                    attribute by a string (a dunder or a library name): a handout function's
                    __globals__ is its library module's namespace (g["sat"], g["__builtins__"], ...)
  evade_side_module the steps are the starter's (or call a name they never define); a module of the
                    submission's own (lab_notes.py beside the lab file: the file's folder is on the
                    child's path), imported by a line added at the end of the file (an added import
                    is allowed), replaces the lab's functions or binds that name
  forge_unflagged   the forge through evade_match or a side module, so no rule need flag it: only the
                    grader's replay (references computed in the parent) stands between it and the points
  vacuous           the step is not written and the function does nothing the probe can see (resolve()
                    returns before any impulse): a check that skips what it cannot see would pass it
  evade_handed      (attack report A1) the steps call a name the handout imports (project, draw_body, inside),
                    which an import added at the end of the file binds to the library's function; or a new
                    module-level name bound to World().sat; the rules once exempted every handed name

The first round (merged in from tests/attack_corpus.py, names kept: <lab>_<kind>) adds kind

  rebind            the step is left undone; code outside the steps rebinds its function to the library's
                    (its forge, rebind and solution entries change the code outside the steps: keeps_handout False)

Issue 35's mechanisms (entry.mechanism = the item number; MECHANISMS_BY_LAB says where each applies):

  line_breaks    (1)  a comment of characters str.splitlines() breaks at and the compiler does not; a step
                      calls the library
  coding         (2)  `# -*- coding: unicode_escape -*-`: a comment to the checker is a line of code to Python
  changed_inputs (3)  the step changes the fields the probe reads its reference from after the call
  frame_read     (4)  a format string reads the reference values the child holds in the probe's frame
  foreign_hook   (5)  the child's tape names a handout function the probe never installed as a hook
  star_import    (6)  `from solutions.<lab> import *` / `from lesson11.physics2d import *` after the defs
  grader_stdout  (7)  the child writes a forged --json document to the grader's stdout (root)
  evade_side_module (8), vacuous (9) as above; wrong_answer and stdlib controls (10)

"No more than the honest work it contains" is formalised as: an issue-35 attack scores no more than
honest(entry), the same file with the attack removed (the steps the entry wrote put back to the
starter's placeholder, no edit, side file or extra text), graded in the same run.

The labs are every lab in checker/labs/ with a mistake corpus (tests/labs_found.py). The first round's seven
kinds and mechanisms 1, 2, 5, 6 and 7 are built for every lab from the lab itself (its first and last step
regions, the function holding each, its STEP_LIBRARY, its corpus's CHECK_STEP); what a lab needs beyond that
(another name for the library's answer, a World call, the step that forges, a side module, which mechanisms
apply) is its corpus's ATTACK dict; its "table" attack and its controls are written per lab below for the
lesson's labs, and by the lab's corpus itself (ATTACK["entries"], own_entries below) for a lab added later.

    ENTRIES: [Entry]; BY_LAB: {lab: [Entry]}; LABS: {lab: its mistake-corpus module}; HONEST: {name: Entry}
    build(entry) -> source text; write(directory, entries=None) -> {name: path}
"""
import os
import sys
import textwrap
from typing import NamedTuple

TESTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(TESTS)
for _path in (TESTS, ROOT):
    if _path not in sys.path:
        sys.path.insert(0, _path)

import corpus_attacks_judge  # noqa: E402  (issue 39's entries on the judging)
import labs_found  # noqa: E402  (every lab in checker/labs/ and its mistake corpus)
import mutants  # noqa: E402
from corpus_files import CorpusFiles  # noqa: E402  (starter + steps + edits, as the mistake corpora build)

# every lab in checker/labs/ with a mistake corpus (each corpus's STARTER, SOLUTION, STEPS, CHECK_STEP,
# FUNCTION_CHECKS; a lab without one fails tests/test_corpus_labs.py), and each lab's title, from the lab
LABS = {lab.id: labs_found.corpus(lab) for lab in labs_found.with_corpus()}
TITLES = {lab.id: lab.title for lab in labs_found.LABS}
LISTED_KINDS = ("import", "world", "dunder", "forge", "rebind", "solution", "detect", "table")
MECHANISM_KINDS = ("line_breaks", "coding", "changed_inputs", "frame_read", "foreign_hook", "star_import",
                   "grader_stdout", "wrong_answer")   # issue 35
EVASIONS = ("evade_alias", "evade_class", "evade_own_import", "evade_match", "evade_side_module", "forge_unflagged",
            "vacuous", "evade_handed")


class Entry(NamedTuple):
    name: str
    lab: str
    kind: str                 # one of LISTED_KINDS, EVASIONS, MECHANISMS' kinds or "control"
    steps: dict               # {step: the code put inside that step's region}; other steps get the solution's
    target: object            # tuple of check ids that must not pass; None for a control (every function check passes)
    why: str                  # one line: what the attack does and why it must fail (or why the control is correct)
    edits: tuple = ()         # ((old, new), ...) outside the steps: an added import (keeps_handout False: code)
    needs_random_inputs: bool = False   # only inputs drawn per grading run can catch it
    extra_files: tuple = ()   # ((file name, text), ...) written beside the lab file (a submission's other files)
    keeps_handout: bool = True   # False: code added outside the steps (the first round's forge, rebind, solution)
    mechanism: int = 0        # the mechanism of issue 35 it builds (1-10), 0 for none
    all_checks: bool = False  # a control whose every check must pass, the scenes included (full marks)
    modes: tuple = ("root",)  # the grading runs it is graded in (GRADING_MODES in tests/test_corpus_attacks.py)
    message: str = ""         # text the first target check's message must hold (the issue's stated outcome)
    extra_text: tuple = ()    # ((old, new), ...) replacements in the built file's text after the edits (bytes-exact
                              # attacks the handout's own parser may not read alike: mechanisms 1 and 2)
    honest_keeps: tuple = ()  # steps the honest file keeps as the solution writes them (the work beside the attack)


def _code(text):
    return textwrap.dedent(text).strip("\n")


def attack(name, lab, kind, steps, target, why, edits=(), needs_random_inputs=False, extra_files=(), **more):
    return Entry(name, lab, kind, {step: _code(code) for step, code in steps.items()}, tuple(target), why,
                 tuple(edits), needs_random_inputs, tuple(extra_files), **more)


def notes(*parts):
    """A module's text from dedented parts (a side file of the submission)."""
    return "\n\n".join(_code(part) for part in parts) + "\n"


def control(name, lab, steps, why, **more):
    return Entry(name, lab, "control", {step: _code(code) for step, code in steps.items()}, None, why, **more)


# the pieces several attacks share

# the library package reached from a handout import (see evade_alias above)
ALIAS = '[random][0]._os.sys.modules["lesson11.physics2d"]'

# what make_world(rng) needs of rng, so a step can build the handout's World and take its type
DICE = """
class Dice:
    def randint(self, low, high):
        return low

    def uniform(self, low, high):
        return low
"""


def dice(code):
    """Step code that first defines Dice, then runs `code`."""
    return _code(DICE) + "\n" + _code(code)


# an added top-level import (outside the steps; the handout comparison allows a new name)
PKGUTIL = (("import random\n", "import random\nfrom pkgutil import resolve_name\n"),)

# an added import of a module of the submission's own, at the end of the file, after every def
MAIN_GUARD = '\n\nif __name__ == "__main__":'
LAB_NOTES = ((MAIN_GUARD, '\n\nimport lab_notes  # noqa: E402, F401\n' + MAIN_GUARD),)

# lab_notes.py's first lines: find the globals of the lab file that imports it
FIND_LAB = """
    import sys

    frame = sys._getframe(1)
    while frame is not None and not ("main" in frame.f_globals and "make_world" in frame.f_globals):
        frame = frame.f_back
    lab_globals = frame.f_globals if frame is not None else {}
"""


def starter_steps(lab):
    """{step: the starter's own code in it} (its comments and placeholder): the steps not done."""
    module = LABS[lab]
    with open(module.STARTER, encoding="utf-8") as handle:
        return CorpusFiles(module.STARTER, module.SOLUTION, module.STEPS, {}, "").step_code(handle.read())


def solution_call(lab, function, args):
    """Step code that runs `function` from solutions/<lab>.py (read once, exec'd) on `args`."""
    return f"""
        global solution_{function}
        try:
            return solution_{function}({args})
        except NameError:
            pass
        os = __import__("os")
        root = os.path.dirname(os.path.dirname(__import__("lesson11").__file__))
        namespace = {{}}
        with open(os.path.join(root, "solutions", "{lab}.py"), encoding="utf-8") as handle:
            exec(handle.read().split("\\ndef main")[0], namespace)
        solution_{function} = namespace["{function}"]
        return solution_{function}({args})
    """


# ---------------------------------------------------------------- the tables (kind "table")
# Each reads the fixed inputs from the lab's probe module, as a student would copy them from a run.
# Unknown inputs get a guess that is wrong for every input the probes draw. An empty table means the
# probe modules moved (tests/test_corpus_attacks.py checks that every table holds the fixed inputs).

def _round_key(numbers, digits):
    return tuple(round(float(x), digits) for x in numbers)


def _points_key(points):
    return _round_key([c for p in points for c in (p[0], p[1])], 6)


def _sat_table():
    try:
        from checker.judging.probe_kit import reference_sat, sat_pairs
        table = {}
        for _, pa, pb in sat_pairs():
            for first, second in ((pa, pb), (pb, pa)):
                hit = reference_sat(first, second)
                table[_points_key(list(first) + list(second))] = \
                    None if hit is None else (hit[0].x, hit[0].y, float(hit[1]))
        return table
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}


def _corner_table():
    try:
        from checker.labs.more_shapes.probes import POLYGONS
        from lesson11.physics2d import regular_polygon
        return {(sides, float(radius)): [(p.x, p.y) for p in regular_polygon(sides, radius)]
                for sides, radius in POLYGONS}
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}


def _closest_table():
    try:
        from checker.labs.ball_on_ramp.probes import outside_cases, reference_closest, segment_cases
        calls = [(p, a, b) for _, p, a, b in segment_cases()]
        for _, center, _, points in outside_cases():   # circle_polygon() calls it once per edge
            calls += [(center, points[i], points[(i + 1) % len(points)]) for i in range(len(points))]
        table = {}
        for p, a, b in calls:
            point = reference_closest(p, a, b)
            table[_points_key([p, a, b])] = (point.x, point.y)
        return table
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}


def _toi_table():
    try:
        from checker.labs.bullets.probes import reference_circle_toi, toi_cases
        table = {}
        for _, p1, v1, r1, p2, v2, r2, dt in toi_cases():
            key = _round_key((p1.x, p1.y, v1.x, v1.y, r1, p2.x, p2.y, v2.x, v2.y, r2, dt), 9)
            table[key] = reference_circle_toi(p1, v1, r1, p2, v2, r2, dt)
        return table
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}


def _timer_table():
    try:
        from checker.labs.sleeping_crates.probes import DT, TIMER_CASES, reference_timer
        return {(timer, speed, spin, round(dt, 12)): reference_timer(timer, speed, spin, dt)
                for _, timer, speed, spin in TIMER_CASES for dt in (DT, 1 / 60)}
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}


TABLES = {"tumbling_crates": _sat_table(), "more_shapes": _corner_table(), "ball_on_ramp": _closest_table(),
          "bullets": _toi_table(), "sleeping_crates": _timer_table()}


# Tables whose default is right for one kind of answer (the attack report of 2026-11-28, holes 1, 2, 4 and 5): the
# fixed cases from the table, the placeholder (or None) for the rest. Only a run that draws each kind of answer
# catches them, at every seed (tests/test_corpus_attacks.py grades them at several seeds).

def _axes_table():
    """More Shapes' separating_axes() for every fixed pair its probes call it on (sat() calls it too)."""
    try:
        from checker.judging.probe_kit import sat_pairs
        from checker.labs.more_shapes.probes import axis_pairs, distinct_directions, edge_normals
        table = {}
        for _, pa, pb in axis_pairs() + sat_pairs():
            for first, second in ((pa, pb), (pb, pa)):
                table[_points_key(list(first) + list(second))] = \
                    [(axis.x, axis.y) for axis in distinct_directions(edge_normals(first) + edge_normals(second))]
        return table
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}


def _out_of_reach():
    """Bullets' fixed time_of_impact() cases the broad test skips: (bullet x, y, vx, crate x), rounded."""
    try:
        from checker.labs.bullets.probes import impact_cases
        return {(round(c["bullet"].pos.x), round(c["bullet"].pos.y), round(c["bullet"].vel.x), round(c["other"].pos.x))
                for c in impact_cases() if not c["needs_exact"]}
    except (ImportError, AttributeError, TypeError, ValueError, KeyError):
        return set()


def _resolve_tables():
    """Tumbling Crates' fixed resolve() contacts, keyed (A's mass, B's mass, point x, point y): ({key: the lesson's
    k}, {key: the lesson's clamped friction impulse jt})."""
    try:
        import math
        from lesson11.physics2d import apply_impulse, cross, relative_velocity
        from checker.labs.tumbling_crates.probes import RESTING_SPEED, resolve_cases, twin
        ks, jts = {}, {}
        for _, a, b, n, point in resolve_cases():
            a, b = twin(a), twin(b)
            key = _round_key((a.mass, b.mass, point.x, point.y), 6)
            ra, rb = point - a.pos, point - b.pos
            vn = relative_velocity(a, b, ra, rb).dot(n)
            ran, rbn = cross(ra, n), cross(rb, n)
            ks[key] = k = a.inv_mass + b.inv_mass + ran * ran * a.inv_inertia + rbn * rbn * b.inv_inertia
            j = -(1 + (min(a.restitution, b.restitution) if vn < -RESTING_SPEED else 0.0)) * vn / k
            apply_impulse(a, b, n * j, ra, rb)
            rel = relative_velocity(a, b, ra, rb)
            t = (rel - n * rel.dot(n)).normalize()
            rat, rbt = cross(ra, t), cross(rb, t)
            stop = -rel.dot(t) / (a.inv_mass + b.inv_mass + rat * rat * a.inv_inertia + rbt * rbt * b.inv_inertia)
            bound = math.sqrt(a.friction * b.friction) * j
            jts[key] = max(-bound, min(bound, stop))
        return ks, jts
    except (ImportError, AttributeError, TypeError, ValueError):
        return {}, {}


DEFAULT_TABLES = {"more_shapes": _axes_table(), "bullets": _out_of_reach(), "tumbling_crates_k": _resolve_tables()[0],
                  "tumbling_crates_jt": _resolve_tables()[1]}
RESOLVE_KEY = "(round(a.mass, 6), round(b.mass, 6), round(point.x, 6), round(point.y, 6))"


# ================================================================ Tumbling Crates: sat, resolve, apply_impulse

TUMBLING = [
    attack("tc_import_library_sat", "tumbling_crates", "import", {2: """
        from lesson11.physics2d import sat as reference
        return reference(pa, pb)
    """}, ["sat_axes"], "step 2 imports the library's sat() and returns its answer: the SAT loop was never written"),
    attack("tc_world_sat", "tumbling_crates", "world", {2: """
        return World().sat(pa, pb)
    """}, ["sat_axes"], "step 2 returns World().sat, which is the library's sat(): no loop written"),
    attack("tc_world_lesson_resolve", "tumbling_crates", "world", {4: """
        World().lesson_resolve(a, b, normal, point)
        return
    """}, ["resolve_k", "resolve_friction"],
        "step 4 hands the whole contact to World.lesson_resolve (the library's resolve): no spin terms written"),
    attack("tc_dunder_import", "tumbling_crates", "dunder", {2: """
        return __import__("lesson11.physics2d", fromlist=["sat"]).sat(pa, pb)
    """}, ["sat_axes"], "step 2 reaches the library's sat() through __import__"),
    attack("tc_forge_reference", "tumbling_crates", "forge", {2: """
        modules = __import__("sys").modules
        for name in ("checker.labs.tumbling_crates.probes", "checker.judging.probe_kit"):
            if name in modules:
                modules[name].reference_sat = lambda *args, **kwargs: None
        return None  # until you write step 2, nothing ever collides
    """}, ["sat_axes"], "step 2 stays the placeholder and makes the child's reference sat() say None too: "
                        "the grader's own reference must still say the pairs overlap"),
    attack("tc_solution_file", "tumbling_crates", "solution", {2: solution_call("tumbling_crates", "sat", "pa, pb")},
           ["sat_axes"], "step 2 reads solutions/tumbling_crates.py, execs it and returns the solution's sat()"),
    attack("tc_detect_checker", "tumbling_crates", "detect", {2: """
        if "checker" in __import__("sys").modules:
            from lesson11.physics2d import sat as reference
            return reference(pa, pb)
        return None  # until you write step 2, nothing ever collides
    """}, ["sat_axes"], "step 2 answers with the library's sat() only when the checker is loaded; the placeholder "
                        "otherwise"),
    attack("tc_table_sat", "tumbling_crates", "table", {2: f"""
        answers = {TABLES["tumbling_crates"]!r}
        key = tuple(round(c, 6) for p in pa + pb for c in (p.x, p.y))
        if key in answers:
            hit = answers[key]
            return None if hit is None else (pygame.Vector2(hit[0], hit[1]), hit[2])
        return pygame.Vector2(1, 0), 1.0  # not in the table: a guess
    """}, ["sat_axes"], "step 2 answers the probes' fixed pairs from a table; a pair drawn for this run is not in it",
        needs_random_inputs=True),
    attack("tc_table_sat_none", "tumbling_crates", "table", {2: f"""
        answers = {TABLES["tumbling_crates"]!r}
        hit = answers.get(tuple(round(c, 6) for p in pa + pb for c in (p.x, p.y)))
        return None if hit is None else (pygame.Vector2(hit[0], hit[1]), hit[2])  # not in the table: apart
    """}, ["sat_axes"], "step 2 answers the fixed pairs from a table and None for the rest: right whenever every "
                        "drawn pair is apart (report hole 5, seeds 102, 251), so a drawn pair overlaps at every seed",
        needs_random_inputs=True),
    attack("tc_table_resolve_k", "tumbling_crates", "table", {4: f"""
        k = {DEFAULT_TABLES["tumbling_crates_k"]!r}.get({RESOLVE_KEY}, k)  # not in the table: no spin terms
    """}, ["resolve_k"], "step 4 answers the fixed contacts' k from a table and keeps the handout's k for the rest "
                         "(report hole 4): the contacts drawn for this run are not in it", needs_random_inputs=True),
    attack("tc_table_friction", "tumbling_crates", "table", {5: f"""
        jt = {DEFAULT_TABLES["tumbling_crates_jt"]!r}.get({RESOLVE_KEY}, jt)  # not in the table: unclamped
    """}, ["resolve_friction"], "step 5 answers the fixed contacts' friction from a table and leaves jt unclamped for "
                                "the rest (report hole 4): a contact drawn for this run is clamped",
        needs_random_inputs=True),
    attack("tc_alias_library_sat", "tumbling_crates", "evade_alias", {2: f"""
        library = {ALIAS}.sat
        return library(pa, pb)
    """}, ["sat_axes"], "step 2 returns the library's sat() reached through random._os.sys.modules, with no "
                        "import, dunder, World or module attribute the old rules named"),
    attack("tc_world_by_type", "tumbling_crates", "evade_class", {2: dice("""
        library = type(make_world(Dice()))().sat
        return library(pa, pb)
    """)}, ["sat_axes"], "step 2 builds the handout's world, takes its type (World) and uses a fresh World's "
                        "default sat hook: the library's sat()"),
    attack("tc_own_import_k", "tumbling_crates", "evade_own_import", {4: """
        def effective_mass(resolve_name=resolve_name):
            return resolve_name("lesson11.physics2d:effective_mass_inverse")
        k = effective_mass()(a, b, ra, rb, normal)
    """}, ["resolve_k"], "an added `from pkgutil import resolve_name` fetches the library's effective_mass_inverse "
                         "for step 4's k; used through a parameter default, no rule flags it", edits=PKGUTIL),
    attack("tc_side_module_free_name", "tumbling_crates", "evade_side_module", {2: """
        return checked_sat(pa, pb)
    """}, ["sat_axes"], "step 2 calls a name it never defines; an imported lab_notes.py beside the file binds it to "
                        "the library's sat() in the lab's globals, so even the spliced probe runs the library",
        edits=LAB_NOTES, extra_files=[("lab_notes.py", notes(FIND_LAB, """
            from lesson11.physics2d import sat

            lab_globals["checked_sat"] = sat
        """))], mechanism=8),
    attack("tc_early_return_friction", "tumbling_crates", "vacuous", {4: """
        return  # (resolve does nothing for now)
    """, 5: ""}, ["resolve_friction"], "steps 4 and 5 are not written (step 4 just returns): a resolve() that applies no "
                                       "impulse must not pass the friction check", mechanism=9),
    attack("tc_forge_unflagged", "tumbling_crates", "forge_unflagged", {2: """
        match edge_normals:
            case object(__globals__=namespace):
                modules = namespace["__builtins__"]["__import__"]("sys").modules
                for name in ("checker.labs.tumbling_crates.probes", "checker.judging.probe_kit"):
                    if name in modules:
                        modules[name].reference_sat = lambda *args, **kwargs: None
        return None  # until you write step 2, nothing ever collides
    """}, ["sat_axes"], "the reference forge reached through a match pattern, so no rule flags it: the child's "
                        "references agree with the placeholder, but the grader computes its own"),
    attack("tc_world_manifolds", "tumbling_crates", "evade_class", {2: """
        match make_crate:
            case object(__globals__=lab_globals):
                engine = lab_globals["World"]([Body.from_world_points(pa, 1.0), Body.from_world_points(pb, 1.0)])
                for _, _, manifold in engine.manifolds():
                    return manifold.normal, manifold.depth
        return None
    """}, ["sat_axes"], "step 2 puts both polygons in a World (taken from the lab's globals by a match pattern) and "
                        "returns the library's contact manifold: no library name the rules list"),
    attack("tc_match_globals", "tumbling_crates", "evade_match", {2: """
        match edge_normals:
            case object(__globals__=library):
                return library["sat"](pa, pb)
    """}, ["sat_axes"], "step 2 reads edge_normals.__globals__ through a match class pattern (a string, not an "
                        "attribute) and returns the library module's sat()"),
    attack("tc_side_module_solution", "tumbling_crates", "evade_side_module",
           starter_steps("tumbling_crates"), ["resolve_k", "resolve_friction", "apply_impulse_spin"],
           "the steps are the starter's; an imported lab_notes.py beside the file execs the solution's functions "
           "over the lab's own (only sat's spliced probe reads the source)", edits=LAB_NOTES,
           extra_files=[("lab_notes.py", notes(FIND_LAB, """
               import os

               import lesson11

               root = os.path.dirname(os.path.dirname(lesson11.__file__))
               with open(os.path.join(root, "solutions", "tumbling_crates.py"), encoding="utf-8") as handle:
                   exec(handle.read().split("\\ndef main")[0], lab_globals)
           """))], mechanism=8),
    control("tc_control_while_and_lambda", "tumbling_crates", {2: """
        axes = edge_normals(pa) + edge_normals(pb)
        k = 0
        while k < len(axes):
            axis = axes[k]
            k += 1
            (low_a, high_a), (low_b, high_b) = project(pa, axis), project(pb, axis)
            result = min(high_a, high_b) - max(low_a, low_b)
            if result <= 0:
                return None
            if result < best_depth:
                best_axis, best_depth = axis, result
    """, 3: """
        towards_b = centre_of(pb) - centre_of(pa)
        best_axis = best_axis if towards_b.dot(best_axis) >= 0 else -best_axis
    """, 4: """
        square = lambda x: x * x
        k += square(ran) * a.inv_inertia + square(rbn) * b.inv_inertia
    """, 5: """
        limit = mu * j
        if jt > limit:
            jt = limit
        elif jt < -limit:
            jt = -limit
    """, 6: """
        spin_a, spin_b = cross(ra, impulse) * a.inv_inertia, cross(rb, impulse) * b.inv_inertia
        a.omega, b.omega = a.omega - spin_a, b.omega + spin_b
    """}, "a while loop, tuple unpacking, a local named result, a conditional expression, a helper lambda, an "
          "if/elif clamp: the lesson's arithmetic in another style"),
    control("tc_control_print_in_step", "tumbling_crates", {2: """
        for axis in edge_normals(pa) + edge_normals(pb):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
        if best_depth > 25:
            print("sat: a deep hit,", round(best_depth, 2), "px")
    """}, "the solution's loop with a debug print of deep hits (a print inside a step is allowed)"),
]


# ================================================================ More Shapes: regular_polygon, centroid, inertia, axes

MORE_SHAPES = [
    attack("ms_import_library_polygon", "more_shapes", "import", {2: """
        from lesson11.physics2d import regular_polygon as reference
        return reference(sides, radius)
    """}, ["polygon_corners"], "step 2 imports the library's regular_polygon() and returns its corners"),
    attack("ms_world_body_inertia", "more_shapes", "world", {4: """
        return World([Body(Polygon(points, recentre=False), (0, 0), mass)]).bodies[0].inertia
    """}, ["inertia_sum"], "step 4 puts the polygon in a World and reads the inertia the library gave its body: no "
                           "triangle-fan sum written"),
    attack("ms_dunder_importlib_centroid", "more_shapes", "dunder", {3: """
        library = __import__("importlib").import_module("lesson11.physics2d")
        return library.polygon_centroid(points)
    """}, ["centroid"], "step 3 reaches the library's polygon_centroid() through __import__('importlib')"),
    attack("ms_forge_json", "more_shapes", "forge", {2: """
        json = __import__("json")
        if not hasattr(json.dumps, "forged"):
            real = json.dumps

            def copy_want(item):
                if isinstance(item, dict):
                    if "want" in item and "got" in item:
                        item["got"] = item["want"]
                    for inner in item.values():
                        copy_want(inner)
                elif isinstance(item, list):
                    for inner in item:
                        copy_want(inner)

            def dumps(value, *args, **kwargs):
                copy_want(value)
                return real(value, *args, **kwargs)

            dumps.forged = True
            json.dumps = dumps
        return box_points(radius, radius)  # until you write step 2, every shape is a square
    """}, ["polygon_corners"], "step 2 stays the placeholder and replaces the child's json.dumps so every 'got' "
                               "reported equals its 'want': the grader must not take the child's word"),
    attack("ms_solution_file", "more_shapes", "solution",
           {2: solution_call("more_shapes", "regular_polygon", "sides, radius")}, ["polygon_corners"],
           "step 2 reads solutions/more_shapes.py, execs it and returns the solution's corners"),
    attack("ms_detect_module_name", "more_shapes", "detect", {2: """
        if __name__ == "lab_under_test":
            from lesson11.physics2d import regular_polygon as reference
            return reference(sides, radius)
        return box_points(radius, radius)  # until you write step 2, every shape is a square
    """}, ["polygon_corners"], "step 2 returns the library's corners only under the checker's module name"),
    attack("ms_table_polygon", "more_shapes", "table", {2: f"""
        corners = {TABLES["more_shapes"]!r}
        if (sides, float(radius)) in corners:
            return [Vector2(x, y) for x, y in corners[(sides, float(radius))]]
        return box_points(radius, radius)  # not in the table: the placeholder
    """}, ["polygon_corners"], "step 2 answers the probes' fixed (sides, radius) from a table; the polygon drawn for "
                               "this run is not in it", needs_random_inputs=True),
    attack("ms_table_axes", "more_shapes", "table", {5: f"""
        known = {DEFAULT_TABLES["more_shapes"]!r}
        key = tuple(round(c, 6) for p in list(pa) + list(pb) for c in (p.x, p.y))
        axes = [Vector2(x, y) for x, y in known[key]] if key in known else edge_normals(pa) + edge_normals(pb)
    """}, ["parallel_axes"], "step 5 answers the fixed pairs' axes from a table and keeps the placeholder (every edge "
                             "normal, which sat() still gets right) for the rest (report hole 1: 18/18): a pair drawn "
                             "for this run has a direction to skip", needs_random_inputs=True),
    attack("ms_alias_library_polygon", "more_shapes", "evade_alias", {2: f"""
        library = {ALIAS}.regular_polygon
        return library(sides, radius)
    """}, ["polygon_corners"], "step 2 returns the library's regular_polygon() reached through random._os, nothing "
                               "flagged"),
    attack("ms_body_centroid", "more_shapes", "evade_class", {3: """
        return Body.from_world_points(points).pos
    """}, ["centroid"], "step 3 lets the handout's Body place a body on the points: its pos is the library's "
                        "area-weighted centroid"),
    attack("ms_body_inertia", "more_shapes", "evade_class", {4: """
        return Body(Polygon(points, recentre=False), (0, 0), mass).inertia
    """}, ["inertia_sum"], "step 4 reads the inertia the handout's Body computes with the library's polygon_inertia "
                           "(an attribute, not a call of .inertia())"),
    attack("ms_alias_solution_axes", "more_shapes", "evade_alias", {5: """
        loader = [random][0]._os.sys.modules["importlib"]
        solution = loader.import_module("solutions.more_shapes").separating_axes
        axes.extend(solution(pa, pb))
    """}, ["parallel_axes"], "step 5 imports solutions/more_shapes.py as a module (it is on the child's path) and "
                             "takes the solution's separating_axes(), nothing flagged"),
    attack("ms_body_inv_inertia", "more_shapes", "evade_class", {4: """
        return 1 / Body(Polygon(points, recentre=False), (0, 0), mass).inv_inertia
    """}, ["inertia_sum"], "step 4 inverts the inverse inertia the handout's Body got from the library's "
                           "polygon_inertia (inv_inertia is no listed name)"),
    attack("ms_match_globals", "more_shapes", "evade_match", {2: """
        match box_points:
            case object(__globals__=library):
                return library["regular_polygon"](sides, radius)
    """}, ["polygon_corners"], "step 2 reads box_points.__globals__ (the library's shapes module) through a match "
                               "class pattern and returns its regular_polygon()"),
    control("ms_control_while_and_zip", "more_shapes", {2: """
        corners = []
        k = 0
        while k < sides:
            theta = 2 * math.pi * k / sides
            corners.append(Vector2(radius * math.cos(theta), radius * math.sin(theta)))
            k += 1
        return corners
    """, 3: """
        pairs = list(zip(points, points[1:] + points[:1]))
        result = sum(((a + b) * cross(a, b) for a, b in pairs), Vector2())
        return result / (6 * area)
    """, 4: """
        weight = lambda a, b: abs(cross(a, b))
        pairs = [(points[i], points[(i + 1) % len(points)]) for i in range(len(points))]
        top = sum(weight(a, b) * (a.dot(a) + a.dot(b) + b.dot(b)) for a, b in pairs)
        bottom = sum(weight(a, b) for a, b in pairs)
        return mass * top / (6 * bottom)
    """, 5: """
        for axis in [*edge_normals(pa), *edge_normals(pb)]:
            parallel = [kept for kept in axes if abs(cross(axis, kept)) <= PARALLEL]
            if not parallel:
                axes.append(axis)
    """}, "a while loop, zip with a rotated copy, sum() over a generator, a weight lambda, a local named result, "
          "a list of parallel axes: the lesson's formulas"),
    control("ms_control_print_in_step", "more_shapes", {3: """
        print("centroid of", len(points), "points")
        total = Vector2()
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            total += (a + b) * cross(a, b)
        return total / (6 * area)
    """}, "the solution's centroid with a debug print first (a print inside a step is allowed)"),
]


# ================================================================ Ball on the Ramp: closest point, inside, push-out, ...

BALL_ON_RAMP = [
    attack("br_import_library_closest", "ball_on_ramp", "import", {2: """
        from lesson11.physics2d import closest_on_segment as reference
        return reference(p, a, b)
    """}, ["closest_point"], "step 2 imports the library's closest_on_segment() and returns its point"),
    attack("br_world_lesson_separate", "ball_on_ramp", "world", {4: """
        World().lesson_separate(a, b, normal, depth)
    """}, ["push_out_split"], "step 4 hands the push-out to World.lesson_separate (the library's separate): no split "
                              "by inverse mass written"),
    attack("br_dunder_import", "ball_on_ramp", "dunder", {2: """
        library = __import__("lesson11.physics2d", fromlist=["closest_on_segment"])
        return library.closest_on_segment(p, a, b)
    """}, ["closest_point"], "step 2 reaches the library's closest_on_segment() through __import__"),
    attack("br_forge_result_pipe", "ball_on_ramp", "forge", {2: """
        os = __import__("os")
        forged = ('{"task": "probe", "phase": "done", "probe": {"missing": [], "functions": '
                  '{"closest_on_segment": {"ok": true, "data": []}}}}\\n')
        os.write(3, forged.encode())  # the result pipe (the old child wrote a file named in sys.argv)
        os.kill(os.getpid(), 9)  # so the forged line stays the last one
        return pygame.Vector2(math.inf, math.inf)  # until you write step 2, no edge is near the ball: it falls through
    """}, ["closest_point"], "step 2 writes a forged 'done' result to the child's result pipe and kills the child: "
                             "the grader must judge only what it replays itself"),
    attack("br_solution_file", "ball_on_ramp", "solution",
           {2: solution_call("ball_on_ramp", "closest_on_segment", "p, a, b")}, ["closest_point"],
           "step 2 reads solutions/ball_on_ramp.py, execs it and returns the solution's point"),
    attack("br_detect_sdl_driver", "ball_on_ramp", "detect", {2: """
        if __import__("os").environ.get("SDL_VIDEODRIVER") == "dummy":
            from lesson11.physics2d import closest_on_segment as reference
            return reference(p, a, b)
        return pygame.Vector2(math.inf, math.inf)  # until you write step 2, no edge is near the ball: it falls through
    """}, ["closest_point"], "step 2 answers with the library only under the checker's dummy SDL driver"),
    attack("br_table_closest", "ball_on_ramp", "table", {2: f"""
        nearest = {TABLES["ball_on_ramp"]!r}
        key = (round(p.x, 6), round(p.y, 6), round(a.x, 6), round(a.y, 6), round(b.x, 6), round(b.y, 6))
        if key in nearest:
            return pygame.Vector2(nearest[key])
        return pygame.Vector2(math.inf, math.inf)  # not in the table: the placeholder
    """}, ["closest_point"], "step 2 answers the probes' fixed points and edges (circle_polygon's too) from a table; "
                             "the points drawn for this run are not in it", needs_random_inputs=True),
    attack("br_body_disc_inertia", "ball_on_ramp", "evade_class", {5: """
        return Body(Circle(radius), (0, 0), mass).inertia
    """}, ["ball_inertia"], "step 5 reads the inertia the handout's Body gives a Circle (the library's ½ m r²)"),
    attack("br_world_by_type_inside", "ball_on_ramp", "evade_class", {3: dice("""
        if inside(center, points):
            library = type(make_world(Dice()))().circle_polygon
            return library(center, radius, points)
    """)}, ["inside_case"], "step 3 takes World from the handout's world and uses its default circle_polygon hook "
                           "(the library's) for the centre-inside case"),
    attack("br_world_by_type_contact", "ball_on_ramp", "evade_class", {6: dice("""
        library = type(make_world(Dice()))().circle_point
        return library(center, radius, normal, depth)
    """)}, ["contact_on_surface"], "step 6 returns the World's default circle_point hook's answer (the library's "
                                  "circle_contact_point, which the check accepts)"),
    attack("br_alias_library_separate", "ball_on_ramp", "evade_alias", {4: f"""
        library = {ALIAS}.separate
        library(a, b, normal, depth)
    """}, ["push_out_split"], "step 4 calls the library's separate() reached through random._os, nothing flagged"),
    attack("br_body_inv_inertia", "ball_on_ramp", "evade_class", {5: """
        return 1 / Body(Circle(radius), (0, 0), mass).inv_inertia
    """}, ["ball_inertia"], "step 5 inverts the inverse inertia the handout's Body gives a Circle (the library's "
                            "½ m r²)"),
    attack("br_match_globals", "ball_on_ramp", "evade_match", {4: """
        match apply_impulse:
            case object(__globals__=library):
                library["separate"](a, b, normal, depth)
    """}, ["push_out_split"], "step 4 reads apply_impulse.__globals__ (the library's response module) through a "
                              "match class pattern and runs its separate()"),
    attack("br_forge_unflagged", "ball_on_ramp", "forge_unflagged", {2: """
        match inside:
            case object(__globals__=namespace):
                os = namespace["__builtins__"]["__import__"]("os")
                forged = ('{"task": "probe", "phase": "done", "probe": {"missing": [], "functions": '
                          '{"closest_on_segment": {"ok": true, "data": []}}}}\\n')
                os.write(3, forged.encode())
                os.kill(os.getpid(), 9)
        return pygame.Vector2(math.inf, math.inf)  # until you write step 2, no edge is near the ball: it falls through
    """}, ["closest_point"], "the result-pipe forge reached through a match pattern, so no rule flags it: only the "
                             "grader's replay stands against it"),
    control("br_control_hypot_and_lambda", "ball_on_ramp", {2: """
        length = math.hypot(ab.x, ab.y)
        t = (p - a).dot(ab) / (length * length)
        t = min(max(t, 0.0), 1.0)
        return a + ab * t
    """, 3: """
        if inside(center, points):
            (nx, ny), result = -offset / dist, radius + dist
            return pygame.Vector2(nx, ny), result
    """, 4: """
        share = lambda inv: push * inv / total
        a.pos, b.pos = a.pos - normal * share(a.inv_mass), b.pos + normal * share(b.inv_mass)
    """, 5: """
        result = mass * radius * radius / 2
        return result
    """, 6: """
        return center + radius * normal
    """, 7: """
        kt = sum((a.inv_mass, b.inv_mass, cross(ra, t) ** 2 * a.inv_inertia, cross(rb, t) ** 2 * b.inv_inertia))
        jt = -rel.dot(t) / kt
        jt = mu * j if jt > mu * j else -mu * j if jt < -mu * j else jt
        apply_impulse(a, b, t * jt, ra, rb)
    """}, "math.hypot squared, min(max()), tuple unpacking, a share lambda, a local named result, sum() of a "
          "tuple, a chained conditional clamp: the lesson's formulas"),
    control("br_control_print_in_step", "ball_on_ramp", {5: """
        print("disc inertia for a ball of radius", radius)
        return 0.5 * mass * radius ** 2
    """}, "the solution's disc inertia with a debug print (a print inside a step is allowed)"),
]


# ================================================================ Bullets: circle_toi, bounding_radius, broad test, swept move

BULLETS = [
    attack("bu_import_library_toi", "bullets", "import", {2: """
        from lesson11.physics2d import circle_toi as reference
        return reference(p1, v1, r1, p2, v2, r2, dt)
    """}, ["toi_matches_root"], "step 2 imports the library's circle_toi() and returns its time"),
    attack("bu_world_swept_move", "bullets", "world", {5: """
        World.swept_move(world, bullet, dt)
    """}, ["swept_move_resolves"], "step 5 runs the library's World.swept_move on the lab's world: no move, resolve "
                                   "and rest of the step written"),
    attack("bu_dunder_importlib", "bullets", "dunder", {2: """
        import importlib
        return importlib.import_module("lesson11.physics2d.collision").circle_toi(p1, v1, r1, p2, v2, r2, dt)
    """}, ["toi_matches_root"], "step 2 imports importlib and takes the library's circle_toi() from its module"),
    attack("bu_forge_reference", "bullets", "forge", {2: """
        modules = __import__("sys").modules
        probes = modules.get("checker.labs.bullets.probes")
        if probes is not None:
            probes.analytic_toi = lambda *args: None
            probes.reference_circle_toi = lambda *args: None
        return None  # until you write step 2, nothing is ever hit: bullets fly through everything under CCD
    """}, ["toi_matches_root"], "step 2 stays the placeholder and makes the child's analytic time None too: the "
                                "grader computes its own"),
    attack("bu_solution_file", "bullets", "solution",
           {2: solution_call("bullets", "circle_toi", "p1, v1, r1, p2, v2, r2, dt")}, ["toi_matches_root"],
           "step 2 reads solutions/bullets.py, execs it and returns the solution's time"),
    attack("bu_detect_work_folder", "bullets", "detect", {2: """
        if "checker-" in __import__("os").getcwd():
            from lesson11.physics2d import circle_toi as reference
            return reference(p1, v1, r1, p2, v2, r2, dt)
        return None  # until you write step 2, nothing is ever hit: bullets fly through everything under CCD
    """}, ["toi_matches_root"], "step 2 answers with the library only inside the checker's temporary working folder"),
    attack("bu_table_toi", "bullets", "table", {2: f"""
        times = {TABLES["bullets"]!r}
        key = tuple(round(x, 9) for x in (p1.x, p1.y, v1.x, v1.y, r1, p2.x, p2.y, v2.x, v2.y, r2, dt))
        if key in times:
            return times[key]
        return 0.0  # not in the table: a guess
    """}, ["toi_matches_root"], "step 2 answers the probes' fixed paths from a table; the paths drawn for this run "
                                "are not in it", needs_random_inputs=True),
    attack("bu_table_toi_none", "bullets", "table", {2: f"""
        times = {TABLES["bullets"]!r}
        return times.get(tuple(round(x, 9) for x in (p1.x, p1.y, v1.x, v1.y, r1, p2.x, p2.y, v2.x, v2.y, r2, dt)))
    """}, ["toi_matches_root"], "step 2 answers the fixed paths from a table and None for the rest: right whenever "
                                "every drawn path misses (report hole 5, seeds 4, 7), so a drawn path hits at every "
                                "seed", needs_random_inputs=True),
    attack("bu_table_broad", "bullets", "table", {4: f"""
        far = {DEFAULT_TABLES["bullets"]!r}
        if (round(bullet.pos.x), round(bullet.pos.y), round(bullet.vel.x), round(other.pos.x)) in far:
            return None  # the fixed bullets out of reach; the rest go to the exact test
    """}, ["broad_test"], "step 4 skips the two fixed bullets out of reach by a table and runs the exact test for "
                          "every other (report hole 2): a bullet drawn for this run is out of reach",
        needs_random_inputs=True),
    attack("bu_super_swept_move", "bullets", "evade_class", {5: """
        library = super(BulletWorld, world).swept_move
        library(bullet, dt)
    """}, ["swept_move_resolves"], "step 5 runs World.swept_move through super(BulletWorld, world), bound first so "
                                   "it is no .swept_move() call: nothing flagged"),
    attack("bu_alias_library_toi", "bullets", "evade_alias", {2: f"""
        library = {ALIAS}.circle_toi
        return library(p1, v1, r1, p2, v2, r2, dt)
    """}, ["toi_matches_root"], "step 2 returns the library's circle_toi() reached through random._os, nothing "
                                "flagged"),
    attack("bu_own_import_solution", "bullets", "evade_own_import", {3: """
        def solution(resolve_name=resolve_name):
            return resolve_name("solutions.bullets:bounding_radius")
        return solution()(points, centre)
    """}, ["bounding_circle"], "an added `from pkgutil import resolve_name` imports solutions/bullets.py and step 3 "
                               "returns the solution's bounding_radius(); a parameter default hides the name",
        edits=PKGUTIL),
    attack("bu_match_super_swept_move", "bullets", "evade_match", {5: """
        match super(type(world), world):
            case object(swept_move=library):
                library(bullet, dt)
    """}, ["swept_move_resolves"], "step 5 takes World.swept_move from super(type(world), world) through a match "
                                   "class pattern (the name is a string) and runs it"),
    attack("bu_match_globals", "bullets", "evade_match", {2: """
        match circle_polygon_toi:
            case object(__globals__=library):
                return library["circle_toi"](p1, v1, r1, p2, v2, r2, dt)
    """}, ["toi_matches_root"], "step 2 reads circle_polygon_toi.__globals__ (the library's collision module) "
                                "through a match class pattern and returns its circle_toi()"),
    control("bu_control_result_and_while", "bullets", {2: """
        c = dp.dot(dp) - reach ** 2
        if c <= 0:
            return 0.0
        a, b = dv.dot(dv), 2 * dp.dot(dv)
        if a == 0:
            return None
        disc = b * b - 4 * a * c
        if disc < 0:
            return None
        result = (-b - math.sqrt(disc)) / (2 * a)
        return result if 0 <= result <= dt else None
    """, 3: """
        farthest, k = 0.0, 0
        while k < len(points):
            offset = points[k] - centre
            farthest = max(farthest, math.hypot(offset.x, offset.y))
            k += 1
        return farthest
    """, 4: """
        reach_of_crate = bounding_radius(points, other.pos)
        broad = circle_toi(bullet.pos, bullet.vel, bullet.radius, other.pos, Vector2(), reach_of_crate, dt)
        if broad is None:
            return None
    """, 5: """
        bullet.pos += bullet.vel * t
        contact = bullet.pos + normal * bullet.radius
        world.resolve(bullet, other, normal, contact)
        remaining = dt - t
        bullet.pos += bullet.vel * remaining
    """}, "two early returns, tuple unpacking, a local named result, a while loop with math.hypot, named "
          "intermediates: the lesson's formulas"),
    control("bu_control_print_in_step", "bullets", {3: """
        result = max(centre.distance_to(p) for p in points)
        print("bounding radius", round(result, 1))
        return result
    """}, "the solution's bounding radius with a debug print (a print inside a step is allowed)"),
]


# ================================================================ Sleeping Crates: sleep_timer, moves, wake_on_contact

SLEEPING = [
    attack("sc_import_world_moves", "sleeping_crates", "import", {3: """
        from lesson11.physics2d.world import World as reference
        return reference.moves_of_world(body)
    """}, ["skips_sleepers"], "step 3 imports the library's World and returns its moves_of_world(body)"),
    attack("sc_world_sleep_timer", "sleeping_crates", "world", {2: """
        return World().sleep_timer_of_world(timer, speed, spin, dt)
    """}, ["timer_rule"], "step 2 returns the library's sleep timer, World().sleep_timer_of_world"),
    attack("sc_dunder_wake", "sleeping_crates", "dunder", {4: """
        return __import__("lesson11.physics2d", fromlist=["World"]).World.wake_of_world(a, b)
    """}, ["wakes_on_contact"], "step 4 reaches World.wake_of_world (the library's rule) through __import__"),
    attack("sc_forge_reference", "sleeping_crates", "forge", {2: """
        probes = __import__("sys").modules.get("checker.labs.sleeping_crates.probes")
        if probes is not None:
            probes.reference_timer = lambda timer, speed, spin, dt: 0.0
        return 0.0
    """}, ["timer_rule"], "step 2 stays the placeholder (0.0) and makes the child's reference timer 0.0 too: the "
                          "grader computes its own"),
    attack("sc_solution_file", "sleeping_crates", "solution",
           {2: solution_call("sleeping_crates", "sleep_timer", "timer, speed, spin, dt")}, ["timer_rule"],
           "step 2 reads solutions/sleeping_crates.py, execs it and returns the solution's timer"),
    attack("sc_detect_checker", "sleeping_crates", "detect", {2: """
        if "checker" in __import__("sys").modules:
            return World().sleep_timer_of_world(timer, speed, spin, dt)
        return 0.0
    """}, ["timer_rule"], "step 2 returns the library's timer only when the checker is loaded, the placeholder "
                          "otherwise"),
    attack("sc_table_timer", "sleeping_crates", "table", {2: f"""
        timers = {TABLES["sleeping_crates"]!r}
        return timers.get((timer, speed, spin, round(dt, 12)), 0.0)
    """}, ["timer_rule"], "step 2 answers the probes' fixed timer cases from a table; the calm crate drawn for this "
                          "run gets 0.0", needs_random_inputs=True),
    attack("sc_world_by_type_timer", "sleeping_crates", "evade_class", {2: dice("""
        library = make_world(Dice()).sleep_timer_of_world
        return library(timer, speed, spin, dt)
    """)}, ["timer_rule"], "step 2 builds the handout's world and uses its library method sleep_timer_of_world, bound "
                          "first so it is no .sleep_timer_of_world() call"),
    attack("sc_world_by_type_wake", "sleeping_crates", "evade_class", {4: dice("""
        library = type(make_world(Dice())).wake_of_world
        return library(a, b)
    """)}, ["wakes_on_contact"], "step 4 takes World from the handout's world and returns its wake_of_world(a, b)"),
    attack("sc_alias_world_moves", "sleeping_crates", "evade_alias", {3: f"""
        library = {ALIAS}.World.moves_of_world
        return library(body)
    """}, ["skips_sleepers"], "step 3 returns World.moves_of_world reached through random._os (World as an "
                              "attribute, not a name), nothing flagged"),
    attack("sc_forge_unflagged", "sleeping_crates", "forge_unflagged", starter_steps("sleeping_crates"),
           ["timer_rule"], "the steps are the starter's; an imported lab_notes.py makes the child's reference timer "
                           "0.0 like the placeholder: nothing in the file is flagged, the grader computes its own",
           edits=LAB_NOTES, extra_files=[("lab_notes.py", notes(FIND_LAB, """
               probes = sys.modules.get("checker.labs.sleeping_crates.probes")
               if probes is not None:
                   probes.reference_timer = lambda timer, speed, spin, dt: 0.0
           """))]),
    attack("sc_world_wake_pair", "sleeping_crates", "evade_class", {4: """
        match build:
            case object(__globals__=lab_globals):
                library = lab_globals["World"]().wake_pair
                return library(a, b)
    """}, ["wakes_on_contact"], "step 4 returns a fresh World's default wake_pair hook's answer (the library's "
                                "wake_of_world under an unlisted name; World from the lab's globals)"),
    attack("sc_world_step_timer", "sleeping_crates", "evade_class", {2: """
        match build:
            case object(__globals__=lab_globals):
                engine = lab_globals["World"](gravity=(0, 0), step_seconds=dt, effects={"sleep"})
                crate = Body(box_points(10, 10), (0, 0), 1.0, vel=(speed, 0), omega=spin)
                crate.sleep_time = timer
                engine.add(crate)
                engine.step()
                return crate.sleep_time
        return 0.0
    """}, ["timer_rule"], "step 2 steps a one-crate World (the library's sleep timer runs in it) and returns the "
                          "crate's sleep_time"),
    attack("sc_match_globals", "sleeping_crates", "evade_match", {3: """
        match build:
            case object(__globals__=lab_globals):
                match lab_globals["World"]:
                    case object(moves_of_world=library):
                        return library(body)
    """}, ["skips_sleepers"], "step 3 reads World from build.__globals__ and its moves_of_world through match "
                              "class patterns: strings, no flagged name"),
    attack("sc_side_module_library", "sleeping_crates", "evade_side_module",
           starter_steps("sleeping_crates"),
           ["timer_rule", "skips_sleepers", "wakes_on_contact"],
           "the steps are the starter's; an imported lab_notes.py beside the file puts the library's three rules "
           "in the lab's globals", edits=LAB_NOTES, extra_files=[("lab_notes.py", notes(FIND_LAB, """
               from lesson11.physics2d import World

               lab_globals["sleep_timer"] = World().sleep_timer_of_world
               lab_globals["moves"] = World.moves_of_world
               lab_globals["wake_on_contact"] = World.wake_of_world
           """))], mechanism=8),
    control("sc_control_comprehension", "sleeping_crates", {2: """
        calm = speed < SLEEP_SPEED and -SLEEP_SPIN < spin < SLEEP_SPIN
        return timer + dt if calm else 0.0
    """, 3: """
        result = bool(body.inv_mass) and not body.asleep
        return result
    """, 4: """
        return [sleeper for sleeper, other in ((a, b), (b, a))
                if sleeper.asleep and other.inv_mass != 0 and not other.asleep]
    """}, "a chained comparison for |spin|, a conditional expression, a local named result, a list comprehension "
          "over both orders: the lesson's rules"),
    control("sc_control_print_in_step", "sleeping_crates", {4: """
        woken = []
        for sleeper, other in ((a, b), (b, a)):
            if sleeper.asleep and other.inv_mass != 0 and not other.asleep:
                woken.append(sleeper)
        if woken:
            print("waking", len(woken), "crate(s)")
        return woken
    """}, "the solution's wake rule with a debug print when something wakes (a print inside a step is allowed)"),
]


# ================================================================ the first round (was tests/attack_corpus.py)
# Merged here from tests/attack_corpus.py (41 entries, names kept): one attacked step per lab,
# the kinds above plus "rebind" (code outside the steps rebinds the undone step's function to the
# library's); its forge, rebind and solution entries add code outside the steps (keeps_handout False),
# and its four controls must get every check, the scenes included (all_checks).

def _attack_data(lab):
    """What this corpus needs of `lab` beyond what it reads from the lab itself: its corpus's ATTACK dict (the
    keys used below; each is optional where the lab itself gives the value)."""
    return getattr(LABS[lab], "ATTACK", {})


def _check_of_step(lab, step):
    """The first of the lab's function checks whose hint names `step` (its corpus's CHECK_STEP)."""
    module = LABS[lab]
    return next(check for check in module.FUNCTION_CHECKS if module.CHECK_STEP[check] == step)


def first_target(lab):
    """(step, the call with its own arguments, the library's name for it, the step's check) of the lab's first
    step: read from the lab (its solution's first step region, the function holding it and its parameters, the
    first name its STEP_LIBRARY lists for it); ATTACK["library_name"] names the library's answer where that is
    another name (Sleeping Crates: World's sleep_timer_of_world)."""
    found = labs_found.by_id(lab)
    step = min(labs_found.steps(found))
    function, parameters = labs_found.step_functions(found)[step]
    call = f"{function}({', '.join(p for p in parameters if p != 'self')})"
    name = _attack_data(lab).get("library_name", found.module.STEP_LIBRARY[step][0])
    return step, call, name, _check_of_step(lab, step)


def _owner(lab):
    """What the library's answer is an attribute of ("World()" for a World method), or "" for a function."""
    return _attack_data(lab).get("library_owner", "")


def first_world_call(lab):
    """Step code asking World to do (or stand in for) the first step's job: ATTACK["world_call"], else World's
    method of the library's name on the step's own arguments."""
    _, call, name, _ = first_target(lab)
    return _attack_data(lab).get("world_call", f"return World().{name}{call[call.index('('):]}")


def _outside(code):
    """Edits that put `code` outside every step, after the last def (before the main guard)."""
    return ((MAIN_GUARD, "\n\n" + code.rstrip("\n") + "\n" + MAIN_GUARD),)


def library_code(lab, call, name):
    """Step code returning the library's answer for `call` (a World method where the lab's ATTACK says so)."""
    args = call[call.index("("):]
    if _owner(lab) == "World()":
        return f"from lesson11.physics2d import World as _W\nreturn _W().{name}{args}"
    return f"from lesson11.physics2d import {name} as _library\nreturn _library{args}"


def first_round(lab):
    """The seven kinds of tests/attack_corpus.py against step 2 of `lab`."""
    step, call, name, check = first_target(lab)
    args = call[call.index("("):]
    function = call[:call.index("(")]
    library = library_code(lab, call, name)
    undone = {step: starter_steps(lab)[step]}
    probes = f"checker.labs.{lab}.probes"
    rebind = (f"from lesson11.physics2d import World as _W\n{function} = lambda *a: _W().{name}(*a)"
              if _owner(lab) == "World()" else f"from lesson11.physics2d import {name} as _library\n"
                                               f"{function} = _library")
    solution = os.path.join(ROOT, "solutions", lab + ".py")
    world = f"{_owner(lab)}." if _owner(lab) else ""
    return [
        attack(f"{lab}_import", lab, "import", {step: library}, [check], "the step imports the library's answer"),
        attack(f"{lab}_world", lab, "world", {step: first_world_call(lab)}, [check],
               "the step asks World, which runs on the library's functions"),
        attack(f"{lab}_dunder", lab, "dunder", {step: f"return __import__('lesson11.physics2d', fromlist=['x']).{world}"
                                                      f"{name}{args}"}, [check],
               "the step reaches the library through __import__"),
        attack(f"{lab}_forge", lab, "forge", undone, [check],
               "the child's references are patched to agree with an undone step", keeps_handout=False,
               edits=_outside(f"import sys as _sys\nfor _name in dir(_sys.modules.get('{probes}')):\n"
                                   f"    if _name.startswith('reference'):\n"
                                   f"        setattr(_sys.modules['{probes}'], _name, lambda *a, **k: None)")),
        attack(f"{lab}_rebind", lab, "rebind", undone, [check],
               "the undone step's function is rebound to the library's after the handout's def", keeps_handout=False,
               edits=_outside(rebind)),
        attack(f"{lab}_solution", lab, "solution", undone, [check],
               "the shipped solution is read and run over the module", keeps_handout=False,
               edits=_outside(f"exec(open({solution!r}).read().split('def main')[0], globals())")),
        attack(f"{lab}_detect", lab, "detect",
               {step: "if __name__ == 'lab_under_test':\n    " + library.replace("\n", "\n    ")}, [check],
               "the library's answer only when graded"),
    ]


def _first_sat_table():
    """Tumbling Crates' step 2 (and 3) answered from a table of the checker's fixed pairs (keys: first corners)."""
    try:
        from checker.judging.probe_kit import reference_sat, sat_pairs
        table = {}
        for _, pa, pb in sat_pairs():
            for first, second in ((pa, pb), (pb, pa)):
                hit = reference_sat(first, second)
                key = (round(first[0].x, 3), round(first[0].y, 3), round(second[0].x, 3), round(second[0].y, 3))
                table[key] = None if hit is None else (round(hit[0].x, 12), round(hit[0].y, 12), hit[1])
    except (ImportError, AttributeError, TypeError, ValueError):
        table = {}
    return ("table = " + repr(table) + "\n"
            "hit = table.get((round(pa[0].x, 3), round(pa[0].y, 3), round(pb[0].x, 3), round(pb[0].y, 3)))\n"
            "if hit is None:\n    return None\nreturn pygame.Vector2(hit[0], hit[1]), hit[2]")


def _first_timer_table():
    """Sleeping Crates' step 2 for the checker's fixed cases only (dt rounded to 9 digits)."""
    table = {(timer, speed, spin, round(dt, 9)): want
             for (timer, speed, spin, dt), want in TABLES["sleeping_crates"].items()}
    return "table = " + repr(table) + "\nreturn table.get((timer, speed, spin, round(dt, 9)), 0.0)"


FIRST_ROUND = [entry for lab in LABS for entry in first_round(lab)] + [
    attack("tumbling_crates_table", "tumbling_crates", "table", {2: _first_sat_table()}, ["sat_axes"],
           "answers copied for the fixed pairs only", needs_random_inputs=True),
    attack("sleeping_crates_table", "sleeping_crates", "table", {2: _first_timer_table()},
           ["timer_rule"], "answers copied for the fixed timer cases only", needs_random_inputs=True),
    control("tumbling_crates_while_loop", "tumbling_crates", {2: """
        axes = edge_normals(pa) + edge_normals(pb)
        k = 0
        while k < len(axes):
            axis = axes[k]
            k += 1
            lo_a, hi_a = project(pa, axis)
            lo_b, hi_b = project(pb, axis)
            overlap = min(hi_a, hi_b) - max(lo_a, lo_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_depth = overlap
                best_axis = axis
    """}, "a while loop and other names", all_checks=True, modes=("root", "child_user")),
    control("more_shapes_comprehension", "more_shapes", {2: """
        return [pygame.Vector2(radius * math.cos(2 * math.pi * k / sides),
                               radius * math.sin(2 * math.pi * k / sides)) for k in range(sides)]
    """}, "a comprehension with math.cos / math.sin and pygame.Vector2", all_checks=True, modes=("root", "child_user")),
    control("sleeping_crates_print_in_step", "sleeping_crates", {2: """
        calm = speed < SLEEP_SPEED and abs(spin) < SLEEP_SPIN
        print('timer', timer, calm)
        return timer + dt if calm else 0.0
    """}, "a debug print inside the step", all_checks=True, modes=("root", "child_user")),
    control("ball_on_ramp_hypot", "ball_on_ramp", {2: """
        ab = b - a
        length_squared = math.hypot(ab.x, ab.y) ** 2
        t = min(1.0, max(0.0, (p - a).dot(ab) / length_squared))
        return a + ab * t
    """}, "math.hypot for |ab|, the clamp written min(max())", all_checks=True, modes=("root", "child_user")),
]


# ================================================================ issue 35: one entry per mechanism per lab
# Each entry names its mechanism (issue 35, items 1-10). "No more than the honest work it contains" is
# measured, not estimated: tests/test_corpus_attacks.py grades beside each attack its HONEST file (honest()
# below: the same file with the attack removed - the steps the attack wrote put back to the starter's
# placeholder, no edit, no side file, no extra text) in the same run, and the attack may score no more.

FILES_SOLUTION_STEPS = {}
for _lab, _module in LABS.items():
    with open(_module.SOLUTION, encoding="utf-8") as _handle:
        FILES_SOLUTION_STEPS[_lab] = CorpusFiles(_module.STARTER, _module.SOLUTION, _module.STEPS, {}, "").step_code(
            _handle.read())

# the library's function each lab's step 2 hands over to: (step, the step's code, its check)
LIBRARY_STEP = {lab: (step, library_code(lab, call, name), check)
                for lab, (step, call, name, check) in ((lab, first_target(lab)) for lab in LABS)}

# 1: characters str.splitlines() breaks at and the compiler does not, 60 of each in one comment
BREAKS = "\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029" * 60
IMPORT_RANDOM = "\nimport random\n"

# 2: what each lab's file hides in a comment under `# -*- coding: unicode_escape -*-`: a line rebinding a
# step function (one no probe splices) to the library's, and the step and check it takes
def hidden(lab):
    """(step, the hidden line, its check): ATTACK["hidden"], else the first step's function rebound to the
    library's answer."""
    if "hidden" in _attack_data(lab):
        return _attack_data(lab)["hidden"]
    step, call, name, check = first_target(lab)
    function = call[:call.index("(")]
    if _owner(lab):
        return step, f"{function} = {_owner(lab)}.{name}", check
    return step, f"from lesson11.physics2d import {name}" + ("" if name == function else f" as {function}"), check


BACKSLASH_N = "\\" + "n"   # the two characters a unicode_escape file decodes to a line break

# 5: the child's tapes (those taken, through run_probe's frame, and those to come, through tape.Recorder.take)
# get, at the first call of each, an event naming draw_text (a
# function of the handout no probe installs; `main` would run the whole handout in the grader). It is put
# in by one step function (FORGER: its steps are flagged, the forgery runs when a probe calls it); the
# other step functions are the solution's, and their checks must come out as a tape mismatch.
FOREIGN_EVENT = """
sys = __import__("sys")
tape = sys.modules.get("checker.judging.tape")
if tape is not None and not hasattr(tape.Recorder.take, "forged"):
    def add_event(entries):
        for entry in entries:
            if isinstance(entry, dict) and entry.get("k") == "call":
                entry["events"] = [{"hook": "draw_text", "state": None,
                                    "args": {"t": [{"t": []}, {"d": {}}]}}] + list(entry.get("events") or [])
                return

    frame = sys._getframe()
    while frame is not None:   # the tapes taken before this call, in run_probe's result
        found = frame.f_locals.get("result")
        if isinstance(found, dict) and isinstance(found.get("tapes"), dict):
            for record in found["tapes"].values():
                add_event(record.get("tape") or [])
        frame = frame.f_back
    real = tape.Recorder.take

    def take(self):   # and the tapes taken after it
        out = real(self)
        add_event(out)
        return out

    take.forged = True
    tape.Recorder.take = take
"""
def forger(lab):
    """(the step that forges, the checks that must not pass): ATTACK["forger"], else the last step forging and the
    checks of every other step."""
    if "forger" in _attack_data(lab):
        return _attack_data(lab)["forger"]
    module = LABS[lab]
    step = max(module.STEPS)
    return step, tuple(check for check in module.FUNCTION_CHECKS if module.CHECK_STEP[check] != step)


# 7: a forged --json document written to the grader's own stdout: the child's parent is the zygote (or the
# grader), whose parent is the grader; as root /proc/<pid>/fd/1 opens the grader's stdout pipe
FORGED_STDOUT = """
import json as _json
import os as _os


def _forge_grades():
    pid = _os.getppid()
    for _ in range(3):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as handle:
                command = handle.read().split(b"\\0")
            if b"checker" in command and b"checker.isolation.zygote" not in command and b"checker.isolation.child" not in command:
                with open(f"/proc/{pid}/fd/1", "w") as out:
                    out.write(_json.dumps({"labs": [{"path": __file__, "lab": "forged", "score": 99,
                                                     "max_score": 99, "criteria": []}]}) + "\\n")
                return
            with open(f"/proc/{pid}/status") as handle:
                pid = int(next(line.split()[1] for line in handle if line.startswith("PPid:")))
        except (OSError, ValueError, StopIteration):
            return


_forge_grades()
"""

# 8: a side module beside the lab, imported by one added line: it binds the step function's name in
# the lab's globals to the library's
# (step, function, the side file's code binding `found`, check) of the labs whose ATTACK has a "side"
SIDE = {lab: _attack_data(lab)["side"] for lab in LABS if "side" in _attack_data(lab)}
CRATE_UTILS = ((MAIN_GUARD, "\n\nimport crate_utils  # noqa: E402, F401\n" + MAIN_GUARD),)


def _issue35(lab):
    """Mechanisms 1, 2, 5, 6, 7 (and 8 where the first round has no side module) against `lab`."""
    short = _attack_data(lab).get("short", lab)   # the entries' name prefix
    module, undone = LABS[lab], starter_steps(lab)
    step, library, check = LIBRARY_STEP[lab]
    hidden_step, hidden_line, hidden_check = hidden(lab)
    forging_step, forged = forger(lab)
    out = [
        attack(f"{short}_m1_line_breaks", lab, "line_breaks", {step: library}, [check],
               "a comment of 480 \\x0b \\x0c \\x1c-\\x1e \\x85 U+2028 U+2029 shifts the checker's line numbers off the "
               "compiler's, so the library call in the step is in no step region it reads",
               extra_text=((IMPORT_RANDOM, IMPORT_RANDOM + "# notes: " + BREAKS + "\n"),), mechanism=1),
        attack(f"{short}_m2_unicode_escape", lab, "coding", {hidden_step: undone[hidden_step]}, [hidden_check],
               "the file declares `coding: unicode_escape`: a comment to a UTF-8 reader holds `\\n` and a line "
               "rebinding the undone step's function to the library's, module code to Python",
               extra_text=(("", "# -*- coding: unicode_escape -*-\n"),
                           (MAIN_GUARD, f"\n\n# see my notes{BACKSLASH_N}{hidden_line}  # (mine)\n" + MAIN_GUARD)),
               mechanism=2),
    ] + ([] if not forged else [   # a one-step lab has no other step whose checks a forged tape could reach
        attack(f"{short}_m5_foreign_hook", lab, "foreign_hook",
               {forging_step: _code(FOREIGN_EVENT) + "\n" + FILES_SOLUTION_STEPS[lab][forging_step]}, forged,
               f"step {forging_step} (the solution's, flagged) patches the child's tape.Recorder.take to add to every tape "
               "an event naming draw_text, a handout function no probe installs: the solution's other steps must "
               "come out as a tape mismatch, never data or a call in the grader", mechanism=5, message="could not replay"),
    ]) + [
        attack(f"{short}_m6_star_solution", lab, "star_import", undone, module.FUNCTION_CHECKS,
               f"the steps are the starter's; `from solutions.{lab} import *` after the defs replaces every step "
               "function with the solution's", edits=((MAIN_GUARD, f"\n\nfrom solutions.{lab} import *  # noqa\n"
                                                       + MAIN_GUARD),), mechanism=6),
        attack(f"{short}_m6_star_library", lab, "star_import", undone, module.FUNCTION_CHECKS,
               "the steps are the starter's; `from lesson11.physics2d import *` after the defs binds the library's "
               "functions under the steps' names", edits=((MAIN_GUARD, "\n\nfrom lesson11.physics2d import *  # noqa\n"
                                                          + MAIN_GUARD),), mechanism=6),
        attack(f"{short}_m7_grader_stdout", lab, "grader_stdout", undone, module.FUNCTION_CHECKS,
               "the steps are the starter's; at import the child finds the grader's process and writes a forged "
               "--json document to its stdout (/proc/<pid>/fd/1, root only)",
               edits=_outside(FORGED_STDOUT), keeps_handout=False, mechanism=7,
               modes=("root", "child_user")),
    ]
    if lab in SIDE:
        side_step, function, found, side_check = SIDE[lab]
        out.append(attack(f"{short}_m8_crate_utils", lab, "evade_side_module", {side_step: undone[side_step]},
                          [side_check], f"step {side_step} is the starter's; crate_utils.py beside the lab, "
                                        f"imported by one added line, binds {function} in the lab's globals",
                          edits=CRATE_UTILS, mechanism=8, extra_files=[("crate_utils.py", notes(FIND_LAB, found, f"""
                              lab_globals["{function}"] = found
                          """))]))
    return out


# 4: the child holds reference values in the probe's frame when it calls the student's function; a format
# string reads them through a running generator's frame (gi_frame.f_back: the step's own frame, then the
# tape's recording wrapper, then the probe), with no forbidden name (the rules never look inside a string)
FRAME_READ = """
def peek():
    yield FIELDS.format(me[0])
me = [None]
me[0] = peek()
try:
    values = [float(text) for text in next(me[0]).split()]
except (KeyError, AttributeError, IndexError, ValueError):
    values = None
"""


def frame_read(fields, then):
    """Step code that reads the probe's locals (`fields`: format fields after f_locals) and then runs `then`."""
    chain = "{0.gi_frame.f_back.f_back.f_back.f_locals"
    text = " ".join(chain + field + "}" for field in fields)
    return _code(FRAME_READ).replace("FIELDS", repr(text)) + "\n" + _code(then)


ISSUE35 = [entry for lab in LABS for entry in _issue35(lab)] + [
    # 3: the probe reads k, mu and kt from the bodies after resolve() changed them
    attack("tc_m3_zero_inertia", "tumbling_crates", "changed_inputs", {4: """
        a.inv_inertia = b.inv_inertia = 0.0
    """, 5: """
        a.friction = b.friction = 1e12
    """}, ["resolve_k", "resolve_friction"], "step 4 zeroes both inverse inertias and step 5 sets friction 1e12, so "
                                            "references read after resolve() agree with no spin terms and no clamp; "
                                            "the check must name the field changed",
        mechanism=3, message="inv_inertia"),
    attack("br_m3_zero_inertia", "ball_on_ramp", "changed_inputs", {7: """
        a.inv_inertia = b.inv_inertia = 0.0
        a.friction = b.friction = 1e12
        kt = a.inv_mass + b.inv_mass
        apply_impulse(a, b, t * (-rel.dot(t) / kt), ra, rb)
    """}, ["friction_rolls"], "step 7 zeroes both inverse inertias and sets friction 1e12 before an unclamped friction "
                              "impulse without spin terms: the references must come from the bodies as given, "
                              "the check name the field changed", mechanism=3, message="inv_inertia"),
    # 4: reference values read from the probe's frame
    attack("tc_m4_frame_format", "tumbling_crates", "frame_read", {6: frame_read(
        ("[ref_a].omega", "[ref_b].omega"), """
        if values:
            a.omega, b.omega = values
    """)}, ["apply_impulse_spin"], "step 6 reads the child's reference spins ref_a, ref_b from probe_apply_impulse's "
                                   "frame through a format string, and does nothing otherwise", mechanism=4),
    attack("br_m4_frame_format", "ball_on_ramp", "frame_read", {4: frame_read(
        ("[want][a][0]", "[want][a][1]", "[want][b][0]", "[want][b][1]"), """
        if values:
            a.pos, b.pos = pygame.Vector2(values[:2]), pygame.Vector2(values[2:])
    """)}, ["push_out_split"], "step 4 reads the child's expected positions `want` from probe_separate's frame through "
                              "a format string, and pushes nothing otherwise", mechanism=4),
    # 9: vacuous checks (tc_early_return_friction above is Tumbling Crates')
    attack("br_m9_early_return_friction", "ball_on_ramp", "vacuous", {7: """
        return  # (no friction yet)
    """}, ["friction_rolls"], "step 7 returns before any friction impulse: the friction check must see that nothing "
                              "was applied", mechanism=9),
    # 10: wrong answers that must fail
    attack("ms_m10_parallel_one_minus_dot", "more_shapes", "wrong_answer", {5: """
        for axis in edge_normals(pa) + edge_normals(pb):
            if all(1 - abs(axis.dot(kept)) >= PARALLEL for kept in axes):
                axes.append(axis)
    """}, ["parallel_axes"], "step 5 counts axes as parallel when 1 - |a.b| < PARALLEL (about theta^2 / 2): axes up "
                             "to 0.08 degrees apart merge", mechanism=10),
    attack("br_m10_contact_halfway", "ball_on_ramp", "wrong_answer", {6: """
        return center + normal * (radius - depth / 2)
    """}, ["contact_on_surface"], "step 6 puts the contact halfway into the overlap, not on the ball's surface",
        mechanism=10),
    # 10: honest steps with a pure standard-library module: full marks
    control("ms_m10_cmath_corners", "more_shapes", {2: """
        import cmath
        corners = [radius * cmath.exp(2j * math.pi * k / sides) for k in range(sides)]
        return [Vector2(z.real, z.imag) for z in corners]
    """}, "step 2's corners as complex exponentials r e^(2 pi i k / n) with cmath", all_checks=True, mechanism=10),
    control("ms_m10_itertools_centroid", "more_shapes", {3: """
        import itertools
        total = Vector2()
        for a, b in itertools.pairwise(points + points[:1]):
            total += (a + b) * cross(a, b)
        return total / (6 * area)
    """}, "step 3's edges as itertools.pairwise over the closed outline", all_checks=True, mechanism=10),
    control("tc_m10_itertools_axes", "tumbling_crates", {2: """
        import itertools
        for axis in itertools.chain(edge_normals(pa), edge_normals(pb)):
            min_a, max_a = project(pa, axis)
            min_b, max_b = project(pb, axis)
            overlap = min(max_a, max_b) - max(min_a, min_b)
            if overlap <= 0:
                return None
            if overlap < best_depth:
                best_axis, best_depth = axis, overlap
    """}, "step 2's axes as itertools.chain of both shapes' edge normals", all_checks=True, mechanism=10),
    control("sc_m10_itertools_wake", "sleeping_crates", {4: """
        import itertools
        return [sleeper for sleeper, other in itertools.permutations((a, b))
                if sleeper.asleep and other.inv_mass != 0 and not other.asleep]
    """}, "step 4's two orders as itertools.permutations((a, b))", all_checks=True, mechanism=10),
]


# where each mechanism of issue 35 applies (tests/test_corpus_attacks.py holds the corpus to it); left out:
#   3 (inputs changed under the reference): More Shapes' and Sleeping Crates' steps are pure (a changed argument
#     fails them, checker/lab_checks.function_data) and Bullets' references come from a fresh world; Ball on the
#     Ramp's come from copies made first (br_m3_zero_inertia shows it);
#   4 (references in the child's frame at the call): More Shapes, Bullets and Sleeping Crates compute a case's
#     reference after the student's call; 9 (a check that can grade nothing): the checks of More Shapes,
#     Bullets and Sleeping Crates compare every case's answer (none skips a case it cannot see);
#   10 (wrong answers) are More Shapes' and Ball on the Ramp's; the stdlib controls are where a step reads
#     naturally with cmath or itertools (More Shapes, Tumbling Crates, Sleeping Crates).
# every lab's issue-35 mechanisms: its corpus's ATTACK["mechanisms"], else those _issue35 builds for any lab (5
# only where a step forges the tape against another step's check)
MECHANISMS_BY_LAB = {lab: _attack_data(lab).get("mechanisms", (1, 2) + ((5,) if forger(lab)[1] else ()) + (6, 7)
                                                + ((8,) if lab in SIDE else ())) for lab in LABS}


# issue 39's attacks on the judging (items 2-4): tests/corpus_attacks_judge.py
ISSUE39_JUDGE = corpus_attacks_judge.entries(attack)
MECHANISM_KINDS += corpus_attacks_judge.KINDS


def own_entries(lab):
    """The attacks and controls a lab's corpus writes for itself: ATTACK["entries"](attack, control), a function
    given this module's two makers, so a lab added as one folder (and its corpus) needs nothing written here."""
    make = _attack_data(lab).get("entries")
    return list(make(attack, control)) if make else []


OWN = [entry for lab in LABS for entry in own_entries(lab)]


def _solution_step(lab, step):
    module = LABS[lab]
    with open(module.SOLUTION, encoding="utf-8") as handle:
        return CorpusFiles(module.STARTER, module.SOLUTION, module.STEPS, {}, "").step_code(handle.read())[step]


def _added_last(line):
    """An edit that puts `line` after the last def, before the main guard (an import added at the end)."""
    return ((MAIN_GUARD, "\n\n" + line + "  # noqa: E402\n" + MAIN_GUARD),)


# attack report of 2026-11-28: a handed name rebound to the library (A1); a local named like the runtime (F1)
ROUND2 = [
    attack("tc_handed_names_library", "tumbling_crates", "evade_handed", {
        2: "return project(pa, pb)",
        4: "k = edge_normals(a, b, ra, rb, normal)",
        6: "a.vel += impulse * a.inv_mass\nb.vel -= impulse * b.inv_mass\ncentre_of(a, b, impulse, ra, rb)"},
        ["sat_axes", "resolve_k", "apply_impulse_spin"],
        "steps 2, 4, 6 call project, edge_normals, centre_of, which an import added at the end binds to the "
        "library's sat, effective_mass_inverse and apply_impulse", keeps_handout=False,
        edits=_added_last("from lesson11.physics2d import sat as project, effective_mass_inverse as edge_normals, "
                          "apply_impulse as centre_of")),
    attack("tc_new_name_world_sat", "tumbling_crates", "evade_handed", {2: "return lesson_sat(pa, pb)"}, ["sat_axes"],
           "step 2 calls lesson_sat, a module-level name added outside the steps as World().sat (the library's sat)",
           keeps_handout=False, edits=_added_last("lesson_sat = World().sat")),
    attack("ms_handed_names_library", "more_shapes", "evade_handed", {
        2: "return draw_body(sides, radius)", 3: "return draw_contacts(points)", 4: "return draw_text(points, mass)"},
        ["polygon_corners", "centroid", "inertia_sum"],
        "steps 2-4 call the handed draw helpers, which an import added at the end binds to the library's "
        "regular_polygon, polygon_centroid and polygon_inertia", keeps_handout=False,
        edits=_added_last("from lesson11.physics2d import regular_polygon as draw_body, polygon_centroid as "
                          "draw_contacts, polygon_inertia as draw_text")),
    attack("br_handed_name_library", "ball_on_ramp", "evade_handed", {3: "return inside(center, radius, points)"},
           ["inside_case"], "step 3 calls the handed inside(), which an import added at the end binds to the "
                            "library's circle_polygon", keeps_handout=False,
           edits=_added_last("from lesson11.physics2d import circle_polygon as inside")),
    control("bu_control_local_runtime", "bullets", {5: _solution_step("bullets", 5).replace(
        "bullet.pos += bullet.vel * (dt - t)",
        "runtime = dt - t  # the part of the step still to run\nbullet.pos += bullet.vel * runtime")},
        "step 5 names the rest of the step a local `runtime` (not the lab runtime)"),
    control("tc_control_local_lab_panel", "tumbling_crates", {5: """
        lab = mu * j
        panel = (-lab, lab)
        jt = max(panel[0], min(panel[1], jt))
    """}, "step 5 clamps with locals named lab and panel (not the lab runtime or the solver panel)"),
]

ENTRIES = (TUMBLING + MORE_SHAPES + BALL_ON_RAMP + BULLETS + SLEEPING + FIRST_ROUND + ISSUE35 + ISSUE39_JUDGE + OWN
           + ROUND2)
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"
BY_LAB = {lab: [entry for entry in ENTRIES if entry.lab == lab] for lab in LABS}
ATTACKS = [entry for entry in ENTRIES if entry.target is not None]
CONTROLS = [entry for entry in ENTRIES if entry.target is None]


def honest(entry):
    """The entry with its attack removed: the steps it wrote back to the starter's, no edit, side file or extra text.

    What it contains of honest work is then exactly what this file earns (the solution's code in the other steps).
    """
    undone = starter_steps(entry.lab)
    steps = {step: undone[step] if step in entry.steps and step not in entry.honest_keeps else code
             for step, code in FILES_SOLUTION_STEPS[entry.lab].items()}
    return Entry(entry.name + "__honest", entry.lab, "honest", steps, None, f"{entry.name} without its attack")


HONEST = {entry.name: honest(entry) for entry in ATTACKS if entry.mechanism}

FILES = {lab: CorpusFiles(module.STARTER, module.SOLUTION, module.STEPS,
                          {e.name: e for e in BY_LAB[lab] + [h for h in HONEST.values() if h.lab == lab]},
                          "tests/corpus_attacks.py")
         for lab, module in LABS.items()}


def build(entry):
    """The entry's whole file: the lab's current starter, steps filled (the entry's, else the solution's), edits,
    then its extra text (an empty `old` puts `new` first in the file)."""
    source = FILES[entry.lab].build(entry.name)
    for old, new in entry.extra_text:
        source = new + source if old == "" else mutants.apply_edits(source, [(old, new)], entry.name, "the built file",
                                                                    "tests/corpus_attacks.py")
    return source


def write(directory, entries=None):
    """Write each entry (all by default) as DIRECTORY/<name>/<lab>.py, as a class folder holds them; {name: path}."""
    paths = {}
    for entry in (ENTRIES if entries is None else entries):
        folder = os.path.join(str(directory), entry.name)
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, entry.lab + ".py")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(build(entry))
        for file, text in entry.extra_files:
            with open(os.path.join(folder, file), "w", encoding="utf-8") as handle:
                handle.write(text)
        paths[entry.name] = path
    return paths
