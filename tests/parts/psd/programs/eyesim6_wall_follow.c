/* An EyeSim 6 style program: PSD 1 is the left sensor, 2 the front, 3 the right. Prints the three
 * readings, follows the wall on its left at the distance it starts with until the front sensor
 * sees a wall 250 mm ahead, then prints where it stopped and the readings there. */
#include <stdio.h>
#include "eyebot.h"

#define LEFT 1
#define FRONT 2
#define RIGHT 3

static void readings(const char *tag)
{
    printf("%s %d %d %d\n", tag, PSDGet(LEFT), PSDGet(FRONT), PSDGet(RIGHT));
}

int main(void)
{
    readings("start");
    int target = PSDGet(LEFT);
    while (PSDGet(FRONT) > 250) {
        int error = PSDGet(LEFT) - target; /* too far from the wall: turn left, towards it */
        int turn = error / 2;
        if (turn > 30) turn = 30;
        if (turn < -30) turn = -30;
        VWSetSpeed(200, turn);
        OSWait(50);
    }
    VWSetSpeed(0, 0);
    OSWait(500);
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("end %d %d %d\n", x, y, phi);
    readings("stopped");
    return 0;
}
