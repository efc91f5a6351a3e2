/* For the watchdog and limit tests: computes for ever without a RoBIOS call after the first. */
#include "eyebot.h"

int main(void)
{
    LCDPrintf("spinning\n");
    volatile unsigned long n = 0;
    for (;;)
        n++;
}
