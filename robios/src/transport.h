/* transport.h: the one connection to the simulator that every API call of every thread goes through. */
#ifndef EYESIM_TRANSPORT_H
#define EYESIM_TRANSPORT_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "codec.h"

#if defined(__GNUC__)
#pragma GCC visibility push(hidden) /* internal to libeyesim, not part of the API */
#endif

/* Exit statuses of a program that cannot go on without its simulator (see docs/c-library.md). */
#define ES_EXIT_NO_SIMULATOR 3    /* nothing answered at EYESIM_HOST:EYESIM_PORT in time */
#define ES_EXIT_REFUSED 4         /* the simulator refused the handshake (no such robot, version, ...) */
#define ES_EXIT_CONNECTION_LOST 5 /* the simulator closed the connection or is shutting down */
#define ES_EXIT_PROTOCOL 6        /* the simulator broke the protocol, or the library could not go on */

/* Sends `op` with `args` (laid out as the op's request) and waits for its reply, decoded into
 * `results` (laid out as the op's reply). Connects on first use. Returns 0 on a reply; -1 when the
 * simulator answered with an error or a malformed reply: that is already reported on stderr as
 * "eyesim: <function>: <reason>", and the caller returns its documented error value.
 * Text or array results point into a reply buffer kept until this thread's next call. */
int es_call(const char *function, uint16_t op, const es_value *args, es_value *results);

/* True when a sleep of the calling thread may wait in simulation time (sleep.c): the program is
 * connected, not exiting, and this is not the library's reader thread (which cannot wait for a reply). */
bool es_may_wait_in_simulation(void);

/* Prints "eyesim: <message>" to stderr and ends the program with `status` (once per process). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
_Noreturn void es_fatal(int status, const char *format, ...);

/* Starts a detached library thread with every signal blocked (signals stay with the program's
 * own threads); returns pthread_create's result. */
int es_start_library_thread(void *(*run)(void *));

static inline es_value es_int(int64_t value)
{
    es_value v = {0};
    v.i = value;
    return v;
}

static inline es_value es_text(const char *text)
{
    es_value v = {0};
    const char *s = text ? text : "";
    v.p = s;
    v.n = (uint32_t)strlen(s);
    return v;
}

/* Stores a result in an out-parameter the caller may have left NULL. */
static inline void es_out(int *out, int64_t value)
{
    if (out)
        *out = (int)value;
}

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif
