/* Test program: starts the camera and ends at once, while the simulator is still preparing its
 * renderer (the run ends with it). */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    printf("init %d\n", CAMInit(VGA));
    return 0;
}
