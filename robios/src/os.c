/* os.c: the RoBIOS system functions that do more than pass values through (api_gen.c has those); time is
 * the simulator's clock, not the host's. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eyebot.h"
#include "transport.h"

#define LIBRARY_VERSION "EyeSim RoBIOS-7 library 1.0"
#define IO_VERSION "EyeSim simulated I/O board 1.0"

int OSGetTime(int *hrs, int *mins, int *secs, int *ticks)
{
    es_value result[1] = {{0}};
    int rc = es_call("OSGetTime", ES_OP_OS_GET_COUNT, NULL, result);
    int ms = rc ? 0 : (int)result[0].i; /* simulation time since the simulator started */
    es_out(hrs, ms / 3600000);
    es_out(mins, ms / 60000 % 60);
    es_out(secs, ms / 1000 % 60);
    es_out(ticks, ms % 1000);
    return rc ? 1 : 0;
}

/* Copies text to a caller's buffer of unknown size, as the RoBIOS functions without a size do. */
static int copy_out(const char *function, char *buf, const char *text, size_t length)
{
    if (!buf) {
        fprintf(stderr, "eyesim: %s: the buffer is NULL\n", function);
        return 1;
    }
    memcpy(buf, text, length);
    buf[length] = '\0';
    return 0;
}

int OSVersion(char *buf)
{
    return copy_out("OSVersion", buf, LIBRARY_VERSION, strlen(LIBRARY_VERSION));
}

int OSVersionIO(char *buf)
{
    return copy_out("OSVersionIO", buf, IO_VERSION, strlen(IO_VERSION));
}

int OSMachineSpeed(void)
{
    return MACHINE_SPEED;
}

int OSMachineName(char *buf)
{
    es_value result[1];
    if (!buf) {
        fprintf(stderr, "eyesim: OSMachineName: the buffer is NULL\n");
        return 1;
    }
    if (es_call("OSMachineName", ES_OP_OS_MACHINE_NAME, NULL, result)) {
        buf[0] = '\0';
        return 1;
    }
    return copy_out("OSMachineName", buf, result[0].p, result[0].n);
}

char *OSExecute(const char *command)
{
    if (!command) {
        fprintf(stderr, "eyesim: OSExecute: the command is NULL\n");
        return NULL;
    }
    fflush(NULL); /* the command's output must not overtake the program's buffered output */
    FILE *pipe = popen(command, "r");
    if (!pipe) {
        fprintf(stderr, "eyesim: OSExecute: cannot run \"%s\"\n", command);
        return NULL;
    }
    size_t length = 0, capacity = 256;
    char *output = malloc(capacity);
    size_t n;
    while (output && (n = fread(output + length, 1, capacity - length - 1, pipe)) > 0) {
        length += n;
        if (capacity - length < 2) {
            char *bigger = realloc(output, capacity * 2);
            if (!bigger) {
                free(output);
                output = NULL;
                break;
            }
            output = bigger;
            capacity *= 2;
        }
    }
    int status = pclose(pipe);
    if (!output) {
        fprintf(stderr, "eyesim: OSExecute: out of memory reading the output of \"%s\"\n", command);
        return NULL;
    }
    output[length] = '\0';
    if (status == -1) {
        free(output);
        return NULL;
    }
    return output;
}
