/* Benchmark client: times sensor calls and prints "<call> <microseconds>" per call:
 * OSGetCount (no sensor work: the protocol's floor), PSDGet and LIDARGet (360 points) in turn,
 * then LIDARGet and SIMLaserScan in turn (each casts its scan anew: the simulator keeps only the
 * last scan made at the current physics state), then CAMGet (QVGA). */
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

static int scan[360];
static QVGAcol image;

static void os_get_count(void) { OSGetCount(); }
static void psd_get(void) { PSDGet(PSD_FRONT); }
static void lidar_get(void) { LIDARGet(scan); }
static void laser_scan(void) { SIMLaserScan(scan); }
static void cam_get(void) { CAMGet(image); }

/* Times the calls in turn, `rounds` times, so each sees the same load on the machine. */
static void measure(const char *const names[], void (*const calls[])(void), int count, int rounds)
{
    for (int i = 0; i < 20; i++) /* warm up outside the measurement */
        for (int k = 0; k < count; k++)
            calls[k]();
    for (int i = 0; i < rounds; i++)
        for (int k = 0; k < count; k++) {
            double start = now_us();
            calls[k]();
            printf("%s %.2f\n", names[k], now_us() - start);
        }
}

int main(int argc, char **argv)
{
    int calls = argc > 1 ? atoi(argv[1]) : 1000;
    int frames = argc > 2 ? atoi(argv[2]) : 100;
    CAMInit(QVGA);
    CAMGet(image); /* the renderer is prepared on the simulator's render thread meanwhile: not while timing */
    const char *const sensors[] = {"os_get_count", "psd_get", "lidar_get"};
    void (*const sensor_calls[])(void) = {os_get_count, psd_get, lidar_get};
    measure(sensors, sensor_calls, 3, calls);
    const char *const fresh[] = {"lidar_get_fresh", "laser_scan_fresh"};
    void (*const fresh_calls[])(void) = {lidar_get, laser_scan};
    measure(fresh, fresh_calls, 2, calls);
    const char *const camera[] = {"cam_get"};
    void (*const camera_calls[])(void) = {cam_get};
    measure(camera, camera_calls, 1, frames);
    return 0;
}
