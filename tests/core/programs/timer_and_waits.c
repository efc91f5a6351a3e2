/* A timer callback that steers (reads the pose, sets the speed every 20 ms) while the main thread
 * reads sensors between waits: timer calls and the main thread's calls interleave at simulation
 * times that repeat exactly. The main thread never computes for long, so no run is timing-bound. */
#include <stdio.h>
#include "eyebot.h"

static volatile int ticks;

static void steer(void)
{
    int x, y, phi;
    VWGetPosition(&x, &y, &phi);
    ticks++;
    VWSetSpeed(120 + (ticks % 5) * 30, (ticks % 7) * 8 - 24);
}

int main(void)
{
    TIMER timer = OSAttachTimer(20, steer);
    int sum = 0;
    for (int i = 0; i < 60; i++) {
        OSWait(i % 3 == 0 ? 30 : 17);
        sum += PSDGet(1) + PSDGet(2);
    }
    OSDetachTimer(timer);
    VWSetSpeed(0, 0);
    LCDPrintf("ticks %d sum %d\n", ticks, sum);
    return 0;
}
