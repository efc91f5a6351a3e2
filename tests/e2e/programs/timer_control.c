/* A timer-driven controller beside a polling main loop, the pattern of real timer labs: the
 * callback reads the pose and sets the speed every 10 ms while the main thread polls and computes.
 * Prints what both saw; a deterministic run prints the same every time. */
#include "eyebot.h"

static volatile int ticks, last_phi;

static void control(void)
{
    int x, y, phi;
    VWGetPosition(&x, &y, &phi);
    last_phi = phi;
    ticks++;
    VWSetSpeed(100 + (ticks % 7) * 20, (ticks % 5) * 10 - 20);
}

int main(void)
{
    TIMER t = OSAttachTimer(10, control);
    int x, y, phi, polls = 0;
    do {
        VWGetPosition(&x, &y, &phi);
        polls++;
        for (volatile long work = 0; work < 100000; work++) {
        }
    } while (ticks < 150);
    OSDetachTimer(t);
    VWSetSpeed(0, 0);
    VWGetPosition(&x, &y, &phi);
    printf("ticks %d polls %d pose %d %d %d last %d\n", ticks, polls, x, y, phi, last_phi);
    return 0;
}
