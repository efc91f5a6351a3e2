/* VW on the Ackermann car: a 1 m straight and a 500 mm quarter arc against the true pose, then
   what the car cannot do: turn on the spot, or drive an arc tighter than its steering allows. */
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
    VWCurve(500, 90, 200);
    VWWait();
    mark("curve");
    printf("refused %d %d %d %d\n", VWTurn(90, 60), VWSetSpeed(0, 30), VWCurve(100, 90, 100),
           VWCurve(0, 90, 100));
    printf("done %d\n", VWDone());
    return 0;
}
