"""Conversions between the files' and API's units (mm, degrees) and SI (m, rad)."""

import math

MM = 0.001  # metres per millimetre


def mm(value: float) -> float:
    """Millimetres to metres."""
    return value * MM


def to_mm(value: float) -> float:
    return value / MM


def rad(degrees: float) -> float:
    return math.radians(degrees)


def yaw_quat(phi: float) -> list[float]:
    """Quaternion (w, x, y, z) of a rotation by phi radians about +z."""
    return [math.cos(phi / 2), 0.0, 0.0, math.sin(phi / 2)]


def quat_yaw(quat) -> float:
    """Heading (radians, CCW from +x) of a body with quaternion (w, x, y, z)."""
    w, x, y, z = quat
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def wrap_degrees(angle: float) -> float:
    """Angle in degrees wrapped to (-180, 180]."""
    wrapped = math.fmod(angle + 180.0, 360.0)
    if wrapped <= 0:
        wrapped += 360.0
    return wrapped - 180.0
