/* Recording test program: one camera image and one lidar scan, with what the program saw printed. */
#include <stdio.h>
#include "eyebot.h"

static BYTE image[QVGA_SIZE];
static int scan[3600]; /* LIDARGet writes LIDAR_RESOLUTION (360) of them */

int main(void)
{
    CAMInit(QVGA);
    CAMGet(image);
    int centre = (CAMHEIGHT / 2 * CAMWIDTH + CAMWIDTH / 2) * 3;
    printf("camera %d %d centre %d %d %d\n", CAMWIDTH, CAMHEIGHT, image[centre], image[centre + 1], image[centre + 2]);
    LIDARGet(scan);
    printf("lidar ahead %d left %d\n", scan[180], scan[90]);
    return 0;
}
