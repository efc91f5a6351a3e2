/* Small corrections and tight arcs: VWTurn by 1 to 5 degrees each way at 90 deg/s, timed from the
   call to VWWait's return, then VWCurve arcs that turn far over a short distance, each with its
   odometry; a mark after each so the test can look up the true pose. */
#include <stdio.h>
#include "eyebot.h"

static void mark(const char *name)
{
    OSWait(300);
    printf("mark %s %d\n", name, OSGetCount());
}

int main(void)
{
    const int turns[] = {1, -1, 2, -2, 3, -3, 4, -4, 5, -5, -1, -1, -1};
    const int curves[][3] = {{18, -354, 50}, {-18, 354, 50}, {50, 360, 100}, {100, -180, 100}, {30, 90, 200}};
    char name[16];
    mark("start");
    for (int i = 0; i < (int)(sizeof turns / sizeof turns[0]); i++) {
        int start = OSGetCount();
        VWTurn(turns[i], 90);
        VWWait();
        printf("turn %d %d\n", turns[i], OSGetCount() - start);
        snprintf(name, sizeof name, "turn%d", i);
        mark(name);
    }
    for (int i = 0; i < (int)(sizeof curves / sizeof curves[0]); i++) {
        int x, y, phi;
        VWSetPosition(0, 0, 0);
        VWCurve(curves[i][0], curves[i][1], curves[i][2]);
        VWWait();
        VWGetPosition(&x, &y, &phi);
        printf("curve %d %d %d %d %d\n", curves[i][0], curves[i][1], x, y, phi);
        snprintf(name, sizeof name, "curve%d", i);
        mark(name);
    }
    return 0;
}
