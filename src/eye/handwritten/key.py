"""Keys: every KEY function is written by hand, because key codes are unsigned in Python (ANYKEY =
0xFFFFFFFF) and the touch functions also fill in ctypes ints, the eye.py way."""

from __future__ import annotations

import ctypes

from eye._library import C
from eye._values import key_code, signed32

__all__ = ["KEYGet", "KEYRead", "KEYWait", "KEYGetXY", "KEYReadXY"]


def KEYGet() -> int:
    """Waits for a soft key and returns it: KEY1, KEY2, KEY3 or KEY4 (NOKEY on error)."""
    return key_code(C.KEYGet())


def KEYRead() -> int:
    """The soft key pressed since the last call, or NOKEY; never waits."""
    return key_code(C.KEYRead())


def KEYWait(key: int) -> int:
    """Waits for the given key (or any of several ORed together; ANYKEY for any key), ignoring
    others, and returns the key pressed."""
    return key_code(C.KEYWait(signed32(key)))


def _xy(function: str, x: ctypes.c_int | None, y: ctypes.c_int | None) -> tuple[int, int, int]:
    cx, cy = ctypes.c_int(), ctypes.c_int()
    result = getattr(C, function)(ctypes.byref(cx), ctypes.byref(cy))
    if x is not None and y is not None:
        x.value, y.value = cx.value, cy.value
    return result, cx.value, cy.value


def KEYGetXY(x: ctypes.c_int | None = None, y: ctypes.c_int | None = None) -> list[int] | int:
    """Waits for a touch (a click) on the LCD and returns its pixel position [x, y]. Given two
    ctypes.c_int objects (the eye.py way), fills them in and returns 0 instead."""
    result, cx, cy = _xy("KEYGetXY", x, y)
    return result if x is not None and y is not None else [cx, cy]


def KEYReadXY(x: ctypes.c_int | None = None, y: ctypes.c_int | None = None) -> list[int] | None | int:
    """The position [x, y] of a touch on the LCD since the last call, or None; never waits. Given
    two ctypes.c_int objects (the eye.py way), fills them in and returns 0 for a touch, 1 for none."""
    result, cx, cy = _xy("KEYReadXY", x, y)
    if x is not None and y is not None:
        return result
    return [cx, cy] if result == 0 else None
