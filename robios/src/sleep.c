/* sleep.c: sleep, usleep, nanosleep and clock_nanosleep in simulation time.
 *
 * Programs pause with the C library's sleeps (the submarine examples time their thrust phases so).
 * libeyesim defines these functions, so the program's calls (and its other libraries', such as
 * C++'s std::this_thread::sleep_for) come here first. While the program is connected they wait
 * in simulation time, exactly as OSWait does: in deterministic mode without stalling the
 * simulation or letting it race ahead, in realtime mode following --speed and pauses. Before the
 * first RoBIOS call, in the library's reader thread and while the program exits, they are the
 * system's own, found with dlsym(RTLD_NEXT). */
#include <dlfcn.h>
#include <errno.h>
#include <stdint.h>
#include <time.h>
#include <unistd.h>

#include "transport.h"

#define NS_PER_S 1000000000L

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

/* Relative sleeps on the wall clocks only. An absolute deadline (TIMER_ABSTIME) is a time of a wall
 * clock, which simulation time does not follow, so it stays a wall-clock sleep; so do sleeps on
 * CPU-time clocks. */
int clock_nanosleep(clockid_t clock, int flags, const struct timespec *request, struct timespec *remaining)
{
    bool wall_clock = clock == CLOCK_REALTIME || clock == CLOCK_MONOTONIC;
#ifdef CLOCK_BOOTTIME
    wall_clock = wall_clock || clock == CLOCK_BOOTTIME;
#endif
    if (wall_clock && !(flags & TIMER_ABSTIME) && valid(request) &&
        simulated_sleep("clock_nanosleep", (uint64_t)request->tv_sec, request->tv_nsec))
        return 0;
    return SYSTEM(clock_nanosleep)(clock, flags, request, remaining);
}

/* For the Python binding's time.sleep: 0 when it waited in simulation time, 1 when the program is
 * not connected (the caller sleeps in wall time itself). */
__attribute__((visibility("default"))) int eyesim_sleep(unsigned seconds, unsigned nanoseconds)
{
    return nanoseconds < NS_PER_S && simulated_sleep("time.sleep", seconds, (long)nanoseconds) ? 0 : 1;
}
