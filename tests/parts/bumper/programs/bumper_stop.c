/* Test program: drive ahead until the front bumper (bumper 1: digital line 9) is pressed, stop. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int x, y, z, phi;
    printf("released %d %d\n", DIGITALRead(9), DIGITALRead(10));
    VWSetSpeed(200, 0);
    while (DIGITALRead(9) == 1)
        OSWait(10);
    VWSetSpeed(0, 0);
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("pressed %d %d %d\n", x, y, phi);
    OSWait(500);
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("stopped %d %d %d %d %d\n", x, y, phi, DIGITALRead(9), DIGITALRead(10));
    return 0;
}
