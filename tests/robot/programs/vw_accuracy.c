/* Twelve VWTurn(90) in a row at 20, 45 and 90 deg/s, then a 500 mm square of VWStraight/VWTurn,
   marking the time after each series so the test can look up the true heading. */
#include <stdio.h>
#include "eyebot.h"

static void mark(const char *name)
{
    OSWait(300);
    printf("mark %s %d\n", name, OSGetCount());
}

int main(void)
{
    const int speeds[] = {20, 45, 90};
    mark("start");
    for (int s = 0; s < 3; s++) {
        for (int i = 0; i < 12; i++) {
            VWTurn(90, speeds[s]);
            VWWait();
        }
        char name[16];
        snprintf(name, sizeof name, "turns%d", speeds[s]);
        mark(name);
    }
    for (int side = 0; side < 4; side++) {
        VWStraight(500, 300);
        VWWait();
        VWTurn(90, 90);
        VWWait();
    }
    mark("square");
    return 0;
}
