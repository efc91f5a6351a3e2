/* Timers: 18 timers count their calls over simulated time; one is detached on the way; a callback
 * uses the API itself; finally the main thread busy-waits for a timer without any RoBIOS call. */
#include <stdio.h>
#include "eyebot.h"

#define EXTRA 16

static volatile int fast, slow, busy_wait_ticks, extra[EXTRA];
static volatile int stamps[8], stamp_count;

static void on_fast(void) { fast++; }

static void on_slow(void) /* also reads the clock: calls from a callback work */
{
    if (stamp_count < 8)
        stamps[stamp_count++] = OSGetCount();
    slow++;
}

static void on_tick(void) { busy_wait_ticks++; }

#define EXTRA_TIMER(n) static void on_extra##n(void) { extra[n]++; }
EXTRA_TIMER(0) EXTRA_TIMER(1) EXTRA_TIMER(2) EXTRA_TIMER(3) EXTRA_TIMER(4) EXTRA_TIMER(5) EXTRA_TIMER(6)
EXTRA_TIMER(7) EXTRA_TIMER(8) EXTRA_TIMER(9) EXTRA_TIMER(10) EXTRA_TIMER(11) EXTRA_TIMER(12)
EXTRA_TIMER(13) EXTRA_TIMER(14) EXTRA_TIMER(15)
static void (*const extras[EXTRA])(void) = {
    on_extra0, on_extra1, on_extra2, on_extra3, on_extra4, on_extra5, on_extra6, on_extra7,
    on_extra8, on_extra9, on_extra10, on_extra11, on_extra12, on_extra13, on_extra14, on_extra15};

int main(void)
{
    int start = OSGetCount();
    TIMER fast_timer = OSAttachTimer(10, on_fast);
    TIMER slow_timer = OSAttachTimer(250, on_slow);
    for (int k = 0; k < EXTRA; k++)
        if (!OSAttachTimer(50, extras[k]))
            return 2;
    OSWait(1000);
    if (OSDetachTimer(fast_timer) != 0)
        return 3;
    int fast_at_detach = fast;
    OSWait(1000);
    printf("fast %d after detach %d slow %d\n", fast_at_detach, fast, slow);
    printf("extra");
    for (int k = 0; k < EXTRA; k++)
        printf(" %d", extra[k]);
    printf("\nslow at");
    for (int k = 0; k < stamp_count; k++)
        printf(" %d", stamps[k] - start);
    printf("\n");
    if (OSDetachTimer(fast_timer) == 0 || OSAttachTimer(0, on_tick) != 0)
        return 4; /* detached twice, and a period of 0: both refused */
    OSDetachTimer(slow_timer);
    TIMER tick = OSAttachTimer(20, on_tick);
    while (busy_wait_ticks < 5) {
    } /* no RoBIOS call: simulation time must still go on */
    OSDetachTimer(tick);
    printf("busy wait done after %d ticks\n", busy_wait_ticks);
    return 0;
}
