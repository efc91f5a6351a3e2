/* Drives diagonally into a corner and turns there: each VWWait must return, VWStalled saying why. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    VWStraight(2000, 300);
    VWWait();
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("straight %d %d %d %d\n", VWDone(), VWStalled(), x, y);
    VWTurn(180, 90); /* the chassis is wedged between the walls */
    VWWait();
    printf("turn %d %d\n", VWDone(), VWStalled());
    VWStraight(-200, 200); /* backing out works again */
    VWWait();
    printf("back %d %d\n", VWDone(), VWStalled());
    return 0;
}
