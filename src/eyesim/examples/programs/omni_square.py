# Omni square (the Python version of omni_square.c): the mecanum robot (the built-in Mecanum) drives a
# 600 mm square facing the same way all along: back, right, ahead, left. Motors 1..4 = front left,
# front right, back left, back right; each leg is measured with the encoders. It is robot 2 of the
# drive-types scene; from the examples folder, with the other two:
#   eyesim run scenes/drive_types.sim --program 1=programs/car_slalom.py --program 2=programs/omni_square.py --program 3=programs/push_crate.py
from eye import *

TICKS_PER_MM = 720 / (3.14159265 * 60)  # 720 ticks per turn of a 60 mm wheel


def leg(direction, mm):
    for motor in range(1, 5):
        ENCODERReset(motor)
        MOTORSpeed(motor, direction[motor - 1] * 600)
    done = False
    while not done:
        OSWait(5)
        total = sum(abs(ENCODERRead(motor)) for motor in range(1, 5))
        done = total // 4 >= mm * TICKS_PER_MM
    for motor in range(1, 5):
        MOTORSpeed(motor, 0)
    OSWait(300)


LCDPrintf("Omni square\n")
leg([-1, -1, -1, -1], 600)  # back
leg([1, -1, -1, 1], 600)  # right
leg([1, 1, 1, 1], 600)  # ahead
leg([-1, 1, 1, -1], 600)  # left
LCDPrintf("back at the start\n")
