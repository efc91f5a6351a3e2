/* Polling loops without a wait, as lab programs write them: 250 turns of PSDGet + VWGetPosition
 * (calls that reach the robot), then waiting 500 ms by polling OSGetCount alone, then a tight
 * loop of LCD calls only until the run's --until ends it. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int x, y, phi;
    int start = OSGetCount();
    for (int i = 0; i < 250; i++) {
        PSDGet(PSD_FRONT);
        VWGetPosition(&x, &y, &phi);
    }
    printf("250 sensor turns took %d ms\n", OSGetCount() - start);
    start = OSGetCount();
    int reads = 0;
    while (OSGetCount() - start < 500)
        reads++;
    printf("waited 500 ms in %d clock reads\n", reads);
    fflush(stdout);
    for (long i = 0;; i++)
        LCDPixel((int)(i % 480), (int)(i / 480 % 280), (COLOR)(i & 0xFFFFFF));
    return 0;
}
