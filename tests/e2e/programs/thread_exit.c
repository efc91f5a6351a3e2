/* Multitasking as in the official examples: main attaches a timer, starts two worker threads (one
 * drives, one prints) and ends with pthread_exit; the program must end when its workers end,
 * although the library's reader and timer threads are still there. */
#include <pthread.h>
#include <stdio.h>
#include "eyebot.h"

static volatile int ticks;

static void count_tick(void) { ticks++; }

static void *drive(void *unused)
{
    (void)unused;
    VWStraight(300, 300);
    VWWait();
    printf("drive done\n");
    return NULL;
}

static void *report(void *unused)
{
    (void)unused;
    for (int k = 1; k <= 3; k++) {
        LCDPrintf("round %d\n", k);
        printf("round %d\n", k);
        OSWait(200);
    }
    printf("timer ticks %d\n", ticks);
    return NULL;
}

int main(void)
{
    pthread_t driver, reporter;
    if (!OSAttachTimer(100, count_tick))
        return 2;
    if (pthread_create(&driver, NULL, drive, NULL) || pthread_create(&reporter, NULL, report, NULL))
        return 3;
    pthread_exit(NULL); /* the workers go on; the process ends with the last of them */
}
