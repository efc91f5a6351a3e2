/* Submarine: holds depth without thrust, rises on its vertical thrusters, moves ahead on its
 * horizontal ones; then falls when put above the water. */
#include <stdio.h>
#include "eyebot.h"

static void report(const char *tag)
{
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("%s %d %d %d %d\n", tag, x, y, z, phi);
}

int main(void)
{
    SIMSetRobot(0, 1500, 1500, 600, 0);
    for (int second = 0; second <= 10; second++) {
        report("hold");
        OSWait(1000);
    }
    MOTORDrive(3, 60);
    MOTORDrive(4, 60);
    OSWait(1500);
    MOTORDrive(3, 0);
    MOTORDrive(4, 0);
    report("up");
    MOTORDrive(1, 60);
    MOTORDrive(2, 60);
    OSWait(1500);
    MOTORDrive(1, 0);
    MOTORDrive(2, 0);
    report("ahead");
    SIMSetRobot(0, 1500, 1500, 2500, 0); /* a metre above the surface */
    OSWait(300);
    report("falling");
    printf("errors %d %d %d\n", MOTORSpeed(1, 100), ENCODERRead(1), MOTORDrive(5, 10));
    return 0;
}
