/* lidar.c: RoBIOS LIDAR scans (mm); LIDAR_RESOLUTION is the number of points a scan array holds. */
#include "eyebot.h"
#include "transport.h"

#include <stdio.h>

int LIDAR_RESOLUTION = 360;

int LIDARSet(int range, int tilt, int points)
{
    es_value args[3] = {es_int(range), es_int(tilt), es_int(points)}, result[1];
    if (es_call("LIDARSet", ES_OP_LIDAR_SET, args, result))
        return 1;
    LIDAR_RESOLUTION = points;
    return (int)result[0].i;
}

int LIDARGet(int distance[])
{
    if (!distance) {
        fprintf(stderr, "eyesim: LIDARGet: the distance array is NULL\n");
        return 1;
    }
    es_value result[2] = {{0}};
    if (es_call("LIDARGet", ES_OP_LIDAR_GET, NULL, result))
        return 1;
    /* The array holds LIDAR_RESOLUTION ints: never write more, whatever the robot file says. */
    int points = (int)result[1].n;
    int stored = points < LIDAR_RESOLUTION ? points : LIDAR_RESOLUTION;
    for (int k = 0; k < stored; k++)
        distance[k] = es_i32s_at(&result[1], (uint32_t)k);
    if (points > LIDAR_RESOLUTION) {
        fprintf(stderr, "eyesim: LIDARGet: the robot's lidar has %d points, LIDAR_RESOLUTION is %d; only %d were "
                "stored: call LIDARSet(360, 0, %d) first\n", points, LIDAR_RESOLUTION, stored, points);
        return 1;
    }
    LIDAR_RESOLUTION = points;
    return (int)result[0].i;
}

int SIMLaserScan(int scan[360])
{
    if (!scan) {
        fprintf(stderr, "eyesim: SIMLaserScan: the scan array is NULL\n");
        return 1;
    }
    es_value result[2] = {{0}};
    if (es_call("SIMLaserScan", ES_OP_SIM_LASER_SCAN, NULL, result))
        return 1;
    if (result[1].n != 360) {
        fprintf(stderr, "eyesim: SIMLaserScan: the simulator sent %u distances instead of 360\n",
                (unsigned)result[1].n);
        return 1;
    }
    for (int k = 0; k < 360; k++)
        scan[k] = es_i32s_at(&result[1], (uint32_t)k);
    return (int)result[0].i;
}
