/* Radio, the driver (robot 2): waits for commands from robot 1 over the radio ("forward <mm>",
 * "left <degrees>", "right <degrees>", "stop"), carries each out and answers where it is now.
 * Runs with radio_commander.c on robot 1. From the examples folder (eyesim compiles them):
 *   eyesim run scenes/radio.sim --program 1=programs/radio_commander.c --program 2=programs/radio_driver.c
 */
#include <stdio.h>
#include <string.h>
#include "eyebot.h"

int main(void)
{
    char command[100], answer[200];
    int from, amount, x, y, phi;
    RADIOInit();
    LCDPrintf("Driver: robot %d, waiting for commands\n", RADIOGetID());
    for (;;) {
        RADIOReceive(&from, command, sizeof command);
        LCDPrintf("robot %d: %s\n", from, command);
        printf("got \"%s\" from robot %d\n", command, from);
        if (strcmp(command, "stop") == 0) {
            RADIOSend(from, "stopped");
            break;
        }
        if (sscanf(command, "forward %d", &amount) == 1)
            VWStraight(amount, 300);
        else if (sscanf(command, "left %d", &amount) == 1)
            VWTurn(amount, 90);
        else if (sscanf(command, "right %d", &amount) == 1)
            VWTurn(-amount, 90);
        else {
            snprintf(answer, sizeof answer, "unknown command: %s", command);
            RADIOSend(from, answer);
            continue;
        }
        VWWait();
        VWGetPosition(&x, &y, &phi);
        snprintf(answer, sizeof answer, "done %s, now at x %d y %d phi %d", command, x, y, phi);
        RADIOSend(from, answer);
    }
    LCDPrintf("stopped\n");
    return 0;
}
