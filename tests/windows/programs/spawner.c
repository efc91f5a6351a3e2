/* Windows test program (C): starts forever.exe from its own folder, waits until it runs and until
   the test creates the file `release`, then keeps the robot busy for ever. */
#include <stdio.h>
#include <string.h>
#include <windows.h>
#include "eyebot.h"

int main(void)
{
    char path[MAX_PATH];
    DWORD length = GetModuleFileNameA(NULL, path, sizeof path);
    char *slash = strrchr(path, '\\');
    if (length == 0 || length >= sizeof path || slash == NULL || slash - path + sizeof "\\forever.exe" > sizeof path)
        return 2;
    strcpy(slash, "\\forever.exe");

    STARTUPINFOA startup = {.cb = sizeof startup};
    PROCESS_INFORMATION child;
    if (!CreateProcessA(path, NULL, NULL, NULL, FALSE, 0, NULL, NULL, &startup, &child)) {
        fprintf(stderr, "cannot start %s: error %lu\n", path, GetLastError());
        return 2;
    }
    /* Before the first RoBIOS call, Sleep is still the system's (wall clock). */
    for (int i = 0; GetFileAttributesA("child-running") == INVALID_FILE_ATTRIBUTES; i++) {
        if (i > 3000 || WaitForSingleObject(child.hProcess, 0) == WAIT_OBJECT_0)
            return 3;
        Sleep(20);
    }
    printf("child %lu running\n", child.dwProcessId);
    fflush(stdout);
    while (GetFileAttributesA("release") == INVALID_FILE_ATTRIBUTES) /* the test looks at the processes */
        Sleep(20);

    LCDPrintf("looping\n");
    for (;;) {
        VWSetSpeed(100, 0);
        OSWait(100);
    }
}
