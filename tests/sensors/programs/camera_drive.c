/* Test program: drives a curve while taking colour and gray QVGA frames (a third robot's PSDs watch
 * it); prints each frame's time and checksum, so that deterministic runs can be compared. */
#include <stdio.h>
#include "eyebot.h"

static BYTE colour[QVGA_SIZE];
static BYTE gray[QVGA_PIXELS];

static unsigned long checksum(const BYTE *data, int size)
{
    unsigned long hash = 5381;
    for (int i = 0; i < size; i++)
        hash = (hash * 33) ^ data[i];
    return hash % 1000000007UL;
}

int main(void)
{
    CAMInit(QVGA);
    VWSetSpeed(200, 40);
    for (int i = 0; i < 8; i++) {
        int got = CAMGet(colour);
        printf("colour %d %d %lu\n", got, OSGetCount(), checksum(colour, QVGA_SIZE));
        got = CAMGetGray(gray);
        printf("gray %d %d %lu\n", got, OSGetCount(), checksum(gray, QVGA_PIXELS));
        printf("psd %d\n", PSDGet(PSD_FRONT));
        OSWait(30);
    }
    VWSetSpeed(0, 0);
    return 0;
}
