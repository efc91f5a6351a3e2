# The demo (the Python version of demo.c): S4 explores its arena, avoiding walls with its PSDs, and
# shows what it senses on the LCD. Soft keys: KEY1 pause/continue, KEY2 drive a 400 mm square,
# KEY4 end. From the examples folder (the default arena; open the printed viewer address):
#   eyesim run --program 1=programs/demo.py
from eye import *

CLEARANCE = 300  # mm: turn away when a wall is closer than this ahead
SIDE_CLEARANCE = 150  # mm: steer away from a wall this close at the side
CRUISE = 250  # mm/s


def show_sensors():
    x, y, phi = VWGetPosition()
    LCDSetPrintf(6, 0, "front %4d mm   left %4d mm   ", PSDGet(PSD_FRONT), PSDGet(PSD_LEFT))
    LCDSetPrintf(7, 0, "right %4d mm   back %4d mm   ", PSDGet(PSD_RIGHT), PSDGet(PSD_BACK))
    LCDSetPrintf(9, 0, "odometry x %5d y %5d phi %4d  ", x, y, phi)
    LCDSetPrintf(10, 0, "time %d.%d s   ", OSGetCount() // 1000, OSGetCount() // 100 % 10)


def drive_square():
    LCDSetPrintf(12, 0, "driving a square...      ")
    for side in range(4):
        VWStraight(400, 200)
        VWWait()
        VWTurn(90, 90)
        VWWait()
        show_sensors()
    LCDSetPrintf(12, 0, "square done              ")


def main():
    paused = False
    LCDClear()
    LCDMenu("PAUSE", "SQUARE", "", "END")
    LCDPrintf("EyeSim demo: S4 explores the arena\n")
    LCDPrintf("KEY1 pause/continue  KEY2 square  KEY4 end\n")
    print("demo: started")
    while True:
        key = KEYRead()
        if key == KEY4:
            break
        if key == KEY1:
            paused = not paused
            LCDMenu("GO" if paused else "PAUSE", "SQUARE", "", "END")
            LCDSetPrintf(12, 0, "paused                   " if paused else "exploring                ")
        if key == KEY2:
            drive_square()
        if paused:
            VWSetSpeed(0, 0)
        elif PSDGet(PSD_FRONT) < CLEARANCE:
            # Turn towards the side with more room.
            VWTurn(90 if PSDGet(PSD_LEFT) > PSDGet(PSD_RIGHT) else -90, 120)
            VWWait()
        else:
            # Steer gently away from a wall that comes close on either side.
            left, right = PSDGet(PSD_LEFT), PSDGet(PSD_RIGHT)
            steer = -30 if left < SIDE_CLEARANCE else 30 if right < SIDE_CLEARANCE else 0
            VWSetSpeed(CRUISE, steer)
        show_sensors()
        OSWait(50)
    VWSetSpeed(0, 0)
    LCDSetPrintf(12, 0, "bye                      ")
    print("demo: ended by KEY4")


main()
