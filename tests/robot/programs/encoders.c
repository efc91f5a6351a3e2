/* Drives both wheels open loop and with speed control, and reports encoders and the true pose. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int x0, y0, z, phi;
    SIMGetRobot(0, &x0, &y0, &z, &phi);
    ENCODERReset(1);
    ENCODERReset(2);
    MOTORDrive(1, 40);
    MOTORDrive(2, 40);
    OSWait(1500);
    MOTORDrive(1, 0);
    MOTORDrive(2, 0);
    OSWait(500);
    int x, y;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("open %d %d %d %d\n", ENCODERRead(1), ENCODERRead(2), x - x0, y - y0);
    MOTORPID(1, 70, 30, 0);
    MOTORPID(2, 70, 30, 0);
    ENCODERReset(1);
    ENCODERReset(2);
    MOTORSpeed(1, 1000);
    MOTORSpeed(2, 1000);
    OSWait(1000);
    int a = ENCODERRead(1), b = ENCODERRead(2);
    OSWait(1000);
    printf("speed %d %d\n", ENCODERRead(1) - a, ENCODERRead(2) - b);
    MOTORPIDOff(1);
    MOTORPIDOff(2);
    printf("errors %d %d %d %d %d %d\n", MOTORDrive(3, 50), MOTORDrive(1, 101), ENCODERRead(5), MOTORSpeed(1, 1000000),
           SERVOSet(1, 100), MOTORPID(1, 256, 0, 0));
    return 0;
}
