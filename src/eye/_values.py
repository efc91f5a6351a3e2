"""Converting between Python values and what the C functions take: byte buffers, strings, key codes."""

from __future__ import annotations

import ctypes
import os
from typing import Any

# An image or data buffer: what CAMGet and the IP functions return (a ctypes array of c_ubyte), or
# any other bytes-like object (bytes, bytearray, memoryview, a numpy uint8 array, a c_byte array),
# or a sequence of ints 0..255. Which one is checked when it is used, so to the type checker it is Any.
Buffer = Any


class CInt(int):
    """An int that also has `.value`, for programs written for EyeSim's eye.py, which returned
    ctypes c_int objects from some functions (SIMGetRobot)."""

    @property
    def value(self) -> int:
        return int(self)


def new_buffer(size: int) -> ctypes.Array:
    """A zeroed buffer of `size` bytes (c_ubyte, values 0..255)."""
    return (ctypes.c_ubyte * size)()


def _size_error(function: str, what: str, have: int, need: int, why: str) -> ValueError:
    return ValueError(f"{function}: {what} has {have} bytes, but {need} are needed ({why})")


def input_buffer(data: Buffer, size: int, function: str, what: str, why: str) -> ctypes.Array:
    """`data` as a C byte array of at least `size` bytes for a function that only reads it
    (without copying when it is a writable buffer)."""
    if isinstance(data, (str, int, float)) or data is None:
        raise TypeError(f"{function}: {what} must be an image buffer (as CAMGet returns), not {type(data).__name__}")
    try:
        view = memoryview(data)
    except TypeError:
        try:
            data = bytes(value & 0xFF for value in data)  # a list of ints (negative ones as c_byte had them)
        except TypeError:
            raise TypeError(
                f"{function}: {what} must be an image buffer or a sequence of ints, not {type(data).__name__}"
            ) from None
        view = memoryview(data)
    if view.nbytes < size:
        raise _size_error(function, what, view.nbytes, size, why)
    if not view.readonly and view.c_contiguous:
        return (ctypes.c_ubyte * view.nbytes).from_buffer(data)
    return (ctypes.c_ubyte * view.nbytes).from_buffer_copy(view.tobytes())


def output_buffer(data: Buffer | None, size: int, function: str, what: str, why: str) -> ctypes.Array:
    """A C byte array the function writes into: `data` itself, or a new one when it is None."""
    if data is None:
        return new_buffer(size)
    try:
        view = memoryview(data)
    except TypeError:
        raise TypeError(
            f"{function}: {what} must be a writable buffer (bytearray, ctypes array, numpy array), "
            f"not {type(data).__name__}"
        ) from None
    if view.readonly or not view.c_contiguous:
        raise TypeError(f"{function}: {what} must be a writable, contiguous buffer")
    if view.nbytes < size:
        raise _size_error(function, what, view.nbytes, size, why)
    return (ctypes.c_ubyte * view.nbytes).from_buffer(data)


def text(value: object) -> bytes:
    """A string argument for C: UTF-8 (as the C library sends text to the simulator)."""
    if isinstance(value, bytes):
        return value
    return str(value).encode("utf-8", errors="replace")


def path(value: str | os.PathLike | bytes) -> bytes:
    """A file name argument for C, in the file system's encoding."""
    return os.fsencode(value)


def c_format(text_: str) -> bytes:
    """Text for a C printf-style function, with every % doubled so that C prints it unchanged."""
    return text(text_).replace(b"%", b"%%")


def key_code(value: int) -> int:
    """A key code as an unsigned 32-bit number, so that ANYKEY and KEY_ESCAPE compare equal."""
    return value & 0xFFFFFFFF


def signed32(value: int) -> int:
    """An unsigned 32-bit constant (ANYKEY) as the C int it stands for."""
    value &= 0xFFFFFFFF
    return value - (1 << 32) if value >= 1 << 31 else value
