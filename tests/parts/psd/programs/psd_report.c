/* Test program: every PSD's distance and raw value, at the start and once the robot has settled. */
#include <stdio.h>
#include "eyebot.h"

static void report(const char *when)
{
    for (int id = PSD_FRONT; id <= PSD_BACK; id++)
        printf("%s %d %d %d\n", when, id, PSDGet(id), PSDGetRaw(id));
}

int main(void)
{
    report("start");
    OSWait(500);
    report("settled");
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("pose %d %d %d\n", x, y, phi);
    printf("missing %d %d\n", PSDGet(7), PSDGetRaw(0));
    return 0;
}
