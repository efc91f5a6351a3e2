/* Windows test program: a child that says it runs (the file child-running) and never ends. */
#include <stdio.h>
#include <windows.h>

int main(void)
{
    FILE *file = fopen("child-running", "w");
    if (file)
        fclose(file);
    for (;;)
        Sleep(100);
}
