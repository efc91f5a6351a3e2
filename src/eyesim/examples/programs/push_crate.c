/* Push a crate: the Trolley (the built-in Trolley, eyesim/data/robots/Trolley.robi) drives up to the crate ahead and
 * pushes it 600 mm further, then backs off.
 * It is robot 3 of the drive-types scene (which names the three C programs); from the examples
 * folder:
 *   eyesim run scenes/drive_types.sim --program 1=programs/car_slalom.c --program 2=programs/omni_square.c --program 3=programs/push_crate.c
 */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    LCDPrintf("Pushing the crate\n");
    while (PSDGet(PSD_FRONT) > 40) {
        VWSetSpeed(200, 0);
        OSWait(20);
    }
    VWStraight(600, 150);
    VWWait();
    VWStraight(-200, 200);
    VWWait();
    int x, y, z, phi;
    SIMGetObject(1, &x, &y, &z, &phi);
    LCDPrintf("crate now at %d %d\n", x, y);
    printf("crate %d %d\n", x, y);
    return 0;
}
