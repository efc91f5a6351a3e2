"""The robot's 480x320 LCD: a framebuffer the simulator keeps, with a text terminal and a menu bar."""

from __future__ import annotations

import io

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from eyesim.robot.component import Component

WIDTH, HEIGHT = 480, 320
MENU_HEIGHT = 38  # pixel rows of the soft-key menu bar at the bottom
CELL_WIDTH, CELL_HEIGHT = 8, 13  # pixels of one text cell
COLUMNS = WIDTH // CELL_WIDTH  # 60
ROWS = (HEIGHT - MENU_HEIGHT) // CELL_HEIGHT  # 21
TAB = 4

WHITE, BLACK = 0xFFFFFF, 0x000000
MENU_BACKGROUND = 0x303030
MENU_BORDER = 0x808080


def rgb(color: int) -> tuple[int, int, int]:
    return (color >> 16) & 0xFF, (color >> 8) & 0xFF, color & 0xFF


def _glyph_masks() -> dict[str, np.ndarray]:
    """Pixel masks (CELL_HEIGHT x CELL_WIDTH) of the printable ASCII characters."""
    font = ImageFont.load_default_imagefont()  # fixed 6x11 bitmap font shipped with Pillow
    masks = {}
    for code in range(32, 127):
        image = Image.new("1", (CELL_WIDTH, CELL_HEIGHT), 0)
        ImageDraw.Draw(image).text((1, 1), chr(code), fill=1, font=font)
        masks[chr(code)] = np.array(image, dtype=bool)
    return masks


GLYPHS = _glyph_masks()


class Lcd(Component):
    """Text output works like a terminal: the cursor advances, `\\n` starts a new line, long lines
    wrap, and printing past the last row scrolls the text area up."""

    kind = "lcd"

    def __init__(self):
        self.pixels = np.zeros((HEIGHT, WIDTH, 3), dtype=np.uint8)
        self.reset()

    def reset(self) -> None:
        self.pixels[:] = 0
        self.row = self.column = 0
        self.foreground, self.background = WHITE, BLACK
        self.menu: list[str] | None = None
        self.version = 0  # bumped on every change, so publishers know when to send

    def _changed(self) -> None:
        self.version += 1

    # -- text ------------------------------------------------------------------------------
    def set_position(self, row: int, column: int) -> None:
        self.row = max(0, min(ROWS - 1, row))
        self.column = max(0, min(COLUMNS - 1, column))

    def print(self, text: str) -> None:
        fg, bg = np.array(rgb(self.foreground), np.uint8), np.array(rgb(self.background), np.uint8)
        for char in text:
            if char == "\n":
                self._new_line()
                continue
            if char == "\r":
                self.column = 0
                continue
            if char == "\t":
                spaces = TAB - self.column % TAB
                self.print(" " * spaces)
                continue
            if self.column >= COLUMNS:
                self._new_line()
            mask = GLYPHS.get(char, GLYPHS["?"])
            y, x = self.row * CELL_HEIGHT, self.column * CELL_WIDTH
            self.pixels[y:y + CELL_HEIGHT, x:x + CELL_WIDTH] = np.where(mask[:, :, None], fg, bg)
            self.column += 1
        self._changed()

    def _new_line(self) -> None:
        self.column = 0
        if self.row + 1 < ROWS:
            self.row += 1
            return
        text_bottom = ROWS * CELL_HEIGHT
        self.pixels[:text_bottom - CELL_HEIGHT] = self.pixels[CELL_HEIGHT:text_bottom]
        self.pixels[text_bottom - CELL_HEIGHT:text_bottom] = rgb(self.background)

    def clear(self) -> None:
        """Black screen, cursor home; the menu bar stays."""
        self.pixels[:HEIGHT - MENU_HEIGHT] = 0
        if self.menu is None:
            self.pixels[HEIGHT - MENU_HEIGHT:] = 0
        self.row = self.column = 0
        self._changed()

    # -- menu --------------------------------------------------------------------------------
    def set_menu(self, labels: list[str]) -> None:
        self.menu = [label[:32] for label in labels]
        self._draw_menu()
        self._changed()

    def _draw_menu(self) -> None:
        image = Image.new("RGB", (WIDTH, MENU_HEIGHT), rgb(BLACK))
        draw = ImageDraw.Draw(image)
        font = ImageFont.load_default_imagefont()
        width = WIDTH // 4
        for index, label in enumerate(self.menu):
            left = index * width
            draw.rectangle([left + 1, 1, left + width - 2, MENU_HEIGHT - 2], fill=rgb(MENU_BACKGROUND),
                           outline=rgb(MENU_BORDER))
            text = label.strip()
            if text:
                text_width = draw.textlength(text, font=font)
                draw.text((left + (width - text_width) / 2, (MENU_HEIGHT - 11) / 2), text, fill=rgb(WHITE), font=font)
        self.pixels[HEIGHT - MENU_HEIGHT:] = np.asarray(image)

    # -- reading back ------------------------------------------------------------------------
    def pixel(self, x: int, y: int) -> int:
        r, g, b = self.pixels[y, x]
        return (int(r) << 16) | (int(g) << 8) | int(b)

    def png(self) -> bytes:
        buffer = io.BytesIO()
        Image.fromarray(self.pixels).save(buffer, format="PNG", compress_level=1)
        return buffer.getvalue()


def create(context) -> list[Component]:
    return [Lcd()]
