"""V-omega driving: mm, mm/s, degrees (counter-clockwise positive) and degrees/s."""

from __future__ import annotations

import ctypes

from eye._library import C

__all__ = ["VWSetSpeed", "VWGetSpeed", "VWSetPosition", "VWGetPosition", "VWStraight", "VWTurn", "VWCurve",
           "VWDrive", "VWRemain", "VWDone", "VWWait", "VWStalled", "VWDriveRemain", "VWDriveDone", "VWDriveWait"]


def VWSetSpeed(linSpeed: int, angSpeed: int) -> int:
    """Drives on at linSpeed mm/s turning at angSpeed degrees/s until changed; (0, 0) stops.
    Returns 0 (1 on error)."""
    return C.VWSetSpeed(linSpeed, angSpeed)


def VWGetSpeed() -> list[int]:
    """The measured speeds [mm/s, degrees/s]."""
    lin, ang = ctypes.c_int(), ctypes.c_int()
    C.VWGetSpeed(ctypes.byref(lin), ctypes.byref(ang))
    return [lin.value, ang.value]


def VWSetPosition(x: int, y: int, phi: int) -> int:
    """Overwrites the odometry pose (mm, mm, degrees); the robot does not move. Returns 0 (1 on error)."""
    return C.VWSetPosition(x, y, phi)


def VWGetPosition() -> list[int]:
    """The odometry pose [x mm, y mm, phi degrees]."""
    x, y, phi = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
    C.VWGetPosition(ctypes.byref(x), ctypes.byref(y), ctypes.byref(phi))
    return [x.value, y.value, phi.value]


def VWStraight(dist: int, lin_speed: int) -> int:
    """Starts driving dist mm (negative: backwards) at lin_speed mm/s; VWWait waits for the end.
    Returns 0 (1 on error)."""
    return C.VWStraight(dist, lin_speed)


def VWTurn(angle: int, ang_speed: int) -> int:
    """Starts turning on the spot by angle degrees at ang_speed degrees/s. Returns 0 (1 on error)."""
    return C.VWTurn(angle, ang_speed)


def VWCurve(dist: int, angle: int, lin_speed: int) -> int:
    """Starts driving an arc of dist mm that changes the heading by angle degrees. Returns 0 (1 on error)."""
    return C.VWCurve(dist, angle, lin_speed)


def VWDrive(dx: int, dy: int, lin_speed: int) -> int:
    """Starts driving along a curve to the point dx mm ahead, dy mm to the left. Returns 0 (1 on error)."""
    return C.VWDrive(dx, dy, lin_speed)


def VWRemain() -> int:
    """The distance in mm the current manoeuvre still has to go."""
    return C.VWRemain()


def VWDone() -> int:
    """1 when the manoeuvre has finished, 0 while driving (-1 on error)."""
    return C.VWDone()


def VWWait() -> int:
    """Waits until the manoeuvre ends. Returns 0 (1 on error)."""
    return C.VWWait()


def VWStalled() -> int:
    """Which wheels are stalled: 0 none, 1 left, 2 right, 3 both."""
    return C.VWStalled()


def VWDriveRemain() -> int:
    """Older name of VWRemain."""
    return C.VWDriveRemain()


def VWDriveDone() -> int:
    """Older name of VWDone."""
    return C.VWDriveDone()


def VWDriveWait() -> int:
    """Older name of VWWait."""
    return C.VWDriveWait()
