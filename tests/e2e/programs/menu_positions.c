/* Soft-key labels set one by one with LCDMenuI(0..3), each in its own colours, as EyeSim's
 * graphics example does; a position past the four keys is refused. Then waits for a key. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    const char *labels[4] = {"First", "Second", "Third", "Fourth"};
    COLOR backgrounds[4] = {BLUE, WHITE, RED, GREEN};
    for (int pos = 0; pos < 4; pos++)
        printf("LCDMenuI(%d) = %d\n", pos, LCDMenuI(pos, labels[pos], BLACK, backgrounds[pos]));
    printf("LCDMenuI(4) = %d\n", LCDMenuI(4, "Fifth", BLACK, YELLOW));
    printf("key %d\n", KEYWait(ANYKEY));
    return 0;
}
