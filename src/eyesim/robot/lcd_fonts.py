"""LCD text fonts: RoBIOS's Helvetica, Times and Courier as DejaVu TrueType look-alikes, cut into cells.

The TTF files come from the `matplotlib` package (a dependency), which ships DejaVu Sans, Serif and
Sans Mono in all four styles; nothing is copied into this repository. Text on the LCD is a grid of
cells whose size depends only on the font size, so switching the face never moves the text: each
character is drawn into its own cell, its ink centred, and squeezed sideways when it is wider than
the cell (proportional fonts have wide letters such as W and m)."""

from __future__ import annotations

import importlib.util
import math
from functools import cache, lru_cache
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from eyesim.protocol.constants import BOLD, COURIER, HELVETICA, TIMES

FONT_NAMES = {HELVETICA: "HELVETICA", TIMES: "TIMES", COURIER: "COURIER"}
MIN_SIZE, MAX_SIZE = 8, 24
# The default gives 6x13-pixel cells, the EyeBot's default X11 font "6x13": 80 columns x 21 rows
# above the menu bar, where EyeSim's text wraps (docs/api/lcd.md#text).
DEFAULT_SIZE = 10
DEFAULT_FONT = COURIER  # fixed-width, like the EyeBot's own default LCD font
CELL_WIDTH_PER_SIZE = 0.6  # cell width = ceil(0.6 * size) pixels: a monospaced font's advance
CELL_HEIGHT_PER_SIZE = 1.3  # cell height = ceil(1.3 * size) pixels

# DejaVu files for (font, variation); variation BOLD | ITALICS = bold italic.
FILES = {
    HELVETICA: ("DejaVuSans.ttf", "DejaVuSans-Bold.ttf", "DejaVuSans-Oblique.ttf", "DejaVuSans-BoldOblique.ttf"),
    TIMES: ("DejaVuSerif.ttf", "DejaVuSerif-Bold.ttf", "DejaVuSerif-Italic.ttf", "DejaVuSerif-BoldItalic.ttf"),
    COURIER: (
        "DejaVuSansMono.ttf",
        "DejaVuSansMono-Bold.ttf",
        "DejaVuSansMono-Oblique.ttf",
        "DejaVuSansMono-BoldOblique.ttf",
    ),
}


class FontsMissing(RuntimeError):
    pass


def cell_size(size: int) -> tuple[int, int]:
    """(width, height) in pixels of a text cell at a font size."""
    return math.ceil(CELL_WIDTH_PER_SIZE * size - 1e-9), math.ceil(CELL_HEIGHT_PER_SIZE * size - 1e-9)


def font_directory() -> Path:
    spec = importlib.util.find_spec("matplotlib")  # found, not imported: importing it is slow
    if spec is None or not spec.submodule_search_locations:
        raise FontsMissing(
            "the LCD fonts come from the matplotlib package, which is not installed (pip install matplotlib)"
        )
    return Path(next(iter(spec.submodule_search_locations))) / "mpl-data" / "fonts" / "ttf"


def font_file(font: int, variation: int) -> Path:
    path = font_directory() / FILES[font][variation]
    if not path.is_file():
        raise FontsMissing(f"the LCD font {path} is missing; reinstall matplotlib")
    return path


@cache
def truetype(font: int, variation: int, size: int) -> ImageFont.FreeTypeFont:
    return ImageFont.truetype(str(font_file(font, variation)), size)


@lru_cache(maxsize=4096)
def glyph(font: int, variation: int, size: int, char: str) -> np.ndarray:
    """Coverage (0..255, uint8) of one character in its cell: cell height x cell width."""
    width, height = cell_size(size)
    face = truetype(font, variation, size)
    ascent, descent = face.getmetrics()
    baseline = ascent + max(0, (height - ascent - descent) // 2)
    canvas = Image.new("L", (3 * size + 8, height), 0)
    ImageDraw.Draw(canvas).text((size, baseline), char, font=face, fill=255, anchor="ls")
    ink = np.asarray(canvas)
    columns = np.flatnonzero(ink.any(axis=0))
    cell = np.zeros((height, width), dtype=np.uint8)
    if columns.size == 0:
        return cell  # a space
    ink = ink[:, columns[0] : columns[-1] + 1]
    if ink.shape[1] > width:
        ink = np.asarray(Image.fromarray(ink).resize((width, height), Image.Resampling.LANCZOS))
    left = (width - ink.shape[1]) // 2
    cell[:, left : left + ink.shape[1]] = ink
    return cell


def label_font(size: int) -> ImageFont.FreeTypeFont:
    """The menu bar's labels: Helvetica bold."""
    return truetype(HELVETICA, BOLD, size)
