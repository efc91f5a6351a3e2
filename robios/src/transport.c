/* transport.c: the connection: lazy connect + handshake, reply routing by request id, clear endings. */
#include "transport.h"

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#include "platform.h" /* sockets, clocks, threads and the process: everything that differs by system */

#define DEFAULT_CONNECT_TIMEOUT_S 10.0
#define MIN_HANDSHAKE_TIMEOUT_S 5.0 /* a busy simulator may take a moment to answer HELLO */
#define RETRY_INTERVAL_MS 100
#define REPORTED_ERRORS_MAX 64
#define WATCH_INTERVAL_MS 20 /* how often the watcher looks whether the program's own threads are gone */
#define LIBRARY_THREADS_MAX 4

/* A caller waiting for the reply to its request; lives on the caller's stack. */
typedef struct waiter {
    uint32_t request_id;
    pthread_cond_t ready;
    uint8_t *body; /* the reply's frame body, handed over by whichever thread read it */
    uint32_t len;
    struct waiter *next;
} waiter;

/* Results of reading from the socket besides 0 (ok) and a positive socket error code. */
enum { READ_EOF = -1, READ_TIMEOUT = -2, READ_BAD_LENGTH = -3, READ_NO_MEMORY = -4 };

static pthread_once_t connect_once = PTHREAD_ONCE_INIT;
static es_socket sock = ES_NO_SOCKET;
static char address[300]; /* "host:port", for messages */

static pthread_mutex_t send_lock = PTHREAD_MUTEX_INITIALIZER; /* whole frames, one at a time */
static pthread_mutex_t wait_lock = PTHREAD_MUTEX_INITIALIZER; /* guards waiters, reading, connection_dead */
static waiter *waiters;
static bool reading;         /* a caller is reading replies from the socket for everyone */
static bool connection_dead; /* set only once the program is exiting anyway */

static atomic_uint last_request_id;
static atomic_bool exiting; /* exit() is running: a lost connection is no longer news */

static pthread_mutex_t ending_lock = PTHREAD_MUTEX_INITIALIZER;
static bool ending; /* es_fatal is ending the program */
static pthread_t ending_thread;

static pthread_mutex_t reported_lock = PTHREAD_MUTEX_INITIALIZER;
static uint32_t reported[REPORTED_ERRORS_MAX];
static unsigned reported_count;

static _Thread_local uint8_t *kept_reply; /* backs text/array results until the thread's next call */
static atomic_bool connected;             /* the handshake is done */

static atomic_long library_tids[LIBRARY_THREADS_MAX]; /* system ids of the library's threads (0 = free) */

/* ---- Ending the program ------------------------------------------------------------------------ */

_Noreturn void es_fatal(int status, const char *format, ...)
{
    char line[3072]; /* a refused handshake's reason and where its token came from */
    va_list ap;
    va_start(ap, format);
    vsnprintf(line, sizeof line, format, ap);
    va_end(ap);

    pthread_mutex_lock(&ending_lock);
    bool first = !ending;
    bool again = ending && pthread_equal(ending_thread, pthread_self());
    if (first) {
        ending = true;
        ending_thread = pthread_self();
    }
    pthread_mutex_unlock(&ending_lock);

    if (first) {
        fprintf(stderr, "eyesim: %s\n", line);
        exit(status); /* exit, not _exit: the program's buffered stdout still gets written */
    }
    if (again)
        _Exit(status); /* failed again inside exit() (an atexit handler): do not re-enter exit */
    es_wait_forever(); /* another thread is ending the program */
}

/* True for the thread that is ending the program (its atexit handlers may still call the API: they
 * get error values). Any other thread calling now just waits for the process to end. */
static bool program_ending(void)
{
    pthread_mutex_lock(&ending_lock);
    bool mine = ending && pthread_equal(ending_thread, pthread_self());
    bool other = ending && !mine;
    pthread_mutex_unlock(&ending_lock);
    if (other)
        es_wait_forever();
    return mine;
}

static void note_exit(void)
{
    atomic_store(&exiting, true);
}

/* The connection is gone: end the program. If it is ending anyway (exit() is running), the calls
 * still waiting, say an atexit handler stopping the robot, get errors instead of hanging. */
static void connection_lost(const char *reason)
{
    if (!atomic_load(&exiting))
        es_fatal(ES_EXIT_CONNECTION_LOST, "lost the connection to the simulator at %s (%s); the program ends",
                 address, reason);
    pthread_mutex_lock(&wait_lock);
    connection_dead = true;
    for (waiter *w = waiters; w; w = w->next)
        pthread_cond_signal(&w->ready);
    pthread_mutex_unlock(&wait_lock);
}

/* ---- Time -------------------------------------------------------------------------------------- */

static double now_s(void)
{
    return es_monotonic_s();
}

/* Milliseconds left until `deadline` (a now_s time); a negative deadline means never. */
static int ms_until(double deadline)
{
    if (deadline < 0)
        return -1;
    double left = (deadline - now_s()) * 1000.0;
    return left <= 0 ? 0 : left > 1e9 ? 1000000000 : (int)ceil(left);
}

/* ---- Socket I/O -------------------------------------------------------------------------------- */

/* Socket errors are the system's codes (es_socket_error_text), besides the READ_* results. */
static int send_all(const uint8_t *data, size_t len)
{
    return es_socket_send_all(sock, data, len);
}

static int recv_exact(uint8_t *data, size_t len, double deadline)
{
    int error = 0;
    while (len > 0) {
        if (deadline >= 0) {
            int ready = es_socket_wait_readable(sock, ms_until(deadline), &error);
            if (ready < 0)
                return error;
            if (ready == 0)
                return READ_TIMEOUT;
        }
        long n = es_socket_receive(sock, data, len, &error);
        if (n == 0)
            return READ_EOF;
        if (n < 0)
            return error;
        data += n;
        len -= (size_t)n;
    }
    return 0;
}

/* Reads one frame; *body (malloc'd) gets everything after the length prefix. */
static int read_frame(double deadline, uint8_t **body, uint32_t *len)
{
    uint8_t prefix[4];
    int rc = recv_exact(prefix, sizeof prefix, deadline);
    if (rc)
        return rc;
    *len = (uint32_t)prefix[0] | (uint32_t)prefix[1] << 8 | (uint32_t)prefix[2] << 16 | (uint32_t)prefix[3] << 24;
    if (*len < ES_HEADER_SIZE || *len > ES_MAX_FRAME)
        return READ_BAD_LENGTH;
    if (!(*body = malloc(*len)))
        return READ_NO_MEMORY;
    if ((rc = recv_exact(*body, *len, deadline))) {
        free(*body);
        *body = NULL;
    }
    return rc;
}

static const char *read_error(int rc)
{
    switch (rc) {
    case READ_EOF: return "connection closed";
    case READ_TIMEOUT: return "timed out";
    case READ_BAD_LENGTH: return "frame length outside the protocol's limits";
    case READ_NO_MEMORY: return "out of memory";
    default: return es_socket_error_text(rc);
    }
}

/* ---- Errors from the simulator ---------------------------------------------------------------- */

static uint32_t error_key(const char *function, int32_t code, const es_value *message)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (const char *c = function; *c; c++)
        h = (h ^ (uint8_t)*c) * 16777619u;
    h = (h ^ (uint32_t)code) * 16777619u;
    for (uint32_t k = 0; k < message->n; k++)
        h = (h ^ ((const uint8_t *)message->p)[k]) * 16777619u;
    return h;
}

/* Prints "eyesim: <function>: <message>" the first time this function gets this error, so a loop
 * that keeps failing does not flood the terminal. SHUTDOWN means the simulator is going away. */
static void report_error(const char *function, const es_value *fields)
{
    int32_t code = (int32_t)fields[0].i;
    const es_value *message = &fields[1];
    if (code == ES_ERR_SHUTDOWN && !atomic_load(&exiting))
        es_fatal(ES_EXIT_CONNECTION_LOST, "the simulator at %s is shutting down (%.*s); the program ends", address,
                 (int)message->n, (const char *)message->p);
    uint32_t key = error_key(function, code, message);
    bool seen = false;
    pthread_mutex_lock(&reported_lock);
    for (unsigned k = 0; k < reported_count && !seen; k++)
        seen = reported[k] == key;
    if (!seen && reported_count < REPORTED_ERRORS_MAX)
        reported[reported_count++] = key;
    pthread_mutex_unlock(&reported_lock);
    if (!seen)
        fprintf(stderr, "eyesim: %s: %.*s\n", function, (int)message->n, (const char *)message->p);
}

/* ---- Reading replies ---------------------------------------------------------------------------
 * No thread of its own reads the socket: a caller waiting for its reply reads, for everyone, while
 * no other caller does (one reader at a time), and hands each reply to its waiter. A single-threaded
 * program thus gets its reply with no thread wake-up in between; with several threads calling, the
 * reader passes the role on when its own reply has come. */

/* Hands a reply to the caller waiting for its request id (wait_lock held). Anything else is dropped;
 * an error nobody asked for (the simulator complaining about the connection) is still shown. */
static void deliver(uint8_t *body, uint32_t len)
{
    es_header header;
    es_decode_header(body, len, &header); /* cannot fail: read_frame checked the length */
    waiter *w = waiters;
    while (w && (w->request_id != header.request_id || w->body))
        w = w->next;
    if (w) {
        w->body = body;
        w->len = len;
        pthread_cond_signal(&w->ready);
        return;
    }
    es_value fields[8];
    unsigned count;
    if (header.kind == ES_KIND_ERROR && es_decode_message(body, len, &header, fields, &count) == ES_CODEC_OK)
        report_error("simulator", fields);
    free(body);
}

/* Called with wait_lock held by a caller whose reply has not come and while nobody reads: reads one
 * frame (the lock let go meanwhile) and delivers it. */
static void read_one_reply(void)
{
    reading = true;
    pthread_mutex_unlock(&wait_lock);
    uint8_t *body;
    uint32_t len;
    int rc = read_frame(-1, &body, &len);
    if (rc == READ_BAD_LENGTH && !atomic_load(&exiting))
        es_fatal(ES_EXIT_PROTOCOL, "the simulator at %s sent a malformed frame; the program ends", address);
    if (rc == READ_NO_MEMORY)
        es_fatal(ES_EXIT_PROTOCOL, "out of memory reading a reply from the simulator");
    if (rc)
        connection_lost(read_error(rc)); /* returns only while the program is exiting anyway */
    pthread_mutex_lock(&wait_lock);
    reading = false;
    if (!rc)
        deliver(body, len);
}

/* A reader whose own reply came lets another waiting caller take over reading (wait_lock held). */
static void pass_on_reading(void)
{
    for (waiter *w = waiters; w; w = w->next)
        if (!w->body) {
            pthread_cond_signal(&w->ready);
            return;
        }
}

/* ---- The library's threads ---------------------------------------------------------------------- */

typedef struct {
    void *(*run)(void *);
} library_start;

/* Every library thread notes its system id first, so the watcher does not count it as the program's. */
static void *run_library_thread(void *arg)
{
    library_start start = *(library_start *)arg;
    free(arg);
    long id = es_thread_id();
    for (int k = 0; k < LIBRARY_THREADS_MAX; k++) {
        long free_slot = 0;
        if (atomic_compare_exchange_strong(&library_tids[k], &free_slot, id))
            break;
    }
    return start.run(NULL);
}

int es_start_library_thread(void *(*run)(void *))
{
    library_start *start = malloc(sizeof *start);
    if (!start)
        return ENOMEM;
    start->run = run;
    int rc = es_start_detached_thread(run_library_thread, start);
    if (rc)
        free(start);
    return rc;
}

static bool is_library_thread(long id)
{
    for (int k = 0; k < LIBRARY_THREADS_MAX; k++)
        if (atomic_load(&library_tids[k]) == id)
            return true;
    return false;
}

/* The simulator closed the connection while no call reads it (the program computes): the program
 * ends now, as it would at its next call. A caller that reads sees the end itself. */
static bool simulator_hung_up(void)
{
    /* Asked under wait_lock, so no caller starts reading (and takes bytes away) meanwhile. */
    pthread_mutex_lock(&wait_lock);
    bool closed = !reading && es_socket_peer_closed(sock);
    pthread_mutex_unlock(&wait_lock);
    return closed && !atomic_load(&exiting);
}

/* A process ends when its last thread ends; the library's threads would keep it alive for ever
 * after a main that ends with pthread_exit (the multitasking examples do). This thread ends the
 * program once only library threads are left, as the last thread's pthread_exit would have: exit(0),
 * which flushes output, runs atexit handlers and closes the connection, so the simulator sees the
 * program end. */
static void *watch_program(void *unused)
{
    (void)unused;
    for (;;) {
        es_pause_ms(WATCH_INTERVAL_MS);
        if (!es_program_threads_alive(is_library_thread))
            exit(0);
        if (simulator_hung_up())
            connection_lost("connection closed");
    }
}

static void start_library_threads(void)
{
    int rc = es_start_library_thread(watch_program);
    if (rc)
        fprintf(stderr, "eyesim: cannot start the thread that ends the program with its own threads (%s)\n",
                strerror(rc));
}

/* ---- Connecting -------------------------------------------------------------------------------- */

static uint32_t new_request_id(void)
{
    uint32_t id;
    do /* 0 is skipped when the counter wraps: it is never a real request */
        id = atomic_fetch_add(&last_request_id, 1u) + 1u;
    while (id == 0);
    return id;
}

static double connect_timeout(void)
{
    const char *text = getenv("EYESIM_CONNECT_TIMEOUT");
    if (!text || !*text)
        return DEFAULT_CONNECT_TIMEOUT_S;
    char *end;
    double seconds = strtod(text, &end);
    if (*end || !(seconds >= 0) || seconds > 1e6) {
        fprintf(stderr, "eyesim: EYESIM_CONNECT_TIMEOUT=%s is not a number of seconds; using %g\n", text,
                DEFAULT_CONNECT_TIMEOUT_S);
        return DEFAULT_CONNECT_TIMEOUT_S;
    }
    return seconds;
}

/* One connection attempt to one address, giving up after timeout_ms. Returns the socket or
 * ES_NO_SOCKET with *error set. */
static es_socket try_connect(const struct addrinfo *ai, int timeout_ms, int *error)
{
    es_socket fd = es_socket_open(ai->ai_family, ai->ai_socktype, ai->ai_protocol, error);
    if (fd == ES_NO_SOCKET)
        return fd;
    if ((*error = es_socket_connect(fd, ai->ai_addr, ai->ai_addrlen, timeout_ms))) {
        es_socket_close(fd);
        return ES_NO_SOCKET;
    }
    return fd;
}

/* Connects to host:port, retrying until `timeout` seconds have passed. */
static es_socket open_connection(const char *host, const char *port, double timeout)
{
    int rc = es_net_start();
    if (rc)
        es_fatal(ES_EXIT_NO_SIMULATOR, "cannot start the network library (%s)", es_socket_error_text(rc));
    struct addrinfo hints = {0}, *found;
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    rc = getaddrinfo(host, port, &hints, &found);
    if (rc)
        es_fatal(ES_EXIT_NO_SIMULATOR, "cannot find the simulator's host %s (%s); check EYESIM_HOST", host,
                 gai_strerror(rc));

    double deadline = now_s() + timeout;
    bool announced = false;
    int error = 0;
    for (;;) {
        for (struct addrinfo *ai = found; ai; ai = ai->ai_next) {
            int wait_ms = ms_until(deadline);
            es_socket fd = try_connect(ai, wait_ms < 50 ? 50 : wait_ms > 1000 ? 1000 : wait_ms, &error);
            if (fd != ES_NO_SOCKET) {
                freeaddrinfo(found);
                return fd;
            }
        }
        int left_ms = ms_until(deadline);
        if (left_ms == 0)
            es_fatal(ES_EXIT_NO_SIMULATOR,
                     "no simulator answered at %s within %g s (%s); start the simulator first, or set "
                     "EYESIM_HOST/EYESIM_PORT",
                     address, timeout, es_socket_error_text(error));
        if (!announced) {
            fprintf(stderr, "eyesim: waiting for the simulator at %s (set EYESIM_HOST/EYESIM_PORT) ...\n", address);
            announced = true;
        }
        es_pause_ms(left_ms < RETRY_INTERVAL_MS ? left_ms : RETRY_INTERVAL_MS);
    }
}

#define TOKEN_MAX 1024 /* as protocol.json's HELLO allows */

/* The run's program token (docs/running.md#the-program-token): EYESIM_TOKEN, set for the programs
 * the simulator starts; else the file its run on `port` wrote for programs started by hand; else ""
 * (a simulator started with --no-token wants none). `source` says where it came from, for the
 * message when the simulator refuses it. */
static void program_token(const char *port, char *token, char *source, size_t source_size)
{
    const char *given = getenv("EYESIM_TOKEN");
    if (given && *given) {
        snprintf(token, TOKEN_MAX + 1, "%s", given);
        snprintf(source, source_size, "it sent EYESIM_TOKEN");
        return;
    }
    char path[1024];
    FILE *file = es_open_token_file(port, path, sizeof path);
    token[0] = '\0';
    if (!file) {
        snprintf(source, source_size, "EYESIM_TOKEN is not set and %s%s", *path ? path : "EyeSim's state folder",
                 *path ? " cannot be read" : " is not known");
        return;
    }
    if (!fgets(token, TOKEN_MAX + 1, file))
        token[0] = '\0';
    fclose(file);
    size_t length = strlen(token);
    while (length && (token[length - 1] == '\n' || token[length - 1] == '\r' || token[length - 1] == ' '))
        token[--length] = '\0';
    snprintf(source, source_size, "it sent the token in %s", path);
}

/* HELLO: protocol version, which robot (EYESIM_ROBOT), program name, pid, the run's program token.
 * Refusal ends the program. */
static void handshake(const char *port, double timeout)
{
    const char *robot = getenv("EYESIM_ROBOT");
    char token[TOKEN_MAX + 1], token_source[1200];
    program_token(port, token, token_source, sizeof token_source);
    es_value hello[5] = {es_int(ES_PROTOCOL_VERSION), es_text(robot), es_text(es_program_name()),
                          es_int(es_process_id()), es_text(token)};
    uint32_t id = new_request_id();
    es_buf frame = {0};
    if (es_encode_message(&frame, ES_OP_HELLO, ES_KIND_REQUEST, id, hello) != ES_CODEC_OK)
        es_fatal(ES_EXIT_PROTOCOL, "cannot encode the handshake (is EYESIM_ROBOT very long?)");
    int rc = send_all(frame.data, frame.len);
    es_buf_free(&frame);
    if (rc)
        es_fatal(ES_EXIT_CONNECTION_LOST, "the simulator at %s closed the connection during the handshake (%s)",
                 address, es_socket_error_text(rc));

    uint8_t *body;
    uint32_t len;
    double wait = timeout < MIN_HANDSHAKE_TIMEOUT_S ? MIN_HANDSHAKE_TIMEOUT_S : timeout;
    rc = read_frame(now_s() + wait, &body, &len);
    if (rc == READ_TIMEOUT)
        es_fatal(ES_EXIT_NO_SIMULATOR, "no handshake reply from %s within %g s; is that the EyeSim simulator?",
                 address, wait);
    if (rc == READ_BAD_LENGTH)
        es_fatal(ES_EXIT_PROTOCOL, "%s sent a malformed handshake reply; is that the EyeSim simulator?", address);
    if (rc)
        es_fatal(ES_EXIT_CONNECTION_LOST, "the simulator at %s closed the connection during the handshake (%s)",
                 address, read_error(rc));

    es_header header;
    es_value fields[8];
    unsigned count;
    rc = es_decode_message(body, len, &header, fields, &count);
    if (rc || header.op != ES_OP_HELLO || header.request_id != id || header.kind == ES_KIND_REQUEST)
        es_fatal(ES_EXIT_PROTOCOL, "%s sent a malformed handshake reply (%s)", address,
                 rc ? es_codec_error(rc) : "not an answer to HELLO");
    if (header.kind == ES_KIND_ERROR && fields[0].i == ES_ERR_BAD_TOKEN)
        es_fatal(ES_EXIT_REFUSED, "the simulator at %s refused this program: %.*s [%s]", address,
                 (int)fields[1].n, (const char *)fields[1].p, token_source);
    if (header.kind == ES_KIND_ERROR)
        es_fatal(ES_EXIT_REFUSED, "the simulator at %s refused this program: %.*s", address, (int)fields[1].n,
                 (const char *)fields[1].p);
    free(body);
}

static void connect_to_simulator(void)
{
    const char *host = getenv("EYESIM_HOST");
    if (!host || !*host)
        host = ES_DEFAULT_HOST;
    char port[16];
    const char *port_text = getenv("EYESIM_PORT");
    if (port_text && *port_text) {
        char *end;
        long number = strtol(port_text, &end, 10);
        if (*end || number < 1 || number > 65535)
            es_fatal(ES_EXIT_NO_SIMULATOR, "EYESIM_PORT=%s is not a port number (1-65535)", port_text);
        snprintf(port, sizeof port, "%ld", number);
    } else {
        snprintf(port, sizeof port, "%d", ES_DEFAULT_PORT);
    }
    bool ipv6_literal = strchr(host, ':') != NULL;
    snprintf(address, sizeof address, ipv6_literal ? "[%s]:%s" : "%s:%s", host, port);

    double timeout = connect_timeout();
    sock = open_connection(host, port, timeout);
    es_socket_configure(sock);
    handshake(port, timeout);
    atexit(note_exit);
    start_library_threads();
    atomic_store(&connected, true);
}

/* ---- Calls ------------------------------------------------------------------------------------- */

bool es_may_wait_in_simulation(void)
{
    return atomic_load(&connected) && !atomic_load(&exiting);
}

static bool has_variable_fields(const es_type *types, unsigned count)
{
    for (unsigned k = 0; k < count; k++)
        if (types[k] == ES_T_STR || types[k] == ES_T_BYTES || types[k] == ES_T_I32S)
            return true;
    return false;
}

/* Checks and decodes the reply to `op`; returns 0 when `results` hold its values. */
static int take_reply(const char *function, uint16_t op, uint8_t *body, uint32_t len, es_value *results)
{
    es_header header;
    es_value fields[8];
    unsigned count;
    int rc = es_decode_message(body, len, &header, fields, &count);
    if (rc == ES_CODEC_OK && header.op == op && header.kind == ES_KIND_ERROR) {
        report_error(function, fields);
        free(body);
        return -1;
    }
    if (rc || header.op != op || header.kind != ES_KIND_REPLY) {
        fprintf(stderr, "eyesim: %s: malformed reply from the simulator (%s)\n", function,
                rc ? es_codec_error(rc) : "not an answer to this call");
        free(body);
        return -1;
    }
    memcpy(results, fields, count * sizeof fields[0]);
    if (has_variable_fields(es_find_op(op)->reply, count))
        kept_reply = body;
    else
        free(body);
    return 0;
}

/* The simulator is told, once, when a second thread of the program makes calls: in a deterministic
 * run the order of two threads' calls is the OS scheduler's, so the run may not repeat. The first
 * caller is the program's own thread; the library's threads (timer callbacks) do not count. */
static void note_calling_thread(void)
{
    static atomic_long first_caller;
    static atomic_bool told;
    long id = es_thread_id();
    long none = 0;
    if (!id || atomic_compare_exchange_strong(&first_caller, &none, id) || none == id || is_library_thread(id))
        return;
    if (!atomic_exchange(&told, true)) {
        es_value reply[1];
        es_call("THREADS", ES_OP_THREADS, NULL, reply);
    }
}

int es_call(const char *function, uint16_t op, const es_value *args, es_value *results)
{
    if (program_ending())
        return -1;
    pthread_once(&connect_once, connect_to_simulator);
    if (op != ES_OP_THREADS)
        note_calling_thread();
    free(kept_reply);
    kept_reply = NULL;

    for (unsigned k = 0; k < ES_LENGTH_LIMIT_COUNT; k++) {
        const es_length_limit *limit = &ES_LENGTH_LIMITS[k];
        if (limit->op == op && args[limit->field].n > limit->most) {
            fprintf(stderr, "eyesim: %s: %s of %u bytes is too large (the simulator takes at most %u)\n", function,
                    limit->name, (unsigned)args[limit->field].n, (unsigned)limit->most);
            return -1;
        }
    }

    waiter me = {.request_id = new_request_id()};
    es_buf frame = {0};
    int rc = es_encode_message(&frame, op, ES_KIND_REQUEST, me.request_id, args);
    if (rc) {
        fprintf(stderr, "eyesim: %s: %s\n", function, es_codec_error(rc));
        es_buf_free(&frame);
        return -1;
    }

    /* Register before sending, so even an instant reply finds its waiter. */
    pthread_cond_init(&me.ready, NULL);
    pthread_mutex_lock(&wait_lock);
    bool dead = connection_dead;
    if (!dead) {
        me.next = waiters;
        waiters = &me;
    }
    pthread_mutex_unlock(&wait_lock);

    if (!dead) {
        pthread_mutex_lock(&send_lock);
        rc = send_all(frame.data, frame.len);
        pthread_mutex_unlock(&send_lock);
        if (rc)
            connection_lost(es_socket_error_text(rc)); /* returns only while the program is exiting anyway */
    }
    es_buf_free(&frame);

    /* Read replies while nobody else does, else sleep until the reader hands this one over (or
     * passes the reading on). Other threads' calls go on meanwhile. */
    pthread_mutex_lock(&wait_lock);
    bool was_reader = false;
    while (!dead && !me.body && !connection_dead) {
        if (reading) {
            pthread_cond_wait(&me.ready, &wait_lock);
        } else {
            was_reader = true;
            read_one_reply();
        }
    }
    for (waiter **link = &waiters; *link; link = &(*link)->next)
        if (*link == &me) {
            *link = me.next;
            break;
        }
    if (was_reader && !reading)
        pass_on_reading();
    pthread_mutex_unlock(&wait_lock);
    pthread_cond_destroy(&me.ready);

    if (!me.body)
        return -1; /* the connection closed while the program exits */
    return take_reply(function, op, me.body, me.len, results);
}
