/* Wall following with PSDs: S4 keeps the wall on its left at DISTANCE mm and turns right where a
 * wall blocks the way. Runs for RUN_SECONDS (or until KEY4) and shows the readings on the LCD.
 * From the examples folder (eyesim compiles it):
 *   eyesim run scenes/wall_follow.sim --program 1=programs/wall_follow.c
 */
#include <stdio.h>
#include "eyebot.h"

#define DISTANCE 200    /* mm between the left PSD and the wall */
#define SPEED 200       /* mm/s along the wall */
#define GAIN 0.6        /* deg/s of turn per mm of error */
#define DAMPING 0.4     /* deg/s of turn per mm/s the error changes by: stops the robot weaving */
#define PERIOD 20       /* ms between readings */
#define MAX_TURN 90     /* deg/s */
#define RUN_SECONDS 60

static int clamp(int value, int low, int high)
{
    return value < low ? low : value > high ? high : value;
}

int main(void)
{
    LCDMenu("", "", "", "END");
    LCDSetPrintf(0, 0, "Wall following: left wall at %d mm", DISTANCE);
    int start = OSGetCount(), last_error = 0;
    while (KEYRead() != KEY4 && OSGetCount() - start < RUN_SECONDS * 1000) {
        int front = PSDGet(PSD_FRONT), left = PSDGet(PSD_LEFT);
        if (front < DISTANCE + 60) {
            VWSetSpeed(0, -MAX_TURN); /* a wall ahead: turn right on the spot */
        } else {
            /* too far from the wall (or none there): steer left; too close: steer right */
            int error = clamp(left - DISTANCE, -150, 150);
            double change = (error - last_error) * 1000.0 / PERIOD; /* mm/s */
            last_error = error;
            VWSetSpeed(SPEED, clamp((int)(GAIN * error + DAMPING * change), -MAX_TURN, MAX_TURN));
        }
        LCDSetPrintf(2, 0, "front %4d mm  left %4d mm  ", front, left);
        OSWait(PERIOD);
    }
    VWSetSpeed(0, 0);
    printf("wall following done after %d ms\n", OSGetCount() - start);
    return 0;
}
