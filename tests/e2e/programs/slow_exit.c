/* A program that has closed its connection to the simulator but takes a while to exit: its exit
 * handler (run after the library's, which was registered later) shuts the connection down, waits
 * 300 ms of wall time and lets the program end with status 3. A run whose --until comes in that
 * window must still report exit code 3. */
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include "eyebot.h"

static void close_connection_then_linger(void)
{
    for (int fd = 3; fd < 256; fd++) { /* the library's socket: the program's only one */
        struct stat st;
        if (fstat(fd, &st) == 0 && S_ISSOCK(st.st_mode))
            shutdown(fd, SHUT_RDWR);
    }
    poll(NULL, 0, 300); /* not a RoBIOS sleep: the connection is gone */
}

int main(void)
{
    atexit(close_connection_then_linger); /* before the first call: runs after the library's own */
    printf("last call at %d ms\n", OSGetCount());
    fflush(stdout);
    exit(3);
}
