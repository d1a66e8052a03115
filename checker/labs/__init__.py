"""The lab registry: which labs the checker knows, found by convention, and how it tells which lab a file is.

A lab is its id and the files named from it (Lab below finds each one; no lab spells a path):
  checker/labs/<id>/checks.py  its checks (CHECKS, TITLE, STEP_LIBRARY, STEP_ADVICE, and optionally
                               recognise(path, source) where Lab.recognise's convention does not fit,
                               PICTURE_SCENES {check id: scene names} for --pictures and SCENE_SECONDS
                               {scene name: CPU s of the solution's run}, so the grader starts the longest
                               scenes first);
  checker/labs/<id>/probes.py  the inputs and references of its probes (REQUIRED, PROBES {name: (function,
                               probe)}, SPLICES): they run in the child to record a tape and again in the
                               grader to judge it (checker/judging/tape.py, checker/judging/probing.py);
  checker/labs/<id>/scenes.py  its scenes: SCENARIOS {name: settings builder}, and what they measure;
  checker/labs/<id>/show.py    optional, what --show and --pictures draw for its checks: SERIES {check id:
                               checker.replay.show_series.Quantity} (a behaviour check's quantity per frame) and
                               CASES {check id: cases(functions, seed) -> [case]} (a failed function check's
                               failing cases, drawn with checker/replay/show_kit.py); a check it does not name gets
                               no plot and no case drawing;
  starters/<id>_starter.py     the handout: its functions holding a step region are the student's, and the
                               grader replays the probes' calls of them through its code;
  solutions/<id>.py            the reference solution (probes splice its steps in; --pictures draws its runs).
To add a lab, add those files (checker/README.md, "Writing a lab"; `python -m checker lint-lab ID` states the rules
they keep): every folder here holding a checks.py is a lab. Helpers several labs share are
in checker/judging/probe_kit.py and checker/judging/lab_checks.py.
"""
import importlib
import importlib.util
import os
from dataclasses import dataclass

from checker.project import PROJECT_ROOT   # the folder holding checker/, starters/ and solutions/

HERE = os.path.dirname(os.path.abspath(__file__))
STARTERS, SOLUTIONS = "starters", "solutions"   # the project's folders of the handouts and of the solutions
ORDER = ("tumbling_crates", "more_shapes", "ball_on_ramp", "bullets", "sleeping_crates")   # the lesson's order;
# a lab not named here comes after these, by id (the order of --list and of identify())


@dataclass(frozen=True)
class Lab:
    """One lab, found from its id (used in JSON and CSV): its modules under checker/labs/<id>/, its starter and
    solution under `root` (the project; a test may give another folder)."""
    id: str
    root: str = PROJECT_ROOT

    def _module(self, name):
        return importlib.import_module(f"{__name__}.{self.id}.{name}")

    @property
    def module(self):
        """The module holding the lab's checks (checker/labs/<id>/checks.py)."""
        return self._module("checks")

    @property
    def scenes(self):
        """The module holding the lab's scenes (checker/labs/<id>/scenes.py)."""
        return self._module("scenes")

    @property
    def replay(self):
        """The module saying what --show draws for the lab's checks (checker/labs/<id>/show.py), or None."""
        name = f"{__name__}.{self.id}.show"
        return importlib.import_module(name) if importlib.util.find_spec(name) is not None else None

    @property
    def probes(self):
        """Import name of the module whose probes the child process runs on this lab's functions."""
        return f"{__name__}.{self.id}.probes"

    @classmethod
    def of_solution(cls, path):
        """The lab whose reference solution is `path` (solutions/<id>.py: the id is the file's name)."""
        return cls(os.path.splitext(os.path.basename(path))[0])

    @property
    def starter_file(self):
        """File name of the lab's handout, <id>_starter.py."""
        return f"{self.id}_starter.py"

    @property
    def starter(self):
        """Path of the lab's handout, starters/<id>_starter.py."""
        return os.path.join(self.root, STARTERS, self.starter_file)

    @property
    def solution(self):
        """Path of the lab's reference solution, solutions/<id>.py."""
        return os.path.join(self.root, SOLUTIONS, f"{self.id}.py")

    @property
    def title(self):
        return self.module.TITLE

    @property
    def checks(self):
        return self.module.CHECKS

    def recognise(self, path, source):
        """True if the file is this lab's: evidence(path, source) above 0."""
        return self.evidence(path, source) > 0

    def evidence(self, path, source):
        """How strongly the file says it is this lab's: 3 if its module's recognise(path, source) says so or, by
        convention, the file's name holds the lab's id; 2 if the file opens with a docstring starting with the
        lab's title; 1 if its text holds the title anywhere (any case); else 0."""
        own = getattr(self.module, "recognise", None)
        if own is not None:
            return 3 if own(path, source) else 0
        name = path.replace("\\", "/").rsplit("/", 1)[-1].lower()
        if self.id in name:
            return 3
        text = source.lower()
        if text.lstrip().startswith(('"""' + self.title.lower(), "'''" + self.title.lower())):
            return 2
        return 1 if self.title.lower() in text else 0

    def scenarios(self):
        """The scenario runs this lab needs, by name (settings for lesson11.runtime.configure)."""
        return {name: build() for name, build in self.scenes.SCENARIOS.items()}

    def scene_seconds(self, name, settings):
        """How long (CPU s) scene `name` is expected to run, for the grader's longest-first order.

        The module's SCENE_SECONDS[name] (measured with the lab's solution), else
        the scene's simulated time, frames / fps.
        """
        known = getattr(self.module, "SCENE_SECONDS", {})
        if name in known:
            return known[name]
        return settings.get("frames", 0) / settings.get("fps", 60)

    @property
    def picture_scenes(self):
        """{check id: (scene name, ...)}: the scenes a behaviour check reads (its module's PICTURE_SCENES)."""
        return getattr(self.module, "PICTURE_SCENES", {})

    @property
    def preview_scene(self):
        """The scene drawn, ungraded, for a file that failed a function check (its scenes never ran): the first
        scene the 'runs' check reads, else the lab's first scene."""
        return (self.picture_scenes.get("runs") or tuple(self.scenarios()) or (None,))[0]


def found(folder=HERE):
    """The ids of the labs in `folder`: its sub-folders holding a checks.py, in ORDER, then the others by id."""
    ids = sorted(name for name in os.listdir(folder)
                 if not name.startswith(("_", ".")) and os.path.isfile(os.path.join(folder, name, "checks.py")))
    return sorted(ids, key=lambda lab_id: (ORDER.index(lab_id) if lab_id in ORDER else len(ORDER), lab_id))


LABS = tuple(Lab(lab_id) for lab_id in found())


def identify(path, source):
    """The Lab a file belongs to, or None: the lab with the strongest evidence (Lab.evidence), the first in the
    lesson's order on a tie; so a file that opens with one lab's title and names another in a comment is the first's."""
    best, strength = None, 0
    for lab in LABS:  # read at each call, so a lab added to LABS later is known
        found = lab.evidence(path, source)
        if found > strength:
            best, strength = lab, found
    return best
