/* sleep.c: sleep, usleep, nanosleep and clock_nanosleep in simulation time.
 *
 * Programs pause with the C library's sleeps (the submarine examples time their thrust phases so).
 * While the program is connected these wait in simulation time, exactly as OSWait does: in
 * deterministic mode without stalling the simulation or letting it race ahead, in realtime mode
 * following --speed and pauses. Before the first RoBIOS call and while the program exits, they are
 * the system's own (wall time).
 *
 * How a program's calls get here differs by system (docs/c-library.md, "Sleeping"):
 * - Linux: libeyesim defines the functions themselves, which interposes them for the whole process
 *   (also other libraries' calls, such as C++'s std::this_thread::sleep_for). The system's own are
 *   found with dlsym(RTLD_NEXT).
 * - Windows: nothing can be interposed, so eyebot.h's macros turn the calls in code that includes
 *   it (sleep, usleep, nanosleep, clock_nanosleep, and Sleep after <windows.h>) into es_sleep,
 *   es_usleep, ... here.
 * - macOS: both. A program's reference to usleep binds (two-level namespace) to whichever library
 *   the linker finds it in first: libeyesim with Apple's linker, which puts libSystem last, but
 *   libSystem with others (Zig's). So eyebot.h's macros send the calls to es_* as on Windows, and
 *   the definitions here still take other direct calls where the linker bound them to libeyesim. */
#include <errno.h>
#include <stdint.h>
#include <time.h>
#include <unistd.h>

#include "eyebot.h"
#include "transport.h"

#define NS_PER_S 1000000000L

static bool valid(const struct timespec *t)
{
    return t && t->tv_sec >= 0 && t->tv_nsec >= 0 && t->tv_nsec < NS_PER_S;
}

/* Waits in simulation time when the program is connected; false: the caller sleeps in wall time. */
static bool simulated_sleep(const char *function, uint64_t seconds, long nanoseconds)
{
    if (!es_may_wait_in_simulation())
        return false;
    es_value args[2] = {es_int(seconds > UINT32_MAX ? UINT32_MAX : seconds), es_int(nanoseconds)}, result[1];
    return es_call(function, ES_OP_OS_SLEEP, args, result) == 0;
}

#if defined(TIMER_ABSTIME) /* macOS has no clock_nanosleep */
/* Relative sleeps on the wall clocks only. An absolute deadline (TIMER_ABSTIME) is a time of a wall
 * clock, which simulation time does not follow, so it stays a wall-clock sleep; so do sleeps on
 * CPU-time clocks. */
static bool simulated_clock_sleep(clockid_t clock, int flags, const struct timespec *request)
{
    bool wall_clock = clock == CLOCK_REALTIME || clock == CLOCK_MONOTONIC;
#ifdef CLOCK_BOOTTIME
    wall_clock = wall_clock || clock == CLOCK_BOOTTIME;
#endif
    return wall_clock && !(flags & TIMER_ABSTIME) && valid(request) &&
           simulated_sleep("clock_nanosleep", (uint64_t)request->tv_sec, request->tv_nsec);
}
#endif

/* The system's own functions, in wall time. */
#if defined(_WIN32)
#define SYSTEM(name) name /* eyebot.h's macros are off inside the library (EYESIM_BUILDING_LIBRARY) */
#else
#include <dlfcn.h>

/* The system's definition of `name`: the next one after libeyesim's in the search order. */
static void *system_function(const char *name)
{
    void *function = dlsym(RTLD_NEXT, name);
    if (!function)
        es_fatal(ES_EXIT_PROTOCOL, "cannot find the system's %s (%s)", name, dlerror());
    return function;
}

typedef unsigned sleep_fn(unsigned);
typedef int usleep_fn(useconds_t);
typedef int nanosleep_fn(const struct timespec *, struct timespec *);
typedef int clock_nanosleep_fn(clockid_t, int, const struct timespec *, struct timespec *);
#define SYSTEM(name) ((name##_fn *)system_function(#name))
#endif

/* Where eyebot.h's macros send a program's calls (Windows, macOS). */

unsigned es_sleep(unsigned seconds)
{
    return simulated_sleep("sleep", seconds, 0) ? 0 : SYSTEM(sleep)(seconds);
}

int es_usleep(useconds_t microseconds)
{
    if (simulated_sleep("usleep", microseconds / 1000000, (long)(microseconds % 1000000) * 1000))
        return 0;
    return SYSTEM(usleep)(microseconds);
}

int es_nanosleep(const struct timespec *request, struct timespec *remaining)
{
    /* Invalid requests go to the system, which reports them (EINVAL, EFAULT) as always. */
    if (valid(request) && simulated_sleep("nanosleep", (uint64_t)request->tv_sec, request->tv_nsec))
        return 0;
    return SYSTEM(nanosleep)(request, remaining);
}

#if defined(TIMER_ABSTIME)
int es_clock_nanosleep(clockid_t clock, int flags, const struct timespec *request, struct timespec *remaining)
{
    if (simulated_clock_sleep(clock, flags, request))
        return 0;
    return SYSTEM(clock_nanosleep)(clock, flags, request, remaining);
}
#endif

#if defined(_WIN32)
/* Declared here rather than with <windows.h>, whose names would collide with eyebot.h's. */
__declspec(dllimport) void __stdcall Sleep(unsigned long milliseconds);

void __stdcall es_Sleep(unsigned long milliseconds)
{
    if (!simulated_sleep("Sleep", milliseconds / 1000, (long)(milliseconds % 1000) * 1000000))
        Sleep(milliseconds);
}
#else
/* The interposers (Linux, macOS): the program's calls of the functions themselves. */

unsigned sleep(unsigned seconds)
{
    return es_sleep(seconds);
}

int usleep(useconds_t microseconds)
{
    return es_usleep(microseconds);
}

int nanosleep(const struct timespec *request, struct timespec *remaining)
{
    return es_nanosleep(request, remaining);
}

#if defined(TIMER_ABSTIME)
int clock_nanosleep(clockid_t clock, int flags, const struct timespec *request, struct timespec *remaining)
{
    return es_clock_nanosleep(clock, flags, request, remaining);
}
#endif
#endif

/* For the Python binding's time.sleep: 0 when it waited in simulation time, 1 when the program is
 * not connected (the caller sleeps in wall time itself). */
#if defined(EYESIM_EXPORTS_MARKED)
__declspec(dllexport)
#endif
__attribute__((visibility("default"))) int eyesim_sleep(unsigned seconds, unsigned nanoseconds)
{
    return nanoseconds < NS_PER_S && simulated_sleep("time.sleep", seconds, (long)nanoseconds) ? 0 : 1;
}
