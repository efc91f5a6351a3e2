/* Reads what the viewer sets (an analog channel, an IR code, a touch, a serial byte, a digital line)
 * and answers through the viewer (a digital output, serial output, a beep). */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    DIGITALSetup(16, 'o');
    SERInit(0, 9600, 0);
    printf("ready\n");
    fflush(stdout);
    while (DIGITALRead(1) == 0) /* the viewer drives line 1 last */
        OSWait(10);
    int value = ANALOGRead(4);
    int code = IRTVGet();
    int x = -1, y = -1;
    KEYGetXY(&x, &y);
    char c = SERReceiveChar(0);
    printf("analog %d irtv %c touch %d,%d serial %c\n", value, code, x, y, c);
    fflush(stdout);
    DIGITALWrite(16, 1);
    SERSend(0, "reply\n");
    AUBeep();
    OSWait(100);
    return 0;
}
