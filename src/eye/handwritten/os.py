"""The OS functions that do more than pass values through (eye/os.py has the rest): text the C library
writes into a buffer or hands over to be freed."""

from __future__ import annotations

import ctypes
import sys

from eye._library import C, lib
from eye._values import text

__all__ = ["OSExecute", "OSVersion", "OSVersionIO", "OSMachineName"]

TEXT_SIZE = 1024  # room for the strings OSVersion and friends write

# The C library's free(): on Linux and macOS found through libeyesim's own dependencies; a Windows
# DLL shows only its own exports, and eyesim.dll's malloc is the Universal C Runtime's.
_free = ctypes.CDLL("ucrtbase").free if sys.platform == "win32" else lib.free
_free.argtypes, _free.restype = [ctypes.c_void_p], None


def _text_out(function: str) -> str:
    buffer = ctypes.create_string_buffer(TEXT_SIZE)
    getattr(C, function)(buffer)
    return buffer.value.decode("utf-8", errors="replace")


def OSExecute(command: str) -> str | None:
    """Runs a shell command and returns what it printed, or None if it could not be run."""
    output = C.OSExecute(text(command))
    if not output:
        return None
    try:
        return ctypes.string_at(output).decode("utf-8", errors="replace")
    finally:
        _free(output)  # the C library hands over a malloc'd string


def OSVersion(buf: object = None) -> str:
    """The RoBIOS version string. (`buf` is ignored: eye.py took one but could not fill it.)"""
    return _text_out("OSVersion")


def OSVersionIO(buf: object = None) -> str:
    """The version string of the I/O board. (`buf` is ignored, as for OSVersion.)"""
    return _text_out("OSVersionIO")


def OSMachineName(buf: object = None) -> str:
    """The robot's name, from the scene. (`buf` is ignored, as for OSVersion.)"""
    return _text_out("OSMachineName")
