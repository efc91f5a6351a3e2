/* Drives into the wall ahead and reports when VWStalled says the wheels are blocked. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    printf("before %d\n", VWStalled());
    VWStraight(3000, 300);
    int stalled = 0;
    for (int i = 0; i < 400 && stalled == 0; i++) {
        OSWait(50);
        stalled = VWStalled();
    }
    OSWait(1000); /* pushing on: the wall must hold */
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("stalled %d %d %d %d\n", stalled, VWStalled(), x, y);
    VWSetSpeed(0, 0);
    OSWait(500);
    printf("after %d\n", VWStalled());
    return 0;
}
