/* Test program (robot 1): waits for robot 2's hello, checks who is on the air, plays ping-pong,
 * then receives a numbered burst and checks its order. */
#include <stdio.h>
#include <string.h>
#include "eyebot.h"

#define ROUNDS 20
#define BURST 50

int main(void)
{
    char text[64];
    int from, ids[256];
    int early_send = RADIOSend(2, "too early");
    printf("before %d %d\n", early_send, RADIOCheck());
    int init = RADIOInit();
    printf("init %d id %d\n", init, RADIOGetID());
    RADIOReceive(&from, text, sizeof text);
    printf("hello from %d: %s\n", from, text);
    int count = RADIOStatus(ids);
    printf("status %d", count);
    for (int i = 0; i < count; i++)
        printf(" %d", ids[i]);
    printf("\n");
    for (int round = 0; round < ROUNDS; round++) {
        char ping[32];
        snprintf(ping, sizeof ping, "ping %d", round);
        RADIOSend(2, ping);
        int n = RADIOReceive(&from, text, sizeof text);
        printf("got %d %d %s\n", from, n, text);
    }
    int in_order = 1;
    for (int k = 0; k < BURST; k++) {
        int expected;
        RADIOReceive(&from, text, sizeof text);
        if (sscanf(text, "burst %d", &expected) != 1 || expected != k)
            in_order = 0;
    }
    printf("burst in order %d, waiting %d\n", in_order, RADIOCheck());
    int unknown = RADIOSend(99, "x");
    printf("unknown %d, short %d\n", unknown, RADIOReceive(&from, text, 0));
    printf("release %d\n", RADIORelease());
    return 0;
}
