/* The pattern of a real lab program: a second thread waits for a key while the main thread turns
 * the robot with its own control loop (VWSetSpeed, then VWGetPosition and some computing until
 * the heading is reached). With an argument, the same loop without the second thread. Prints the
 * turn. */
#include "eyebot.h"

static void *wait_for_key(void *unused)
{
    (void)unused;
    KEYGet();
    return NULL;
}

int main(int argc, char **argv)
{
    (void)argv;
    pthread_t keys;
    if (argc == 1)
        pthread_create(&keys, NULL, wait_for_key, NULL);
    int x, y, phi;
    VWSetSpeed(0, 60);
    do {
        VWGetPosition(&x, &y, &phi);
        for (volatile long work = 0; work < 300000; work++) { /* the controller's own computing */
        }
    } while (phi < 34);
    VWSetSpeed(0, 0);
    OSWait(200);
    VWGetPosition(&x, &y, &phi);
    printf("turned %d\n", phi);
    return 0;
}
