"""What a check measures per frame, and the frame a failure is shown at (--show's timeline, --pictures' frames).

A behaviour check's quantity is its lab's: SERIES {check id: Quantity} in checker/labs/<id>/show.py (see
checker/labs/__init__.py), built from the measures here or its own; a check without one gets none. A function check's
scene, run ungraded, is measured by how far the student's bodies are from the solution's (DIVERGENCE).

failure(lab, result, frames, reference, graded) picks the failing frame: the frame the check's message
names, else the first frame the quantity passes its bound, else the first frame the student's run visibly
differs from the solution's (checker/replay/preview.py's VISIBLE_PX px or VISIBLE_DEG degrees).
"""
import math
import re
from dataclasses import dataclass

from lesson11 import records as metrics

from checker.replay import preview as previews

FRAME_IN_MESSAGE = re.compile(r"\bframe (\d+)\b")


@dataclass(frozen=True)
class Quantity:
    """What a check measures per frame: a label with its unit, how to measure a frame, its bound.

    measure: a frame -> a number, or a class taking the run's frames and `only` (a measure relative to the
    start, of the dynamic bodies numbered `only`, or all);
    bound: the check's bound in the same unit, or None; above: True when exceeding the bound fails;
    at_end: True when the check judges the run's end only (a frame before it may exceed the bound).
    """
    label: str
    measure: object
    bound: float | None = None
    above: bool = True
    at_end: bool = False
    only: tuple | None = None


# ---------------------------------------------------------------- measures of a recorded frame

def sink_depth(frame):
    """Deepest floor penetration (px) of any dynamic polygon in a frame (0 when none is below the floor)."""
    depths = [metrics.floor_penetration(b) for b in metrics.dynamic(frame) if len(b["points"]) >= 3]
    return max(depths + [0.0])


def top_speed(frame):
    """The fastest dynamic body's speed (px/s) in a frame."""
    return max([metrics.speed(b) for b in metrics.dynamic(frame)] + [0.0])


class Moved:
    """How far (px) the dynamic body that moved most is from where it was in the run's first frame.

    only: the indices (among the dynamic bodies) of the bodies the check reads (None: all)."""

    def __init__(self, frames, only=None):
        self.only = only
        self.start = self.chosen(frames[0]) if frames else []

    def chosen(self, frame):
        """The dynamic bodies of a frame the measure reads."""
        bodies = metrics.dynamic(frame)
        return [bodies[i] for i in self.only if i < len(bodies)] if self.only is not None else bodies

    def __call__(self, frame):
        return max([math.dist(a["pos"], b["pos"]) for a, b in zip(self.start, self.chosen(frame))] + [0.0])


FASTEST = Quantity("fastest body (px/s)", top_speed)   # a check of the whole run: how fast it went


def series_for(lab, check_id):
    """The Quantity plotted for a check of a lab (SERIES of the lab's show module), or None."""
    return getattr(lab.replay, "SERIES", {}).get(check_id)


def divergence(frame, reference):
    """How far the student's bodies are from the solution's in the same frame: the largest distance (px) between
    bodies of the same index, or the largest difference of their angles (degrees) if larger, counted in the
    same units as preview.VISIBLE_PX (infinite when the frames hold different numbers of bodies)."""
    px, deg = previews.apart(frame, reference)
    return max(px, deg * previews.VISIBLE_PX / previews.VISIBLE_DEG)


DIVERGENCE = Quantity("off the solution's (px or degrees)", None, previews.VISIBLE_PX)


# ---------------------------------------------------------------- the failing frame

def nearest(frames, number):
    """The recorded frame whose number is nearest `number`, or None."""
    if not frames:
        return None
    return min(frames, key=lambda f: abs(f.get("frame", 0) - number))


def marked_frame(result):
    """The frame number a check's message names ("... at frame 42 ..."), or None."""
    found = FRAME_IN_MESSAGE.search(getattr(result, "message", "") or "")
    return int(found.group(1)) if found else None


def _first_crossing(frames, values, quantity):
    if quantity is None or quantity.bound is None:
        return None
    if quantity.at_end:
        frames, values = frames[-1:], values[-1:]
    for frame, value in zip(frames, values):
        if (value > quantity.bound) if quantity.above else (value < quantity.bound):
            return frame["frame"]
    return None


def failure(lab, result, frames, reference, graded):
    """(failing frame or None, why that frame, Quantity or None, its value per frame) for a result's run.

    graded: the frames are the scene the check read (else a scene run ungraded for a function check,
    whose quantity is the distance from the solution's bodies).
    """
    quantity = series_for(lab, result.id) if graded else None
    if quantity is None and reference:
        quantity = DIVERGENCE
    if quantity is DIVERGENCE:
        values = [divergence(f, nearest(reference, f["frame"])) for f in frames]
    elif quantity is not None:
        measure = quantity.measure(frames, quantity.only) if isinstance(quantity.measure, type) else quantity.measure
        values = [measure(f) for f in frames]
    else:
        values = []
    values = [v if math.isfinite(v) else float("nan") for v in values]
    named = marked_frame(result) if graded else None
    if named is not None:
        return named, f"the frame the check names ({result.message})", quantity, values
    if quantity is not None and quantity is not DIVERGENCE:
        crossing = _first_crossing(frames, values, quantity)
        if crossing is not None:
            where = "at the end" if quantity.at_end else "first"
            return crossing, f"{quantity.label} {where} beyond {quantity.bound:g}", quantity, values
    differs = previews.first_visible(frames, reference) if reference else None
    if differs is not None:
        return differs, f"the first frame a body is {previews.VISIBLE_PX:g} px or {previews.VISIBLE_DEG:g} degrees " \
            "from the solution's", quantity, values
    return None, "", quantity, values
