"""Pictures of what happened: a filmstrip PNG for each failed behaviour check.

A behaviour check reads recorded scenes; each lab module says which ones in
PICTURE_SCENES {check id: (scene name, ...)}. When such a check fails (or
errs) and the LabReport kept its records (Grader(keep_records=True)), this
module draws the scene from the recorded frames, headless, with pygame:
FRAMES frames spread over the run, the bodies' outlines (static grey, moving
in colours, asleep paler, outlines over the fills), every contact point as a red dot with its normal, and
under it the lab's reference solution running the same scene (run once per
process and scene, then cached). The pictures follow the failure: the frames
run from LEAD frames before the failing frame (checker/replay/show_series.py failure(): the
frame the message names, "... at frame 42 ...", else the first frame the check's
quantity passes its bound, else the first frame the run differs from the
solution's) to TRAIL frames after it, that frame is framed in red in both rows,
the tiles are framed on the bodies the failure is about, and the caption names
the frame and the quantity there.

Nothing here knows a lab: the scenes come from PICTURE_SCENES, the reference
from the lab module's SOLUTION, the settings from its scenarios().

Entry points:
  pictures_for(report, check_id)  -> [Picture(check_id, scene, png bytes)]
  prairielearn_images(report, check_id) -> [{"label", "url": "data:image/png;base64,..."}]
  base64_pngs(report, check_id)   -> [base64 str]
  write_pictures(rows, folder)    -> {row path: {check id: [written paths]}}
"""
import base64
import io
import os
import re
from dataclasses import dataclass

# the video driver the user's environment named (None: SDL picks the desktop's), before the pictures' own default:
# --show (checker/replay/show.py) opens its window with it
USER_VIDEO_DRIVER = os.environ.get("SDL_VIDEODRIVER")
os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402

from checker.replay.preview import recorded_colour, reference_record   # noqa: E402,F401 (reference_record: used here, and by callers)
from checker.replay.show_kit import text_font as _font   # noqa: E402
from checker.replay.show_series import failure, nearest as _nearest   # noqa: E402

FRAMES = 6                 # frames per row
TILE = (220, 150)          # px of one frame (the 900 × 600 scene drawn at about 1/4)
WORLD = (0, 0, 900, 600)   # px: the labs' window, shown when no body moves
MARGIN = 40                # px around the moving bodies
MIN_VIEW = (300, 200)      # px: the smallest part of the scene a tile shows
LEAD, TRAIL = 30, 30       # frames shown before and after the failing frame (0.5 s each at 60 fps)
FPS = 60
LABEL_H = 18
HEAD_H = 22
GAP = 4
BACKGROUND = (250, 250, 247)
SKY = (236, 240, 246)
STATIC = (120, 124, 134)
MOVING = (70, 140, 215)    # the first moving body; the others take the next colours (asleep: paler)
PALETTE = (MOVING, (235, 150, 60), (120, 185, 95), (175, 120, 200), (230, 200, 80), (90, 190, 190))
OUTLINE = (25, 25, 30)
CONTACT = (225, 40, 40)
MARK = (220, 30, 30)
TEXT = (30, 30, 35)
FAILED = ("fail", "error")


@dataclass
class Picture:
    """One PNG: the check it shows, the scene drawn, and the bytes."""
    check_id: str
    scene: str
    png: bytes

    @property
    def base64(self):
        return base64.b64encode(self.png).decode("ascii")

    @property
    def data_url(self):
        return "data:image/png;base64," + self.base64


# the reference solution's runs: checker/replay/preview.py reference_record (one child run per process and scene, cached)


# ---------------------------------------------------------------- drawing

def _view(frames, focus=None):
    """(left, top, width, height) in px: around every moving body shown (40 px margin, at least MIN_VIEW px),
    or only the bodies whose indices are in `focus` (the bodies the check is about), in the tile's shape;
    the labs' whole window when nothing moves."""
    xs, ys = [], []
    for frame in frames:
        for index, body in enumerate(frame.get("bodies", ())):
            if body.get("static") or (focus and index not in focus):
                continue
            r = _radius(body)
            points = body.get("points") or [body["pos"]]
            for x, y in points:
                if abs(x) < 1e5 and abs(y) < 1e5:
                    xs += [x - r, x + r]
                    ys += [y - r, y + r]
    if not xs:
        left, top, right, bottom = WORLD
    else:
        left, top, right, bottom = min(xs) - MARGIN, min(ys) - MARGIN, max(xs) + MARGIN, max(ys) + MARGIN
    width, height = max(right - left, MIN_VIEW[0]), max(bottom - top, MIN_VIEW[1])
    cx, cy = (left + right) / 2, (top + bottom) / 2
    aspect = TILE[0] / TILE[1]
    if width / height < aspect:   # keep the tile's shape: widen or heighten around the centre
        width = height * aspect
    else:
        height = width / aspect
    return cx - width / 2, cy - height / 2, width, height


def _pick(frames, marked=None, count=FRAMES):
    """`count` recorded frames spread evenly, the marked frame (a frame number) among them: from LEAD frames
    before the marked frame to TRAIL frames after it (the run's first to last frame when none is marked)."""
    if not frames:
        return []
    if marked is not None:
        window = [f for f in frames if marked - LEAD <= f.get("frame", 0) <= marked + TRAIL]
        frames = window or frames
    n = len(frames)
    indices = sorted({round(i * (n - 1) / max(count - 1, 1)) for i in range(min(count, n))})
    if marked is not None:
        at = min(range(n), key=lambda i: abs(frames[i].get("frame", i) - marked))
        if at not in indices:
            nearest = min(range(len(indices)), key=lambda k: abs(indices[k] - at))
            indices[nearest] = at
            indices.sort()
    return [frames[i] for i in indices]


def _radius(body):
    """A body's radius in px when the record holds a finite one below 1e5 (the child wrote it), else 0."""
    r = body.get("radius")
    return r if isinstance(r, (int, float)) and not isinstance(r, bool) and 0 < r < 1e5 else 0.0


def _pair(value):
    return isinstance(value, list) and len(value) == 2 and all(
        isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)


def _draw_frame(surface, rect, frame, view, marked):
    """Draw one recorded frame into rect (a pygame.Rect) of surface, seen through view."""
    left, top, width, height = view
    scale = rect.width / width
    clip = surface.get_clip()
    surface.set_clip(rect)
    surface.fill(SKY, rect)

    def at(p):
        return (rect.x + (p[0] - left) * scale, rect.y + (p[1] - top) * scale)

    if frame is None:
        surface.blit(_font(16).render("no frame", True, TEXT), (rect.x + 6, rect.y + 6))
    else:
        moving = 0
        outlines = []
        for body in frame.get("bodies", ()):
            if not all(abs(v) < 1e6 for v in body["pos"]):
                continue
            own = recorded_colour(body)   # the lab's own colour, when the record holds one
            if body.get("static"):
                fill = own or STATIC
            else:
                fill = own or PALETTE[moving % len(PALETTE)]
                fill = tuple((c + 255) // 2 for c in fill) if body.get("asleep") else fill
                moving += 1
            points = body.get("points") or []
            if len(points) >= 3:
                corners = [at(p) for p in points]
                pygame.draw.polygon(surface, fill, corners)
                outlines.append(("polygon", corners))
            elif _radius(body):
                centre = at(body["pos"])
                r = max(2, round(_radius(body) * scale))
                pygame.draw.circle(surface, fill, centre, r)
                spoke = pygame.Vector2(1, 0).rotate_rad(body.get("angle", 0.0)) * r
                outlines.append(("circle", (centre, r, (centre[0] + spoke.x, centre[1] + spoke.y))))
        for kind, shape in outlines:   # after every fill, so an overlap shows as crossing outlines
            if kind == "polygon":
                pygame.draw.polygon(surface, OUTLINE, shape, 1)
            else:
                centre, r, tip = shape
                pygame.draw.circle(surface, OUTLINE, centre, r, 1)
                pygame.draw.line(surface, OUTLINE, centre, tip, 1)
        for contact in frame.get("touching") or ():   # the child wrote these: drawn only when they are numbers
            point, normal = (contact.get("point"), contact.get("normal")) if isinstance(contact, dict) else (0, 0)
            if not (_pair(point) and _pair(normal) and all(abs(v) < 1e6 for v in point + normal)):
                continue
            p = at(point)
            pygame.draw.line(surface, CONTACT, p, (p[0] + normal[0] * 9, p[1] + normal[1] * 9), 1)
            pygame.draw.circle(surface, CONTACT, p, 2)
    surface.set_clip(clip)
    if marked:
        pygame.draw.rect(surface, MARK, rect.inflate(4, 4), 3)


def filmstrip(record, reference=None, marked=None, title="", count=FRAMES, focus=None):
    """A pygame Surface: the run's frames in a row (and the reference's same frames below), labelled.

    record / reference: lesson11.runtime records ({"records": [frame, ...]});
    marked: the frame number of the failure, if known (the frames then run from a little before it to a
    little after); focus: the indices of the bodies to frame (None: every moving body).
    """
    frames = (record or {}).get("records") or []
    shown = _pick(frames, marked, count)
    ref_frames = (reference or {}).get("records") or []
    rows = [("yours", shown)]
    if ref_frames:
        rows.append(("solution", [_nearest(ref_frames, f.get("frame", 0)) for f in shown]))
    view = _view(shown + [f for f in rows[-1][1] if f is not None], focus)
    label_w = 70
    width = label_w + len(shown) * (TILE[0] + GAP) + GAP
    small, big = _font(16), _font(19)
    titles = _title_lines(big, title, max(width, 320) - 2 * GAP - 4)
    head = HEAD_H + (len(titles) - 1) * (HEAD_H - 4)
    height = head + len(rows) * (TILE[1] + LABEL_H + GAP) + GAP
    surface = pygame.Surface((max(width, 320), height))
    surface.fill(BACKGROUND)
    for k, line in enumerate(titles):
        surface.blit(big.render(line, True, TEXT), (GAP + 2, 4 + k * (HEAD_H - 4)))
    marked_at = min(shown, key=lambda f: abs(f.get("frame", 0) - marked)).get("frame") \
        if marked is not None and shown else None
    for r, (name, row) in enumerate(rows):
        y = head + r * (TILE[1] + LABEL_H + GAP)
        surface.blit(small.render(name, True, TEXT), (GAP + 2, y + LABEL_H + TILE[1] // 2 - 6))
        for k, frame in enumerate(row):
            x = label_w + k * (TILE[0] + GAP)
            number = shown[k].get("frame", 0)
            is_marked = marked_at is not None and number == marked_at
            label = f"frame {number}  t = {number / FPS:.2f} s" + ("  <- here" if is_marked and r == 0 else "")
            surface.blit(small.render(label, True, MARK if is_marked else TEXT), (x + 2, y + 3))
            _draw_frame(surface, pygame.Rect(x, y + LABEL_H, TILE[0], TILE[1]), frame, view, is_marked)
    return surface


def _title_lines(font, title, width):
    """The title broken after "; " where it is wider than `width` px (a piece wider alone stays whole)."""
    lines, current = [], ""
    for piece in re.split(r"(?<=;) ", title):
        joined = f"{current} {piece}" if current else piece
        if current and font.size(joined)[0] > width:
            lines.append(current)
            current = piece
        else:
            current = joined
    return lines + [current]


def png_bytes(surface):
    """The surface as PNG bytes (pygame.image.save into memory)."""
    buffer = io.BytesIO()
    pygame.image.save(surface, buffer, "picture.png")
    return buffer.getvalue()


# ---------------------------------------------------------------- per check

def pictured_results(report):
    """The results of a report that get a picture: failed behaviour checks whose scenes were recorded, and,
    when the report ran its lab's scene ungraded (report.preview), the first failed check."""
    lab = getattr(report, "lab", None)
    scenes = getattr(lab, "picture_scenes", None) or {}
    records = getattr(report, "records", None) or {}
    results = getattr(report, "results", ())
    found = [r for r in results if r.status in FAILED and any(s in records for s in scenes.get(r.id, ()))]
    first = next((r for r in results if r.status in FAILED), None)
    if getattr(report, "preview", "") in records and first is not None and first not in found:
        found.insert(0, first)
    return found


def _scenes_of(report, check_id):
    """The recorded scenes to draw for a check: those it reads, else the ungraded preview scene."""
    scenes = report.lab.picture_scenes.get(check_id, ())
    if any(scene in report.records for scene in scenes):
        return scenes, False
    preview = getattr(report, "preview", "")
    return ((preview,), True) if preview else ((), False)


def focus_bodies(frame, reference):
    """Indices of the moving bodies a failure is about in a frame: those more than preview.VISIBLE_PX from the
    solution's body of the same index, else every moving body."""
    from checker.replay.preview import VISIBLE_PX as VISIBLE
    moving = [i for i, b in enumerate((frame or {}).get("bodies", ())) if not b.get("static")]
    if reference is None or len(reference.get("bodies", ())) != len(frame.get("bodies", ())):
        return set(moving)
    apart = {i for i in moving if _distance(frame["bodies"][i]["pos"], reference["bodies"][i]["pos"]) > VISIBLE}
    return apart or set(moving)


def _distance(a, b):
    return ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5


def caption(check_id, scene, title, ungraded, fail_frame, quantity, value, spliced=""):
    """The filmstrip's title: the check, the scene (and what ran, when the preview spliced the lesson's other
    steps in: checker/replay/preview.py), the failing frame and the check's quantity there."""
    head = (f"not graded, to show what {check_id} means: " if ungraded else f"{check_id}: ") + \
        f"scene '{scene}' ({title})" + (f", {spliced}" if spliced else "")
    if fail_frame is not None:
        head += f"; frame {fail_frame} (t = {fail_frame / FPS:.2f} s)"
        if quantity is not None and value is not None:
            bound = f", bound {quantity.bound:g}" if quantity.bound is not None else ""
            head += f": {quantity.label} {value:.3g}{bound}"
    return head + "; top: this file, bottom: the solution"


def pictures_for(report, check_id, with_reference=True):
    """[Picture] for one failed behaviour check of a report: one filmstrip per scene it reads ([] otherwise).

    Each filmstrip runs from a little before the failing frame to a little after it (checker/replay/show_series.py
    failure(): the frame the message names, or where the check's quantity first passes its bound, or
    where the run first differs from the solution's), framed on the bodies the failure is about.
    """
    result = next((r for r in pictured_results(report) if r.id == check_id), None)
    if result is None:
        return []
    pictures = []
    scenes, ungraded = _scenes_of(report, check_id)
    for scene in scenes:
        record = report.records.get(scene)
        if not record or not record.get("records"):
            continue
        reference = reference_record(report.lab, scene) if with_reference else None
        frames, theirs = record["records"], (reference or {}).get("records") or []
        fail_frame, _, quantity, values = failure(report.lab, result, frames, theirs, not ungraded)
        at = min(range(len(frames)), key=lambda i: abs(frames[i]["frame"] - fail_frame)) \
            if fail_frame is not None else None
        value = values[at] if at is not None and values else None
        focus = focus_bodies(frames[at], _nearest(theirs, fail_frame)) if at is not None else None
        title = caption(check_id, scene, report.lab.title, ungraded, fail_frame, quantity, value,
                        getattr(report, "preview_note", "") if ungraded else "")
        surface = filmstrip(record, reference, fail_frame, title, focus=focus)
        pictures.append(Picture(check_id, scene, png_bytes(surface)))
    return pictures


def base64_pngs(report, check_id):
    """The check's pictures as base64 PNG strings (for PrairieLearn's images[] or an <img> data: URI)."""
    return [p.base64 for p in pictures_for(report, check_id)]


def prairielearn_images(report, check_id):
    """PrairieLearn results.json images[] entries for the check: [{"label", "url": data: URI}]."""
    return [{"label": f"{p.check_id}: scene {p.scene}", "url": p.data_url} for p in pictures_for(report, check_id)]


def all_pictures(rows, problems=None):
    """{row path: {check id: [Picture]}} for every failed behaviour check of every row (rows without any left out).

    A row whose pictures cannot be drawn loses only its own: with a list as `problems`, one line naming
    it is appended there (else the exception is raised, as before)."""
    found = {}
    for row in rows:
        try:
            for result in pictured_results(row):
                shown = pictures_for(row, result.id)
                if shown:
                    found.setdefault(row.path, {})[result.id] = shown
        except Exception as exc:  # noqa: BLE001 - one row's record or our drawing: that row goes without
            if problems is None:
                raise
            found.pop(row.path, None)
            problems.append(f"{row.path}: cannot draw its pictures ({type(exc).__name__}: {exc}); none for it")
    return found


def write_pictures(rows, folder, names, pictures=None, problems=None):
    """Write each picture to folder/<submission name>/<check id>[-<scene>].png; returns {row path: {check id: [paths]}}.

    names: {row path: submission folder name} (checker/outputs.submission_names).
    pictures: all_pictures(rows), if already made.
    Every file is created by the grader in folders it made, following no link (outputs.write_below): a
    picture or folder some other user planted there (a link to /etc/...) is replaced or refused, never
    written through. A row whose pictures cannot be written loses only its own: one line naming it is
    appended to `problems` (a list; else the OSError is raised).
    """
    from checker.reporting.outputs import write_below
    pictures = all_pictures(rows, problems) if pictures is None else pictures
    written = {}
    for path, by_check in pictures.items():
        try:
            for check_id, shown in by_check.items():
                for picture in shown:
                    name = check_id if len(shown) == 1 else f"{check_id}-{picture.scene}"
                    file = write_below(folder, names[path], name + ".png", picture.png)
                    written.setdefault(path, {}).setdefault(check_id, []).append(file)
        except OSError as exc:
            if problems is None:
                raise
            written.pop(path, None)
            problems.append(f"--pictures {folder}: {path}: its pictures were not written "
                            f"({exc.strerror or exc})")
    return written
