"""Digital and analog I/O: 16 digital lines and 8 analog channels per robot, and the battery voltage."""

from __future__ import annotations

import ctypes

from eye._library import C

__all__ = ["DIGITALSetup", "DIGITALRead", "DIGITALReadAll", "DIGITALWrite", "ANALOGRead", "ANALOGVoltage",
           "ANALOGRecord", "ANALOGTransfer"]

_recording = [0]  # samples asked for by the last ANALOGRecord, for ANALOGTransfer's buffer


def DIGITALSetup(io: int, direction: str | int) -> int:
    """Sets up a digital line (1 .. 16): 'i' input, 'o' output, 'I' input with pull-up, 'J' with
    pull-down. Returns 0 (1 on error)."""
    code = direction if isinstance(direction, int) else ord(str(direction)[:1] or "\0")
    return C.DIGITALSetup(io, bytes([code & 0xFF]))


def DIGITALRead(io: int) -> int:
    """The level of a digital line (0 or 1)."""
    return C.DIGITALRead(io)


def DIGITALReadAll() -> int:
    """The levels of all 16 lines as bits (bit 0 = line 1)."""
    return C.DIGITALReadAll()


def DIGITALWrite(io: int, state: int) -> int:
    """Sets an output line to 0 or 1. Returns 0 (1 on error)."""
    return C.DIGITALWrite(io, state)


def ANALOGRead(channel: int) -> int:
    """The value of an analog channel (1 .. 8)."""
    return C.ANALOGRead(channel)


def ANALOGVoltage() -> int:
    """The battery voltage in 0.01 V (-1 on error)."""
    return C.ANALOGVoltage()


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
