/* End-to-end test program: says it is ready, then blocks in VWWait on a long drive. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    VWStraight(100000, 10);
    printf("ready\n");
    fflush(stdout);
    VWWait();
    printf("VWWait returned\n");
    return 0;
}
