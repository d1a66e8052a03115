"""The SAT explorer: shine the flashlight along one axis at a time.

A blue box (A) and an orange box (B). For the axis you pick, the explorer
draws both shadows (the projections of the corners onto the axis), the part
where they overlap or the gap between them, with its length, and a label
that says whether the boxes as a whole OVERLAP or are APART. The edge whose
normal is the axis is drawn thick, with a white arrow pointing along the
normal exactly as the first text line prints it. Only edge normals of the two
boxes are offered as axes, because for convex polygons those are the only
directions that need testing.

Try the lesson's experiment: move the orange box right until the label says
APART, then press Next axis until you find the axis with the gap. Predict
first: is it one of the blue box's normals or one of the orange box's?

Controls
  arrow keys          move the orange box 5 px (hold Shift for 1 px)
  drag with the mouse move the orange box
  Q / E, mouse wheel  turn the orange box by 5°
  A / D               turn the blue box by 5°
  N, Space, button    next axis (P: previous axis)
  R                   reset

The collision code is the package's own (lesson11/physics2d/collision.py):
edge_normals, project and sat. Run: python -m lesson11.explorer
To redraw the screenshots in assets/: python -m lesson11.explorer --screenshots assets
"""
import argparse
import math
import os
import sys

import pygame

from lesson11.console import safe_output
from lesson11.physics2d import (Body, TOUCH_TOLERANCE, Vector2, box_points, edge_normals, inside,
                               project, sat)

WIDTH, HEIGHT = 900, 600
MOVE_STEP = 5            # px per arrow-key press (1 px with Shift)
TURN_STEP = math.radians(5)  # rad per Q/E/A/D press or wheel notch
AXIS_OFFSET = 200        # px from the boxes' midpoint to the drawn axis line
SHADOW_GAP = 14          # px between the axis line and each shadow bar
SHADOW_WIDTH = 9         # px, thickness of a shadow bar
NORMAL_LENGTH = 30       # px, the arrow along the current axis's normal on its edge

BACKGROUND = (24, 26, 34)
BLUE = (70, 130, 235)
ORANGE = (245, 150, 40)
AXIS_GREY = (150, 155, 170)
SEPARATING = (90, 210, 120)   # an axis that separates, and the gap on it
OVERLAP_RED = (235, 80, 80)
MTV_YELLOW = (250, 220, 80)
TEXT = (230, 230, 230)
DIM_TEXT = (160, 165, 180)

BLUE_START = {"w": 150, "h": 90, "pos": (370, 300), "angle": math.radians(10)}
ORANGE_START = {"w": 90, "h": 90, "pos": (465, 255), "angle": math.radians(-30)}


class Explorer:
    """The explorer's state and drawing, without the event loop (so tests can drive it).

    blue, orange   Body objects (mass 0: the explorer only moves them by hand)
    axis_index     which of the axes() is shown, 0 .. 7 for two boxes
    """

    def __init__(self, width=WIDTH, height=HEIGHT):
        self.width, self.height = width, height
        self.button = pygame.Rect(width - 170, 16, 150, 40)
        self.font = pygame.font.Font(None, 24)
        self.big_font = pygame.font.Font(None, 56)
        self.reset()

    def reset(self):
        """Put both boxes back where they started and show the first axis."""
        self.blue = Body(box_points(BLUE_START["w"], BLUE_START["h"]), BLUE_START["pos"], 0,
                         angle=BLUE_START["angle"], color=BLUE)
        self.orange = Body(box_points(ORANGE_START["w"], ORANGE_START["h"]), ORANGE_START["pos"], 0,
                           angle=ORANGE_START["angle"], color=ORANGE)
        self.axis_index = 0
        self.dragging = False

    # ---- what the picture shows -------------------------------------------------------------

    def axes(self):
        """Every axis SAT tests: [(owner, edge number, unit normal)], blue's edges first, then orange's."""
        blue = [("blue", i, n) for i, n in enumerate(edge_normals(self.blue.world_points()))]
        orange = [("orange", i, n) for i, n in enumerate(edge_normals(self.orange.world_points()))]
        return blue + orange

    def current_axis(self):
        """(owner, edge number, unit normal) of the axis on screen."""
        return self.axes()[self.axis_index]

    def shadows(self, axis):
        """Both shadows on a unit axis and how they meet.

        Returns (blue (min, max), orange (min, max), overlap px), where
        overlap = min(max_a, max_b) - max(min_a, min_b); a negative overlap is a gap.
        """
        blue = project(self.blue.world_points(), axis)
        orange = project(self.orange.world_points(), axis)
        overlap = min(blue[1], orange[1]) - max(blue[0], orange[0])
        return blue, orange, overlap

    def separates(self, axis):
        """True if the shadows on this axis do not overlap (touching counts as apart, as in sat)."""
        return self.shadows(axis)[2] <= TOUCH_TOLERANCE

    def separating_axes(self):
        """The axes (owner, edge number, normal) whose shadows show a gap; empty while the boxes overlap."""
        return [axis for axis in self.axes() if self.separates(axis[2])]

    def hit(self):
        """physics2d's sat() for blue (A) against orange (B): None, or (normal A→B, depth px)."""
        return sat(self.blue.world_points(), self.orange.world_points())

    def status(self):
        """The big label: "OVERLAP" if every axis overlaps, else "APART"."""
        return "APART" if self.hit() is None else "OVERLAP"

    def lines(self):
        """The text lines under the label, in drawing order: what the current axis shows, and the answer."""
        owner, edge, normal = self.current_axis()
        _, _, overlap = self.shadows(normal)
        count = len(self.axes())
        lines = [f"axis {self.axis_index + 1} of {count}: the {owner} box's edge normal #{edge}, "
                 f"({normal.x + 0.0:.2f}, {normal.y + 0.0:.2f})"]
        hit = self.hit()
        if overlap > TOUCH_TOLERANCE:
            smallest = hit is not None and abs(overlap - hit[1]) <= TOUCH_TOLERANCE
            lines.append(f"on this axis the shadows overlap by {overlap:.1f} px"
                         + (": the smallest overlap of all, so this axis gives the MTV" if smallest else ""))
        else:
            lines.append(f"on this axis the shadows have a gap of {-overlap:.1f} px: it separates the boxes!")
        if hit is not None:
            normal, depth = hit
            lines.append(f"every axis overlaps, so the boxes touch. Minimum translation vector: "
                         f"{depth:.1f} px along ({normal.x + 0.0:.2f}, {normal.y + 0.0:.2f})")
        elif overlap > TOUCH_TOLERANCE:
            lines.append("the boxes are apart, so some axis has a gap. Predict: a blue normal or an orange one?"
                         " Press Next axis.")
        else:
            owners = sorted({axis[0] for axis in self.separating_axes()})
            answer = " and ".join(owners)
            lines.append(f"Answer: the gap shows on the {answer} box's normal"
                         f"{'s' if len(owners) > 1 else ''}. One gap is enough to say apart.")
        return lines

    # ---- input ------------------------------------------------------------------------------

    def next_axis(self, step=1):
        """Show the next axis (step=-1: the previous one), wrapping around."""
        self.axis_index = (self.axis_index + step) % len(self.axes())

    def handle_event(self, event):
        """React to one pygame event. Returns False for QUIT or Escape, True otherwise."""
        if event.type == pygame.QUIT:
            return False
        if event.type == pygame.KEYDOWN:
            return self.handle_key(event.key, event.mod)
        if event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            if self.button.collidepoint(event.pos):
                self.next_axis()
            elif inside(Vector2(event.pos), self.orange.world_points()):
                self.dragging = True
        elif event.type == pygame.MOUSEBUTTONUP and event.button == 1:
            self.dragging = False
        elif event.type == pygame.MOUSEMOTION and self.dragging:
            self.orange.pos += Vector2(event.rel)
        elif event.type == pygame.MOUSEWHEEL:
            self.orange.angle += TURN_STEP * event.y
        return True

    def handle_key(self, key, mod=0):
        """Keys: arrows move orange, Q/E turn orange, A/D turn blue, N/Space/P change axis, R resets."""
        step = 1 if mod & pygame.KMOD_SHIFT else MOVE_STEP
        moves = {pygame.K_LEFT: (-step, 0), pygame.K_RIGHT: (step, 0),
                 pygame.K_UP: (0, -step), pygame.K_DOWN: (0, step)}
        if key == pygame.K_ESCAPE:
            return False
        if key in moves:
            self.orange.pos += Vector2(moves[key])
        elif key == pygame.K_q:
            self.orange.angle -= TURN_STEP
        elif key == pygame.K_e:
            self.orange.angle += TURN_STEP
        elif key == pygame.K_a:
            self.blue.angle -= TURN_STEP
        elif key == pygame.K_d:
            self.blue.angle += TURN_STEP
        elif key in (pygame.K_n, pygame.K_SPACE):
            self.next_axis()
        elif key == pygame.K_p:
            self.next_axis(-1)
        elif key == pygame.K_r:
            self.reset()
        return True

    # ---- drawing ----------------------------------------------------------------------------

    def axis_anchor(self, normal):
        """A point (px) the axis line passes through: AXIS_OFFSET px sideways from the boxes, on screen.

        Of the two sides, the one whose point stays farther inside the window wins.
        """
        middle = (self.blue.pos + self.orange.pos) / 2
        side = Vector2(-normal.y, normal.x)
        candidates = [middle + side * AXIS_OFFSET, middle - side * AXIS_OFFSET]

        def room(p):
            return min(p.x, self.width - p.x, p.y, self.height - p.y)

        return max(candidates, key=room)

    def on_axis(self, value, normal, anchor, sideways=0.0):
        """The screen point (px) for axis coordinate `value` (= point·normal), moved `sideways` px off the line."""
        side = Vector2(-normal.y, normal.x)
        return anchor + normal * (value - anchor.dot(normal)) + side * sideways

    def normal_arrow(self):
        """(start, end) in px of the arrow drawn on the current axis's edge: from the edge's middle,
        NORMAL_LENGTH px along the normal exactly as the first text line prints it.

        edge_normals gives (-e.y, e.x) / |e|, which for the boxes' corner order points into the box;
        the arrow shows that direction rather than an outward one, so picture and text agree.
        """
        owner, edge, normal = self.current_axis()
        points = (self.blue if owner == "blue" else self.orange).world_points()
        middle = (points[edge] + points[(edge + 1) % len(points)]) / 2
        return middle, middle + normal * NORMAL_LENGTH

    def draw(self, surface):
        """Draw the whole picture onto `surface`."""
        surface.fill(BACKGROUND)
        owner, edge, normal = self.current_axis()
        blue_shadow, orange_shadow, overlap = self.shadows(normal)
        separating = overlap <= TOUCH_TOLERANCE
        anchor = self.axis_anchor(normal)
        # Which way is "towards the boxes" from the axis line: the blue shadow sits on that side.
        towards = 1.0 if (self.blue.pos - anchor).dot(Vector2(-normal.y, normal.x)) > 0 else -1.0

        # the axis line, green when it separates the boxes
        axis_color = SEPARATING if separating else AXIS_GREY
        pygame.draw.line(surface, axis_color, anchor - normal * 1500, anchor + normal * 1500,
                         4 if separating else 2)
        # the edge whose normal this is, drawn thick on its box
        points = (self.blue if owner == "blue" else self.orange).world_points()
        edge_a, edge_b = points[edge], points[(edge + 1) % len(points)]

        # the light rays: from each box's two extreme corners to the ends of its shadow
        shadows = ((self.blue, blue_shadow, towards * SHADOW_GAP),
                   (self.orange, orange_shadow, -towards * SHADOW_GAP))
        for body, shadow, sideways in shadows:
            for value in shadow:
                corner = min(body.world_points(), key=lambda p: abs(p.dot(normal) - value))
                dashed_line(surface, body.color, corner, self.on_axis(value, normal, anchor, sideways))

        # the boxes, and the edge whose normal is the axis (thick, with an arrow along the printed normal)
        layer = pygame.Surface(surface.get_size(), pygame.SRCALPHA)  # see-through, so overlaps show
        for body in (self.blue, self.orange):
            pygame.draw.polygon(layer, body.color + (170,), body.world_points())
        surface.blit(layer, (0, 0))
        for body in (self.blue, self.orange):
            pygame.draw.polygon(surface, body.color, body.world_points(), 2)
        pygame.draw.line(surface, TEXT, edge_a, edge_b, 5)
        draw_arrow(surface, TEXT, *self.normal_arrow(), 2)

        # the shadows: blue on the boxes' side of the line, orange on the other side
        for body, shadow, sideways in shadows:
            start = self.on_axis(shadow[0], normal, anchor, sideways)
            end = self.on_axis(shadow[1], normal, anchor, sideways)
            pygame.draw.line(surface, body.color, start, end, SHADOW_WIDTH)

        # where the shadows meet: the overlap (red) or the gap (green), with its length
        low, high = max(blue_shadow[0], orange_shadow[0]), min(blue_shadow[1], orange_shadow[1])
        if not separating:
            band_color, label = OVERLAP_RED, f"overlap {overlap:.1f} px"
        else:
            low, high = high, low
            band_color, label = SEPARATING, f"gap {-overlap:.1f} px"
        reach = SHADOW_GAP + SHADOW_WIDTH
        corners = [self.on_axis(low, normal, anchor, reach), self.on_axis(high, normal, anchor, reach),
                   self.on_axis(high, normal, anchor, -reach), self.on_axis(low, normal, anchor, -reach)]
        pygame.draw.polygon(surface, band_color, corners, 3)
        text = self.font.render(label, True, band_color)
        side = Vector2(-normal.y, normal.x)
        clearance = reach + 10 + abs(side.x) * text.get_width() / 2 + abs(side.y) * text.get_height() / 2
        label_at = self.on_axis((low + high) / 2, normal, anchor, -towards * clearance)
        surface.blit(text, text.get_rect(center=(round(label_at.x), round(label_at.y))))

        # the minimum translation vector, when they overlap: the arrow, and a ghost of where B would go
        hit = self.hit()
        if hit is not None:
            mtv_normal, depth = hit
            ghost = [p + mtv_normal * depth for p in self.orange.world_points()]
            pygame.draw.polygon(surface, MTV_YELLOW, ghost, 1)
            tip = self.orange.pos + mtv_normal * depth
            draw_arrow(surface, MTV_YELLOW, self.orange.pos, tip, 3)
            text = self.font.render(f"MTV {depth:.1f} px", True, MTV_YELLOW)
            label_at = tip + mtv_normal * (self.orange.radius + 45)  # beyond the ghost
            surface.blit(text, text.get_rect(center=(round(label_at.x), round(label_at.y))))

        # the label and the explanation lines
        status = self.status()
        big = self.big_font.render(status, True, OVERLAP_RED if status == "OVERLAP" else SEPARATING)
        surface.blit(big, (20, 16))
        for row, line in enumerate(self.lines()):
            surface.blit(self.font.render(line, True, TEXT), (20, 66 + 24 * row))
        help_text = ("arrows/drag: move orange   Q/E, wheel: turn orange   A/D: turn blue   "
                     "N/Space: next axis   R: reset")
        surface.blit(self.font.render(help_text, True, DIM_TEXT), (20, self.height - 28))

        # the Next axis button
        pygame.draw.rect(surface, (60, 64, 80), self.button, border_radius=6)
        pygame.draw.rect(surface, TEXT, self.button, 2, border_radius=6)
        caption = self.font.render("Next axis  [N]", True, TEXT)
        surface.blit(caption, caption.get_rect(center=self.button.center))


def dashed_line(surface, color, start, end, dash=6, width=1):
    """A dashed line from start to end (px), dashes `dash` px long."""
    start, end = Vector2(start), Vector2(end)
    length = start.distance_to(end)
    if length == 0:
        return
    direction = (end - start) / length
    for k in range(0, int(length), dash * 2):
        a = start + direction * k
        b = start + direction * min(k + dash, length)
        pygame.draw.line(surface, color, a, b, width)


def draw_arrow(surface, color, start, end, width=2):
    """A line from start to end (px) with a small arrowhead at end."""
    start, end = Vector2(start), Vector2(end)
    pygame.draw.line(surface, color, start, end, width)
    if start.distance_to(end) < 1:
        return
    back = (start - end).normalize() * 10
    pygame.draw.polygon(surface, color, [end, end + back.rotate(25), end + back.rotate(-25)])


def save_screenshots(folder):
    """Replay the lesson's experiment with scripted input and save two PNGs in `folder`.

    sat_explorer_overlap.png: the starting position, overlapping, on the axis of the MTV.
    sat_explorer.png: after moving orange right until APART and pressing Next
    axis until the axis with the gap shows. Returns the two paths.
    """
    surface = pygame.Surface((WIDTH, HEIGHT))
    explorer = Explorer()
    while explorer.shadows(explorer.current_axis()[2])[2] > explorer.hit()[1] + TOUCH_TOLERANCE:
        explorer.handle_key(pygame.K_n)  # step to the axis with the smallest overlap: the MTV's
    overlap_path = os.path.join(folder, "sat_explorer_overlap.png")
    explorer.draw(surface)
    pygame.image.save(surface, overlap_path)
    explorer.reset()
    while explorer.status() == "OVERLAP":
        explorer.handle_key(pygame.K_RIGHT)
    while not explorer.separates(explorer.current_axis()[2]):
        explorer.handle_key(pygame.K_n)
    apart_path = os.path.join(folder, "sat_explorer.png")
    explorer.draw(surface)
    pygame.image.save(surface, apart_path)
    return overlap_path, apart_path


def main(argv=None, frames=None):
    """Open the window and run until it is closed (or for `frames` frames). Returns the exit code."""
    safe_output()
    parser = argparse.ArgumentParser(prog="python -m lesson11.explorer", description="The SAT explorer.")
    parser.add_argument("--screenshots", metavar="FOLDER",
                        help="save sat_explorer.png and sat_explorer_overlap.png in FOLDER and exit")
    args = parser.parse_args(argv)
    pygame.display.init()  # only what the explorer needs: no sound
    pygame.font.init()
    try:
        if args.screenshots:
            if not os.path.isdir(args.screenshots):
                print(f"explorer: --screenshots needs an existing folder, got {args.screenshots!r}",
                      file=sys.stderr)
                return 2
            for path in save_screenshots(args.screenshots):
                print(f"saved {path}")
            return 0
        screen = pygame.display.set_mode((WIDTH, HEIGHT))
        pygame.display.set_caption("SAT explorer")
        pygame.key.set_repeat(300, 40)  # hold an arrow key to keep moving
        run(Explorer(), screen, frames)
        return 0
    finally:
        pygame.quit()


def run(explorer, screen, frames=None):
    """The event loop: handle events, draw, show, 60 frames a second.

    Stops when the window is closed or Escape is pressed, or after `frames`
    frames if given. Returns the number of frames drawn.
    """
    clock = pygame.time.Clock()
    running = True
    frame = 0
    while running and (frames is None or frame < frames):
        for event in pygame.event.get():
            if not explorer.handle_event(event):
                running = False
        explorer.draw(screen)
        pygame.display.flip()
        clock.tick(60)
        frame += 1
    return frame


if __name__ == "__main__":
    sys.exit(main())
