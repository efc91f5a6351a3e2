/* Browser end-to-end program: prints, drives for a while, and reports the soft key it gets. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    LCDMenu("GO", "B", "C", "END");
    LCDPrintf("Hello browser\n");
    VWSetSpeed(150, 0);
    int key = KEYGet();
    VWSetSpeed(0, 0);
    LCDPrintf("got key %d\n", key);
    printf("got key %d\n", key);
    return key == KEY1 ? 0 : 9;
}
