# Lidar mapping (the Python version of lidar_map.c): the robot wanders, turning away from what its
# lidar sees ahead, and enters every scan into an occupancy grid around its start (poses from
# odometry). The map grows on the LCD; at the end it is saved as map.pgm beside this program (black =
# seen as occupied, 1 pixel = CELL mm, start at the centre, x to the right, y up). KEY4 ends it early.
# From the examples folder:
#   eyesim run scenes/lidar_map.sim --program 1=programs/lidar_map.py
import math

from eye import *

CELL = 20  # mm per map cell
SIZE = 300  # cells per side: a 6 m square around the start
RUN_SECONDS = 40
CLEARANCE = 380  # mm: turn when something is this close ahead
SCALE = 1  # map cells per LCD pixel

hits = [bytearray(SIZE) for _ in range(SIZE)]  # hits[cy][cx]: how often a beam ended in the cell


def nearest(scan, centre, half):
    """Smallest distance of the beams within `half` degrees of `centre` (360-point scan, 180 = ahead)."""
    return min(scan[i % 360] for i in range(centre - half, centre + half + 1))


def enter_scan(scan, x, y, phi):
    points = len(scan)
    for i, distance in enumerate(scan):
        if distance >= 9999:
            continue  # nothing in range
        angle = math.radians(phi - (i - points // 2) * 360.0 / points)
        cx = math.floor((x + distance * math.cos(angle)) / CELL) + SIZE // 2
        cy = math.floor((y + distance * math.sin(angle)) / CELL) + SIZE // 2
        if not (0 <= cx < SIZE and 0 <= cy < SIZE) or hits[cy][cx] == 255:
            continue
        hits[cy][cx] += 1
        if hits[cy][cx] == 2:  # seen twice: occupied
            LCDPixel(240 + (cx - SIZE // 2) // SCALE, 140 - (cy - SIZE // 2) // SCALE, WHITE)


def save_map(name):
    with open(name, "wb") as file:
        file.write(b"P5\n%d %d\n255\n" % (SIZE, SIZE))
        for row in reversed(hits):  # the top row is the map's largest y
            file.write(bytes(0 if count >= 2 else 255 for count in row))


def main():
    LCDMenu("", "", "", "END")
    LCDSetPrintf(0, 0, "Lidar map (1 pixel = %d mm)", CELL * SCALE)
    LIDARSet(360, 0, 360)
    start = OSGetCount()
    scans = 0
    while KEYRead() != KEY4 and OSGetCount() - start < RUN_SECONDS * 1000:
        scan = LIDARGet()
        x, y, phi = VWGetPosition()
        enter_scan(scan, x, y, phi)
        scans += 1
        if nearest(scan, 180, 25) < CLEARANCE:
            # blocked: turn towards the side with more room until the way ahead is clear
            left, right = nearest(scan, 90, 40), nearest(scan, 270, 40)
            VWSetSpeed(0, 60 if left > right else -60)
        else:
            VWSetSpeed(250, 0)
        OSWait(50)
    VWSetSpeed(0, 0)
    save_map("map.pgm")
    print("mapped %d scans" % scans)


main()
