/* Maze solving by the right-hand rule: S4 drives from cell to cell, always keeping a wall on its
 * right: at each cell it turns right if it can, else goes straight, else left, else back. It knows
 * where the finish is (GOAL_X, GOAL_Y cells from its start) and counts cells as it goes; the PSDs
 * tell it where the walls are. The LCD shows each move.
 * From the examples folder (the scene names this program; eyesim compiles it):
 *   eyesim run scenes/maze.sim
 *   eyesim run scenes/maze.sim --program 1=programs/maze_right_hand.c
 */
#include <stdio.h>
#include "eyebot.h"

#define CELL 360     /* mm: the maze's cell size */
#define WALL 250     /* mm: a PSD reading below this is a wall of this cell */
#define GOAL_X 4     /* the finish, in cells east ... */
#define GOAL_Y 3     /* ... and north of the start */
#define MAX_MOVES 60 /* give up after this many cells */

static const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1}; /* east, north, west, south */
static const char *names[4] = {"east", "north", "west", "south"};

static int heading = 1; /* the robot starts facing north */

static void turn(int quarters) /* 1: a quarter turn left, -1: right, 2: about */
{
    VWTurn(90 * quarters, 180);
    VWWait();
    heading = ((heading + quarters) % 4 + 4) % 4;
}

int main(void)
{
    int x = 0, y = 0, moves = 0;
    LCDMenu("", "", "", "END");
    LCDPrintf("Right-hand rule: finish at cell (%d, %d)\n", GOAL_X, GOAL_Y);
    while (!(x == GOAL_X && y == GOAL_Y)) {
        if (moves == MAX_MOVES || KEYRead() == KEY4) {
            LCDPrintf("giving up at (%d, %d)\n", x, y);
            printf("gave up at cell %d %d\n", x, y);
            return 1;
        }
        int quarters; /* to turn before the next cell: -1 right, 0 none, 1 left, 2 back */
        if (PSDGet(PSD_RIGHT) > WALL)
            quarters = -1;
        else if (PSDGet(PSD_FRONT) > WALL)
            quarters = 0;
        else if (PSDGet(PSD_LEFT) > WALL)
            quarters = 1;
        else
            quarters = 2;
        if (quarters != 0)
            turn(quarters);
        VWStraight(CELL, 300);
        VWWait();
        x += dx[heading];
        y += dy[heading];
        moves++;
        LCDPrintf("%2d: %-5s to (%d, %d)\n", moves, names[heading], x, y);
    }
    LCDPrintf("Finish reached in %d moves\n", moves);
    printf("finish reached at cell %d %d in %d moves\n", x, y, moves);
    return 0;
}
