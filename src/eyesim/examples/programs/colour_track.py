# Colour tracking with the camera (the Python version of colour_track.c): S4 turns until it sees
# something red, steers to keep it in the middle of the image, drives up to it and stops once it
# fills a quarter of the picture. The LCD shows the camera image with the red pixels' centre marked.
# From the examples folder:
#   eyesim run scenes/colour_track.sim --program 1=programs/colour_track.py
import sys

from eye import *

MIN_PIXELS = 20  # red pixels that count as seeing the target
ARRIVED = 0.25  # share of the image the target fills when the robot is there
TURN_GAIN = 0.8  # deg/s per pixel the target is off the middle
RUN_SECONDS = 60


def red_pixels(image):
    """How many pixels of the frame are red, and the sum of their columns."""
    data = bytes(image)  # R G B, R G B, ... row by row from the top left
    count = columns = 0
    for i, (r, g, b) in enumerate(zip(data[0::3], data[1::3], data[2::3])):
        if r > 120 and r > 2 * g and r > 2 * b:
            count += 1
            columns += i % QQVGA_X
    return count, columns


def main():
    CAMInit(QQVGA)
    LCDMenu("", "", "", "END")
    start = OSGetCount()
    while KEYRead() != KEY4 and OSGetCount() - start < RUN_SECONDS * 1000:
        image = CAMGet()
        count, columns = red_pixels(image)
        LCDImage(image)
        if count < MIN_PIXELS:
            VWSetSpeed(0, 45)  # nothing red in sight: look around
            LCDSetPrintf(10, 0, "searching...               ")
        else:
            offset = columns // count - QQVGA_X // 2
            LCDLine(offset + QQVGA_X // 2, 0, offset + QQVGA_X // 2, QQVGA_Y - 1, GREEN)
            LCDSetPrintf(10, 0, "target %3d px off, %5d px  ", offset, count)
            if count > ARRIVED * QQVGA_PIXELS:
                VWSetSpeed(0, 0)
                print("arrived: the target fills %d of %d pixels" % (count, QQVGA_PIXELS))
                return 0
            ahead = -12 < offset < 12
            VWSetSpeed(200 if ahead else 0, int(-TURN_GAIN * offset))
        OSWait(50)
    VWSetSpeed(0, 0)
    print("no target reached")
    return 1


sys.exit(main())
