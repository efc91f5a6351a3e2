# Submarine dive (the Python version of submarine_dive.c): Minnow (the built-in Minnow) goes to
# 500 mm under the surface of its pool (it is as heavy as the water it displaces, so it starts on the
# pool floor and rises there), holds that depth with its vertical thrusters (3 front, 4 back) while
# it cruises and turns on its horizontal ones (1 left, 2 right), then surfaces. Depth comes from
# SIMGetRobot. From the examples folder:
#   eyesim run scenes/pool.sim --program 1=programs/submarine_dive.py
from eye import *

SURFACE = 1500  # mm: the pool's rim
HEIGHT = 200  # mm: Minnow's hull


def depth():
    """How far the hull's top is under the surface, mm."""
    x, y, z, phi = SIMGetRobot(0)
    return SURFACE - (z + HEIGHT)


def clamp(value, low, high):
    return max(low, min(high, value))


def hold_depth(target, ms, left, right):
    last = depth()
    for t in range(0, ms, 50):
        now = depth()
        # too deep: push up; damped by the rate (integer division as C's: towards zero)
        push = clamp(int((now - target) / 4) + (now - last) * 2, -100, 100)
        MOTORDrive(3, push)
        MOTORDrive(4, push)
        MOTORDrive(1, left)
        MOTORDrive(2, right)
        last = now
        OSWait(50)


LCDPrintf("Going to 500 mm depth\n")
hold_depth(500, 6000, 0, 0)  # to 0.5 m under the surface
LCDPrintf("depth %d mm, cruising\n", depth())
print("dived", depth())
hold_depth(500, 4000, 60, 60)  # ahead
hold_depth(500, 3000, 50, -50)  # turning right
hold_depth(500, 1000, 0, 0)
LCDPrintf("depth %d mm, surfacing\n", depth())
print("cruised", depth())
MOTORDrive(1, 0)
MOTORDrive(2, 0)
MOTORDrive(3, 100)
MOTORDrive(4, 100)
OSWait(3000)
MOTORDrive(3, 0)
MOTORDrive(4, 0)
OSWait(2000)
LCDPrintf("at the surface: depth %d mm\n", depth())
print("surfaced", depth())
