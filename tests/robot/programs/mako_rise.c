/* Mako: rises from where it starts on its vertical thrusters (FRONT 2, BACK 4 pushing up) for
 * 1 s, then stops them. Prints <tag> <ms> <true height of the hull's bottom> <DOWN PSD>. */
#include <stdio.h>
#include "eyebot.h"

#define FRONT 2
#define BACK 4
#define PSD_DOWN 6

static void report(const char *tag)
{
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("%s %d %d %d\n", tag, OSGetCount(), z, PSDGet(PSD_DOWN));
}

int main(void)
{
    report("start");
    MOTORDrive(FRONT, 60);
    MOTORDrive(BACK, 60);
    OSWait(1000);
    MOTORDrive(FRONT, 0);
    MOTORDrive(BACK, 0);
    report("rose");
    return 0;
}
