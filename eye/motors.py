"""Servos, motors and their encoders."""

from __future__ import annotations

from eye._library import C

__all__ = ["SERVOSet", "SERVOSetRaw", "SERVORange", "MOTORDrive", "MOTORDriveRaw", "MOTORPID", "MOTORPIDOff",
           "MOTORSpeed", "ENCODERRead", "ENCODERReset"]


def SERVOSet(servo: int, angle: int) -> int:
    """Moves a servo (1 .. 14) to a position 0 .. 255. Returns 0 (1 on error)."""
    return C.SERVOSet(servo, angle)


def SERVOSetRaw(servo: int, angle: int) -> int:
    """Moves a servo to a raw position 0 .. 255, bypassing its calibration. Returns 0 (1 on error)."""
    return C.SERVOSetRaw(servo, angle)


def SERVORange(servo: int, low: int, high: int) -> int:
    """The limits of a servo's travel. Returns 0 (1 on error)."""
    return C.SERVORange(servo, low, high)


def MOTORDrive(motor: int, speed: int) -> int:
    """Drives a motor (1 .. 4) at -100 .. 100 percent. Returns 0 (1 on error)."""
    return C.MOTORDrive(motor, speed)


def MOTORDriveRaw(motor: int, speed: int) -> int:
    """Drives a motor at -100 .. 100, bypassing its calibration. Returns 0 (1 on error)."""
    return C.MOTORDriveRaw(motor, speed)


def MOTORPID(motor: int, p: int, i: int, d: int) -> int:
    """Turns on speed control of a motor with these gains. Returns 0 (1 on error)."""
    return C.MOTORPID(motor, p, i, d)


def MOTORPIDOff(motor: int) -> int:
    """Turns off a motor's speed control. Returns 0 (1 on error)."""
    return C.MOTORPIDOff(motor)


def MOTORSpeed(motor: int, ticks: int) -> int:
    """The speed a controlled motor keeps, in encoder ticks. Returns 0 (1 on error)."""
    return C.MOTORSpeed(motor, ticks)


def ENCODERRead(quad: int) -> int:
    """The tick count of an encoder (1 .. 4)."""
    return C.ENCODERRead(quad)


def ENCODERReset(quad: int) -> int:
    """Sets an encoder's count to 0. Returns 0 (1 on error)."""
    return C.ENCODERReset(quad)
