/* End-to-end test program: waits for KEY1, drives 1000 mm, turns 90 degrees, reports on the LCD. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    LCDMenu("GO", "", "", "END");
    LCDPrintf("Hello EyeSim\n");
    int key = KEYGet();
    LCDPrintf("key %d\n", key);
    VWStraight(1000, 300);
    VWWait();
    VWTurn(90, 60);
    VWWait();
    int x, y, phi;
    VWGetPosition(&x, &y, &phi);
    LCDPrintf("odometry %d %d %d\n", x, y, phi);
    printf("done key=%d x=%d y=%d phi=%d\n", key, x, y, phi);
    return key == KEY1 ? 0 : 9;
}
