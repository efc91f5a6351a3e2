"""The RADIO functions that return what C writes into buffers (eye/radio.py has the rest)."""

from __future__ import annotations

import ctypes

from eye._library import C

__all__ = ["RADIOReceive", "RADIOStatus"]

MESSAGE_SIZE = 1024  # the longest message
MAX_ROBOTS = 256


def RADIOReceive() -> list:
    """Waits for a message and returns [sender id, message text]."""
    sender = ctypes.c_int()
    buffer = ctypes.create_string_buffer(MESSAGE_SIZE + 1)
    C.RADIOReceive(ctypes.byref(sender), buffer, MESSAGE_SIZE + 1)
    return [sender.value, buffer.value.decode("utf-8", errors="replace")]


def RADIOStatus() -> list:
    """[count, ids]: how many robots have their radio on (this one included) and an array of their ids."""
    ids = (ctypes.c_int * MAX_ROBOTS)()
    count = C.RADIOStatus(ids)
    return [count, ids]
