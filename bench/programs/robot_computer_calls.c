/* Benchmark client: times N calls of each robot-computer function and prints "<name> <microseconds>"
 * per call; then the timer section: "timer_lateness_ms <ms>" per callback of a 10 ms timer.
 * With the argument "rate": the wall time of 2 s of simulation time with a 1 ms timer, and of
 * 2000 OSWait(1) calls, as "timer_1ms_2000_callbacks_s" and "oswait_1ms_2000_calls_s". */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "eyebot.h"

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

static BYTE colour[QVGA_SIZE], gray[QVGA_PIXELS];
static volatile int ticks, lateness[200];
static int attached_at;

static void on_fast_tick(void)
{
    ticks++;
}

static int rate(void)
{
    double start = now_us();
    OSAttachTimer(1, on_fast_tick);
    OSWait(2000);
    printf("timer_1ms_2000_callbacks_s %.4f\n", (now_us() - start) / 1e6);
    printf("callbacks %d\n", ticks);
    start = now_us();
    for (int i = 0; i < 2000; i++)
        OSWait(1);
    printf("oswait_1ms_2000_calls_s %.4f\n", (now_us() - start) / 1e6);
    return 0;
}

static void on_tick(void)
{
    if (ticks < 200)
        lateness[ticks] = OSGetCount() - attached_at - 10 * (ticks + 1);
    ticks++;
}

#define TIME(name, calls, statement)                                 \
    for (int i = 0; i < (calls); i++) {                              \
        double start = now_us();                                     \
        statement;                                                   \
        printf("%s %.2f\n", name, now_us() - start);                 \
    }

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "rate") == 0)
        return rate();
    int calls = argc > 1 ? atoi(argv[1]) : 300;
    char buffer[128];
    for (int i = 0; i < QVGA_SIZE; i++)
        colour[i] = (BYTE)(i * 7);
    memset(gray, 99, sizeof gray);
    for (int i = 0; i < 50; i++) /* connect and warm up outside the measurement */
        OSGetCount();
    SERInit(0, 115200, 0); /* with a loopback plug: nothing leaves the robot */

    TIME("OSGetCount", calls, OSGetCount());
    TIME("LCDPrintf_40_chars_newline", calls, LCDPrintf("%-39d\n", i));
    TIME("LCDSetPrintf_10_chars", calls, LCDSetPrintf(5, 10, "%10d", i));
    TIME("LCDPixel", calls, LCDPixel(i % 480, 100, RED));
    TIME("LCDGetPixel", calls, LCDGetPixel(i % 480, 100));
    TIME("LCDLine_diagonal", calls, LCDLine(0, 0, 479, 319, GREEN));
    TIME("LCDCircle_filled_r50", calls, LCDCircle(240, 160, 50, BLUE, 1));
    TIME("LCDImage_QVGA_colour", calls / 3, LCDImage(colour));
    TIME("LCDImageGray_QVGA", calls / 3, LCDImageGray(gray));
    TIME("KEYRead", calls, KEYRead());
    TIME("SERSend_64_bytes", calls, SERSend(0, "0123456789012345678901234567890123456789012345678901234567890123"));
    TIME("SERReceive_64_bytes", calls, SERReceive(0, buffer, 64));
    TIME("DIGITALReadAll", calls, DIGITALReadAll());
    TIME("ANALOGVoltage", calls, ANALOGVoltage());

    attached_at = OSGetCount();
    OSAttachTimer(10, on_tick);
    while (ticks < 200)
        OSWait(50);
    for (int i = 0; i < 200; i++)
        printf("timer_lateness_ms %d\n", lateness[i]);
    return 0;
}
