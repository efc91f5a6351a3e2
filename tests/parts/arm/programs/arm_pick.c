/* The Reacher arm lifts over a can, lowers its open gripper round it, grips, lifts and swings. */
#include <stdio.h>
#include "eyebot.h"

static void can(const char *tag)
{
    int x, y, z, phi;
    SIMGetObject(1, &x, &y, &z, &phi);
    printf("%s %d %d %d %d\n", tag, x, y, z, phi);
}

int main(void)
{
    can("before");
    SERVOSet(1, 153); /* lift 150 mm: above the can */
    SERVOSet(4, 255); /* open */
    OSWait(2000);
    SERVOSet(2, 169); /* shoulder 49 degrees, elbow 82: the can between the fingers' middles */
    SERVOSet(3, 197);
    OSWait(3000);
    SERVOSet(1, 41); /* down to 40 mm: the fingers at the can's middle */
    OSWait(2000);
    SERVOSet(4, 0); /* grip */
    OSWait(1500);
    SERVOSet(1, 153); /* lift */
    OSWait(2000);
    can("lifted");
    SERVOSet(2, 100); /* swing */
    OSWait(3000);
    can("swung");
    printf("errors %d %d %d %d\n", SERVOSet(5, 100), SERVOSet(1, -1), SERVORange(2, 200, 100), VWStraight(10, 10));
    return 0;
}
