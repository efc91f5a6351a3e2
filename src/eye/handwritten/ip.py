"""Image processing, done by the C library on images of the IP size (IPSetSize, or CAMInit).

Functions that make an image return a new buffer (as EyeSim's eye.py did); most also take an
optional output buffer to fill instead, as in C. IPSetSize only passes its value through (eye/ip.py)."""

from __future__ import annotations

import ctypes
import os

from eye._library import C, library_int
from eye._values import Buffer, input_buffer, new_buffer, output_buffer, path

__all__ = ["IPReadFile", "IPWriteFile", "IPWriteFileGray", "IPLaplace", "IPSobel", "IPCol2Gray", "IPGray2Col",
           "IPRGB2Col", "IPCol2HSI", "IPOverlay", "IPOverlayGray", "IPPRGB2Col", "IPPCol2RGB", "IPPCol2HSI",
           "IPPRGB2Hue", "IPPRGB2HSI"]


def _size() -> tuple[int, int, str]:
    """Pixels and colour bytes of the current IP size, and words saying what it is."""
    width, height = library_int("IP_WIDTH"), library_int("IP_HEIGHT")
    assert width is not None and height is not None, "libeyesim exports IP_WIDTH and IP_HEIGHT"
    return width * height, 3 * width * height, f"the IP size is {width} x {height}"


def _gray(function: str, data: Buffer, what: str) -> ctypes.Array:
    pixels, _, why = _size()
    return input_buffer(data, pixels, function, what, why)


def _colour(function: str, data: Buffer, what: str) -> ctypes.Array:
    _, size, why = _size()
    return input_buffer(data, size, function, what, why)


def _out(function: str, data: Buffer | None, colour: bool) -> ctypes.Array:
    pixels, size, why = _size()
    return output_buffer(data, size if colour else pixels, function, "the output image", why)


def IPReadFile(filename: str | os.PathLike, img: Buffer | None = None) -> list | int:
    """Reads a PNM file (P1 .. P6), cropped or filled with black to the IP size. Returns [code, image]:
    code 3 and a colour image for P3/P6, 2 and a gray image for P2/P5, 1 and a gray image of 0 (black)
    and 255 (white) for P1/P4, or [-1, None] on error (the C library says why on stderr). Given a
    writable buffer of the colour size, fills that and returns only the code, as in C."""
    pixels, size, why = _size()
    buffer = output_buffer(img, size, "IPReadFile", "the image buffer", why)
    code = C.IPReadFile(path(filename), buffer)
    if img is not None:
        return code
    if code < 0:
        return [code, None]
    if code == 3:
        return [code, buffer]
    gray = new_buffer(pixels)
    ctypes.memmove(gray, buffer, pixels)
    return [code, gray]


def IPWriteFile(filename: str | os.PathLike, img: Buffer) -> int:
    """Writes a colour image as a binary PPM (P6) file. Returns 0 (1 on error)."""
    return C.IPWriteFile(path(filename), _colour("IPWriteFile", img, "the image"))


def IPWriteFileGray(filename: str | os.PathLike, gray: Buffer) -> int:
    """Writes a gray image as a binary PGM (P5) file. Returns 0 (1 on error)."""
    return C.IPWriteFileGray(path(filename), _gray("IPWriteFileGray", gray, "the gray image"))


def IPLaplace(grayIn: Buffer, grayOut: Buffer | None = None) -> ctypes.Array:
    """Laplace edges of a gray image: |4 x centre - its 4 neighbours|, at most 255; the border is 0."""
    out = _out("IPLaplace", grayOut, colour=False)
    C.IPLaplace(_gray("IPLaplace", grayIn, "the gray image"), out)
    return out


def IPSobel(grayIn: Buffer, grayOut: Buffer | None = None) -> ctypes.Array:
    """Sobel edges of a gray image: (|gx| + |gy|) / 3, at most 255; the border is 0."""
    out = _out("IPSobel", grayOut, colour=False)
    C.IPSobel(_gray("IPSobel", grayIn, "the gray image"), out)
    return out


def IPCol2Gray(imgIn: Buffer, grayOut: Buffer | None = None) -> ctypes.Array:
    """A colour image in gray: (r + g + b) / 3 per pixel."""
    out = _out("IPCol2Gray", grayOut, colour=False)
    C.IPCol2Gray(_colour("IPCol2Gray", imgIn, "the colour image"), out)
    return out


def IPGray2Col(imgIn: Buffer, colOut: Buffer | None = None) -> ctypes.Array:
    """A gray image as a colour image (r = g = b = gray)."""
    out = _out("IPGray2Col", colOut, colour=True)
    C.IPGray2Col(_gray("IPGray2Col", imgIn, "the gray image"), out)
    return out


def IPRGB2Col(r: Buffer, g: Buffer, b: Buffer, imgOut: Buffer | None = None) -> ctypes.Array:
    """One colour image from three planes of red, green and blue (1 byte per pixel each)."""
    out = _out("IPRGB2Col", imgOut, colour=True)
    C.IPRGB2Col(_gray("IPRGB2Col", r, "the red plane"), _gray("IPRGB2Col", g, "the green plane"),
                _gray("IPRGB2Col", b, "the blue plane"), out)
    return out


def IPCol2HSI(img: Buffer) -> list[ctypes.Array]:
    """A colour image as three planes [H, S, I] (1 byte per pixel each; see IPPRGB2HSI)."""
    planes = [_out("IPCol2HSI", None, colour=False) for _ in range(3)]
    C.IPCol2HSI(_colour("IPCol2HSI", img, "the colour image"), *planes)
    return planes


def IPOverlay(c1: Buffer, c2: Buffer, cOut: Buffer | None = None) -> ctypes.Array:
    """Colour image c1 with the pixels of c2 that are not black on top."""
    out = _out("IPOverlay", cOut, colour=True)
    C.IPOverlay(_colour("IPOverlay", c1, "the first image"), _colour("IPOverlay", c2, "the second image"), out)
    return out


def IPOverlayGray(g1: Buffer, g2: Buffer, col: int, cOut: Buffer | None = None) -> ctypes.Array:
    """Gray image g1 as a colour image, with the pixels where g2 is not 0 in colour `col`."""
    out = _out("IPOverlayGray", cOut, colour=True)
    C.IPOverlayGray(_gray("IPOverlayGray", g1, "the gray image"), _gray("IPOverlayGray", g2, "the mask"), col, out)
    return out


def _bytes3(function: str, r: int, g: int, b: int) -> tuple[int, int, int]:
    """r, g, b as C BYTEs; -128 .. -1 are taken as the bytes 128 .. 255 (eye.py's signed pixels)."""
    for name, value in zip("rgb", (r, g, b)):
        if not -128 <= value <= 255:
            raise ValueError(f"{function}: {name} = {value} is not a byte value (0 .. 255)")
    return r & 0xFF, g & 0xFF, b & 0xFF


def IPPRGB2Col(r: int, g: int, b: int) -> int:
    """Red, green and blue (0 .. 255) as one colour 0xRRGGBB."""
    return C.IPPRGB2Col(*_bytes3("IPPRGB2Col", r, g, b))


def _three_bytes() -> list[ctypes.c_ubyte]:
    return [ctypes.c_ubyte() for _ in range(3)]


def IPPCol2RGB(col: int) -> list[int]:
    """A colour 0xRRGGBB as [r, g, b]."""
    r, g, b = _three_bytes()
    C.IPPCol2RGB(col, ctypes.byref(r), ctypes.byref(g), ctypes.byref(b))
    return [r.value, g.value, b.value]


def IPPCol2HSI(c: int) -> list[int]:
    """A colour 0xRRGGBB as [hue, saturation, intensity] (see IPPRGB2HSI)."""
    h, s, i = _three_bytes()
    C.IPPCol2HSI(c, ctypes.byref(h), ctypes.byref(s), ctypes.byref(i))
    return [h.value, s.value, i.value]


def IPPRGB2Hue(r: int, g: int, b: int) -> int:
    """The hue of a colour: 1 .. 252 around the colour circle (red 42, green 126, blue 210), 0 for gray."""
    return C.IPPRGB2Hue(*_bytes3("IPPRGB2Hue", r, g, b))


def IPPRGB2HSI(r: int, g: int, b: int) -> list[int]:
    """[hue, saturation, intensity] of a colour: hue as IPPRGB2Hue, saturation 255 x (1 - min / mean),
    intensity the mean of r, g and b."""
    h, s, i = _three_bytes()
    C.IPPRGB2HSI(*_bytes3("IPPRGB2HSI", r, g, b), ctypes.byref(h), ctypes.byref(s), ctypes.byref(i))
    return [h.value, s.value, i.value]
