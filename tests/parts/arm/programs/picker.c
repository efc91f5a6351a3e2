/* Picker drives up to a can while lowering its arm over it, grips it, lifts it and backs away. */
#include <stdio.h>
#include "eyebot.h"

static void report(void)
{
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("robot %d %d %d %d\n", x, y, z, phi);
    SIMGetObject(1, &x, &y, &z, &phi);
    printf("can %d %d %d %d\n", x, y, z, phi);
}

int main(void)
{
    report();
    VWStraight(400, 200);
    SERVOSet(4, 255); /* open */
    SERVOSet(2, 145); /* shoulder a little up ... */
    SERVOSet(3, 31);  /* ... and the wrist down: the gripper points at the floor, 150 mm up */
    VWWait();
    OSWait(1000);
    SERVOSet(4, 0); /* grip */
    OSWait(1500);
    SERVOSet(2, 200); /* lift */
    OSWait(1500);
    report();
    VWStraight(-300, 200);
    VWWait();
    OSWait(300);
    report();
    return 0;
}
