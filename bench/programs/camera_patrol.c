/* Recording benchmark client: drives in slow curves and, ten times a second, takes a QVGA camera
 * image, shows it on the LCD with a line of text and reads the four PSDs: a busy robot for a recording. */
#include "eyebot.h"

static QVGAcol image;

int main(void)
{
    CAMInit(QVGA);
    for (int step = 0;; step++) {
        VWSetSpeed(150, (step / 20) % 2 ? 25 : -25);
        CAMGet(image);
        LCDImage(image);
        LCDSetPrintf(18, 0, "step %d front %d left %d right %d", step, PSDGet(PSD_FRONT), PSDGet(PSD_LEFT),
                     PSDGet(PSD_RIGHT));
        PSDGet(PSD_BACK);
        OSWait(90);
    }
    return 0;
}
