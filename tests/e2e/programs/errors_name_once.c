/* Calls that the simulator refuses: each prints one "eyesim: <function>: <reason>" line. */
#include "eyebot.h"

int main(void)
{
    int drive = VWDrive(10, 100, 100); /* dx must be greater than |dy| */
    int lidar = LIDARSet(0, 0, 360);
    int servo = SERVOSet(9, 0);
    int robot = SIMGetRobot(9, NULL, NULL, NULL, NULL);
    printf("results %d %d %d %d\n", drive, lidar, servo, robot);
    return 0;
}
