/* Car slalom: the Ackermann car (the built-in Car, eyesim/data/robots/Car.robi) drives ahead, steering left and right
 * in turn. Motor 1 drives the rear axle; servo 1 steers: 0 = 45 deg left, 127 = ahead, 255 = right.
 * The car is robot 1 of the drive-types scene (which names the three C programs); from the
 * examples folder:
 *   eyesim run scenes/drive_types.sim --program 1=programs/car_slalom.c --program 2=programs/omni_square.c --program 3=programs/push_crate.c
 */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    LCDPrintf("Car slalom\n");
    MOTORDrive(1, 30);
    /* about 15 degrees left, right, left, right; the first and last swings are half as long, so
       the car weaves about a straight line east */
    const int times[4] = {600, 1200, 1200, 600};
    for (int turn = 0; turn < 4; turn++) {
        SERVOSet(1, turn % 2 ? 170 : 84);
        OSWait(times[turn]);
    }
    SERVOSet(1, 127);
    OSWait(500);
    MOTORDrive(1, 0);
    LCDPrintf("done, axle turned %d ticks\n", ENCODERRead(1));
    printf("axle %d\n", ENCODERRead(1));
    return 0;
}
