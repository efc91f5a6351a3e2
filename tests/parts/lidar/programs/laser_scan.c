/* Test program: EyeSim 6's SIMLaserScan after the program set its own narrow LIDAR field, then a
 * LIDARGet that must still use that field. */
#include "eyebot.h"

int main(void)
{
    int scan[360], narrow[8];
    printf("set %d\n", LIDARSet(180, 0, 8));
    int rc = SIMLaserScan(scan);
    printf("laser %d", rc);
    for (int i = 0; i < 360; i++)
        printf(" %d", scan[i]);
    printf("\nresolution %d\n", LIDAR_RESOLUTION);
    rc = LIDARGet(narrow);
    printf("narrow %d", rc);
    for (int i = 0; i < 8; i++)
        printf(" %d", narrow[i]);
    printf("\nnull %d\n", SIMLaserScan(NULL));
    return 0;
}
