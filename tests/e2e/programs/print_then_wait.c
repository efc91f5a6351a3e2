/* End-to-end test program: prints a line without flushing, then waits 3 s of simulation time. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    printf("hello before waiting\n");
    OSWait(3000);
    printf("after waiting\n");
    return 0;
}
