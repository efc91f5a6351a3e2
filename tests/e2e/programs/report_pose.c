/* Browser end-to-end program: after KEY1, reports its true pose, its odometry and object 1's pose. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int x, y, z, phi, ox, oy, ophi;
    LCDMenu("POSE", "", "", "");
    KEYWait(KEY1);
    SIMGetRobot(0, &x, &y, &z, &phi);
    VWGetPosition(&ox, &oy, &ophi);
    printf("true %d %d %d\n", x, y, phi);
    printf("odometry %d %d %d\n", ox, oy, ophi);
    SIMGetObject(1, &x, &y, &z, &phi);
    printf("object %d %d %d\n", x, y, phi);
    return 0;
}
