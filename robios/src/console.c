/* Makes a program's printf output appear line by line when its stdout is a pipe (as when the
 * simulator starts it and shows its output live), instead of in one block when it exits. */
#include <stdio.h>

#include "platform.h"

__attribute__((constructor)) static void line_buffer_piped_stdout(void)
{
    /* Runs when the library loads, before main() can write anything, as setvbuf requires. */
    if (es_stdout_is_pipe())
        setvbuf(stdout, NULL, ES_LINE_BUFFERED, 0);
}
