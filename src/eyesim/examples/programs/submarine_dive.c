/* Submarine dive: Minnow (the built-in Minnow, eyesim/data/robots/Minnow.robi) goes to 500 mm under the surface of
 * its pool (it is as heavy as the water it displaces, so it starts on the pool floor and rises there),
 * holds that depth with its vertical thrusters (3 front, 4 back) while it cruises and turns on its
 * horizontal ones (1 left, 2 right), then surfaces. Depth comes from SIMGetRobot.
 * From the examples folder (eyesim compiles it):
 *   eyesim run scenes/pool.sim --program 1=programs/submarine_dive.c
 */
#include <stdio.h>
#include "eyebot.h"

#define SURFACE 1500 /* mm: the pool's rim */
#define HEIGHT 200   /* mm: Minnow's hull */

static int depth(void) /* of the hull's top under the surface, mm */
{
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    return SURFACE - (z + HEIGHT);
}

static void hold_depth(int target, int ms, int left, int right)
{
    int last = depth();
    for (int t = 0; t < ms; t += 50) {
        int now = depth();
        int push = (now - target) / 4 + (now - last) * 2; /* too deep: push up; damped by the rate */
        if (push > 100)
            push = 100;
        if (push < -100)
            push = -100;
        MOTORDrive(3, push);
        MOTORDrive(4, push);
        MOTORDrive(1, left);
        MOTORDrive(2, right);
        last = now;
        OSWait(50);
    }
}

int main(void)
{
    LCDPrintf("Going to 500 mm depth\n");
    hold_depth(500, 6000, 0, 0);   /* to 0.5 m under the surface */
    LCDPrintf("depth %d mm, cruising\n", depth());
    printf("dived %d\n", depth());
    hold_depth(500, 4000, 60, 60); /* ahead */
    hold_depth(500, 3000, 50, -50); /* turning right */
    hold_depth(500, 1000, 0, 0);
    LCDPrintf("depth %d mm, surfacing\n", depth());
    printf("cruised %d\n", depth());
    MOTORDrive(1, 0);
    MOTORDrive(2, 0);
    MOTORDrive(3, 100);
    MOTORDrive(4, 100);
    OSWait(3000);
    MOTORDrive(3, 0);
    MOTORDrive(4, 0);
    OSWait(2000);
    LCDPrintf("at the surface: depth %d mm\n", depth());
    printf("surfaced %d\n", depth());
    return 0;
}
