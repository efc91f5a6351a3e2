/* Drives each VW manoeuvre once and marks the time it ended, so the test can look up the true pose. */
#include <stdio.h>
#include "eyebot.h"

static void settle_and_mark(const char *name)
{
    OSWait(300);
    printf("mark %s %d\n", name, OSGetCount());
}

int main(void)
{
    settle_and_mark("start");
    if (VWStraight(1000, 300) != 0)
        return 1;
    int remain_start = VWRemain(), done_start = VWDone();
    int previous = remain_start, decreasing = 1, samples = 0;
    while (!VWDone()) {
        int remain = VWRemain();
        if (remain > previous)
            decreasing = 0;
        previous = remain;
        samples++;
        OSWait(50);
    }
    printf("remain %d %d %d %d %d\n", remain_start, done_start, decreasing, samples, VWRemain());
    settle_and_mark("straight");
    VWTurn(90, 60);
    VWWait();
    settle_and_mark("turn");
    VWCurve(600, 90, 200);
    VWWait();
    settle_and_mark("curve");
    VWDrive(400, 150, 200);
    VWWait();
    settle_and_mark("drive");
    printf("unreachable %d\n", VWDrive(100, 300, 200));
    return 0;
}
