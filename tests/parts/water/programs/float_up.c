/* A buoyant submarine let go under water rises until it floats. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    SIMSetRobot(0, 1500, 1500, 300, 0);
    for (int second = 0; second <= 15; second++) {
        int x, y, z, phi;
        SIMGetRobot(0, &x, &y, &z, &phi);
        printf("depth %d %d\n", second, z);
        OSWait(1000);
    }
    return 0;
}
