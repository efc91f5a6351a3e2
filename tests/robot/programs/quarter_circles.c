/* VWDrive to a point as far ahead as to the side: a quarter circle, left then right. */
#include <stdio.h>
#include "eyebot.h"

static void mark(const char *name)
{
    OSWait(300);
    printf("mark %s %d\n", name, OSGetCount());
}

int main(void)
{
    mark("start");
    printf("left %d\n", VWDrive(200, 200, 150));
    VWWait();
    mark("left");
    printf("right %d\n", VWDrive(200, -200, 150));
    VWWait();
    mark("right");
    return 0;
}
