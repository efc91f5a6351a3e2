/* Menu-driven lab programs redraw their screen pixel by pixel and then wait for a key: two
 * screens of a 40 x 90 block (3 600 LCDPixel calls each), a KEYGet after each, then a map of
 * 16 000 one-pixel LCDArea calls. Prints when each screen was ready, which key came when, and
 * how long the map took (OSGetCount, simulation time). */
#include <stdio.h>
#include "eyebot.h"

static void block(COLOR color)
{
    for (int y = 0; y < 90; y++)
        for (int x = 0; x < 40; x++)
            LCDPixel(200 + x, 100 + y, color);
}

int main(void)
{
    COLOR colors[2] = {RED, GREEN};
    for (int screen = 1; screen <= 2; screen++) {
        LCDMenu("A", "B", "C", "D");
        block(colors[screen - 1]);
        int ready = OSGetCount();
        int key = KEYGet();
        printf("screen %d ready at %d ms, key %d at %d ms\n", screen, ready, key, OSGetCount());
    }
    int start = OSGetCount();
    for (int i = 0; i < 16000; i++)
        LCDArea(i % 160, i / 160, i % 160, i / 160, BLUE, 1);
    printf("map of 16000 areas took %d ms\n", OSGetCount() - start);
    return 0;
}
