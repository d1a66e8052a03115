"""The wrong-kind values tests/test_wrong_kinds.py writes into a lab's step regions, and how a case is written.

A lab's corpus (tests/corpus_<id>.py) lists its cases as WRONG_KINDS: [(function, step, [case, ...])], a case
being a step region's whole code or one of the tuples made below; a lab whose corpus has none gets
derived_cases(): each step of its solution whose region returns its function's answer returns it as a string.
"""
V = "pygame.Vector2"   # the one module attribute a step may use (checker/reading/step_rules.py)

# wrong kinds by the kind the function returns
NUMBER = [f"{V}(1, 0)", "'1.5'", "[1.5]", "float('nan')", "True", "10 ** 400", "{'x': 1.0}", "10 ** 5000", "-float('inf')"]
VECTOR = ["(1.0, 2.0)", "[1.0, 2.0]", "3.0", f"{V}(float('nan'), 0)", "'v'", "{'x': 1.0}"]
POINTS = ["[(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)]", f"{V}(1, 0)", "[1.0, 2.0, 3.0]", "'abc'",
          f"[{V}(float('nan'), 0)] * 3", "5", "[{V}(1, 0), 'x', None]".replace("{V}", V)]
HIT = [f"({V}(1, 0), (1.0, 2.0))", "((1.0, 0.0), 2.0)", f"({V}(1, 0), 2.0, 3.0)", "2.0",
       f"({V}(1, 0), {V}(1, 0))", f"({V}(1, 0), float('nan'))", f"({V}(1, 0), '3')", f"({V}(1, 0), 10 ** 400)",
       "{'normal': 1}", f"({V}(1, 0), True)", f"({V}(0, float('inf')), 2.0)", "[[1.0, 0.0], 2.0]"]
TOI = ["(0.5, (1.0, 0.0))", f"({V}(1, 0), 0.5)", f"(0.5, {V}(1, 0), 1)", "0.5", f"('0.5', {V}(1, 0))",
       f"(float('nan'), {V}(1, 0))", f"(10 ** 400, {V}(1, 0))", f"(True, {V}(1, 0))"]
AS_TEXT = ["str(answer)"]
FLAGS = ["'yes'", f"{V}(1, 0)", "[True]", "float('nan')"]


def returns(values):
    """Each value as a step region's whole code: `return value`."""
    return [f"return {value}" for value in values]


def after_solution(statements):
    """Each statement run after the solution's own code of the step (a body left of the wrong kind)."""
    return [("+", statement) for statement in statements]


def wrapped(wraps):
    """Each wrap of the solution's own answer (`answer`), for a step region that holds its function's return: the
    right value in the wrong kind (a string, a one-item list) must fail as surely as a wrong value."""
    return [("wrap", wrap) for wrap in wraps]


def substituted(old, news):
    """The solution's code with `old` replaced by each of `news` (a hook called with a wrong-kind argument)."""
    return [("sub", old, new) for new in news]


def before_solution(statements):
    """Each statement run before the solution's own code of the step (for a step region that returns)."""
    return [("pre", statement) for statement in statements]


MOTION = ["a.omega = 'spin'", "b.omega = float('nan')", "a.omega = [0.5]", "b.omega = 10 ** 400",
          f"a.vel = {V}(float('nan'), 0)", "b.vel = (0.0, 0.0)"]
PLACES = ["a.pos = (1.0, 2.0)", "b.pos = 'here'", f"b.pos = {V}(float('nan'), 0)", "a.angle = [0.5]",
          f"b.angle = {V}(1, 0)", "b.pos = None"]


def derived_cases(lab):
    """The cases of a lab whose corpus lists none, read from the lab itself: each step of its solution whose
    region returns its function's answer (a line `return ...` at the region's own indent) returns that answer as
    a string, never the right kind for a number, a vector, a list or None."""
    import labs_found
    from corpus_files import CorpusFiles
    with open(lab.solution, encoding="utf-8") as handle:
        solution = handle.read()
    steps = labs_found.steps(lab)
    solved = CorpusFiles(lab.starter, lab.solution, list(steps), {}, "tests/wrong_kinds.py").step_code(solution)
    functions = labs_found.step_functions(lab)
    return [(functions[step][0], step, wrapped(AS_TEXT)) for step in sorted(solved)
            if step in functions and any(line.startswith("return ") for line in solved[step].split("\n"))]
