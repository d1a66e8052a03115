'''The files `python -m checker new-lab ID --title "..."` writes: a one-step lab in today's form, in one place.

FILES maps each path (under the project) to its text; `$lab_id` and `$title` are filled in (string.Template:
Python's own braces stay as they are). The lab: three crates are tossed onto the floor, and the World gives a
contact its impulse only while the student's step 2, normal_speed(va, vb, normal) = (vB - vA) · n, says it
closes. The step is declared as data (checker/judging/declared.py: fixed and drawn cases, ten known wrong forms
named by the one-formula rule); `runs` runs one scene; show.py draws its cases. new_lab.py also writes the
starter, with assign's starter_text.
'''

SOLUTION = '''"""$title: a Lesson 11 lab (written by `python -m checker new-lab`; make it yours).

Three crates are tossed onto the floor and slide to a stop. At every contact point the World asks
normal_speed() how fast B moves relative to A along the contact's normal
(px/s): negative while the two approach, and only then does the contact get
its impulse (the library's resolve()). The HUD shows the fastest approach
seen so far.

The comments "Step 1" to "Step 3" follow the exercise's steps. Step 2 is the
code between the lines `# --- step 2: ... ---` and `# --- end of step 2 ---`:
yours to write in the starter, done in the solution (where the step opens
with the starter's text for it, between `# BEGIN PROMPT` and `# END PROMPT`).
The step's comment names the section of the lesson (lesson11/README.md) that
explains it. In the starter the step holds a placeholder line, marked
"replace this placeholder", that keeps the file running until you write the
step: replace that line with your code. Code written above a placeholder left
in place is wasted: a placeholder `return` hands back its stand-in value
unless your code returned first.

Controls: left click drops a crate (up to 20), R resets.
"""
import random

import pygame

from lesson11 import runtime as lab  # lab runtime
from lesson11.panel import LabPanel  # solver panel
from lesson11.physics2d import Body, World, box_points, spin_velocity
from lesson11.physics2d import resolve as library_resolve
from lesson11.physics2d.draw import draw_text

WIDTH, HEIGHT = 900, 600
MAX_CRATES = 20
STATIC_BODIES = 1    # the floor
BACKGROUND = (24, 26, 34)
GREY = (90, 96, 110)

# Step 1: run this file. Until you write step 2 no contact closes: the crates get no impulse, so no friction
# either, and slide on across the floor.


def normal_speed(va, vb, normal):
    """How fast B moves relative to A along the unit normal (px/s): (vB - vA) · n.

    va, vb: the two bodies' velocities (px/s); normal: the contact's unit
    normal, from A to B. Negative while the bodies approach, positive while
    they separate, 0 when they slide past each other.
    """
    # --- step 2: the speed along the normal ---
    # BEGIN PROMPT
    # Step 2 (lesson: "5. Impulses that spin, and friction"): return B's velocity relative to A's,
    # projected on the normal (a dot product); it is negative while the two approach.
    # starter: return 0.0  # until you write step 2, no contact closes: replace this placeholder
    # END PROMPT
    return (vb - va).dot(normal)
    # --- end of step 2 ---


def build(item):
    """One crate from {"w", "h", "pos", optional "angle", "vel", "omega"} (mass w·h/1000)."""
    return Body(box_points(item["w"], item["h"]), item["pos"], mass=item["w"] * item["h"] / 1000,
                angle=item.get("angle", 0.0), vel=item.get("vel", (0, 0)), omega=item.get("omega", 0.0),
                color=item.get("color", (214, 150, 86)))


def make_scene(rng):
    """The floor and three crates tossed onto it (300 to 400 px above it, 120-160 px/s sideways), in colours
    drawn from rng."""
    floor = Body(box_points(WIDTH, 40), (WIDTH / 2, HEIGHT - 20), 0, color=GREY)
    return [floor] + [build({"w": 60, "h": 40, "pos": pos, "vel": vel, "color": (rng.randint(170, 240), 150, 86)})
                      for pos, vel in (([200, 240], [160, 0]), ([450, 190], [-120, 0]), ([600, 140], [140, 0]))]


def resolve(a, b, normal, point):
    """The World's contact impulse: the library's resolve(), given only while normal_speed() says the point closes.

    The velocities are the contact point's on each body (px/s): the centre's plus the spin's, ω × r.
    """
    va = a.vel + spin_velocity(a.omega, point - a.pos)
    vb = b.vel + spin_velocity(b.omega, point - b.pos)
    if normal_speed(va, vb, normal) >= 0:
        return 0.0   # separating, or sliding past: no impulse
    return library_resolve(a, b, normal, point)


def make_world(rng):
    """The World the window starts with: the scene's bodies, the course's gravity, steps of 1/120 s, and this
    file's resolve() at every contact point."""
    return World(lab.scene(make_scene(rng), build=build), resolve=resolve)  # lab runtime: scene()


def fastest_approach(world):
    """The fastest approach along a normal among the world's contacts (px/s, 0 when none approaches)."""
    return max([0.0] + [-normal_speed(c.a.vel, c.b.vel, c.normal) for c in world.contacts])


def main():
    pygame.init()
    screen = pygame.display.set_mode((WIDTH, HEIGHT))
    pygame.display.set_caption("$title")
    clock = pygame.time.Clock()
    font = pygame.font.Font(None, 24)
    rng = random.Random(lab.seed(11))  # lab runtime: seed()
    world = make_world(rng)
    panel = LabPanel()  # solver panel
    fastest = 0.0
    running = True
    # Step 3: watch the crates land, then click to drop more and read the fastest approach.
    while running and lab.frame_budget():  # lab runtime: frame_budget()
        dt = lab.tick(clock, 60) / 1000  # lab runtime: clock.tick(60)
        for event in lab.events():  # lab runtime: pygame.event.get()
            panel.handle(event)  # solver panel: its keys
            if event.type == pygame.QUIT:
                running = False
            elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
                if len(world.bodies) - STATIC_BODIES < MAX_CRATES:
                    world.add(build({"w": rng.randint(36, 56), "h": rng.randint(28, 44), "pos": list(event.pos)}))
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                world = make_world(rng)
                fastest = 0.0
        panel.advance(world, dt)  # solver panel: fixed steps, long frames clamped
        lab.record(world.bodies, world.contacts)  # lab runtime: record()
        fastest = max(fastest, fastest_approach(world))

        screen.fill(BACKGROUND)
        for body in world.bodies:
            pygame.draw.polygon(screen, body.color, body.world_points())
        draw_text(screen, font, f"crates {len(world.bodies) - STATIC_BODIES}/{MAX_CRATES} | fastest approach "
                                f"{fastest:.1f} px/s | [click] drop  [R] reset")
        panel.draw(screen, world)  # solver panel: settings, ms, graph
        pygame.display.flip()
    pygame.quit()
    print(f"fastest approach along a normal: {fastest:.1f} px/s")


if __name__ == "__main__":
    main()
'''

INIT = '''"""The $title lab: checks.py (its checks), probes.py (its probes), scenes.py (its scenes), show.py (what
--show draws)."""
'''

CHECKS = '''"""$title: the checks and the hints (written by `python -m checker new-lab`; make them yours).

Order of checks: loads, handout_unchanged, runtime_lines, normal_speed_right (step 2, declared in probes.py as
data: checker/judging/declared.py grades it), runs (the scene).
"""
from checker.judging import lab_checks
from checker.judging.checks import Hint, Registry
from . import probes, scenes

TITLE = "$title"
# the library functions step 2 asks the student to write: a step that calls one fails (checker/reading/step_rules.py)
STEP_LIBRARY = {2: ("relative_velocity",)}
STEP_ADVICE = {2: "subtract the velocities and take the dot product with the normal yourself"}

HINTS = {
    "normal": Hint(2, "the speed along the normal",
                   "Section 5: the relative velocity is B's minus A's; its part along the unit normal n (from A "
                   "to B) is a dot product, negative while the bodies approach."),
    "handout": lab_checks.handout_hint("the scene, the World, the `# lab runtime` lines, the final print"),
    "runtime": lab_checks.RUNTIME_HINT,
    "crash": Hint(1, "run the file", "Run the file yourself (python $lab_id.py) and fix the error at the line shown."),
}

# The scenes each behaviour check reads, by check id (checker/replay/pictures.py draws them when one fails).
PICTURE_SCENES = {"runs": ("drop",)}

# CPU s of the solution's run of each scene (the template's: 0.4 s in a child process; measure yours again when
# the scene changes: the grader starts the longest first).
SCENE_SECONDS = {"drop": 0.4}

CHECKS = Registry()

lab_checks.register_common(CHECKS, HINTS, ("normal_speed", "main"))
probes.NORMAL_SPEED.register(CHECKS, HINTS)
lab_checks.register_runs(CHECKS, HINTS, scenes.SCENARIOS, ["loads", "handout_unchanged", "runtime_lines",
                         "normal_speed_right"], "main() runs the checker's scene to the end.", "a crate", hint="crash")
'''

PROBES = '''"""Probes of a $title file's own functions, run inside the checker's child process (new-lab's template).

    normal_speed  (step 2) pairs approaching, separating, sliding past each other, moving together and at
                  rest, with normals along the axes and slanted, and two pairs drawn for this run; beside
                  the lesson's answer, what each known wrong form gives (NORMAL_MISTAKES)

The lesson's answers are added in the grader only (checker/judging/declared.py's lesson_answers). Units: px, s.
"""
import math

from pygame import Vector2

from checker.judging.common import as_number
from checker.judging.declared import Step, forms_of
from checker.judging.lab_checks import vec_text
from checker.judging.probe_kit import reference
from checker.judging.tape import run_rng

REQUIRED = ("normal_speed", "main")
RELATIVE = 1e-9   # the answer against (vB - vA) · n, relative to its size (other orders of the same sums differ)

CASES = (
    # (what, vA px/s, vB px/s, unit normal from A to B)
    ("head-on along x", (240, 0), (-240, 0), (1, 0)),
    ("B falling onto A at rest", (0, 0), (0, 300), (0, -1)),
    ("B catching up with A from behind", (50, 0), (200, 0), (-1, 0)),
    ("a slanted normal", (30, 80), (-60, 10), (0.6, 0.8)),
    ("separating along y", (0, -50), (0, 120), (0, 1)),
    ("sliding past each other", (100, 0), (-100, 0), (0, 1)),
    ("moving together", (75, -20), (75, -20), (0.8, -0.6)),
    ("both at rest", (0, 0), (0, 0), (1, 0)),
)


@reference
def reference_normal_speed(va, vb, normal):
    """The lesson's speed along the normal (px/s): (vB - vA) · n."""
    return (Vector2(vb) - Vector2(va)).dot(Vector2(normal))


@reference
def reference_approach(case):
    """How the pair moves along the normal: "approaching", "separating" or "level" (the evidence's words)."""
    speed = reference_normal_speed(case["va"], case["vb"], case["normal"])
    return "approaching" if speed < 0 else "separating" if speed > 0 else "level"


# the known wrong forms of step 2: name -> the sentence that names it (its mistake id: normal_<name>)
NORMAL_MISTAKES = {
    "sign": "you take A's velocity relative to B's: vB - vA, so that approaching reads negative",
    "only_b": "only B's velocity is projected: subtract A's first",
    "only_a": "only A's velocity is projected: take B's minus A's",
    "length": "the length of vB - vA is not its part along the normal: take the dot product with n",
    "sum": "vB + vA is projected: the relative velocity is vB - vA",
    "cross": "a cross product gives the part across the normal: take the dot product",
    "abs": "the speed lost its sign: approaching must read negative",
    "halved": "the speed is halved: (vB - vA) · n has no factor 1/2",
    "clamped": "a separating pair reads 0: keep the positive speeds too",
    "x_only": "only the x part is taken: the normal is not always along x, take the dot product",
}


@reference
def normal_mistakes(case):
    """{name: what a known wrong normal_speed gives} for one case (NORMAL_MISTAKES)."""
    va, vb, n = Vector2(case["va"]), Vector2(case["vb"]), Vector2(case["normal"])
    right = (vb - va).dot(n)
    return {"sign": (va - vb).dot(n), "only_b": vb.dot(n), "only_a": va.dot(n), "length": (vb - va).length(),
            "sum": (vb + va).dot(n), "cross": (vb - va).cross(n), "abs": abs(right), "halved": right / 2,
            "clamped": min(0.0, right), "x_only": (vb - va).x}


def normal_speed_cases(module):
    """CASES and two pairs drawn for this run (one approaching, one separating), each a dict of inputs."""
    rng = run_rng(module, "normal_speed")
    drawn = []
    for what, sign in (("a pair drawn for this run, approaching", -1), ("a pair drawn for this run, separating", 1)):
        angle = rng.uniform(0, 2 * math.pi)
        normal = (math.cos(angle), math.sin(angle))
        va = (rng.uniform(-200, 200), rng.uniform(-200, 200))
        along, across = sign * rng.uniform(20, 300), rng.uniform(-50, 50)
        drawn.append((what, va, (va[0] + along * normal[0] + across * normal[1],
                                 va[1] + along * normal[1] - across * normal[0]), normal))
    return [{"case": what, "va": list(va), "vb": list(vb), "normal": list(normal)}
            for what, va, vb, normal in CASES + tuple(drawn)]


def _label(case):
    return f"normal_speed({vec_text(case['va'])}, {vec_text(case['vb'])}, {vec_text(case['normal'])}) ({case['case']})"


# step 2 as data: the cases, the student's call, the lesson's answer (in the grader only) and the wrong forms;
# checker/judging/declared.py probes, compares, names a form when it alone fits every case and words the message
NORMAL_SPEED = Step(
    "normal_speed_right", "Step 2: normal_speed(va, vb, normal) is (vB - vA) · n, negative while the bodies approach.",
    2, "normal_speed", normal_speed_cases,
    lambda normal_speed, c: normal_speed(Vector2(c["va"]), Vector2(c["vb"]), Vector2(c["normal"])),
    lambda c: reference_normal_speed(c["va"], c["vb"], c["normal"]), answer=as_number, hint="normal",
    same=lambda got, want: not isinstance(got, str) and abs(got - want) <= RELATIVE * max(1.0, abs(want)),
    bad=lambda got: isinstance(got, str), kind="a number (px/s)", label=_label, show=lambda v: f"{v:.6g} px/s",
    unnamed="the speed along the normal is not (vB - vA) · n", extra={"how": lambda c: reference_approach(c)},
    evidence=lambda c: f"{_label(c)} returned {c['got']:.6g} px/s; expected {c['want']:.6g} ({c['how']}).",
    passed="all {n} pairs (approaching, separating, sliding past, at rest) read (vB - vA) · n",
    wrong=forms_of(NORMAL_MISTAKES, lambda c: normal_mistakes(c), "normal_"))

# the step functions that answer a question and must leave their arguments as they got them
PURE = ("normal_speed",)

# probe name -> (the lab function it needs, the probe)
PROBES = NORMAL_SPEED.probes()
'''

SCENES = '''"""The $title scene: two crates dropped onto the floor (new-lab's template).

The floor's top face is at y = 560 px; y grows downward. Scenario items are the lab's own crate
descriptions ({"w", "h", "pos", "angle", "vel"}), made by the lab's build().
"""
from lesson11 import records as metrics

FRAMES = 90   # 1.5 s at 60 fps: the solution's crates fall 300, 350 and 400 px, land at 0.78, 0.85 and 0.90 s
              # and friction (0.6) stops their slide; with no impulse (a wrong step 2) nothing stops it


def drop():
    """Three 60 x 40 crates tossed from 300 to 400 px above the floor, 120-160 px/s sideways."""
    crates = [{"w": 60, "h": 40, "pos": [200, 240], "vel": [160, 0]}, {"w": 60, "h": 40, "pos": [450, 190],
              "vel": [-120, 0]}, {"w": 60, "h": 40, "pos": [600, 140], "vel": [140, 0]}]
    return {"frames": FRAMES, "fps": metrics.FPS, "seed": metrics.SEED, "record_every": 1, "scenario": crates}


SCENARIOS = {"drop": drop}
'''

SHOW = '''"""What --show and --pictures draw for $title's checks (new-lab's template; checker/labs/__init__.py says how
it is found). SERIES: the quantity each behaviour check is plotted by; CASES: a failed function check's failing
cases, from the probe's judged data:

  SpeedCase  normal_speed(): both velocities and the normal as arrows, the two answers as bars from 0
"""
from pygame import Vector2

from checker.replay.show_kit import BACK, GREY, LESSON, STUDENT, TEXT, Case, arrow, close, data, numbered, text_font
from checker.replay.show_series import FASTEST

SERIES = {"runs": FASTEST}
SCALE = 0.5   # screen px per px/s


class SpeedCase(Case):
    """normal_speed(va, vb, normal): vA (white) and vB (grey) as arrows, the normal (white, between them), and
    each answer as a bar from 0 (the lesson's yellow, the student's magenta)."""

    kind = "speed"

    def lines(self):
        case, got = self.case, self.case["got"]
        return [f"{self.head()}", f"yours (magenta): {got if isinstance(got, str) else f'{got:.4g} px/s'}",
                f"the lesson's (yellow): {case['want']:.4g} px/s"]

    def draw(self, surface):
        surface.fill(BACK)
        font = text_font(20)
        a, b, middle = Vector2(230, 170), Vector2(670, 170), Vector2(450, 250)
        for start, vector, colour, name in ((a, self.case["va"], TEXT, "vA"), (b, self.case["vb"], GREY, "vB"),
                                            (middle, Vector2(self.case["normal"]) * 120, TEXT, "n")):
            arrow(surface, colour, start, start + Vector2(vector) * (1 if name == "n" else SCALE))
            surface.blit(font.render(name, True, colour), start + Vector2(-10, -28))
        for row, (value, colour) in enumerate(((self.case["want"], LESSON), (self.case["got"], STUDENT))):
            y = 360 + 30 * row
            if not isinstance(value, str):
                width = max(-440.0, min(440.0, value * SCALE))
                surface.fill(colour, (min(450, 450 + width), y, max(abs(width), 2), 16))
            surface.blit(font.render("0", True, TEXT), (446, 410))
        self.finish(surface, "bars: the speed along the normal")


def speed_cases(functions, seed):
    wrong = [c for c in data(functions, "normal_speed") or [] if "want" in c and
             (isinstance(c["got"], str) or not close(c["got"], c["want"]))]
    return numbered(SpeedCase, wrong)


CASES = {"normal_speed_right": speed_cases}
'''

CORPUS = '''"""The $title mistake corpus: plausible student files and the verdict the checker owes each one.

Every entry is a whole student file built from the CURRENT starter (starters/${lab_id}_starter.py): the
lines strictly between a step's markers are replaced by the student's code for that step; a step the
entry does not give gets the solution's code, so the corpus follows the lab when the lab changes. An
entry that changes code OUTSIDE the steps lists exact (old, new) edits (tests/mutants.py).

Verdicts (tests/corpus_verdicts.py): a CORRECT entry passes every check; a WRONG one fails `check`,
naming `step`, with a first message holding the words of `says` and the mistake id of MISTAKE_IDS.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_files import CorpusFiles, with_says  # noqa: E402  (tests/corpus_files.py: starter + steps + edits)
from corpus_entries import makers  # noqa: E402  (tests/corpus_entries.py: Entry, wrong, correct)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STARTER = os.path.join(ROOT, "starters", "${lab_id}_starter.py")
SOLUTION = os.path.join(ROOT, "solutions", "${lab_id}.py")

STEPS = (2,)
CHECK_STEP = {"loads": None, "handout_unchanged": None, "runtime_lines": None, "normal_speed_right": 2, "runs": None}
FUNCTION_CHECKS = ("normal_speed_right",)


wrong, correct = makers(CHECK_STEP)


CORRECT = [
    correct("correct_solution_steps", "the solution's own step", why="the reference build"),
    correct("correct_components", "writes the dot product out by components", {2: """
        return (vb.x - va.x) * normal.x + (vb.y - va.y) * normal.y
    """}, why="the same sums in the same order"),
    correct("correct_two_dots", "projects each velocity, then subtracts", {2: """
        return vb.dot(normal) - va.dot(normal)
    """}, why="equal up to rounding, within the check's 1e-9 relative tolerance"),
    correct("correct_vector_product", "Vector2 * Vector2, pygame's dot product", {2: """
        relative = vb - va
        return relative * normal
    """}, why="pygame's Vector2 * Vector2 is the dot product"),
]

WRONG = [
    wrong("sign_flipped", "takes vA - vB", "normal_speed_right", {2: "return (va - vb).dot(normal)"},
          why="head-on along x reads +480 instead of -480"),
    wrong("only_b", "projects vB only", "normal_speed_right", {2: "return vb.dot(normal)"},
          why="B catching up with A reads -200 instead of -150"),
    wrong("only_a", "projects vA only", "normal_speed_right", {2: "return va.dot(normal)"},
          why="B falling onto A at rest reads 0"),
    wrong("length", "the length of the relative velocity", "normal_speed_right", {2: "return (vb - va).length()"},
          why="sliding past each other reads 200 instead of 0"),
    wrong("sum", "projects vB + vA", "normal_speed_right", {2: "return (vb + va).dot(normal)"},
          why="head-on along x reads 0"),
    wrong("cross", "a cross product instead of the dot product", "normal_speed_right",
          {2: "return (vb - va).cross(normal)"}, why="head-on along x reads 0"),
    wrong("absolute", "abs() of the projection", "normal_speed_right", {2: "return abs((vb - va).dot(normal))"},
          why="an approaching pair reads positive"),
    wrong("halved", "half the projection", "normal_speed_right", {2: "return (vb - va).dot(normal) / 2"},
          why="head-on along x reads -240"),
    wrong("clamped", "keeps only approaching speeds", "normal_speed_right",
          {2: "return min(0.0, (vb - va).dot(normal))"}, why="separating along y reads 0 instead of 170"),
    wrong("x_only", "the x part of the relative velocity", "normal_speed_right", {2: "return vb.x - va.x"},
          why="B falling onto A reads 0"),
    wrong("returns_none", "computes the speed but returns nothing", "normal_speed_right", {2: """
        speed = (vb - va).dot(normal)
    """}, why="the function returns None: the checker must say it needs a number, not crash"),
    wrong("outside_scene_changed", "edits make_scene(): the first crate starts on the floor", "handout_unchanged",
          edits=[("(([200, 240], [160, 0])", "(([200, 540], [160, 0])")],
          why="code outside the steps differs from the handout"),
]

SAYS = {
    "sign_flipped": ("A's velocity relative to B's",), "only_b": ("only B's velocity",),
    "only_a": ("only A's velocity",), "length": ("the length of vB - vA",), "sum": ("vB + vA",),
    "cross": ("cross product",), "absolute": ("lost its sign",), "halved": ("halved",),
    "clamped": ("separating pair reads 0",), "x_only": ("only the x part",), "returns_none": ("a number",),
    "outside_scene_changed": ("[200, 540]",),
}
WRONG = with_says(WRONG, SAYS)

# the mistake id each entry's failing check must carry (--json's "mistake")
MISTAKE_IDS = {"sign_flipped": "normal_sign", "only_b": "normal_only_b", "only_a": "normal_only_a",
               "length": "normal_length", "sum": "normal_sum", "cross": "normal_cross", "absolute": "normal_abs",
               "halved": "normal_halved", "clamped": "normal_clamped", "x_only": "normal_x_only"}

ENTRIES = CORRECT + WRONG
BY_NAME = {entry.name: entry for entry in ENTRIES}
assert len(BY_NAME) == len(ENTRIES), "duplicate entry names"


def attack_entries(attack, control):
    """This lab's entries of the attack corpus (tests/corpus_attacks.py builds the others from the lab itself): a
    step answered from a table of the probe's fixed cases, and two honest controls in other styles."""
    from checker.labs.${lab_id}.probes import CASES, reference_normal_speed
    speeds = {(va, vb, n): reference_normal_speed(va, vb, n) for _, va, vb, n in CASES}
    assert len(speeds) >= 5, "the probe's fixed cases moved: the table would test nothing"
    return [
        attack("${lab_id}_table", "${lab_id}", "table", {2: f"""
            speeds = {speeds!r}
            return speeds.get((tuple(va), tuple(vb), tuple(normal)), 0.0)  # not in the table: the placeholder
        """}, ["normal_speed_right"], "step 2 answers the probe's fixed cases from a table; the pairs drawn for "
               "this run are not in it", needs_random_inputs=True),
        control("${lab_id}_control_zip", "${lab_id}", {2: """
            return sum(a * b for a, b in zip(vb - va, normal))
        """}, "the dot product as a sum over zip()"),
        control("${lab_id}_control_print", "${lab_id}", {2: """
            relative = vb - va
            print("relative velocity", relative)
            return relative.dot(normal)
        """}, "a debug print inside the step"),
    ]


# what tests/corpus_attacks.py needs of this lab beyond what it reads from the lab itself
ATTACK = {"entries": attack_entries}

# the wrong entry `python -m checker FILE --show` is tried on (tests/test_checker_show.py), and the kind of
# failing case --show draws for it (show.py)
SHOW_ENTRY, SHOW_CASE = "sign_flipped", "SpeedCase"

FILES = CorpusFiles(STARTER, SOLUTION, STEPS, BY_NAME, "tests/corpus_${lab_id}.py")
regions, step_code, fill, build, write_corpus = FILES.regions, FILES.step_code, FILES.fill, FILES.build, FILES.write
'''

# path under the project -> text (string.Template: $lab_id, $title)
FILES = {
    "solutions/${lab_id}.py": SOLUTION,
    "checker/labs/${lab_id}/__init__.py": INIT,
    "checker/labs/${lab_id}/checks.py": CHECKS,
    "checker/labs/${lab_id}/probes.py": PROBES,
    "checker/labs/${lab_id}/scenes.py": SCENES,
    "checker/labs/${lab_id}/show.py": SHOW,
    "tests/corpus_${lab_id}.py": CORPUS,
}
