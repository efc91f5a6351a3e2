/* Omni square: the mecanum robot (the built-in Mecanum, eyesim/data/robots/Mecanum.robi) drives a 600 mm square facing the
 * same way all along: back, right, ahead, left. Motors 1..4 = front left, front right, back left,
 * back right; each leg is measured with the encoders.
 * It is robot 2 of the drive-types scene (which names the three C programs); from the examples
 * folder:
 *   eyesim run scenes/drive_types.sim --program 1=programs/car_slalom.c --program 2=programs/omni_square.c --program 3=programs/push_crate.c
 */
#include <stdlib.h>
#include "eyebot.h"

#define TICKS_PER_MM (720 / (3.14159265 * 60)) /* 720 ticks per turn of a 60 mm wheel */

static void leg(const int direction[4], int mm)
{
    for (int motor = 1; motor <= 4; motor++) {
        ENCODERReset(motor);
        MOTORSpeed(motor, direction[motor - 1] * 600);
    }
    int done = 0;
    while (!done) {
        OSWait(5);
        int sum = 0;
        for (int motor = 1; motor <= 4; motor++)
            sum += abs(ENCODERRead(motor));
        done = sum / 4 >= mm * TICKS_PER_MM;
    }
    for (int motor = 1; motor <= 4; motor++)
        MOTORSpeed(motor, 0);
    OSWait(300);
}

int main(void)
{
    const int back[4] = {-1, -1, -1, -1}, right[4] = {1, -1, -1, 1};
    const int ahead[4] = {1, 1, 1, 1}, left[4] = {-1, 1, 1, -1};
    LCDPrintf("Omni square\n");
    leg(back, 600);
    leg(right, 600);
    leg(ahead, 600);
    leg(left, 600);
    LCDPrintf("back at the start\n");
    return 0;
}
