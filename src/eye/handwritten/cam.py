"""Camera: frames from the robot's virtual camera, returned as new buffers as EyeSim's eye.py did, and the
size CAMInit chose (every CAM function keeps or checks it, so all are written by hand)."""

from __future__ import annotations

import ctypes
import sys

from eye.handwritten import lcd
from eye._library import C, EyeSimError, library_int
from eye._values import Buffer, new_buffer, output_buffer

__all__ = ["CAMInit", "CAMRelease", "CAMGet", "CAMGetGray", "CAMWIDTH", "CAMHEIGHT", "CAMPIXELS", "CAMSIZE"]

# The camera's image size; 0 until CAMInit. `from eye import *` copies these values when it runs,
# so read them as eye.CAMWIDTH (or use QVGA_X, ...) after CAMInit.
CAMWIDTH = CAMHEIGHT = CAMPIXELS = CAMSIZE = 0


def _publish_size(width: int, height: int) -> None:
    values = {"CAMWIDTH": width, "CAMHEIGHT": height, "CAMPIXELS": width * height, "CAMSIZE": 3 * width * height}
    for module in (sys.modules[__name__], sys.modules.get("eye.cam"), sys.modules.get("eye")):
        if module is not None:
            for name, value in values.items():
                setattr(module, name, value)


def CAMInit(resolution: int) -> int:
    """Starts the camera at a resolution (QQVGA .. CAM5MP) and makes it the IP size and the
    LCDImage size. Sets CAMWIDTH, CAMHEIGHT, CAMPIXELS and CAMSIZE. Returns 0 (non-zero on error)."""
    result = C.CAMInit(resolution)
    if result == 0:
        width, height = library_int("CAMWIDTH"), library_int("CAMHEIGHT")
        if width is None or height is None:
            width, height = lcd.RESOLUTION_SIZES[resolution]
        _publish_size(width, height)
        lcd._image_size[:] = [width, height]  # CAMInit calls LCDImageSize(resolution)
    return result


def CAMRelease() -> int:
    """Stops the camera. Returns 0 (non-zero on error)."""
    result = C.CAMRelease()
    if result == 0:
        _publish_size(0, 0)
    return result


def _frame(function: str, buf: Buffer | None, bytes_per_pixel: int) -> ctypes.Array | int:
    pixels = CAMWIDTH * CAMHEIGHT
    if pixels == 0:
        raise EyeSimError(f"{function}: the camera is not started; call CAMInit first")
    size = pixels * bytes_per_pixel
    why = f"a {CAMWIDTH} x {CAMHEIGHT} frame"
    if buf is None:
        frame = new_buffer(size)
        getattr(C, function)(frame)  # an error is reported by the C library; the frame stays black
        return frame
    return getattr(C, function)(output_buffer(buf, size, function, "the buffer", why))


def CAMGet(buf: Buffer | None = None) -> ctypes.Array | int:
    """A new colour frame: CAMSIZE bytes, R G B per pixel, row by row from the top left (values
    0 .. 255). Given a writable buffer, fills that instead and returns 0 (non-zero on error)."""
    return _frame("CAMGet", buf, 3)


def CAMGetGray(buf: Buffer | None = None) -> ctypes.Array | int:
    """A new gray frame: CAMPIXELS bytes, one per pixel. Given a writable buffer, fills that
    instead and returns 0 (non-zero on error)."""
    return _frame("CAMGetGray", buf, 1)
