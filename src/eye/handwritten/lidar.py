"""LIDARGet returns a new array of as many points as the scan has; LIDARSet only passes values through
(eye/lidar.py)."""

from __future__ import annotations

import ctypes

from eye._library import C, library_int

__all__ = ["LIDARGet"]

LIDAR_POINTS = 360  # the scan size before any LIDARSet, if the library does not say


def LIDARGet() -> ctypes.Array:
    """One LIDAR scan: a new array of distances in mm, as many as LIDARSet asked for (360 at the
    start); index it, or turn it into a list with list(...)."""
    points = library_int("LIDAR_RESOLUTION") or LIDAR_POINTS
    scan = (ctypes.c_int * points)()
    C.LIDARGet(scan)
    return scan
