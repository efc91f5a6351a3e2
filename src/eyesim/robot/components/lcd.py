"""The robot's 480x320 LCD: a framebuffer the simulator keeps, with a text terminal, graphics and a menu bar."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import math

import numpy as np
from PIL import Image, ImageDraw

from eyesim.protocol.constants import (
    BLACK,
    BOLD,
    ITALICS,
    LCD_AUTOREFRESH,
    LCD_FB_ROTATE,
    LCD_LINEFEED,
    LCD_LISTMENU,
    LCD_MENU_STRLENGTH,
    LCD_SCROLLING,
    LCD_SHOWMENU,
    MENU_HEIGHT,
    NORMAL,
    WHITE,
)
from eyesim.robot import lcd_fonts
from eyesim.robot.component import Component
from eyesim.robot.lcd_fonts import FONT_NAMES, cell_size

WIDTH, HEIGHT = 480, 320
CELL_WIDTH, CELL_HEIGHT = cell_size(lcd_fonts.DEFAULT_SIZE)  # 6 x 13 pixels at the default font size
COLUMNS = WIDTH // CELL_WIDTH  # 80 at the default font size, as EyeSim's 6x13 font
ROWS = (HEIGHT - MENU_HEIGHT) // CELL_HEIGHT  # 21 at the default font size, with the menu shown
TAB = 4
MENU_LABEL_LENGTH = LCD_MENU_STRLENGTH
# Characters of one LCDPrintf's text drawn at most, the last ones (docs/api/lcd.md): more than a
# screen holds (at size 8 with the menu hidden 29 rows of 96 cells and their line feeds: 2813),
# and what keeps one call's drawing within a few ms of the simulation thread.
MAX_PRINT = 4096

MENU_BACKGROUND = 0x303030
MENU_BORDER = 0x808080

# LCDSetMode flags: each "off" flag is the "on" flag shifted 8 bits up.
AUTOREFRESH, SCROLLING, LINEFEED = LCD_AUTOREFRESH, LCD_SCROLLING, LCD_LINEFEED
SHOWMENU, LISTMENU, FB_ROTATE = LCD_SHOWMENU, LCD_LISTMENU, LCD_FB_ROTATE
MODE_SETTINGS = {
    AUTOREFRESH: "autorefresh",
    SCROLLING: "scrolling",
    LINEFEED: "linefeed",
    SHOWMENU: "menu_visible",
    LISTMENU: "list_menu",
    FB_ROTATE: "rotated",
}
KNOWN_MODE_BITS = sum(MODE_SETTINGS) | (sum(MODE_SETTINGS) << 8)

IMAGE_COLOR, IMAGE_GRAY, IMAGE_BINARY = 0, 1, 2
IMAGE_CHANNELS = {IMAGE_COLOR: 3, IMAGE_GRAY: 1, IMAGE_BINARY: 1}


def rgb(color: int) -> tuple[int, int, int]:
    return (color >> 16) & 0xFF, (color >> 8) & 0xFF, color & 0xFF


def check_color(color: int, what: str = "colour") -> int:
    if not 0 <= color <= 0xFFFFFF:
        raise ValueError(
            f"{what} {color:#x} is not a 0xRRGGBB colour" if color >= 0 else f"{what} {color} is not a 0xRRGGBB colour"
        )
    return color


@lru_cache(maxsize=8192)
def _cell_pixels(font: int, variation: int, size: int, char: str, fg: int, bg: int) -> np.ndarray:
    """A character cell in colour: the glyph's coverage blends the foreground into the background."""
    coverage = lcd_fonts.glyph(font, variation, size, char).astype(np.uint32)[:, :, None]
    fg_rgb, bg_rgb = np.array(rgb(fg), np.uint32), np.array(rgb(bg), np.uint32)
    return ((fg_rgb * coverage + bg_rgb * (255 - coverage) + 127) // 255).astype(np.uint8)


@dataclass
class MenuEntry:
    label: str = ""
    fg: int = WHITE
    bg: int = MENU_BACKGROUND


class Lcd(Component):
    """Text output works like a terminal: the cursor advances, `\\n` starts a new line, long lines
    wrap, and printing past the last row scrolls the text area up (LCDSetMode can turn wrapping
    and scrolling off). `pixels` is what the program drew, read back by LCDGetPixel; `screen()` is
    what the LCD shows, which lags behind until LCDRefresh when auto-refresh is off."""

    noun = "LCD"

    def __init__(self):
        self.pixels = np.zeros((HEIGHT, WIDTH, 3), dtype=np.uint8)
        self.version = 0  # bumped on every visible change, so publishers know when to send
        self._published: int | None = None  # the version the viewer was last sent
        self.reset()

    def reset(self) -> None:
        self.pixels[:] = 0
        self.shown: np.ndarray | None = None  # frozen screen while auto-refresh is off
        # The text layer: which character each printed cell shows, so tests and graders read the
        # LCD's text exactly instead of recognising pixels. (y, x) of a cell's top-left pixel ->
        # (char, cell width, cell height); blanks are not kept.
        self.text: dict[tuple[int, int], tuple[str, int, int]] = {}
        self.shown_text: dict | None = None  # frozen with `shown` while auto-refresh is off
        self._text_cells: set[tuple[int, int]] = set()  # cell sizes present in `text`
        self.row = self.column = 0
        self.foreground, self.background = WHITE, BLACK
        self.font, self.variation, self.font_size = lcd_fonts.DEFAULT_FONT, NORMAL, lcd_fonts.DEFAULT_SIZE
        self.autorefresh = self.scrolling = self.linefeed = self.menu_visible = True
        self.list_menu = self.rotated = False
        self.menu: list[str] | None = None  # the soft-key labels, once LCDMenu set them
        self.menu_entries = [MenuEntry() for _ in range(4)]
        self.version += 1

    def program_started(self) -> None:
        """The screen, cursor, font and menu are the program's: the next one starts on a blank LCD,
        not under the text the one before left (a restart from the page, a program run again)."""
        self.reset()

    def publish(self, robot_id: int, events, again: bool) -> None:
        if again or self._published != self.version:
            self._published = self.version
            events.lcd(robot_id, self.screen().copy())

    def _changed(self) -> None:
        if self.autorefresh:
            self.version += 1

    # -- geometry ---------------------------------------------------------------------------
    @property
    def cell(self) -> tuple[int, int]:
        """(width, height) of a text cell at the current font size."""
        return cell_size(self.font_size)

    @property
    def text_height(self) -> int:
        """Pixel rows available to text: all but the menu bar while it is shown."""
        return HEIGHT - MENU_HEIGHT if self.menu_visible else HEIGHT

    @property
    def rows(self) -> int:
        return self.text_height // self.cell[1]

    @property
    def columns(self) -> int:
        return WIDTH // self.cell[0]

    # -- text ------------------------------------------------------------------------------
    def set_position(self, row: int, column: int) -> None:
        if not 0 <= row < self.rows:
            raise ValueError(f"row {row} is outside the text rows 0..{self.rows - 1}")
        if not 0 <= column < self.columns:
            raise ValueError(f"column {column} is outside the text columns 0..{self.columns - 1}")
        self.row, self.column = row, column

    def print(self, text: str) -> None:
        for char in self._reaching_screen(text):
            if char == "\n":
                self._new_line()
            elif char == "\r":
                self.column = 0
            elif char == "\t":
                for _ in range(TAB - self.column % TAB):
                    self._put(" ")
            else:
                self._put(char if char.isprintable() else "?")
        self._changed()

    def _reaching_screen(self, text: str) -> str:
        """The end of `text` that decides what the LCD shows. While text scrolls and wraps, text
        followed by 2 x rows line feeds has scrolled off, and so has everything on the screen
        before it: printing only what follows from the last row gives the same screen and cursor
        (the first `rows` line feeds bring the cursor to the last row at most, the next `rows`
        scroll everything above it away). Of what is left, at most the last MAX_PRINT characters
        are drawn: the cost of one call stays bounded whatever a program sends."""
        if self.scrolling and self.linefeed:
            cut = len(text)
            for _ in range(2 * self.rows):
                cut = text.rfind("\n", 0, cut)
                if cut < 0:
                    break
            else:
                self.row, self.column = self.rows - 1, 0
                text = text[cut + 1 :]
        return text[-MAX_PRINT:]

    def _put(self, char: str) -> None:
        if self.column >= self.columns:
            if not self.linefeed:
                return  # without line feed, text beyond the last column is cut off
            self._new_line()
        width, height = self.cell
        y, x = self.row * height, self.column * width
        self.pixels[y : y + height, x : x + width] = _cell_pixels(
            self.font, self.variation, self.font_size, char, self.foreground, self.background
        )
        self._put_text(y, x, char, width, height)
        self.column += 1

    def _put_text(self, y: int, x: int, char: str, width: int, height: int) -> None:
        if self._text_cells <= {(width, height)}:
            self.text.pop((y, x), None)  # one grid only: the cell covers exactly the old one
        else:
            self._erase_text(x, y, x + width, y + height)
        if char != " ":
            self.text[(y, x)] = (char, width, height)
            self._text_cells.add((width, height))

    def _erase_text(self, left: int, top: int, right: int, bottom: int) -> None:
        """Forget the characters whose cells overlap the pixels [left, right) x [top, bottom)."""
        covered = [
            key
            for key, (_, w, h) in self.text.items()
            if key[1] < right and key[1] + w > left and key[0] < bottom and key[0] + h > top
        ]
        for key in covered:
            del self.text[key]

    def _new_line(self) -> None:
        self.column = 0
        if self.row + 1 < self.rows:
            self.row += 1
        elif self.scrolling:
            height = self.cell[1]
            bottom = self.rows * height
            self.pixels[: bottom - height] = self.pixels[height:bottom]
            self.pixels[bottom - height : bottom] = rgb(self.background)
            # The text moves with its pixels: the top row scrolls away, rows below the text area stay.
            self.text = {
                (y - height if y < bottom else y, x): cell
                for (y, x), cell in self.text.items()
                if y >= height or y >= bottom
            }
        else:
            self.row = 0

    def clear(self) -> None:
        """Black screen, cursor home; a menu that is set stays."""
        self.pixels[:] = 0
        self.text.clear()
        self._text_cells.clear()
        self._draw_menu()
        self.row = self.column = 0
        self._changed()

    def set_color(self, foreground: int, background: int) -> None:
        self.foreground = check_color(foreground, "foreground")
        self.background = check_color(background, "background")

    def set_font(self, font: int, variation: int) -> None:
        if font not in FONT_NAMES:
            raise ValueError(f"font {font} is not HELVETICA (0), TIMES (1) or COURIER (2)")
        if variation not in (NORMAL, BOLD, ITALICS, BOLD | ITALICS):
            raise ValueError(f"variation {variation} is not NORMAL (0), BOLD (1), ITALICS (2) or BOLD|ITALICS (3)")
        lcd_fonts.truetype(font, variation, self.font_size)  # a missing font file fails here, clearly
        self.font, self.variation = font, variation

    def set_font_size(self, size: int) -> None:
        if not lcd_fonts.MIN_SIZE <= size <= lcd_fonts.MAX_SIZE:
            raise ValueError(f"font size {size} is outside {lcd_fonts.MIN_SIZE}..{lcd_fonts.MAX_SIZE}")
        old_width, old_height = self.cell
        self.font_size = size
        self._keep_cursor(self.column * old_width, self.row * old_height)

    def _keep_cursor(self, x: int, y: int) -> None:
        """Put the cursor in the first cell of the current grid at or after pixel (x, y), so new
        text does not cover what is already there."""
        width, height = self.cell
        self.row = min(-(-y // height), self.rows - 1)
        self.column = min(-(-x // width), self.columns)

    # -- modes -------------------------------------------------------------------------------
    def set_mode(self, mode: int) -> None:
        """LCDSetMode: each flag turns its setting on, its partner 8 bits up turns it off."""
        unknown = mode & ~KNOWN_MODE_BITS
        if mode < 0 or unknown:
            raise ValueError(f"mode {mode:#x} has unknown flag bits {unknown & 0xFFFFFFFF:#x}")
        for flag in MODE_SETTINGS:
            if mode & flag and mode & (flag << 8):
                raise ValueError(f"mode {mode:#x} turns one setting both on ({flag:#x}) and off ({flag << 8:#x})")
        width, height = self.cell
        x, y = self.column * width, self.row * height
        for flag, setting in MODE_SETTINGS.items():
            if mode & flag:
                self._set(setting, True)
            elif mode & (flag << 8):
                self._set(setting, False)
        self._keep_cursor(x, y)
        self.version += 1

    def _set(self, setting: str, on: bool) -> None:
        if getattr(self, setting) == on:
            return
        setattr(self, setting, on)
        if setting == "autorefresh":
            self.shown = None if on else self.pixels.copy()
            self.shown_text = None if on else dict(self.text)
        elif setting == "menu_visible":
            if on:
                self._draw_menu()
            else:
                self.pixels[HEIGHT - MENU_HEIGHT :] = 0

    def refresh(self) -> None:
        """LCDRefresh: redraw the menu and show everything drawn so far."""
        self._draw_menu()
        if self.shown is not None:
            self.shown = self.pixels.copy()
            self.shown_text = dict(self.text)
        self.version += 1

    def screen(self) -> np.ndarray:
        """The image the LCD shows now (a view; copy it to keep it)."""
        image = self.pixels if self.shown is None else self.shown
        return image[::-1, ::-1] if self.rotated else image

    def text_rows(self) -> list[str]:
        """The text the LCD shows, one string per text row (trailing blanks removed), from the
        top down to the last row with text. Rows and columns are those of the grid each
        character was printed in: the default 6x13-pixel cells unless the program changed the
        font size. Text that a filled area or an image covered is gone; lines and pixels drawn
        over text leave it."""
        cells = self.text if self.shown_text is None else self.shown_text
        rows: dict[int, dict[int, str]] = {}
        for (y, x), (char, width, height) in sorted(cells.items()):
            rows.setdefault(y // height, {})[x // width] = char
        if not rows:
            return []
        return [
            "".join(chars.get(c, " ") for c in range(max(chars) + 1)) if (chars := rows.get(r)) else ""
            for r in range(max(rows) + 1)
        ]

    # -- menu --------------------------------------------------------------------------------
    def set_menu(self, labels: list[str]) -> None:
        self.menu = [label[:MENU_LABEL_LENGTH] for label in labels]
        self.menu_entries = [MenuEntry(label) for label in self.menu]
        self._draw_menu()
        self._changed()

    def set_menu_entry(self, position: int, label: str, foreground: int, background: int) -> None:
        """LCDMenuI: one soft key's label in its own colours. Positions count from 0, as EyeSim and the
        EyeBot's LCD library index their menu entries (0 is KEY1 ... 3 is KEY4; the official
        graphics example labels the four keys with 0..3), although the headers' comment says 1..4
        (docs/api/compatibility.md#lcdmenui-positions-count-from-0)."""
        if not 0 <= position <= 3:
            raise ValueError(f"menu position {position} is not 0..3 (0 is KEY1 ... 3 is KEY4, as on EyeSim)")
        entry = MenuEntry(
            label[:MENU_LABEL_LENGTH], check_color(foreground, "foreground"), check_color(background, "background")
        )
        if self.menu is None:
            self.menu = ["", "", "", ""]
        self.menu[position] = entry.label
        self.menu_entries[position] = entry
        self._draw_menu()
        self._changed()

    def _draw_menu(self) -> None:
        if self.menu is None or not self.menu_visible:
            return
        self._erase_text(0, HEIGHT - MENU_HEIGHT, WIDTH, HEIGHT)
        image = Image.new("RGB", (WIDTH, MENU_HEIGHT), rgb(BLACK))
        draw = ImageDraw.Draw(image)
        width = WIDTH // 4
        for index, entry in enumerate(self.menu_entries):
            left = index * width
            draw.rectangle(
                [left + 1, 1, left + width - 2, MENU_HEIGHT - 2], fill=rgb(entry.bg), outline=rgb(MENU_BORDER)
            )
            text = entry.label.strip()
            if not text:
                continue
            size = 14
            font = lcd_fonts.label_font(size)
            while draw.textlength(text, font=font) > width - 8 and size > 8:
                size -= 1
                font = lcd_fonts.label_font(size)
            while draw.textlength(text, font=font) > width - 8:
                text = text[:-1]  # still too long at the smallest size: cut it
            draw.text((left + width / 2, MENU_HEIGHT / 2), text, fill=rgb(entry.fg), font=font, anchor="mm")
        self.pixels[HEIGHT - MENU_HEIGHT :] = np.asarray(image)

    def menu_key_at(self, x: int, y: int) -> int | None:
        """The soft key (1, 2, 4, 8) whose button is at pixel (x, y) of the shown menu bar, if any."""
        if not self.menu_visible or not HEIGHT - MENU_HEIGHT <= y < HEIGHT or not 0 <= x < WIDTH:
            return None
        return 1 << (x * 4 // WIDTH)

    # -- graphics: drawing is clipped to the screen ------------------------------------------
    def pixel(self, x: int, y: int) -> int:
        if not (0 <= x < WIDTH and 0 <= y < HEIGHT):
            raise ValueError(f"pixel ({x}, {y}) is outside the {WIDTH}x{HEIGHT} screen")
        r, g, b = self.pixels[y, x]
        return (int(r) << 16) | (int(g) << 8) | int(b)

    def set_pixel(self, x: int, y: int, color: int) -> None:
        check_color(color)
        if 0 <= x < WIDTH and 0 <= y < HEIGHT:
            self.pixels[y, x] = rgb(color)
        self._changed()

    def _plot(self, xs: np.ndarray, ys: np.ndarray, color: int) -> None:
        inside = (xs >= 0) & (xs < WIDTH) & (ys >= 0) & (ys < HEIGHT)
        self.pixels[ys[inside], xs[inside]] = rgb(color)

    def line(self, x1: int, y1: int, x2: int, y2: int, color: int) -> None:
        """Both end points included; one pixel per step along the longer axis. Only the steps
        that can land on the screen are computed, so a line of any length costs the same."""
        check_color(color)
        steps = max(abs(x2 - x1), abs(y2 - y1))
        if steps == 0:
            self._plot(np.array([x1]), np.array([y1]), color)
            self._changed()
            return
        first, last = 0, steps
        for start, end, size in ((x1, x2, WIDTH), (y1, y2, HEIGHT)):
            if start == end:
                if not 0 <= start < size:
                    first, last = 1, 0  # all of it off screen
                continue
            # steps t where this coordinate is within a pixel of the screen (with a margin)
            low, high = sorted(((-1 - start) * steps / (end - start), (size - start) * steps / (end - start)))
            first, last = max(first, math.floor(low) - 1), min(last, math.ceil(high) + 1)
        # Exact integer rounding (half up), so every platform draws the same pixels; Python
        # integers because the products can exceed 64 bits for far-away end points.
        ts = range(first, last + 1)
        xs = [x1 + (2 * (x2 - x1) * t + steps) // (2 * steps) for t in ts]
        ys = [y1 + (2 * (y2 - y1) * t + steps) // (2 * steps) for t in ts]
        self._plot(*_on_screen(xs, ys), color)
        self._changed()

    def area(self, x1: int, y1: int, x2: int, y2: int, color: int, fill: bool) -> None:
        """The rectangle between two corners, both included; filled or a one-pixel outline."""
        check_color(color)
        # Clipped to one pixel beyond the screen: an edge off screen stays off screen.
        left, right = (min(max(v, -1), WIDTH) for v in sorted((x1, x2)))
        top, bottom = (min(max(v, -1), HEIGHT) for v in sorted((y1, y2)))
        if fill:
            self.pixels[max(top, 0) : bottom + 1, max(left, 0) : right + 1] = rgb(color)
            self._erase_text(left, top, right + 1, bottom + 1)
        else:
            across, down = np.arange(left, right + 1), np.arange(top, bottom + 1)
            on_left, on_right = (left if left == min(x1, x2) else -1), (right if right == max(x1, x2) else -1)
            on_top, on_bottom = (top if top == min(y1, y2) else -1), (bottom if bottom == max(y1, y2) else -1)
            xs = np.concatenate([across, across, np.full(down.size, on_left), np.full(down.size, on_right)])
            ys = np.concatenate([np.full(across.size, on_top), np.full(across.size, on_bottom), down, down])
            self._plot(xs, ys, color)
        self._changed()

    def circle(self, cx: int, cy: int, radius: int, color: int, fill: bool) -> None:
        """Pixels within `radius` of the centre (filled), or the midpoint-circle outline. Only
        offsets that can land on the screen are computed, so any radius costs about the same."""
        check_color(color)
        if radius < 0:
            raise ValueError(f"radius {radius} is negative")
        if fill:  # row by row: the span of x with dx^2 + dy^2 <= r^2 + r, the same edge as the outline
            limit = radius * radius + radius
            for row in range(max(cy - radius, 0), min(cy + radius, HEIGHT - 1) + 1):
                half = math.isqrt(limit - (row - cy) ** 2)
                left, right = max(cx - half, 0), min(cx + half, WIDTH - 1)
                if left <= right:
                    self.pixels[row, left : right + 1] = rgb(color)
        else:
            offsets = [o for y in _outline_parameters(cx, cy, radius) for o in _octants(_outline_x(radius, y), y)]
            self._plot(*_on_screen([cx + dx for dx, _ in offsets], [cy + dy for _, dy in offsets]), color)
        self._changed()

    def image(
        self,
        x: int,
        y: int,
        width: int,
        height: int,
        display_width: int,
        display_height: int,
        image_format: int,
        data: bytes,
    ) -> None:
        """An image of width x height pixels, scaled (nearest pixel) to the display size at (x, y)."""
        if image_format not in IMAGE_CHANNELS:
            raise ValueError(f"image format {image_format} is not 0 (colour), 1 (gray) or 2 (binary)")
        if width <= 0 or height <= 0 or display_width <= 0 or display_height <= 0:
            raise ValueError(
                f"image size {width}x{height} shown as {display_width}x{display_height}: sizes must be positive"
            )
        channels = IMAGE_CHANNELS[image_format]
        if len(data) != width * height * channels:
            raise ValueError(f"a {width}x{height} image needs {width * height * channels} bytes, got {len(data)}")
        pixels = np.frombuffer(data, dtype=np.uint8).reshape(height, width, channels)
        # Only the displayed pixels that land on the screen are looked up (nearest pixel), and
        # only they are converted: a 5-megapixel image shows at most the screen's 153 600.
        top, left = max(0, y), max(0, x)
        bottom, right = min(HEIGHT, y + display_height), min(WIDTH, x + display_width)
        if top < bottom and left < right:
            rows = [(row - y) * height // display_height for row in range(top, bottom)]
            cols = [(col - x) * width // display_width for col in range(left, right)]
            shown = pixels[rows][:, cols]
            if image_format == IMAGE_BINARY:
                shown = np.where(shown != 0, 0, 255).astype(np.uint8)  # 1 = black, 0 = white
            if channels == 1:
                shown = np.repeat(shown, 3, axis=2)
            self.pixels[top:bottom, left:right] = shown
            self._erase_text(left, top, right, bottom)
        self._changed()


def _on_screen(xs: list[int], ys: list[int]) -> tuple[np.ndarray, np.ndarray]:
    """The points (Python integers, any size) that lie on the screen, as pixel index arrays."""
    kept = [(x, y) for x, y in zip(xs, ys) if 0 <= x < WIDTH and 0 <= y < HEIGHT]
    return np.array([p[0] for p in kept], dtype=np.int64), np.array([p[1] for p in kept], dtype=np.int64)


def _outline_x(radius: int, y: int) -> int:
    """x of the midpoint-circle outline at height y in its first octant: the algorithm keeps x
    while the midpoint (x - 1/2, y) lies inside the circle, so x is the largest such integer."""
    if y == 0:
        return radius
    d = 4 * (radius * radius - y * y)  # (2x - 1)^2 < d
    if d <= 0:
        return 0
    x = (1 + math.isqrt(d - 1)) // 2
    while x > 0 and (2 * x - 1) ** 2 >= d:
        x -= 1
    while (2 * x + 1) ** 2 < d:
        x += 1
    return x


def _outline_parameters(cx: int, cy: int, radius: int) -> list[int]:
    """The octant parameters y (0 <= y <= x) whose points can be on the screen: every octant
    point has y as its horizontal or vertical offset from the centre."""
    candidates = {abs(px - cx) for px in range(WIDTH)} | {abs(py - cy) for py in range(HEIGHT)}
    return sorted(y for y in candidates if y <= radius and _outline_x(radius, y) >= y)


def _octants(x: int, y: int) -> list[tuple[int, int]]:
    return [(x, y), (y, x), (-y, x), (-x, y), (-x, -y), (-y, -x), (y, -x), (x, -y)]


def create(context) -> list[Component]:
    # The default font is opened now, once per process, not by the first LCDPrintf of a run.
    lcd_fonts.truetype(lcd_fonts.DEFAULT_FONT, NORMAL, lcd_fonts.DEFAULT_SIZE)
    return [Lcd()]
