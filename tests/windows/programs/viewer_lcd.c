/* Windows test program for the viewer (C): a menu, a line and a blue square on the LCD; drives
   slowly until a soft key comes, then says which. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    LCDMenu("GO", "", "", "END");
    LCDPrintf("Hello from Windows\n");
    LCDArea(200, 120, 279, 179, BLUE, 1);
    VWSetSpeed(150, 0);
    int key = KEYGet();
    VWSetSpeed(0, 0);
    LCDPrintf("got key %d\n", key);
    printf("got key %d\n", key);
    return key == KEY1 ? 0 : 9;
}
