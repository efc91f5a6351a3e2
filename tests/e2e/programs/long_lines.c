/* Text on the LCD's default grid, as EyeSim lab programs print it: a status line longer than the
 * screen, the last cell set directly, a cell past it refused, and the screen's size. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int row, column, width, height;
    LCDPrintf("%s", "0123456789abcdefghijklmnopqrstuvwxyz0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-wrapped");
    LCDGetPos(&row, &column);
    printf("after the long line: row %d column %d\n", row, column);
    printf("last cell %d\n", LCDSetPrintf(20, 79, "Z"));
    printf("column 80 %d\n", LCDSetPrintf(0, 80, "!"));
    LCDGetSize(&width, &height);
    printf("size %d x %d\n", width, height);
    return 0;
}
