"""The LCD functions that do more than pass values through (eye/lcd.py has the rest): printf formatting
in Python, the two ways of LCDGetPos, and images checked against the size the program chose."""

from __future__ import annotations

import ctypes

from eye._library import C
from eye._printf import printf
from eye._values import Buffer, c_format, input_buffer
from eye.constants import CAM1MP, CAM1MP_X, CAM1MP_Y, CAM5MP, CAM5MP_X, CAM5MP_Y, CAMHD, CAMHD_X, CAMHD_Y, \
    QQVGA, QQVGA_X, QQVGA_Y, QVGA, QVGA_X, QVGA_Y, VGA, VGA_X, VGA_Y

__all__ = ["LCDPrintf", "LCDSetPrintf", "LCDGetPos", "LCDImageSize", "LCDImageStart", "LCDImage", "LCDImageGray",
           "LCDImageBinary"]

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


def LCDGetPos(row: ctypes.c_int | None = None, column: ctypes.c_int | None = None) -> list[int] | int:
    """The text cursor as [row, column]. Given two ctypes.c_int objects (the eye.py way), fills
    them in and returns 0 (1 on error) instead."""
    r, c = ctypes.c_int(), ctypes.c_int()
    result = C.LCDGetPos(ctypes.byref(r), ctypes.byref(c))
    if row is not None and column is not None:
        row.value, column.value = r.value, c.value
        return result
    return [r.value, c.value]


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
