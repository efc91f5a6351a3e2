"""Distance sensors: PSDs and the LIDAR."""

from __future__ import annotations

import ctypes

from eye._library import C, library_int

__all__ = ["PSDGet", "PSDGetRaw", "LIDARGet", "LIDARSet"]

LIDAR_POINTS = 360  # the scan size before any LIDARSet, if the library does not say


def PSDGet(psd: int) -> int:
    """The distance in mm that a PSD sensor (PSD_FRONT, PSD_LEFT, ... or 1 .. 6) measures (-1 on error)."""
    return C.PSDGet(psd)


def PSDGetRaw(psd: int) -> int:
    """The raw value of a PSD sensor (-1 on error)."""
    return C.PSDGetRaw(psd)


def LIDARGet() -> ctypes.Array:
    """One LIDAR scan: a new array of distances in mm, as many as LIDARSet asked for (360 at the
    start); index it, or turn it into a list with list(...)."""
    points = library_int("LIDAR_RESOLUTION") or LIDAR_POINTS
    scan = (ctypes.c_int * points)()
    C.LIDARGet(scan)
    return scan


def LIDARSet(range: int, tilt: int, points: int) -> int:
    """The scan: field of view in degrees (1 .. 360, centred ahead), tilt in degrees, number of points.
    Returns 0 (1 on error)."""
    return C.LIDARSet(range, tilt, points)
