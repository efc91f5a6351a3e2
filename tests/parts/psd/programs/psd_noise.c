/* Test program: 200 readings of the front PSD of a robot standing still. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    for (int i = 0; i < 200; i++)
        printf("front %d\n", PSDGet(PSD_FRONT));
    return 0;
}
