/* Radio, the commander (robot 1): tells robot 2 over the radio how to drive, one command at a
 * time, and waits for its answer before sending the next. Runs with radio_driver.c on robot 2.
 * From the examples folder (the scene names both programs; eyesim compiles them):
 *   eyesim run scenes/radio.sim
 *   eyesim run scenes/radio.sim --program 1=programs/radio_commander.c --program 2=programs/radio_driver.c
 */
#include <stdio.h>
#include "eyebot.h"

#define DRIVER 2 /* the robot that drives */

static const char *commands[] = {"forward 600", "left 90", "forward 400", "left 90", "forward 300", "stop"};

int main(void)
{
    int count = sizeof commands / sizeof commands[0];
    RADIOInit();
    LCDPrintf("Commander: robot %d, driver: robot %d\n", RADIOGetID(), DRIVER);
    for (int i = 0; i < count; i++) {
        char answer[256];
        int from;
        RADIOSend(DRIVER, commands[i]);
        LCDPrintf("sent:  %s\n", commands[i]);
        RADIOReceive(&from, answer, sizeof answer);
        LCDPrintf("robot %d: %s\n", from, answer);
        printf("robot %d answered: %s\n", from, answer);
    }
    LCDPrintf("all %d commands done\n", count);
    return 0;
}
