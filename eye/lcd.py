"""LCD: text, the soft-key menu, drawing and images on the robot's 480 x 320 screen."""

from __future__ import annotations

import ctypes

from eye._library import C
from eye._printf import printf
from eye._values import Buffer, c_format, input_buffer, text
from eye.constants import CAM1MP, CAM1MP_X, CAM1MP_Y, CAM5MP, CAM5MP_X, CAM5MP_Y, CAMHD, CAMHD_X, CAMHD_Y, \
    CUSTOM, QQVGA, QQVGA_X, QQVGA_Y, QVGA, QVGA_X, QVGA_Y, VGA, VGA_X, VGA_Y

__all__ = ["LCDPrintf", "LCDSetPrintf", "LCDClear", "LCDSetPos", "LCDGetPos", "LCDSetColor", "LCDSetFont",
           "LCDSetFontSize", "LCDSetMode", "LCDMenu", "LCDMenuI", "LCDGetSize", "LCDPixel", "LCDGetPixel",
           "LCDLine", "LCDArea", "LCDCircle", "LCDImageSize", "LCDImageStart", "LCDImage", "LCDImageGray",
           "LCDImageBinary", "LCDRefresh"]

RESOLUTION_SIZES = {QQVGA: (QQVGA_X, QQVGA_Y), QVGA: (QVGA_X, QVGA_Y), VGA: (VGA_X, VGA_Y),
                    CAM1MP: (CAM1MP_X, CAM1MP_Y), CAMHD: (CAMHD_X, CAMHD_Y), CAM5MP: (CAM5MP_X, CAM5MP_Y)}


def LCDPrintf(format: object, *args: object) -> int:
    """Prints at the text cursor, formatted as C's printf does (every conversion, flag, width,
    precision and length modifier; arguments beyond the format's are ignored). `\\n` starts a
    new line; long lines wrap and the screen scrolls. Returns 0 (1 on error)."""
    return C.LCDPrintf(c_format(printf("LCDPrintf", format, args)))


def LCDSetPrintf(row: int, column: int, format: object, *args: object) -> int:
    """Moves the text cursor to (row, column), then prints as LCDPrintf. Returns 0 (1 on error)."""
    return C.LCDSetPrintf(row, column, c_format(printf("LCDSetPrintf", format, args)))


def LCDClear() -> int:
    """Clears the screen to black and puts the text cursor at (0, 0). Returns 0 (1 on error)."""
    return C.LCDClear()


def LCDSetPos(row: int, column: int) -> int:
    """Moves the text cursor to a text cell. Returns 0 (1 on error)."""
    return C.LCDSetPos(row, column)


def LCDGetPos(row: ctypes.c_int | None = None, column: ctypes.c_int | None = None) -> list[int] | int:
    """The text cursor as [row, column]. Given two ctypes.c_int objects (the eye.py way), fills
    them in and returns 0 (1 on error) instead."""
    r, c = ctypes.c_int(), ctypes.c_int()
    result = C.LCDGetPos(ctypes.byref(r), ctypes.byref(c))
    if row is not None and column is not None:
        row.value, column.value = r.value, c.value
        return result
    return [r.value, c.value]


def LCDSetColor(fg: int, bg: int) -> int:
    """Text colours (0xRRGGBB) for what is printed from now on. Returns 0 (1 on error)."""
    return C.LCDSetColor(fg, bg)


def LCDSetFont(font: int, variation: int) -> int:
    """Text font: HELVETICA, TIMES or COURIER, and NORMAL, BOLD or ITALICS. Returns 0 (1 on error)."""
    return C.LCDSetFont(font, variation)


def LCDSetFontSize(fontsize: int) -> int:
    """Text size in pixels (8 .. 24). Returns 0, or 1 for a size the LCD does not have."""
    return C.LCDSetFontSize(fontsize)


def LCDSetMode(mode: int) -> int:
    """LCD mode flags ORed together (LCD_SCROLLING, LCD_HIDEMENU, ...; 0 = default). Returns 0 (1 on error)."""
    return C.LCDSetMode(mode)


def LCDMenu(st1: str, st2: str, st3: str, st4: str) -> int:
    """Labels of the four soft keys KEY1 .. KEY4 in the menu bar ("" leaves a key blank). Returns 0 (1 on error)."""
    return C.LCDMenu(text(st1), text(st2), text(st3), text(st4))


def LCDMenuI(pos: int, string: str, fg: int, bg: int) -> int:
    """One menu entry (pos 1 .. 4) with its own colours. Returns 0 (1 on error)."""
    return C.LCDMenuI(pos, text(string), fg, bg)


def LCDGetSize() -> list[int]:
    """The screen size in pixels, [width, height]."""
    x, y = ctypes.c_int(), ctypes.c_int()
    C.LCDGetSize(ctypes.byref(x), ctypes.byref(y))
    return [x.value, y.value]


def LCDPixel(x: int, y: int, col: int) -> int:
    """Sets one pixel (0, 0 is the top left corner). Returns 0 (1 on error)."""
    return C.LCDPixel(x, y, col)


def LCDGetPixel(x: int, y: int) -> int:
    """The colour (0xRRGGBB) of one pixel, exactly as drawn."""
    return C.LCDGetPixel(x, y)


def LCDLine(x1: int, y1: int, x2: int, y2: int, col: int) -> int:
    """A line between two points, both included. Returns 0 (1 on error)."""
    return C.LCDLine(x1, y1, x2, y2, col)


def LCDArea(x1: int, y1: int, x2: int, y2: int, col: int, fill: int) -> int:
    """A rectangle from its top left to its bottom right corner; fill 1 filled, 0 outline. Returns 0 (1 on error)."""
    return C.LCDArea(x1, y1, x2, y2, col, fill)


def LCDCircle(x1: int, y1: int, size: int, col: int, fill: int) -> int:
    """A circle around (x1, y1) with radius `size`; fill 1 filled, 0 outline. Returns 0 (1 on error)."""
    return C.LCDCircle(x1, y1, size, col, fill)


# The size in pixels of the images LCDImage* get, mirrored from the C library so that a buffer too
# small for it is refused before C reads past its end. As in EyeSim, LCDImageStart sets it (with
# where the images show); LCDImageSize and CAMInit set it for programs that never call that.
_image_size = [QVGA_X, QVGA_Y]


def LCDImageSize(t: int) -> int:
    """The resolution (QQVGA .. CAM5MP) of the images LCDImage, LCDImageGray and LCDImageBinary
    draw from now on (CAMInit sets it too); CUSTOM keeps the size LCDImageStart gave.
    Returns 0 (1 on error)."""
    result = C.LCDImageSize(t)
    if result == 0 and t in RESOLUTION_SIZES:
        _image_size[:] = RESOLUTION_SIZES[t]
    return result


def LCDImageStart(x: int, y: int, xs: int, ys: int) -> int:
    """Where images are drawn (top left corner x, y) and their size: the next images have xs x ys
    pixels, shown 1:1. Returns 0 (1 on error)."""
    result = C.LCDImageStart(x, y, xs, ys)
    if result == 0:
        _image_size[:] = [xs, ys]
    return result


def _image(function: str, img: Buffer, bytes_per_pixel: int) -> int:
    width, height = _image_size
    buffer = input_buffer(img, width * height * bytes_per_pixel, function, "the image",
                          f"a {width} x {height} image, LCDImageStart/LCDImageSize")
    return getattr(C, function)(buffer)


def LCDImage(img: Buffer) -> int:
    """Draws a colour image (3 bytes per pixel, R G B, of the LCDImageStart/LCDImageSize size). Returns 0 (1 on error)."""
    return _image("LCDImage", img, 3)


def LCDImageGray(g: Buffer) -> int:
    """Draws a gray image (1 byte per pixel, 0 black .. 255 white). Returns 0 (1 on error)."""
    return _image("LCDImageGray", g, 1)


def LCDImageBinary(b: Buffer) -> int:
    """Draws a black and white image (1 byte per pixel: non-zero black, 0 white). Returns 0 (1 on error)."""
    return _image("LCDImageBinary", b, 1)


def LCDRefresh() -> int:
    """Redraws the screen, menu included. Returns 0 (1 on error)."""
    return C.LCDRefresh()
