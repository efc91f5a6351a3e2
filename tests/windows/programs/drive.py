"""Windows test program (Python): writes on the LCD, drives 400 mm ahead, turns 90 degrees left and
prints where its odometry says it is."""

from eye import *

LCDPrintf("Windows Python\n")
LCDArea(380, 200, 459, 259, RED, 1)
VWStraight(400, 300)
VWWait()
VWTurn(90, 90)
VWWait()
x, y, phi = VWGetPosition()
LCDPrintf("x=%d y=%d phi=%d\n", x, y, phi)
print(f"odometry {x} {y} {phi}", flush=True)
