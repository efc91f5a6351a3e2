/* Benchmark client for the per-call time: three kinds of lab program, chosen by argv[1].
 *   poll  a tight loop without any wait: PSDGet + VWGetPosition + LCDSetPrintf per iteration,
 *         driving slowly, until 5 s of simulation time or 3 s of wall time have passed
 *   lab   a square driven with VWStraight/VWTurn + VWWait, PSD checks and OSWait(100) pauses
 *   count a busy-wait pause: for (i = 0; i < 1000; i++) KEYRead();
 * Prints "<simulated ms> <wall ms> <iterations>". */
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "eyebot.h"

static double wall_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "poll";
    OSGetCount(); /* connect outside the measurement */
    int start = OSGetCount(), iterations = 0;
    double wall_start = wall_ms();
    if (strcmp(mode, "poll") == 0) {
        VWSetSpeed(50, 0);
        int x, y, phi;
        while (OSGetCount() - start < 5000 && wall_ms() - wall_start < 3000) {
            int front = PSDGet(PSD_FRONT);
            VWGetPosition(&x, &y, &phi);
            LCDSetPrintf(0, 0, "front %4d x %4d", front, x);
            iterations++;
        }
        VWSetSpeed(0, 0);
    } else if (strcmp(mode, "lab") == 0) {
        for (int side = 0; side < 4; side++) {
            LCDPrintf("side %d front %d\n", side, PSDGet(PSD_FRONT));
            VWStraight(400, 300);
            VWWait();
            OSWait(100);
            VWTurn(90, 90);
            VWWait();
            OSWait(100);
            iterations++;
        }
    } else {
        for (int i = 0; i < 1000; i++, iterations++)
            KEYRead();
    }
    int simulated = OSGetCount() - start;
    printf("%d %.1f %d\n", simulated, wall_ms() - wall_start, iterations);
    return 0;
}
