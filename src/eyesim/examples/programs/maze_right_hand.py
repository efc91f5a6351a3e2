# Maze solving by the right-hand rule (the Python version of maze_right_hand.c): S4 drives from cell
# to cell, always keeping a wall on its right: at each cell it turns right if it can, else goes
# straight, else left, else back. It knows where the finish is (GOAL cells from its start) and counts
# cells as it goes; the PSDs tell it where the walls are. The LCD shows each move.
# From the examples folder:
#   eyesim run scenes/maze.sim --program 1=programs/maze_right_hand.py
import sys

from eye import *

CELL = 360  # mm: the maze's cell size
WALL = 250  # mm: a PSD reading below this is a wall of this cell
GOAL = (4, 3)  # the finish, in cells east and north of the start
MAX_MOVES = 60  # give up after this many cells

STEPS = [(1, 0), (0, 1), (-1, 0), (0, -1)]  # a cell east, north, west, south
NAMES = ["east", "north", "west", "south"]


def main():
    heading = 1  # the robot starts facing north
    x, y, moves = 0, 0, 0
    LCDMenu("", "", "", "END")
    LCDPrintf("Right-hand rule: finish at cell (%d, %d)\n", *GOAL)
    while (x, y) != GOAL:
        if moves == MAX_MOVES or KEYRead() == KEY4:
            LCDPrintf("giving up at (%d, %d)\n", x, y)
            print("gave up at cell", x, y)
            return 1
        if PSDGet(PSD_RIGHT) > WALL:
            quarters = -1  # right
        elif PSDGet(PSD_FRONT) > WALL:
            quarters = 0  # straight on
        elif PSDGet(PSD_LEFT) > WALL:
            quarters = 1  # left
        else:
            quarters = 2  # back
        if quarters:
            VWTurn(90 * quarters, 180)
            VWWait()
            heading = (heading + quarters) % 4
        VWStraight(CELL, 300)
        VWWait()
        x += STEPS[heading][0]
        y += STEPS[heading][1]
        moves += 1
        LCDPrintf("%2d: %-5s to (%d, %d)\n", moves, NAMES[heading], x, y)
    LCDPrintf("Finish reached in %d moves\n", moves)
    print("finish reached at cell %d %d in %d moves" % (x, y, moves))
    return 0


sys.exit(main())
