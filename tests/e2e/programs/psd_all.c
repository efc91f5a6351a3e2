/* Prints what PSDs 1..6 read, once, standing still (-1 where the robot has no such sensor). */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    printf("psd");
    for (int psd = 1; psd <= 6; psd++)
        printf(" %d", PSDGet(psd));
    printf("\n");
    return 0;
}
