/* Two threads of the program read the robot's sensors at the same time (and a timer counts):
 * a deterministic run warns that it may not repeat. With an argument, only the main thread and
 * the timer call RoBIOS: no warning. */
#include "eyebot.h"

static volatile int ticks;

static void tick(void) { ticks += PSDGet(PSD_FRONT) > 0; } /* calls from the library's timer thread */

static void *poll_sensors(void *unused)
{
    (void)unused;
    for (int k = 0; k < 50; k++)
        PSDGet(PSD_LEFT);
    return NULL;
}

int main(int argc, char **argv)
{
    (void)argv;
    TIMER timer = OSAttachTimer(10, tick);
    if (argc > 1) {
        for (int k = 0; k < 50; k++)
            PSDGet(PSD_RIGHT);
        OSWait(100);
    } else {
        pthread_t other;
        pthread_create(&other, NULL, poll_sensors, NULL);
        for (int k = 0; k < 50; k++)
            PSDGet(PSD_RIGHT);
        pthread_join(other, NULL);
    }
    OSDetachTimer(timer);
    printf("ticks %d\n", ticks > 0);
    return 0;
}
