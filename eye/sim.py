"""Simulation only: true poses of robots and objects, as the simulator knows them."""

from __future__ import annotations

import ctypes

from eye._library import C
from eye._values import CInt

__all__ = ["SIMGetRobot", "SIMSetRobot", "SIMGetObject", "SIMSetObject", "SIMGetRobotCount", "SIMGetObjectCount"]


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


def SIMSetRobot(id: int, x: int, y: int, z: int, phi: int) -> int:
    """Moves a robot to a pose at once. Returns 0 (non-zero for an unknown id)."""
    return C.SIMSetRobot(id, x, y, z, phi)


def SIMGetObject(id: int) -> list[CInt] | None:
    """The true pose [x mm, y mm, z mm, phi degrees] of an object (1.. in scene order), or None
    for an unknown id."""
    return _pose("SIMGetObject", id)


def SIMSetObject(id: int, x: int, y: int, z: int, phi: int) -> int:
    """Moves an object to a pose at once. Returns 0 (non-zero for an unknown id)."""
    return C.SIMSetObject(id, x, y, z, phi)


def SIMGetRobotCount() -> int:
    """The number of robots in the scene."""
    return C.SIMGetRobotCount()


def SIMGetObjectCount() -> int:
    """The number of objects (not robots) in the scene."""
    return C.SIMGetObjectCount()
