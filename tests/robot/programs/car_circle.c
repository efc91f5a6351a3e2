/* Steers the car left by a fixed servo setting and drives it round in circles. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    SERVOSet(1, 80); /* 47 of 127 steps left of straight: (127 - 80) / 127 * 45 degrees */
    OSWait(500);
    MOTORDrive(1, 30);
    OSWait(9000);
    MOTORDrive(1, 0);
    printf("encoder %d\n", ENCODERRead(1));
    printf("errors %d %d %d %d\n", SERVOSet(2, 100), SERVOSet(1, 256), MOTORDrive(2, 10), VWTurn(90, 60));
    return 0;
}
