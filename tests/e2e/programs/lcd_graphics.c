/* The LCD and key functions from C: draws and prints, reads pixels back, waits for keys and touches.
 * Prints "name value" lines the test checks; the LCD image is checked from --save-lcd. */
#include <stdio.h>
#include <string.h>
#include "eyebot.h"

static void check(const char *what, int value, int expected)
{
    printf("%s %s %d\n", value == expected ? "ok" : "FAIL", what, value);
}

int main(void)
{
    int x = -1, y = -1, row = -1, column = -1;

    LCDGetSize(&x, &y);
    check("width", x, 480);
    check("height", y, 320);

    /* Text: a title in red on blue, then the cursor moves on like a terminal. */
    LCDSetColor(RED, BLUE);
    LCDPrintf("Title");
    LCDGetPos(&row, &column);
    check("column after Title", column, 5);
    LCDSetColor(WHITE, BLACK);
    LCDPrintf("\nline two\n");
    LCDGetPos(&row, &column);
    check("row after two lines", row, 2);
    check("set pos", LCDSetPos(20, 59), 0);
    check("set pos outside", LCDSetPos(21, 0), 1);
    LCDSetPrintf(3, 10, "%s=%d", "x", 42);
    LCDGetPos(&row, &column);
    check("row after set printf", row, 3);
    check("column after set printf", column, 14);

    /* Fonts and sizes. */
    check("font times bold", LCDSetFont(TIMES, BOLD), 0);
    check("font size 24", LCDSetFontSize(24), 0);
    check("font size 30", LCDSetFontSize(30), 1);
    LCDSetPrintf(4, 0, "Big"); /* 15 x 32 cells: row 4 starts at y = 128 */
    LCDSetFont(COURIER, NORMAL);
    LCDSetFontSize(10);

    /* Graphics, read back exactly. */
    LCDPixel(300, 10, 0x123456);
    check("pixel", LCDGetPixel(300, 10), 0x123456);
    LCDLine(300, 20, 400, 20, GREEN);
    check("line middle", LCDGetPixel(350, 20), GREEN);
    LCDArea(300, 30, 340, 60, YELLOW, 1);
    check("area inside", LCDGetPixel(320, 45), YELLOW);
    LCDArea(350, 30, 390, 60, WHITE, 0);
    check("outline edge", LCDGetPixel(350, 45), WHITE);
    check("outline inside", LCDGetPixel(370, 45), BLACK);
    LCDCircle(440, 45, 15, MAGENTA, 1);
    check("circle centre", LCDGetPixel(440, 45), MAGENTA);
    check("outside the screen", LCDGetPixel(480, 0), -1);

    /* Images: a 4 x 2 colour image (LCDImageStart gives the size), a gray and a binary one. */
    BYTE colour[4 * 2 * 3] = {0};
    for (int k = 0; k < 8; k++)
        colour[3 * k + (k % 3)] = 255; /* red, green, blue, red, ... */
    LCDImageStart(400, 100, 4, 2);
    LCDImageSize(CUSTOM);            /* keeps the 4 x 2 pixels */
    check("image", LCDImage(colour), 0);
    check("image pixel 0", LCDGetPixel(400, 100), RED);
    check("image pixel 1", LCDGetPixel(401, 100), GREEN);
    check("image pixel 5", LCDGetPixel(401, 101), BLUE);
    BYTE gray[QQVGA_PIXELS];
    memset(gray, 200, sizeof gray);
    LCDImageSize(QQVGA);
    LCDImageStart(0, 160, 160, 120);
    check("gray image", LCDImageGray(gray), 0);
    check("gray pixel", LCDGetPixel(80, 200), 0xC8C8C8);
    BYTE binary[QQVGA_PIXELS] = {0};
    binary[0] = 1;
    LCDImageStart(160, 160, 160, 120);
    LCDImageBinary(binary);
    check("binary black", LCDGetPixel(160, 160), BLACK);
    check("binary white", LCDGetPixel(161, 160), WHITE);
    check("bad image size", LCDImageSize(7), 1);

    /* The menu, and keys: KEYWait ignores KEY1, KEYGet takes the next key. */
    LCDMenu("A", "B", "C", "END");
    LCDMenuI(1, "GO", BLACK, GREEN); /* positions count from 0, as on EyeSim: 1 is KEY2 */
    check("key wait", KEYWait(KEY3), KEY3);
    check("key get", KEYGet(), KEY4);

    /* Touches: one waits, one is read, then none is left. */
    check("get xy", KEYGetXY(&x, &y), 0);
    check("touch x", x, 100);
    check("touch y", y, 50);
    OSWait(600);
    check("read xy", KEYReadXY(&x, &y), 0);
    check("touch 2 x", x, 5);
    check("read xy none", KEYReadXY(&x, &y), 1);
    check("touch 2 x kept", x, 5);

    /* Without auto-refresh the drawing shows only after LCDRefresh (checked in the saved image). */
    LCDSetMode(LCD_NOAUTOREFRESH);
    LCDArea(0, 250, 50, 270, CYAN, 1);
    LCDRefresh();
    LCDArea(60, 250, 110, 270, CYAN, 1); /* never shown */
    check("mode conflict", LCDSetMode(LCD_SCROLLING | LCD_NOSCROLLING), 1);
    printf("done\n");
    return 0;
}
