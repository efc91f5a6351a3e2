/* VW on the mecanum robot: a 1 m straight, a quarter turn on the spot, a 500 mm quarter arc,
   marking the time (and the odometry) after each so the test can compare with the true pose. */
#include <stdio.h>
#include "eyebot.h"

static void mark(const char *name)
{
    int x, y, phi;
    OSWait(300);
    VWGetPosition(&x, &y, &phi);
    printf("mark %s %d\n", name, OSGetCount());
    printf("odometry_%s %d %d %d\n", name, x, y, phi);
}

int main(void)
{
    mark("start");
    VWStraight(1000, 300);
    VWWait();
    mark("straight");
    VWTurn(90, 60);
    VWWait();
    mark("turn");
    VWCurve(500, 90, 200);
    VWWait();
    mark("curve");
    return 0;
}
