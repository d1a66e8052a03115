"""The --show window: a recorded scene replayed with the lab's own drawing code, the solution's beside it.

The student's frames and the solution's come from checker/replay/show.py's Replay (recorded by the runtime
in the isolated child, and by a run of the solution on the grading side); they are drawn with
lesson11.physics2d.draw's draw_body and draw_contacts, the functions the labs draw with, through
RecordedBody (a recorded body that looks like a Body to them). Both runs advance in lockstep.

The lab's solver panel (lesson11/panel.py, LabPanel.draw_recorded) shows the World's settings the
replayed run had (recorded by the runtime, validated by checker/judging/lab_checks.py world_settings) and, where
they differ, the solution's; read-only: no panel key reaches it but H (its size), and it says "replay"
where the live panel has its timings. It sits where it covers the fewest moving bodies of both runs
(place_panel), never over the title or the timeline.

Keys:  P pause / play    O / Right one frame on (paused)    Left one frame back    Home the start
       J jump to the failing frame    G ghost (the solution's outlines over yours) / side by side
       Tab the scene / the failing cases    [ ] previous / next case    N next axis (SAT)
       H the solver panel: compact / full / hidden    Esc, Q quit
"""
import math
import os

import pygame
from pygame import Vector2

from lesson11.panel import MODES, LabPanel
from lesson11.physics2d.draw import draw_body, draw_contacts

from checker.replay.preview import recorded_colour
from checker.replay.show_kit import text_font as _font, wrapped

SCENE = (900, 600)          # px: the labs' window
TIMELINE_H = 130            # px: the timeline under the scene
SIDE_TOP = 120              # px: side by side, the top of the two half-size columns (their labels above it)
SIZE = (SCENE[0], SCENE[1] + TIMELINE_H)
BACKGROUND = (30, 30, 36)   # the labs' background
GHOST = (60, 235, 235)      # the solution's outlines (ghost mode) and its line on the timeline
PALETTE = ((200, 150, 90), (70, 140, 215), (120, 185, 95), (175, 120, 200), (230, 200, 80), (90, 190, 190))
STATIC = (130, 130, 140)
TEXT = (230, 230, 230)
DIM = (150, 155, 170)
BOUND = (250, 220, 80)
FAIL = (235, 60, 60)
CURSOR = (240, 240, 240)


class Shape:
    def __init__(self, kind):
        self.kind = kind


class RecordedBody:
    """One recorded body (lesson11.runtime's frame["bodies"][i]) seen through a view (scale, offset), with
    what draw_body reads: shape.kind, color, pos, radius, angle, world_points()."""

    def __init__(self, body, colour, scale=1.0, offset=(0, 0)):
        self.body, self.scale, self.offset = body, scale, Vector2(offset)
        self.shape = Shape("circle" if body.get("radius") and not body.get("points") else "polygon")
        self.color = colour
        self.pos = self.at(body["pos"])
        self.radius = (body.get("radius") or 0.0) * scale
        self.angle = body.get("angle", 0.0)

    def at(self, point):
        return Vector2(point) * self.scale + self.offset

    def world_points(self):
        return [self.at(p) for p in self.body.get("points") or ()]


class RecordedContact:
    """One recorded contact with what draw_contacts reads: point and normal (Vector2)."""

    def __init__(self, contact, scale=1.0, offset=(0, 0)):
        self.point = Vector2(contact["point"]) * scale + Vector2(offset)
        self.normal = Vector2(contact["normal"])


def _finite(body):
    """True when every coordinate of the body is a number pygame can draw (|v| < 1e6 px)."""
    values = list(body["pos"]) + [c for p in body.get("points") or () for c in p] + [body.get("radius") or 0.0]
    return all(math.isfinite(v) and abs(v) < 1e6 for v in values)


def bodies_of(frame, scale=1.0, offset=(0, 0)):
    """The frame's bodies as RecordedBody in the lab's own colours (recorded; a record without them: grey
    statics, a colour per moving body); a sleeping body darker, as the labs draw one."""
    shown, moving = [], 0
    for body in (frame or {}).get("bodies", ()):
        if not _finite(body):
            continue
        colour = recorded_colour(body)
        if body.get("static"):
            colour = colour or STATIC
        else:
            colour = colour or PALETTE[moving % len(PALETTE)]
            colour = tuple(int(c * 0.45) for c in colour) if body.get("asleep") else colour
            moving += 1
        shown.append(RecordedBody(body, colour, scale, offset))
    return shown


class Viewer:
    """The replay's state and drawing, without the event loop (tests drive it with handle / tick)."""

    def __init__(self, replay):
        self.replay = replay
        self.index = 0
        self.playing = bool(replay.frames)
        self.side_by_side = False
        self.case_index = 0
        self.showing_cases = bool(replay.cases) and not replay.graded
        self.font = _font(22)
        self.small = _font(18)
        self.panel = LabPanel()   # draws the recorded settings only (draw_recorded): never handed an event
        self.panel_at = {}        # (panel size, side by side, top) -> its top-left corner (px), chosen once

    # ---- what is shown
    @property
    def frame(self):
        """The student's recorded frame on screen (None when the scene was not recorded)."""
        return self.replay.frames[self.index] if self.replay.frames else None

    @property
    def reference_frame(self):
        """The solution's recorded frame with the same frame number (lockstep)."""
        return self.replay.reference_at(self.frame["frame"]) if self.frame else None

    @property
    def case(self):
        return self.replay.cases[self.case_index] if self.replay.cases else None

    # ---- input
    def handle(self, event):
        """Apply one event; False when the window should close."""
        if event.type == pygame.QUIT:
            return False
        if event.type != pygame.KEYDOWN:
            return True
        key = event.key
        if key in (pygame.K_ESCAPE, pygame.K_q):
            return False
        if key == pygame.K_TAB and self.replay.cases:
            self.showing_cases = not self.showing_cases or not self.replay.frames
        elif self.showing_cases and key in (pygame.K_RIGHTBRACKET, pygame.K_LEFTBRACKET):
            step = 1 if key == pygame.K_RIGHTBRACKET else -1
            self.case_index = (self.case_index + step) % len(self.replay.cases)
        elif self.showing_cases and self.case is not None and self.case.key(key):
            pass
        elif key == pygame.K_p:
            self.playing = not self.playing and bool(self.replay.frames)
        elif key in (pygame.K_o, pygame.K_RIGHT):
            self.playing = False
            self.index = min(self.index + 1, max(len(self.replay.frames) - 1, 0))
        elif key == pygame.K_LEFT:
            self.playing = False
            self.index = max(self.index - 1, 0)
        elif key == pygame.K_HOME:
            self.index = 0
        elif key == pygame.K_j and self.replay.fail_frame is not None:
            self.playing = False
            self.showing_cases = False
            self.index = self.replay.index_of(self.replay.fail_frame)
        elif key == pygame.K_g:
            self.side_by_side = not self.side_by_side
        elif key == pygame.K_h:
            self.panel.mode = MODES[(MODES.index(self.panel.mode) + 1) % len(MODES)]
        return True

    def tick(self):
        """One displayed frame: the replay moves on one recorded frame while it plays (stops at the end)."""
        if self.playing and self.replay.frames:
            if self.index + 1 < len(self.replay.frames):
                self.index += 1
            else:
                self.playing = False

    # ---- drawing
    def draw(self, surface):
        surface.fill(BACKGROUND)
        if self.showing_cases and self.case is not None:
            self.case.draw(surface.subsurface((0, 0) + SCENE))
        elif self.frame is None:
            _text(surface, self.font, "no scene was recorded for this check: Tab shows its failing cases"
                  if self.replay.cases else "no scene was recorded for this check", (20, 60))
        elif self.side_by_side:
            self.draw_side_by_side(surface)
        else:
            self.draw_ghost(surface)
        self.draw_hud(surface)
        if self.frame is not None and not (self.showing_cases and self.case is not None):
            self.draw_panel(surface)
        self.draw_timeline(surface, pygame.Rect(0, SCENE[1], SIZE[0], TIMELINE_H))

    def hud_bottom(self):
        """The y (px) below the title and keys lines."""
        return 12 + 22 * max(len(self.hud_lines()), 1) + 6

    def draw_panel(self, surface):
        """The lab's solver panel with the settings of the frame on screen, the solution's where they differ."""
        mine, theirs = self.replay.settings_at(self.index)
        note = self.replay.settings_note
        if self.panel.mode == "hidden":
            label = "[H] show the solver panel"
            _text(surface, self.small, label, (SCENE[0] - 10 - self.small.size(label)[0], self.hud_bottom()), DIM)
            self.panel.box = None
            return
        size = self.panel.recorded_size(mine, theirs, note)
        key = (size, self.side_by_side, self.hud_bottom())
        if key not in self.panel_at:
            self.panel_at[key] = place_panel(self.replay, size, key[2], self.side_by_side)
        self.panel.draw_recorded(surface, mine, theirs, note, self.panel_at[key], GHOST)

    def draw_ghost(self, surface):
        """The student's bodies (filled, as the lab draws them), the solution's as GHOST outlines over them."""
        for body in bodies_of(self.frame):
            draw_body(surface, body)
        draw_contacts(surface, [RecordedContact(c) for c in self.frame.get("touching", ())])
        for body in bodies_of(self.reference_frame):
            if not body.body.get("static"):
                _outline(surface, body, GHOST)

    def draw_side_by_side(self, surface):
        """Yours on the left, the solution's on the right, each at half size."""
        scale = 0.5
        top = SIDE_TOP
        for column, (frame, label) in enumerate(((self.frame, "yours"), (self.reference_frame, "the solution"))):
            offset = (column * SCENE[0] / 2, top)
            pygame.draw.rect(surface, (40, 40, 48), (offset[0], top, SCENE[0] / 2, SCENE[1] / 2))
            for body in bodies_of(frame, scale, offset):
                draw_body(surface, body)
            draw_contacts(surface, [RecordedContact(c, scale, offset) for c in (frame or {}).get("touching", ())],
                          length=10)
            _text(surface, self.font, label, (offset[0] + 10, top - 26), GHOST if column else TEXT)
        pygame.draw.line(surface, DIM, (SCENE[0] / 2, top), (SCENE[0] / 2, top + SCENE[1] / 2), 1)

    def hud_lines(self):
        """The title (lab, check, scene, frame, mode), broken at " | " to fit the window, and the keys line;
        [] while the cases are on screen (they have their own text)."""
        replay, frame = self.replay, self.frame
        if frame is None or (self.showing_cases and self.case is not None):
            return []
        mode = "side by side" if self.side_by_side else "ghost: the solution in cyan"
        head = f"{replay.lab.title} - {replay.check.id} ({replay.check.status}) | '{replay.scene}'" \
               f"{'' if replay.graded else ' ungraded'} | frame {frame['frame']} ({frame['frame'] / 60:.2f} s)" \
               f"{'' if self.playing else ' PAUSED'} | {mode}" + (f" | {replay.spliced}" if replay.spliced else "")
        rows = wrapped(self.font, [head], SCENE[0] - 30, " | ")
        keys = "P pause  O / Right one frame on  Left one back  Home start  J the failing frame  G ghost / side by " \
            "side  H panel" + ("  Tab cases" if replay.cases else "") + "  Esc quit"
        return [rows[0]] + ["| " + row for row in rows[1:]] + [keys]

    def draw_hud(self, surface):
        lines = self.hud_lines()
        for row, line in enumerate(lines[:-1]):
            _text(surface, self.font, line, (10, 8 + 22 * row))
        if lines:
            _text(surface, self.small, lines[-1], (10, 12 + 22 * (len(lines) - 1)), DIM)

    def draw_timeline(self, surface, rect):
        """The quantity per frame, its bound (a line), the failing frame (red) and the frame on screen."""
        replay = self.replay
        pygame.draw.rect(surface, (18, 18, 22), rect)
        frames = replay.frames
        if not frames:
            return
        plot = rect.inflate(-130, -46)
        plot.left = rect.left + 40
        plot.top = rect.top + 26
        first, last = frames[0]["frame"], max(frames[-1]["frame"], frames[0]["frame"] + 1)
        values = [v for v in replay.values if math.isfinite(v)]
        bound = replay.quantity.bound if replay.quantity else None
        low = min(values + [0.0] + ([bound] if bound is not None else []))
        high = max(values + [1e-9] + ([bound] if bound is not None else []))
        high = high + (high - low) * 0.1 or 1.0

        def x_of(number):
            return plot.left + (number - first) / (last - first) * plot.width

        def y_of(value):
            return plot.bottom - (value - low) / (high - low) * plot.height

        pygame.draw.rect(surface, (40, 40, 48), plot, 1)
        points = [(x_of(f["frame"]), y_of(v)) for f, v in zip(frames, replay.values) if math.isfinite(v)]
        if len(points) > 1:
            pygame.draw.lines(surface, TEXT, False, points, 2)
        if bound is not None:
            pygame.draw.line(surface, BOUND, (plot.left, y_of(bound)), (plot.right, y_of(bound)), 1)
            _text(surface, self.small, f"bound {bound:g}", (plot.right + 4, y_of(bound) - 7), BOUND)
        if replay.fail_frame is not None:
            x = x_of(replay.fail_frame)
            pygame.draw.line(surface, FAIL, (x, plot.top - 4), (x, plot.bottom + 4), 2)
            _text(surface, self.small, f"failing frame {replay.fail_frame} (J)", (x + 4, plot.bottom + 4), FAIL)
        if self.frame is not None:
            x = x_of(self.frame["frame"])
            pygame.draw.line(surface, CURSOR, (x, plot.top), (x, plot.bottom), 1)
        label = replay.quantity.label if replay.quantity else "(no quantity for this check)"
        value = replay.values[self.index] if replay.values else None
        shown = f": {value:.3g} now" if value is not None and math.isfinite(value) else ""
        _text(surface, self.small, f"{label}{shown}   frames {first}-{frames[-1]['frame']}", (plot.left, rect.top + 6))


def _boxes(frame, scale=1.0, offset=(0, 0)):
    """The bounding rectangles (px, on screen) of a recorded frame's moving bodies."""
    boxes = []
    for body in bodies_of(frame, scale, offset):
        if body.body.get("static"):
            continue
        points = body.world_points() or [body.pos - Vector2(body.radius), body.pos + Vector2(body.radius)]
        xs, ys = [p.x for p in points], [p.y for p in points]
        boxes.append(pygame.Rect(min(xs), min(ys), max(xs) - min(xs) + 1, max(ys) - min(ys) + 1))
    return boxes


def place_panel(replay, size, top, side_by_side=False):
    """Where the solver panel goes (its top-left, px): of the scene's four corners below the title (`top`; side
    by side, below the columns' labels) and above the timeline, the one whose rectangle covers the least of the
    moving bodies of both runs over all frames (px² of their boxes; side by side, as drawn there: half size, from
    y SIDE_TOP). On a tie the lab's own corner, top right (side by side: the bottom corners first, under the
    columns, where a compact panel fits).

    A full panel (H) side by side fits nowhere whole: it goes where it covers least.
    """
    width, height = size
    right, left = SCENE[0] - 10 - width, 10
    top = max(top, SIDE_TOP) if side_by_side else top
    bottom = max(top, SCENE[1] - 6 - height)
    corners = [(right, bottom), (left, bottom), (right, top), (left, top)] if side_by_side else \
        [(right, top), (left, top), (right, bottom), (left, bottom)]
    view = [(0.5, (0, SIDE_TOP)), (0.5, (SCENE[0] / 2, SIDE_TOP))] if side_by_side else [(1.0, (0, 0))] * 2
    boxes = [box for frame in replay.frames for box in _boxes(frame, *view[0])] + \
        [box for frame in replay.reference for box in _boxes(frame, *view[1])]

    def covered(at):   # px² of moving bodies' boxes under the panel, summed over the frames
        panel = pygame.Rect(at, size)
        return sum(panel.clip(boxes[i]).width * panel.clip(boxes[i]).height for i in panel.collidelistall(boxes))

    return min(corners, key=lambda at: (covered(at), corners.index(at)))


def _outline(surface, body, colour):
    if body.shape.kind == "circle":
        pygame.draw.circle(surface, colour, body.pos, max(body.radius, 2), 2)
    elif len(body.world_points()) >= 3:
        pygame.draw.polygon(surface, colour, body.world_points(), 2)


def _text(surface, font, words, pos, colour=TEXT):
    surface.blit(font.render(words, True, colour), pos)


def run(replay, events=None, frames=None, screen=None):
    """Open the window and replay until it is closed (or for `frames` displayed frames). Returns the Viewer.

    events: a callable returning this frame's events (default pygame.event.get; tests script keys).
    With a driver that shows nothing (dummy, offscreen) and no `frames`, the replay plays once and stops.
    """
    from checker.replay.pictures import USER_VIDEO_DRIVER
    if USER_VIDEO_DRIVER is None:   # checker/replay/pictures.py set "dummy" for its own drawing: the window needs the desktop
        os.environ.pop("SDL_VIDEODRIVER", None)
    if frames is None and (USER_VIDEO_DRIVER or "").lower() in ("dummy", "offscreen"):
        frames = len(replay.frames) + 1
    pygame.display.init()
    pygame.font.init()
    try:
        screen = screen or pygame.display.set_mode(SIZE)
        pygame.display.set_caption(f"checker --show: {replay.check.id}")
        viewer = Viewer(replay)
        events = events or pygame.event.get
        clock = pygame.time.Clock()
        shown = 0
        while frames is None or shown < frames:
            if not all([viewer.handle(event) for event in events()]):
                break
            viewer.tick()
            viewer.draw(screen)
            pygame.display.flip()
            if events is pygame.event.get:
                clock.tick(60)
            shown += 1
        return viewer
    finally:
        pygame.display.quit()
