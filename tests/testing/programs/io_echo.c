/* For the testing API's tests: echoes its arguments, a line of standard input and an
 * environment variable to the LCD and stdout, writes result.txt in its working directory,
 * waits for KEY1 and exits with the status given as its first argument. */
#include <stdio.h>
#include <stdlib.h>
#include "eyebot.h"

int main(int argc, char **argv)
{
    char line[100] = "";
    if (!fgets(line, sizeof line, stdin))
        line[0] = 0;
    for (char *p = line; *p; p++)
        if (*p == '\n')
            *p = 0;
    const char *colour = getenv("COLOUR");
    LCDSetPrintf(1, 2, "args %d first %s", argc, argc > 1 ? argv[1] : "-");
    LCDSetPrintf(3, 0, "stdin %s colour %s", line, colour ? colour : "-");
    printf("read '%s'\n", line);
    FILE *file = fopen("result.txt", "w");
    fprintf(file, "answer %s\n", line);
    fclose(file);
    KEYWait(KEY1);
    LCDSetPrintf(4, 0, "key at %d ms", OSGetCount());
    return argc > 1 ? atoi(argv[1]) : 0;
}
