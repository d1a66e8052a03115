"""What the READMEs document exists (physics2d's page the World settings, the root README the panel's keys): every World setting in its table is a World attribute with the documented
default, and every solver-panel key in its table is a key the panel handles. A renamed setting or a dropped key
fails here, not in a student's window."""
import os
import re

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")

import pygame  # noqa: E402
import pytest  # noqa: E402

from lesson11 import panel as lp  # noqa: E402
from lesson11.physics2d import World  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
README = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()                       # the panel's keys
PHYSICS2D = open(os.path.join(ROOT, "lesson11", "physics2d", "README.md"), encoding="utf-8").read()  # World settings
KEY_NAMES = {"Up": pygame.K_UP, "Down": pygame.K_DOWN, "Left": pygame.K_LEFT, "Right": pygame.K_RIGHT}


def table_after(heading, text=README):
    """The rows (lists of cells) of the first table after the line that starts with `heading` in `text`."""
    lines = text[text.index(heading):].splitlines()[1:]
    start = next(i for i, line in enumerate(lines) if line.startswith("|"))
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    return rows


def documented_settings():
    """[(name, documented default text)] from the World settings table; `a`, `b` rows give one pair each."""
    pairs = []
    for name_cell, default_cell, *_ in table_after("### World settings", PHYSICS2D):
        names = re.findall(r"`(\w+)`", name_cell)
        defaults = [d.strip() for d in default_cell.split(",")] if len(names) > 1 else [default_cell]
        pairs += list(zip(names, defaults))
    return pairs


def test_the_tables_are_found():
    assert len(documented_settings()) >= 12
    assert len(panel_keys()) >= 10


@pytest.mark.parametrize("name,default", documented_settings())
def test_every_documented_world_setting_exists_with_its_default(name, default):
    world = World()
    assert hasattr(world, name), f"README documents World.{name}, which World does not have"
    value = getattr(world, name)
    text = default.strip("`")
    if re.fullmatch(r"-?[\d.]+", text):
        assert float(value) == pytest.approx(float(text)), f"World.{name} is {value!r}, README says {text}"
    elif text in ("True", "False", "None"):
        assert value == {"True": True, "False": False, "None": None}[text] or (name == "substeps" and text == "None")
    elif text.startswith('"'):
        assert value == text.strip('"'), f"World.{name} is {value!r}, README says {text}"


def panel_keys():
    """Every key named in the panel's table (the lab's own row left out)."""
    keys = []
    for cell, *_ in table_after("| key | what it does"):
        if "click" in cell:
            continue
        keys += [name.strip() for name in cell.split("/")]
    return keys


@pytest.mark.parametrize("name", panel_keys())
def test_every_documented_panel_key_is_handled(name):
    panel = lp.LabPanel()
    world = World()
    panel.advance(world, 1 / 60)   # the panel has a world: its setting keys act
    key = KEY_NAMES.get(name) or getattr(pygame, f"K_{name.lower()}")
    assert panel.handle(pygame.event.Event(pygame.KEYDOWN, key=key)), f"README documents key {name}; the panel ignores it"
