/* Drive phases timed with the C library's sleeps, as the submarine examples time their thrust:
 * forward, stop, forward, stop, each phase one pause. SLEEP_KIND chooses the pause (usleep,
 * nanosleep, clock_nanosleep, sleep or OSWait for comparison), SLEEP_MS its length. A first
 * usleep before any RoBIOS call shows that sleeps are the system's until the program connects. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "eyebot.h"

static double wall_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int pause_for(const char *kind, int ms)
{
    struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    if (strcmp(kind, "usleep") == 0)
        return usleep((useconds_t)ms * 1000);
    if (strcmp(kind, "nanosleep") == 0)
        return nanosleep(&t, NULL);
    if (strcmp(kind, "clock_nanosleep") == 0)
        return clock_nanosleep(CLOCK_MONOTONIC, 0, &t, NULL);
    if (strcmp(kind, "sleep") == 0)
        return (int)sleep((unsigned)ms / 1000);
    return OSWait(ms);
}

int main(void)
{
    const char *kind = getenv("SLEEP_KIND") ? getenv("SLEEP_KIND") : "usleep";
    int ms = getenv("SLEEP_MS") ? atoi(getenv("SLEEP_MS")) : 500;
    double before = wall_ms();
    usleep(100000); /* not connected yet: the system's sleep, in wall time */
    printf("wall before connecting %.0f ms\n", wall_ms() - before);

    int start = OSGetCount();
    for (int phase = 0; phase < 4; phase++) {
        int speed = phase % 2 == 0 ? 40 : 0;
        MOTORDrive(1, speed);
        MOTORDrive(2, speed);
        if (pause_for(kind, ms) != 0)
            return 2;
    }
    printf("slept %d ms\n", OSGetCount() - start);
    return 0;
}
