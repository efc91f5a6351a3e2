/* Test program: lidar scans with the default set-up, a narrow 8-point field, and a tilted plane. */
#include <stdio.h>
#include "eyebot.h"

static int scan[3600];

static void report(const char *name)
{
    int rc = LIDARGet(scan);
    printf("%s %d %d", name, rc, LIDAR_RESOLUTION);
    for (int i = 0; i < LIDAR_RESOLUTION; i++)
        printf(" %d", scan[i]);
    printf("\n");
}

int main(void)
{
    report("default");
    printf("set %d\n", LIDARSet(180, 0, 8));
    report("narrow");
    printf("set %d\n", LIDARSet(360, 10, 360));
    report("tilted");
    int bad[4] = {LIDARSet(0, 0, 360), 0, 0, 0}; /* one call per statement: printed in this order */
    bad[1] = LIDARSet(360, 90, 360);
    bad[2] = LIDARSet(360, 0, 0);
    bad[3] = LIDARSet(360, 0, 3601);
    printf("bad %d %d %d %d\n", bad[0], bad[1], bad[2], bad[3]);
    printf("still %d\n", LIDAR_RESOLUTION);
    return 0;
}
