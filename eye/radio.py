"""Radio: messages between robots."""

from __future__ import annotations

import ctypes

from eye._library import C
from eye._values import text

__all__ = ["RADIOInit", "RADIOGetID", "RADIOSend", "RADIOReceive", "RADIOCheck", "RADIOStatus", "RADIORelease"]

MESSAGE_SIZE = 1024  # the longest message
MAX_ROBOTS = 256


def RADIOInit() -> int:
    """Turns the radio on. Returns 0 (1 on error)."""
    return C.RADIOInit()


def RADIOGetID() -> int:
    """This robot's radio id."""
    return C.RADIOGetID()


def RADIOSend(id: int, buf: str | bytes) -> int:
    """Sends a message (text) to the robot with radio id `id`. Returns 0 (1 on error)."""
    return C.RADIOSend(id, text(buf))


def RADIOReceive() -> list:
    """Waits for a message and returns [sender id, message text]."""
    sender = ctypes.c_int()
    buffer = ctypes.create_string_buffer(MESSAGE_SIZE + 1)
    C.RADIOReceive(ctypes.byref(sender), buffer, MESSAGE_SIZE + 1)
    return [sender.value, buffer.value.decode("utf-8", errors="replace")]


def RADIOCheck() -> int:
    """1 if a message is waiting, 0 if not; never waits."""
    return C.RADIOCheck()


def RADIOStatus() -> list:
    """[count, ids]: how many robots have their radio on (this one included) and an array of their ids."""
    ids = (ctypes.c_int * MAX_ROBOTS)()
    count = C.RADIOStatus(ids)
    return [count, ids]


def RADIORelease() -> int:
    """Turns the radio off. Returns 0 (1 on error)."""
    return C.RADIORelease()
