"""SIMGetRobot and SIMGetObject: the pose as a list of ints that also have `.value` (as eye.py's c_ints),
or None for an unknown id; the other SIM functions only pass values through (eye/sim.py)."""

from __future__ import annotations

import ctypes

from eye._library import C
from eye._values import CInt

__all__ = ["SIMGetRobot", "SIMGetObject"]


def _pose(function: str, id: int) -> list[CInt] | None:
    values = [ctypes.c_int() for _ in range(4)]
    if getattr(C, function)(id, *(ctypes.byref(v) for v in values)) != 0:
        return None
    return [CInt(v.value) for v in values]


def SIMGetRobot(id: int) -> list[CInt] | None:
    """The true pose [x mm, y mm, z mm, phi degrees] of a robot (0 = this program's robot, 1.. in
    scene order), or None for an unknown id. The values are ints that also have `.value`, as
    eye.py's c_ints had."""
    return _pose("SIMGetRobot", id)


def SIMGetObject(id: int) -> list[CInt] | None:
    """The true pose [x mm, y mm, z mm, phi degrees] of an object (1.. in scene order), or None
    for an unknown id."""
    return _pose("SIMGetObject", id)
