/* Windows test program (C, cross-compiled with Zig): writes on the LCD, drives 300 mm ahead, turns
   90 degrees right, drives 200 mm and prints where its odometry says it is. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int x, y, phi;
    LCDPrintf("Windows C\n");
    LCDArea(20, 200, 99, 259, GREEN, 1);
    VWStraight(300, 300);
    VWWait();
    VWTurn(-90, 90);
    VWWait();
    VWStraight(200, 200);
    VWWait();
    VWGetPosition(&x, &y, &phi);
    LCDPrintf("x=%d y=%d phi=%d\n", x, y, phi);
    printf("odometry %d %d %d\n", x, y, phi);
    return 0;
}
