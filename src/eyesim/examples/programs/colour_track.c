/* Colour tracking with the camera: S4 turns until it sees something red, steers to keep it in the
 * middle of the image, drives up to it and stops once it fills a quarter of the picture. The LCD
 * shows the camera image with the red pixels' centre marked.
 * From the examples folder (eyesim compiles it):
 *   eyesim run scenes/colour_track.sim --program 1=programs/colour_track.c
 */
#include <stdio.h>
#include "eyebot.h"

#define MIN_PIXELS 20        /* red pixels that count as seeing the target */
#define ARRIVED 0.25         /* share of the image the target fills when the robot is there */
#define TURN_GAIN 0.8        /* deg/s per pixel the target is off the middle */
#define RUN_SECONDS 60

static QQVGAcol image;

static int is_red(const BYTE *p)
{
    return p[0] > 120 && p[0] > 2 * p[1] && p[0] > 2 * p[2];
}

int main(void)
{
    CAMInit(QQVGA);
    LCDMenu("", "", "", "END");
    int start = OSGetCount();
    while (KEYRead() != KEY4 && OSGetCount() - start < RUN_SECONDS * 1000) {
        CAMGet(image);
        long count = 0, sum = 0;
        for (int i = 0; i < QQVGA_PIXELS; i++)
            if (is_red(image + 3 * i)) {
                count++;
                sum += i % QQVGA_X;
            }
        LCDImage(image);
        if (count < MIN_PIXELS) {
            VWSetSpeed(0, 45); /* nothing red in sight: look around */
            LCDSetPrintf(10, 0, "searching...               ");
        } else {
            int offset = (int)(sum / count) - QQVGA_X / 2;
            LCDLine(offset + QQVGA_X / 2, 0, offset + QQVGA_X / 2, QQVGA_Y - 1, GREEN);
            LCDSetPrintf(10, 0, "target %3d px off, %5ld px  ", offset, count);
            if (count > ARRIVED * QQVGA_PIXELS) {
                VWSetSpeed(0, 0);
                printf("arrived: the target fills %ld of %d pixels\n", count, QQVGA_PIXELS);
                return 0;
            }
            int ahead = offset > -12 && offset < 12;
            VWSetSpeed(ahead ? 200 : 0, (int)(-TURN_GAIN * offset));
        }
        OSWait(50);
    }
    VWSetSpeed(0, 0);
    printf("no target reached\n");
    return 1;
}
