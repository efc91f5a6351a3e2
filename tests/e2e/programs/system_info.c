/* The system functions from C: the machine's identity, versions, the clock and OSExecute. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "eyebot.h"

int main(void)
{
    char name[64], version[128], io[128];
    OSMachineName(name);
    OSVersion(version);
    OSVersionIO(io);
    printf("name %s id %d type %d speed %d\n", name, OSMachineID(), OSMachineType(), OSMachineSpeed());
    printf("version %s | %s\n", version, io);

    OSWait(3723); /* plus the time already passed: read it back both ways */
    int count = OSGetCount();
    int hrs, mins, secs, ticks;
    OSGetTime(&hrs, &mins, &secs, &ticks);
    int from_time = ((hrs * 60 + mins) * 60 + secs) * 1000 + ticks;
    printf("clock difference %d\n", from_time - count); /* read again at once: the next millisecond */

    char *output = OSExecute("echo shell says hi; echo second line");
    printf("execute [%s]\n", output ? output : "(null)");
    free(output);
    printf("execute null %d\n", OSExecute(NULL) == NULL);
    return 0;
}
