"""The paused lab window (lesson11/breakdown.py decides what broke; this draws it and waits for a key).

The frame that broke: every body, the call's two bodies outlined (A yellow, B blue) and named, its
contact point and normal, and a box of lines at the top: the function, its line, the engine phase
that called it, the error and, for a known mistake, what it means. R runs the lab again from its
file (a fix made while paused is in), Escape or the window's close button ends it. For the tests,
LESSON11_PAUSE_REPORT names a JSON file the pause writes what it shows to (and a PNG beside it), then it
presses Escape itself.
"""
import contextlib
import json
import os
import sys

import pygame

REPORT_VAR = "LESSON11_PAUSE_REPORT"   # tests: write what the pause shows to this JSON file (and a .png), then Escape
BACKGROUND = (24, 26, 34)
PANEL = (12, 14, 20, 230)
TEXT = (235, 235, 235)
DIM = (160, 165, 180)
KEY = (250, 220, 80)
ALARM = (255, 110, 90)
OUTLINE_A = (255, 210, 60)        # body A of the call (its first argument)
OUTLINE_B = (90, 200, 255)        # body B
NORMAL_LENGTH = 40                # px: the drawn normal


def body_name(body, bodies):
    """"body 4", or "body 0 (static)": its index in the World's list, as the window labels it."""
    index = next((i for i, other in enumerate(bodies) if other is body), None)
    name = f"body {index}" if index is not None else "a body"
    return name + (" (static)" if getattr(body, "inv_mass", 1) == 0 else "")


def screen_lines(finding, frame_number, seconds):
    """[(text, colour)] the pause draws, top to bottom."""
    where = f"line {finding.line}: {finding.text}" if finding.text else f"line {finding.line}"
    did = ("returned a bad value" if finding.message.startswith("returned") else "left a bad value") \
        if finding.kind == "value" else "raised an error"
    if finding.frame is None:   # nothing of the student's file to point at: a bad value found between frames
        lines = [(f"PAUSED on frame {frame_number} (t = {seconds:.2f} s): {finding.headline()}", ALARM)]
    else:
        lines = [(f"PAUSED on frame {frame_number} (t = {seconds:.2f} s): your {finding.function}() {did}", ALARM),
                 (where, TEXT)]
        if finding.phase:
            lines.append((finding.phase, DIM))
        lines.append((finding.headline() if finding.kind == "value" else finding.message, TEXT))
    if finding.meaning:
        lines.append((f"What it means: {finding.meaning}.", KEY))
    lines.append(("[R] restart the lab (after fixing your file)    [Esc] close    the terminal has the lines", DIM))
    return lines


def _wrap(font, text, width):
    words, lines = text.split(" "), []
    for word in words:
        if lines and font.size(lines[-1] + " " + word)[0] <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return lines


def draw(surface, world, finding, frame_number, font):
    """The paused frame: every body, the call's bodies outlined (A yellow, B blue, with their numbers), its
    contact point and normal, and the finding's lines in a box at the top. Returns the lines drawn."""
    from .physics2d.draw import draw_body
    surface.fill(BACKGROUND)
    bodies = world.bodies if world is not None else []
    for body in bodies:
        with contextlib.suppress(Exception):   # a body whose state is bad is not drawn (the text names it)
            draw_body(surface, body)
    for points, colour in zip(finding.polygons, (OUTLINE_A, OUTLINE_B)):
        with contextlib.suppress(Exception):
            pygame.draw.polygon(surface, colour, points, 3)
    for body, colour in zip(finding.bodies, (OUTLINE_A, OUTLINE_B)):
        with contextlib.suppress(Exception):
            _outline(surface, body, colour)
    taken = []   # where text already is, and the small bodies outlined: a body's name goes elsewhere
    for body in finding.bodies:
        with contextlib.suppress(Exception):
            if body.radius < 60:
                taken.append(pygame.Rect(0, 0, 2 * body.radius, 2 * body.radius))
                taken[-1].center = (int(body.pos.x), int(body.pos.y))
    with contextlib.suppress(Exception):
        if finding.point is not None:
            pygame.draw.circle(surface, ALARM, finding.point, 6)
            if finding.normal is not None:
                pygame.draw.line(surface, ALARM, finding.point, finding.point + finding.normal * NORMAL_LENGTH, 3)
                tip = font.render("normal", True, ALARM)
                at = finding.point + finding.normal * (NORMAL_LENGTH + 4)
                patch = tip.get_rect(topleft=(int(at.x), int(at.y)))
                surface.fill(BACKGROUND, patch.inflate(4, 2))   # readable over a body
                taken.append(surface.blit(tip, patch))
    for body, colour in zip(finding.bodies, (OUTLINE_A, OUTLINE_B)):
        with contextlib.suppress(Exception):
            taken.append(_label(surface, font.render(body_name(body, bodies), True, colour), body, taken))
    seconds = getattr(world, "time", 0.0) if world is not None else 0.0
    width = surface.get_width() - 40
    rows = [(piece, colour) for text, colour in screen_lines(finding, frame_number, seconds)
            for piece in _wrap(font, text, width)]
    height = 20 + 22 * len(rows)
    box = pygame.Surface((surface.get_width() - 20, height), pygame.SRCALPHA)
    box.fill(PANEL)
    top = 10   # at the top: what breaks is usually at the bottom, on the floor
    surface.blit(box, (10, top))
    for k, (text, colour) in enumerate(rows):
        surface.blit(font.render(text, True, colour), (20, top + 10 + 22 * k))
    return rows


def _label(surface, image, body, taken):
    """Blit a body's name beside it: above, below, right or left, the first place clear of `taken`; its rect."""
    reach = min(body.radius, 60) + 8
    x, y = int(body.pos.x), int(body.pos.y)
    places = [image.get_rect(midbottom=(x, y - reach)), image.get_rect(midtop=(x, y + reach)),
              image.get_rect(midleft=(x + reach, y)), image.get_rect(midright=(x - reach, y))]
    places = [rect.clamp(surface.get_rect()) for rect in places]
    rect = next((rect for rect in places if rect.collidelist(taken) < 0), places[0])
    surface.blit(image, rect)
    return rect


def _outline(surface, body, colour):
    if body.shape.kind == "circle":
        pygame.draw.circle(surface, colour, body.pos, max(body.radius + 2, 12), 3)   # a bullet gets a ring to see
    else:
        pygame.draw.polygon(surface, colour, body.world_points(), 3)


def pause(world, finding, frame_number):
    """Hold the window on the paused frame until Escape (or the window's close) ends the lab, or R restarts it."""
    surface = pygame.display.get_surface() if pygame.display.get_init() else None
    if surface is None:   # no window yet (the error came before it opened): the terminal has it all
        raise SystemExit(1)
    font = pygame.font.Font(None, 22)
    clock = pygame.time.Clock()
    report = os.environ.get(REPORT_VAR)
    while True:
        for event in pygame.event.get():
            if event.type == pygame.QUIT or (event.type == pygame.KEYDOWN and event.key == pygame.K_ESCAPE):
                pygame.quit()
                raise SystemExit(1)
            if event.type == pygame.KEYDOWN and event.key == pygame.K_r:
                restart()
        rows = draw(surface, world, finding, frame_number, font)
        pygame.display.flip()
        if report:
            write_report(report, surface, finding, frame_number, rows)
            report = None
            pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_ESCAPE, mod=0, unicode="\x1b"))
        clock.tick(30)


def write_report(path, surface, finding, frame_number, rows):
    """What the pause shows, for the tests: JSON at `path` and the picture at path with .png."""
    pygame.image.save(surface, os.path.splitext(path)[0] + ".png")
    with open(path, "w", encoding="utf-8") as handle:
        json.dump({"frame": frame_number, "kind": finding.kind, "function": finding.function, "line": finding.line,
                   "text": finding.text, "message": finding.message, "meaning": finding.meaning,
                   "phase": finding.phase, "window_open": pygame.display.get_surface() is not None,
                   "shown": [text for text, _ in rows]}, handle)


def restart():
    """Run the lab again from its file, as it was started (so a fix made while paused is in)."""
    pygame.quit()
    sys.stdout.flush()
    sys.stderr.flush()
    argv = getattr(sys, "orig_argv", None) or [sys.executable] + sys.argv
    os.execv(sys.executable, [sys.executable] + list(argv[1:]))
