/* Makes a program's printf output appear line by line when its stdout is a pipe (as when the
 * simulator starts it and shows its output live), instead of in one block when it exits. */
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

__attribute__((constructor)) static void line_buffer_piped_stdout(void)
{
    struct stat info;
    /* Runs when the library loads, before main() can write anything, as setvbuf requires. */
    if (fstat(STDOUT_FILENO, &info) == 0 && S_ISFIFO(info.st_mode))
        setvbuf(stdout, NULL, _IOLBF, 0);
}
