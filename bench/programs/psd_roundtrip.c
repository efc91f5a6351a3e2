/* Benchmark client: times N PSDGet round trips and prints each in microseconds, one per line. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "eyebot.h"

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

int main(int argc, char **argv)
{
    int calls = argc > 1 ? atoi(argv[1]) : 1000;
    PSDGet(PSD_FRONT); /* connect and warm up outside the measurement */
    for (int i = 0; i < 50; i++)
        PSDGet(PSD_FRONT);
    for (int i = 0; i < calls; i++) {
        double start = now_us();
        PSDGet(PSD_FRONT);
        printf("%.2f\n", now_us() - start);
    }
    return 0;
}
