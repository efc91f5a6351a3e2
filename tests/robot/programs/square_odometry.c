/* Drives a square of 500 mm sides (2 m) and prints odometry and the true pose at every corner. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int x0, y0, z0, phi0;
    SIMGetRobot(0, &x0, &y0, &z0, &phi0);
    VWSetPosition(0, 0, 0);
    for (int side = 1; side <= 4; side++) {
        VWStraight(500, 300);
        VWWait();
        VWTurn(90, 90);
        VWWait();
        OSWait(200);
        int ox, oy, ophi, x, y, z, phi;
        VWGetPosition(&ox, &oy, &ophi);
        SIMGetRobot(0, &x, &y, &z, &phi);
        printf("corner %d %d %d %d %d %d\n", ox, oy, ophi, x - x0, y - y0, phi - phi0);
    }
    return 0;
}
