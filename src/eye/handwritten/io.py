"""The DIGITAL and ANALOG functions that do more than pass values through (eye/io.py has the rest): a
direction given as a character, and the buffer for the recording ANALOGRecord asked for."""

from __future__ import annotations

import ctypes

from eye._library import C

__all__ = ["DIGITALSetup", "ANALOGRecord", "ANALOGTransfer"]

_recording = [0]  # samples asked for by the last ANALOGRecord, for ANALOGTransfer's buffer


def DIGITALSetup(io: int, direction: str | int) -> int:
    """Sets up a digital line (1 .. 16): 'i' input, 'o' output, 'I' input with pull-up, 'J' with
    pull-down. Returns 0 (1 on error)."""
    code = direction if isinstance(direction, int) else ord(str(direction)[:1] or "\0")
    return C.DIGITALSetup(io, bytes([code & 0xFF]))


def ANALOGRecord(channel: int, iterations: int) -> int:
    """Starts recording `iterations` samples of a channel at 1 kHz; never waits. Returns 0 (1 on error)."""
    result = C.ANALOGRecord(channel, iterations)
    if result == 0:
        _recording[0] = max(iterations, 0)
    return result


def ANALOGTransfer() -> bytes:
    """The samples of the last ANALOGRecord once it is complete (waits until then): 2 bytes per
    sample, little-endian."""
    buffer = (ctypes.c_ubyte * max(2 * _recording[0], 1))()
    count = C.ANALOGTransfer(buffer)
    return bytes(buffer[:max(count, 0)])
