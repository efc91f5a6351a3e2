/* For the crash tests: drives a little, then dereferences a null pointer. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    VWSetSpeed(100, 0);
    OSWait(500);
    printf("about to crash\n");
    fflush(stdout);
    volatile int *nowhere = 0;
    return *nowhere;
}
