"""The lab registry: which labs the checker knows, and how it tells which lab a file is.

Each lab is one folder, checker/labs/<lab>/:
  checks.py  its checks (CHECKS, TITLE, STARTER, SOLUTION, PROBES, STEP_LIBRARY, STEP_ADVICE,
             recognise(path, source), scenarios(), and optionally PICTURE_SCENES {check id: scene
             names} for --pictures and SCENE_SECONDS {scene name: CPU s of the solution's run}, so
             the grader starts the longest scenes first);
  probes.py  the inputs and references of its probes (REQUIRED, PROBES {name: (function, probe)},
             SPLICES): they run in the child to record a tape and again in the grader to judge it
             (checker/tape.py, checker/probing.py);
  scenes.py  its scenes' settings.
STARTER is the handout: its functions holding a step region are the student's, and the grader
replays the probes' calls of them through its code. Helpers several labs share are in
checker/probe_kit.py and checker/lab_checks.py. To add a lab, add its folder and one row to LABS.
"""
from dataclasses import dataclass

from .ball_on_ramp import checks as ball_on_ramp
from .bullets import checks as bullets
from .more_shapes import checks as more_shapes
from .sleeping_crates import checks as sleeping_crates
from .tumbling_crates import checks as tumbling_crates


@dataclass(frozen=True)
class Lab:
    """One lab: its id (used in JSON and CSV), its title, and the module holding its checks."""
    id: str
    title: str
    module: object

    @property
    def checks(self):
        return self.module.CHECKS

    def recognise(self, path, source):
        return self.module.recognise(path, source)

    def scenarios(self):
        return self.module.scenarios()

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

    @property
    def solution(self):
        """Path of the lab's reference solution (its module's SOLUTION), or None."""
        return getattr(self.module, "SOLUTION", None)

    @property
    def probes(self):
        """Import name of the module whose probes the child process runs on this lab's functions."""
        return self.module.PROBES


LABS = (
    Lab("tumbling_crates", tumbling_crates.TITLE, tumbling_crates),
    Lab("more_shapes", more_shapes.TITLE, more_shapes),
    Lab("ball_on_ramp", ball_on_ramp.TITLE, ball_on_ramp),
    Lab("bullets", bullets.TITLE, bullets),
    Lab("sleeping_crates", sleeping_crates.TITLE, sleeping_crates),
)


def identify(path, source):
    """The Lab a file belongs to, or None."""
    for lab in LABS:  # read at each call, so a lab added to LABS later is known
        if lab.recognise(path, source):
            return lab
    return None
