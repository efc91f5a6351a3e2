/* Load client: polls PSDGet and VWGetPosition in a tight loop for SECONDS of wall time, then
 * prints "calls p50_us p99_us max_us sim_ms" (sim_ms: simulation time that passed meanwhile). */
#include <stdlib.h>
#include <time.h>
#include "eyebot.h"

#define MAX_SAMPLES 2000000

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

static int by_value(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    double seconds = argc > 1 ? atof(argv[1]) : 5.0;
    static float samples[MAX_SAMPLES];
    int calls = 0, x, y, phi;
    int sim_start = OSGetCount();
    double end = now_us() + seconds * 1e6;
    while (now_us() < end && calls < MAX_SAMPLES - 1) {
        double start = now_us();
        if (calls % 2 == 0)
            PSDGet(PSD_FRONT);
        else
            VWGetPosition(&x, &y, &phi);
        samples[calls++] = (float)(now_us() - start);
    }
    int sim_ms = OSGetCount() - sim_start;
    qsort(samples, calls, sizeof samples[0], by_value);
    printf("%d %.1f %.1f %.1f %d\n", calls, samples[calls / 2], samples[(int)(calls * 0.99)], samples[calls - 1],
           sim_ms);
    return 0;
}
