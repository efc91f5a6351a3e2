/* Drives the mecanum robot 500 mm to the left by its encoders, then 300 mm ahead. */
#include <stdio.h>
#include "eyebot.h"

#define TICKS_PER_MM (720 / (3.14159265 * 60)) /* Mecanum.robi: 720 ticks per turn of a 60 mm wheel */

static int mean_ticks(void)
{
    int sum = 0;
    for (int motor = 1; motor <= 4; motor++) {
        int ticks = ENCODERRead(motor);
        sum += ticks < 0 ? -ticks : ticks;
    }
    return sum / 4;
}

static void drive(const int direction[4], int mm)
{
    for (int motor = 1; motor <= 4; motor++) {
        ENCODERReset(motor);
        MOTORSpeed(motor, direction[motor - 1] * 500);
    }
    while (mean_ticks() < mm * TICKS_PER_MM)
        OSWait(2);
    for (int motor = 1; motor <= 4; motor++)
        MOTORSpeed(motor, 0);
    OSWait(500);
}

int main(void)
{
    const int left[4] = {-1, 1, 1, -1}; /* front left, front right, back left, back right */
    const int forward[4] = {1, 1, 1, 1};
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("start %d %d %d\n", x, y, phi);
    drive(left, 500);
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("left %d %d %d\n", x, y, phi);
    drive(forward, 300);
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("forward %d %d %d\n", x, y, phi);
    return 0;
}
