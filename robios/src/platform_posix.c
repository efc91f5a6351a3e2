/* platform_posix.c: platform.h for Linux, macOS and other POSIX systems. */
#include "platform.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pwd.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#if defined(__linux__)
#include <dirent.h>
#include <sys/syscall.h>
#endif

#ifndef MSG_NOSIGNAL
#define MSG_NOSIGNAL 0 /* macOS: SO_NOSIGPIPE is set on the socket instead */
#endif

/* ---- Sockets ----------------------------------------------------------------------------------- */

int es_net_start(void)
{
    return 0;
}

const char *es_socket_error_text(int error)
{
    return strerror(error);
}

es_socket es_socket_open(int family, int type, int protocol, int *error)
{
    /* Close-on-exec: programs the robot program starts must not hold the connection open. */
#ifdef SOCK_CLOEXEC
    int fd = socket(family, type | SOCK_CLOEXEC, protocol);
#else
    int fd = socket(family, type, protocol);
    if (fd >= 0)
        fcntl(fd, F_SETFD, FD_CLOEXEC);
#endif
    if (fd < 0)
        *error = errno;
    return fd;
}

void es_socket_close(es_socket sock)
{
    close(sock);
}

int es_socket_connect(es_socket sock, const struct sockaddr *address, size_t length, int timeout_ms)
{
    int flags = fcntl(sock, F_GETFL);
    fcntl(sock, F_SETFL, flags | O_NONBLOCK); /* so an unreachable host cannot outlast the timeout */
    int error = 0;
    if (connect(sock, address, (socklen_t)length) < 0) {
        error = errno;
        if (error == EINPROGRESS || error == EINTR) {
            struct pollfd p = {.fd = sock, .events = POLLOUT};
            int ready = poll(&p, 1, timeout_ms);
            if (ready == 0) {
                error = ETIMEDOUT;
            } else if (ready < 0) {
                error = errno;
            } else {
                socklen_t size = sizeof error;
                if (getsockopt(sock, SOL_SOCKET, SO_ERROR, &error, &size) < 0)
                    error = errno;
            }
        }
    }
    fcntl(sock, F_SETFL, flags);
    return error;
}

void es_socket_configure(es_socket sock)
{
    int on = 1;
    setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on); /* calls are small and latency-bound */
#ifdef SO_NOSIGPIPE
    setsockopt(sock, SOL_SOCKET, SO_NOSIGPIPE, &on, sizeof on);
#endif
}

int es_socket_send_all(es_socket sock, const void *data, size_t length)
{
    const uint8_t *next = data;
    while (length > 0) {
        ssize_t n = send(sock, next, length, MSG_NOSIGNAL);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        next += n;
        length -= (size_t)n;
    }
    return 0;
}

long es_socket_receive(es_socket sock, void *data, size_t length, int *error)
{
    for (;;) {
        ssize_t n = recv(sock, data, length, 0);
        if (n >= 0)
            return (long)n;
        if (errno != EINTR) {
            *error = errno;
            return -1;
        }
    }
}

/* Milliseconds left until `deadline` (an es_monotonic_s time), for poll. */
static int ms_until(double deadline)
{
    double left = (deadline - es_monotonic_s()) * 1000.0;
    return left <= 0 ? 0 : left > 1e9 ? 1000000000 : (int)ceil(left);
}

int es_socket_wait_readable(es_socket sock, int timeout_ms, int *error)
{
    double deadline = es_monotonic_s() + timeout_ms / 1000.0;
    for (;;) {
        struct pollfd p = {.fd = sock, .events = POLLIN};
        int ready = poll(&p, 1, timeout_ms < 0 ? -1 : ms_until(deadline));
        if (ready >= 0)
            return ready;
        if (errno != EINTR) {
            *error = errno;
            return -1;
        }
    }
}

bool es_socket_peer_closed(es_socket sock)
{
#if defined(POLLRDHUP)
    struct pollfd p = {.fd = sock, .events = POLLRDHUP};
    return poll(&p, 1, 0) == 1 && (p.revents & (POLLRDHUP | POLLHUP));
#else
    /* Readable with nothing to read is the end of the connection (nobody else reads meanwhile). */
    struct pollfd p = {.fd = sock, .events = POLLIN};
    if (poll(&p, 1, 0) != 1)
        return false;
    if (p.revents & POLLHUP)
        return true;
    char byte;
    ssize_t n = recv(sock, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
    return n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
#endif
}

/* ---- Time and threads -------------------------------------------------------------------------- */

double es_monotonic_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

/* poll, not nanosleep: libeyesim reroutes nanosleep into simulation time. */
void es_pause_ms(int ms)
{
    double deadline = es_monotonic_s() + ms / 1000.0;
    while (poll(NULL, 0, ms_until(deadline)) < 0 && errno == EINTR) {
    }
}

_Noreturn void es_wait_forever(void)
{
    for (;;)
        pause();
}

long es_thread_id(void)
{
#if defined(__linux__)
    return (long)syscall(SYS_gettid);
#elif defined(__APPLE__)
    uint64_t id = 0;
    pthread_threadid_np(NULL, &id);
    return (long)id;
#else
    return (long)(uintptr_t)pthread_self();
#endif
}

int es_start_detached_thread(void *(*run)(void *), void *arg)
{
    /* The library's threads must never run the program's signal handlers: block everything. */
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    pthread_t thread;
    int rc = pthread_create(&thread, &attr, run, arg);
    pthread_attr_destroy(&attr);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    return rc;
}

#if defined(__linux__)
/* A thread that has ended but is still listed: the main thread after pthread_exit stays a zombie
 * until the whole process ends. Unreadable means it is gone. */
static bool thread_ended(const char *id)
{
    char path[64], stat[512];
    snprintf(path, sizeof path, "/proc/self/task/%s/stat", id);
    FILE *file = fopen(path, "re");
    if (!file)
        return true;
    size_t n = fread(stat, 1, sizeof stat - 1, file);
    fclose(file);
    stat[n] = '\0';
    const char *name_end = strrchr(stat, ')'); /* "tid (name) S ...": the name may hold anything */
    return !name_end || name_end[1] != ' ' || name_end[2] == 'Z' || name_end[2] == 'X';
}

bool es_program_threads_alive(bool (*is_library)(long id))
{
    DIR *tasks = opendir("/proc/self/task");
    if (!tasks)
        return true; /* cannot tell: keep the program as it is */
    bool alive = false;
    struct dirent *entry;
    while (!alive && (entry = readdir(tasks)))
        if (entry->d_name[0] != '.' && !is_library(atol(entry->d_name)))
            alive = !thread_ended(entry->d_name);
    closedir(tasks);
    return alive;
}
#else
/* No /proc (macOS): the threads of the process cannot be told apart here, so the program is taken
 * to be alive; a main that ends with pthread_exit then leaves the program running (docs/c-library.md). */
bool es_program_threads_alive(bool (*is_library)(long id))
{
    (void)is_library;
    return true;
}
#endif

/* ---- The process ------------------------------------------------------------------------------- */

const char *es_program_name(void)
{
#if defined(__linux__)
    extern char *program_invocation_short_name;
    return program_invocation_short_name;
#elif defined(__APPLE__) || defined(__FreeBSD__)
    return getprogname();
#else
    return "";
#endif
}

long es_process_id(void)
{
    return (long)getpid();
}

bool es_stdout_is_pipe(void)
{
    struct stat info;
    return fstat(STDOUT_FILENO, &info) == 0 && S_ISFIFO(info.st_mode);
}

FILE *es_open_token_file(const char *port, char *path, size_t path_size)
{
    const char *dir = getenv("EYESIM_STATE_DIR");
    const char *state = getenv("XDG_STATE_HOME");
    const char *home = getenv("HOME");
    if (!home || !*home) {
        struct passwd *user = getpwuid(getuid());
        home = user ? user->pw_dir : NULL;
    }
    int n;
    if (dir && *dir)
        n = snprintf(path, path_size, "%s/program-token-%s", dir, port);
#if defined(__APPLE__)
    else if (home && *home)
        n = snprintf(path, path_size, "%s/Library/Application Support/eyesim/program-token-%s", home, port);
#else
    else if (state && *state)
        n = snprintf(path, path_size, "%s/eyesim/program-token-%s", state, port);
    else if (home && *home)
        n = snprintf(path, path_size, "%s/.local/state/eyesim/program-token-%s", home, port);
#endif
    else
        n = -1;
    (void)state;
    if (n < 0 || (size_t)n >= path_size) {
        if (path_size)
            path[0] = '\0';
        return NULL;
    }
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    FILE *file = fd < 0 ? NULL : fdopen(fd, "r");
    if (fd >= 0 && !file)
        close(fd);
    return file;
}
