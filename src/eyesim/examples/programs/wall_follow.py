# Wall following with PSDs (the Python version of wall_follow.c): S4 keeps the wall on its left at
# DISTANCE mm and turns right where a wall blocks the way. Runs for RUN_SECONDS (or until KEY4) and
# shows the readings on the LCD. From the examples folder:
#   eyesim run scenes/wall_follow.sim --program 1=programs/wall_follow.py
from eye import *

DISTANCE = 200  # mm between the left PSD and the wall
SPEED = 200  # mm/s along the wall
GAIN = 0.6  # deg/s of turn per mm of error
DAMPING = 0.4  # deg/s of turn per mm/s the error changes by: stops the robot weaving
PERIOD = 20  # ms between readings
MAX_TURN = 90  # deg/s
RUN_SECONDS = 60


def clamp(value, low, high):
    return max(low, min(high, value))


def main():
    LCDMenu("", "", "", "END")
    LCDSetPrintf(0, 0, "Wall following: left wall at %d mm", DISTANCE)
    start = OSGetCount()
    last_error = 0
    while KEYRead() != KEY4 and OSGetCount() - start < RUN_SECONDS * 1000:
        front, left = PSDGet(PSD_FRONT), PSDGet(PSD_LEFT)
        if front < DISTANCE + 60:
            VWSetSpeed(0, -MAX_TURN)  # a wall ahead: turn right on the spot
        else:
            # too far from the wall (or none there): steer left; too close: steer right
            error = clamp(left - DISTANCE, -150, 150)
            change = (error - last_error) * 1000.0 / PERIOD  # mm/s
            last_error = error
            VWSetSpeed(SPEED, clamp(int(GAIN * error + DAMPING * change), -MAX_TURN, MAX_TURN))
        LCDSetPrintf(2, 0, "front %4d mm  left %4d mm  ", front, left)
        OSWait(PERIOD)
    VWSetSpeed(0, 0)
    print("wall following done after %d ms" % (OSGetCount() - start))


main()
