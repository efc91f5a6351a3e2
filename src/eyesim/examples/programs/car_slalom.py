# Car slalom (the Python version of car_slalom.c): the Ackermann car (the built-in Car) drives ahead,
# steering left and right in turn. Motor 1 drives the rear axle; servo 1 steers: 0 = 45 deg left,
# 127 = ahead, 255 = right. The car is robot 1 of the drive-types scene; from the examples folder,
# with the other two:
#   eyesim run scenes/drive_types.sim --program 1=programs/car_slalom.py --program 2=programs/omni_square.py --program 3=programs/push_crate.py
from eye import *

LCDPrintf("Car slalom\n")
MOTORDrive(1, 30)
# about 15 degrees left, right, left, right; the first and last swings are half as long, so the car
# weaves about a straight line east
for turn, ms in enumerate([600, 1200, 1200, 600]):
    SERVOSet(1, 170 if turn % 2 else 84)
    OSWait(ms)
SERVOSet(1, 127)
OSWait(500)
MOTORDrive(1, 0)
LCDPrintf("done, axle turned %d ticks\n", ENCODERRead(1))
print("axle", ENCODERRead(1))
