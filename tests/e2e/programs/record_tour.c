/* Recording test program: numbered LCD lines at known times, PSD readings, VW driving, console lines. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    LCDMenu("", "", "", "END");
    for (int step = 1; step <= 4; step++) {
        LCDPrintf("step %d psd %d\n", step, PSDGet(PSD_FRONT));
        printf("step %d\n", step);
        fflush(stdout);
        VWSetSpeed(200, step % 2 ? 30 : -30);
        OSWait(500);
    }
    VWSetSpeed(0, 0);
    LCDPrintf("done\n");
    printf("done\n");
    return 0;
}
