/* Test program (robot 2): says hello to robot 1, answers each ping with a pong, then sends a burst. */
#include <stdio.h>
#include <string.h>
#include "eyebot.h"

int main(void)
{
    char text[64], pong[64];
    int from;
    RADIOInit();
    RADIOSend(1, "hello");
    for (int round = 0; round < 20; round++) {
        RADIOReceive(&from, text, sizeof text);
        snprintf(pong, sizeof pong, "pong %s", text + 5);
        RADIOSend(from, pong);
    }
    for (int k = 0; k < 50; k++) {
        snprintf(text, sizeof text, "burst %d", k);
        RADIOSend(1, text);
    }
    printf("done %d\n", RADIOGetID());
    return 0;
}
