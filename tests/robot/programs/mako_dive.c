/* Mako: dives on its vertical thrusters (FRONT 2, BACK 4) to 1 m above the pool floor, holds that
 * height for 10 s with its DOWN PSD (6), then stops the thrusters and rises to the surface.
 * Prints <tag> <ms> <true height of the hull's bottom> <DOWN PSD> at each stage. */
#include <stdio.h>
#include "eyebot.h"

#define FRONT 2
#define BACK 4
#define PSD_DOWN 6
#define HOLD_MM 1000

static void report(const char *tag)
{
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("%s %d %d %d\n", tag, OSGetCount(), z, PSDGet(PSD_DOWN));
}

static void vertical(int speed)
{
    MOTORDrive(FRONT, speed);
    MOTORDrive(BACK, speed);
}

int main(void)
{
    report("start");
    vertical(-60); /* negative: push down */
    while (PSDGet(PSD_DOWN) > HOLD_MM + 100)
        OSWait(50);
    report("dived");
    /* hold: a little downward trim against the Mako's buoyancy, more the higher it is */
    for (int tick = 0; tick < 200; tick++) {
        int error = PSDGet(PSD_DOWN) - HOLD_MM;
        int speed = -(25 + error / 5);
        if (speed > 100) speed = 100;
        if (speed < -100) speed = -100;
        vertical(speed);
        OSWait(50);
        if (tick % 20 == 19)
            report("hold");
    }
    vertical(0);
    OSWait(2000);
    report("rising");
    OSWait(18000);
    report("surfaced");
    return 0;
}
