/* The `make demo` program: S4 explores its arena, avoiding walls with its PSDs, and shows what it
 * senses on the LCD. Soft keys: KEY1 pause/continue, KEY2 drive a 400 mm square, KEY4 end.
 * From the examples folder (the default arena; eyesim compiles it; open the printed viewer address):
 *   eyesim run --program 1=programs/demo.c
 */
#include <stdio.h>
#include "eyebot.h"

#define CLEARANCE 300 /* mm: turn away when a wall is closer than this ahead */
#define SIDE_CLEARANCE 150 /* mm: steer away from a wall this close at the side */
#define CRUISE 250    /* mm/s */

static void show_sensors(void)
{
    int x, y, phi;
    VWGetPosition(&x, &y, &phi);
    LCDSetPrintf(6, 0, "front %4d mm   left %4d mm   ", PSDGet(PSD_FRONT), PSDGet(PSD_LEFT));
    LCDSetPrintf(7, 0, "right %4d mm   back %4d mm   ", PSDGet(PSD_RIGHT), PSDGet(PSD_BACK));
    LCDSetPrintf(9, 0, "odometry x %5d y %5d phi %4d  ", x, y, phi);
    LCDSetPrintf(10, 0, "time %d.%d s   ", OSGetCount() / 1000, OSGetCount() / 100 % 10);
}

static void drive_square(void)
{
    LCDSetPrintf(12, 0, "driving a square...      ");
    for (int side = 0; side < 4; side++) {
        VWStraight(400, 200);
        VWWait();
        VWTurn(90, 90);
        VWWait();
        show_sensors();
    }
    LCDSetPrintf(12, 0, "square done              ");
}

int main(void)
{
    int paused = 0;
    LCDClear();
    LCDMenu("PAUSE", "SQUARE", "", "END");
    LCDPrintf("EyeSim demo: S4 explores the arena\n");
    LCDPrintf("KEY1 pause/continue  KEY2 square  KEY4 end\n");
    printf("demo: started\n");
    for (;;) {
        int key = KEYRead();
        if (key == KEY4)
            break;
        if (key == KEY1) {
            paused = !paused;
            LCDMenu(paused ? "GO" : "PAUSE", "SQUARE", "", "END");
            LCDSetPrintf(12, 0, paused ? "paused                   " : "exploring                ");
        }
        if (key == KEY2)
            drive_square();
        if (paused) {
            VWSetSpeed(0, 0);
        } else if (PSDGet(PSD_FRONT) < CLEARANCE) {
            /* Turn towards the side with more room. */
            VWTurn(PSDGet(PSD_LEFT) > PSDGet(PSD_RIGHT) ? 90 : -90, 120);
            VWWait();
        } else {
            /* Steer gently away from a wall that comes close on either side. */
            int left = PSDGet(PSD_LEFT), right = PSDGet(PSD_RIGHT);
            int steer = left < SIDE_CLEARANCE ? -30 : right < SIDE_CLEARANCE ? 30 : 0;
            VWSetSpeed(CRUISE, steer);
        }
        show_sensors();
        OSWait(50);
    }
    VWSetSpeed(0, 0);
    LCDSetPrintf(12, 0, "bye                      ");
    printf("demo: ended by KEY4\n");
    return 0;
}
