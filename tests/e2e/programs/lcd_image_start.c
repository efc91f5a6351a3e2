/* LCDImageStart gives the size of the image data, as in EyeSim: a 128 x 128 binary map and
 * 160 x 120 tiles, each in a buffer of exactly that many pixels (the test builds this program with
 * AddressSanitizer, which stops it at any read past a buffer). Prints "ok/FAIL name value" lines. */
#include "eyebot.h"

static void check(const char *what, int value, int expected)
{
    printf("%s %s %d\n", value == expected ? "ok" : "FAIL", what, value);
}

int main(void)
{
    /* A program that never calls LCDImageStart: CAMInit's resolution (QQVGA) at (0, 0). */
    CAMInit(QQVGA);
    BYTE *frame = malloc(QQVGA_SIZE);
    for (int k = 0; k < QQVGA_PIXELS; k++) {
        frame[3 * k] = 255; /* red */
        frame[3 * k + 1] = frame[3 * k + 2] = 0;
    }
    check("camera-sized image", LCDImage(frame), 0);
    check("its last pixel", LCDGetPixel(159, 119), RED);
    check("not beyond it", LCDGetPixel(160, 120), BLACK);

    /* The binary map: 128 x 128 bytes, a black cross on white. */
    BYTE *map = malloc(128 * 128);
    for (int y = 0; y < 128; y++)
        for (int x = 0; x < 128; x++)
            map[y * 128 + x] = (x == 64 || y == 32);
    LCDImageStart(200, 10, 128, 128);
    check("map", LCDImageBinary(map), 0);
    check("map white", LCDGetPixel(200, 10), WHITE);
    check("map cross", LCDGetPixel(200 + 64, 10 + 100), BLACK);
    check("map cross row", LCDGetPixel(200 + 3, 10 + 32), BLACK);
    check("map corner", LCDGetPixel(200 + 127, 10 + 127), WHITE);
    check("beside the map", LCDGetPixel(200 + 128, 10 + 127), BLACK);

    /* Tiles of 160 x 120 after CAMInit(QVGA), which set 320 x 240: LCDImageStart decides. */
    CAMInit(QVGA);
    BYTE *gray = malloc(QQVGA_PIXELS);
    BYTE *colour = malloc(QQVGA_SIZE);
    for (int k = 0; k < QQVGA_PIXELS; k++) {
        gray[k] = (BYTE)(k % 160); /* brighter to the right */
        colour[3 * k] = colour[3 * k + 1] = 0;
        colour[3 * k + 2] = 255; /* blue */
    }
    LCDImageStart(0, 160, 160, 120);
    check("gray tile", LCDImageGray(gray), 0);
    LCDImageStart(160, 160, 160, 120);
    check("colour tile", LCDImage(colour), 0);
    check("gray tile left", LCDGetPixel(0, 200), 0x000000);
    check("gray tile right", LCDGetPixel(159, 279), 0x9F9F9F);
    check("colour tile", LCDGetPixel(319, 279), BLUE);
    check("right of the tiles", LCDGetPixel(320, 200), BLACK);

    /* LCDImageSize(CUSTOM) keeps the LCDImageStart size; a resolution replaces it. */
    check("custom", LCDImageSize(CUSTOM), 0);
    LCDImageStart(320, 160, 160, 120);
    check("custom tile", LCDImageGray(gray), 0);
    check("custom tile right", LCDGetPixel(479, 279), 0x9F9F9F);
    LCDImageSize(QQVGA);
    check("after LCDImageSize", LCDImage(frame), 0);
    check("at the same place", LCDGetPixel(479, 279), RED);

    free(frame);
    free(map);
    free(gray);
    free(colour);
    printf("done\n");
    return 0;
}
