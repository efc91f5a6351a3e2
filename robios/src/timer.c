/* timer.c: OSAttachTimer/OSDetachTimer. The simulator keeps the timers' due times in simulation time;
 * one library thread waits for the next due timers (TIMER_WAIT) and calls their functions. */
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "eyebot.h"
#include "transport.h"

#define MAX_TIMERS 32 /* the simulator's limit; handles are 1..MAX_TIMERS */

/* Recursive: a timer function may attach or detach timers while the timer thread holds it. */
static pthread_mutex_t timer_lock;
static pthread_once_t lock_once = PTHREAD_ONCE_INIT;
static pthread_once_t thread_once = PTHREAD_ONCE_INIT;
static void (*functions[MAX_TIMERS + 1])(void); /* by handle; NULL = not attached */

static void init_lock(void)
{
    pthread_mutexattr_t attr;
    pthread_mutexattr_init(&attr);
    pthread_mutexattr_settype(&attr, PTHREAD_MUTEX_RECURSIVE);
    pthread_mutex_init(&timer_lock, &attr);
    pthread_mutexattr_destroy(&attr);
}

static void lock_timers(void)
{
    pthread_once(&lock_once, init_lock);
    pthread_mutex_lock(&timer_lock);
}

/* Waits for the simulator to name the due timers, then calls their functions in handle order.
 * The lock is held while a function runs, so a timer that OSDetachTimer removed never runs again. */
static void *run_timers(void *unused)
{
    (void)unused;
    for (;;) {
        es_value result[1];
        if (es_call("OSAttachTimer", ES_OP_TIMER_WAIT, NULL, result))
            return NULL; /* reported already; without the simulator there is no time to wait for */
        int due[MAX_TIMERS];
        uint32_t count = result[0].n < MAX_TIMERS ? result[0].n : MAX_TIMERS;
        for (uint32_t k = 0; k < count; k++) /* copied: the reply is gone after the next call */
            due[k] = es_i32s_at(&result[0], k);
        for (uint32_t k = 0; k < count; k++) {
            lock_timers();
            if (due[k] >= 1 && due[k] <= MAX_TIMERS && functions[due[k]])
                functions[due[k]]();
            pthread_mutex_unlock(&timer_lock);
        }
    }
}

static void start_timer_thread(void)
{
    int rc = es_start_library_thread(run_timers);
    if (rc)
        fprintf(stderr, "eyesim: OSAttachTimer: cannot start the timer thread (%s); timers will not run\n",
                strerror(rc));
}

TIMER OSAttachTimer(int scale, void (*fct)(void))
{
    if (!fct) {
        fprintf(stderr, "eyesim: OSAttachTimer: the timer function is NULL\n");
        return 0;
    }
    es_value args[1] = {es_int(scale)}, result[1];
    /* Held across the call: the timer thread cannot look up the new handle before it is filled in. */
    lock_timers();
    int handle = es_call("OSAttachTimer", ES_OP_TIMER_ATTACH, args, result) ? 0 : (int)result[0].i;
    if (handle >= 1 && handle <= MAX_TIMERS)
        functions[handle] = fct;
    else
        handle = 0;
    pthread_mutex_unlock(&timer_lock);
    if (handle)
        pthread_once(&thread_once, start_timer_thread);
    return handle;
}

int OSDetachTimer(TIMER t)
{
    es_value args[1] = {es_int(t)}, result[1];
    lock_timers();
    int rc = es_call("OSDetachTimer", ES_OP_TIMER_DETACH, args, result) ? 1 : (int)result[0].i;
    if (rc == 0 && t >= 1 && t <= MAX_TIMERS)
        functions[t] = NULL;
    pthread_mutex_unlock(&timer_lock);
    return rc;
}
