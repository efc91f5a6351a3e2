/* End-to-end test program: prints its clock between calls while simulation time runs fast
 * (short waits), and one line written in two parts with a call in between. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    for (int i = 0; i < 40; i++) {
        printf("at %d\n", OSGetCount());
        OSWait(7);
    }
    printf("first half, ");
    fflush(stdout); /* written without its end, as print(..., end="") in Python does */
    OSWait(5);
    printf("second half\n");
    return 0;
}
