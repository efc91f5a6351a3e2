/* Mako: a timed thrust script at the surface. LEFT (1) and RIGHT (3) push ahead together for 5 s,
 * then it coasts; then LEFT alone for 5 s turns it. */
#include <stdio.h>
#include "eyebot.h"

#define LEFT 1
#define RIGHT 3

static void report(const char *tag)
{
    int x, y, z, phi;
    SIMGetRobot(0, &x, &y, &z, &phi);
    printf("%s %d %d %d %d\n", tag, x, y, z, phi);
}

int main(void)
{
    SIMSetRobot(0, 2000, 3000, 1565, 0); /* afloat at the surface: its 2 kg of lift held by the air */
    OSWait(500);
    report("start");
    MOTORDrive(LEFT, 50);
    MOTORDrive(RIGHT, 50);
    OSWait(5000);
    MOTORDrive(LEFT, 0);
    MOTORDrive(RIGHT, 0);
    OSWait(3000);
    report("ahead");
    MOTORDrive(LEFT, 50);
    OSWait(5000);
    MOTORDrive(LEFT, 0);
    OSWait(3000);
    report("turned");
    return 0;
}
