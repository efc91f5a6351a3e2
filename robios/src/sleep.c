/* sleep.c: sleep, usleep, nanosleep and clock_nanosleep in simulation time.
 *
 * Programs pause with the C library's sleeps (the submarine examples time their thrust phases so).
 * While the program is connected these wait in simulation time, exactly as OSWait does: in
 * deterministic mode without stalling the simulation or letting it race ahead, in realtime mode
 * following --speed and pauses. Before the first RoBIOS call and while the program exits, they are
 * the system's own (wall time).
 *
 * How a program's calls get here differs by system (docs/c-library.md, "Sleeping"):
 * - Linux and macOS: libeyesim defines the functions themselves. On Linux that interposes them for
 *   the whole process (also other libraries' calls, such as C++'s std::this_thread::sleep_for); on
 *   macOS (two-level namespace) the program's own calls bind to libeyesim, which the link line
 *   names before libSystem. The system's functions are found with dlsym(RTLD_NEXT).
 * - Windows: nothing can be interposed, so eyebot.h turns the program's calls of sleep, usleep,
 *   nanosleep, clock_nanosleep (and Sleep after <windows.h>) into es_sleep, es_usleep, ... here. */
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

#if defined(_WIN32)

/* eyebot.h's macros call these; EYESIM_BUILDING_LIBRARY keeps the names below the system's own. */

unsigned es_sleep(unsigned seconds)
{
    return simulated_sleep("sleep", seconds, 0) ? 0 : sleep(seconds);
}

int es_usleep(useconds_t microseconds)
{
    if (simulated_sleep("usleep", microseconds / 1000000, (long)(microseconds % 1000000) * 1000))
        return 0;
    return usleep(microseconds);
}

int es_nanosleep(const struct timespec *request, struct timespec *remaining)
{
    /* Invalid requests go to the system, which reports them (EINVAL) as always. */
    if (valid(request) && simulated_sleep("nanosleep", (uint64_t)request->tv_sec, request->tv_nsec))
        return 0;
    return nanosleep(request, remaining);
}

int es_clock_nanosleep(clockid_t clock, int flags, const struct timespec *request, struct timespec *remaining)
{
    return simulated_clock_sleep(clock, flags, request) ? 0 : clock_nanosleep(clock, flags, request, remaining);
}

/* Declared here rather than with <windows.h>, whose names would collide with eyebot.h's. */
__declspec(dllimport) void __stdcall Sleep(unsigned long milliseconds);

void __stdcall es_Sleep(unsigned long milliseconds)
{
    if (!simulated_sleep("Sleep", milliseconds / 1000, (long)(milliseconds % 1000) * 1000000))
        Sleep(milliseconds);
}

#else

#include <dlfcn.h>

/* The system's definition of `name`: the next one after ours in the search order. */
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

unsigned sleep(unsigned seconds)
{
    return simulated_sleep("sleep", seconds, 0) ? 0 : SYSTEM(sleep)(seconds);
}

int usleep(useconds_t microseconds)
{
    if (simulated_sleep("usleep", microseconds / 1000000, (long)(microseconds % 1000000) * 1000))
        return 0;
    return SYSTEM(usleep)(microseconds);
}

int nanosleep(const struct timespec *request, struct timespec *remaining)
{
    /* Invalid requests go to the system, which reports them (EINVAL, EFAULT) as always. */
    if (valid(request) && simulated_sleep("nanosleep", (uint64_t)request->tv_sec, request->tv_nsec))
        return 0;
    return SYSTEM(nanosleep)(request, remaining);
}

#if defined(TIMER_ABSTIME)
int clock_nanosleep(clockid_t clock, int flags, const struct timespec *request, struct timespec *remaining)
{
    if (simulated_clock_sleep(clock, flags, request))
        return 0;
    return SYSTEM(clock_nanosleep)(clock, flags, request, remaining);
}
#endif

#endif

/* For the Python binding's time.sleep: 0 when it waited in simulation time, 1 when the program is
 * not connected (the caller sleeps in wall time itself). */
__attribute__((visibility("default"))) int eyesim_sleep(unsigned seconds, unsigned nanoseconds)
{
    return nanoseconds < NS_PER_S && simulated_sleep("time.sleep", seconds, (long)nanoseconds) ? 0 : 1;
}
