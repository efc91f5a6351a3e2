/* platform.h: what libeyesim needs from the operating system, in one place. platform_posix.c
 * implements it for Linux and macOS (and other POSIX systems), platform_win.c for Windows (Winsock2,
 * MinGW-w64 with winpthreads). Everything else in the library is the same on every system. */
#ifndef EYESIM_PLATFORM_H
#define EYESIM_PLATFORM_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#if defined(_WIN32)
/* Windows 7 and later: WSAPoll, WSA_FLAG_NO_HANDLE_INHERIT, AI_NUMERICSERV. */
#if !defined(_WIN32_WINNT) || _WIN32_WINNT < 0x0601
#undef _WIN32_WINNT
#define _WIN32_WINNT 0x0601
#endif
#include <winsock2.h>
#include <ws2tcpip.h>
typedef SOCKET es_socket;
#define ES_NO_SOCKET INVALID_SOCKET
#define ES_ETIMEDOUT WSAETIMEDOUT
#else
#include <errno.h>
#include <netdb.h>
#include <sys/socket.h>
typedef int es_socket;
#define ES_NO_SOCKET (-1)
#define ES_ETIMEDOUT ETIMEDOUT
#endif

#if defined(__GNUC__)
#pragma GCC visibility push(hidden) /* internal to libeyesim, not part of the API */
#endif

/* ---- Sockets. Errors are the system's socket error codes (errno values, or WSA codes on
 * Windows); es_socket_error_text turns one into a message. --------------------------------------- */

/* Prepares the socket library (WSAStartup on Windows; nothing elsewhere). 0 or an error code. */
int es_net_start(void);

/* The text of a socket error code (valid until this thread's next call). */
const char *es_socket_error_text(int error);

/* A socket that programs started by this program do not inherit; ES_NO_SOCKET and *error on failure. */
es_socket es_socket_open(int family, int type, int protocol, int *error);
void es_socket_close(es_socket sock);

/* Connects within timeout_ms (the socket is non-blocking meanwhile, blocking again after); 0 or an
 * error code (ES_ETIMEDOUT when the time ran out). */
int es_socket_connect(es_socket sock, const struct sockaddr *address, size_t length, int timeout_ms);

/* TCP_NODELAY, and no SIGPIPE from writes to a closed connection where that takes a socket option. */
void es_socket_configure(es_socket sock);

/* Sends all of data; 0 or an error code. Writing to a closed connection raises no signal. */
int es_socket_send_all(es_socket sock, const void *data, size_t length);

/* Receives up to length bytes (at least one, blocking): the count, 0 when the peer closed the
 * connection, or -1 with *error set. */
long es_socket_receive(es_socket sock, void *data, size_t length, int *error);

/* Waits up to timeout_ms (-1: no limit) until data or the end of the connection can be read:
 * 1 readable, 0 timed out, -1 with *error set. */
int es_socket_wait_readable(es_socket sock, int timeout_ms, int *error);

/* True when the peer has closed the connection. Only asked while no thread reads the socket. */
bool es_socket_peer_closed(es_socket sock);

/* ---- Time and threads -------------------------------------------------------------------------- */

/* Seconds on a monotonic wall clock. */
double es_monotonic_s(void);

/* A pause of ms milliseconds in wall time, through nothing that libeyesim reroutes into simulation
 * time (not sleep, usleep or nanosleep). */
void es_pause_ms(int ms);

/* Never returns (another thread is ending the process). */
_Noreturn void es_wait_forever(void);

/* The calling thread's id from the system (non-zero), as es_program_threads_alive sees threads. */
long es_thread_id(void);

/* Starts a detached thread running run(arg) with every signal blocked (signals stay with the
 * program's own threads); 0 or pthread_create's error. */
int es_start_detached_thread(void *(*run)(void *), void *arg);

/* True while a thread of the process that is not a library thread (is_library says which ids are)
 * is alive. True when it cannot tell (on macOS it cannot: the program then keeps running while a
 * library thread does). */
bool es_program_threads_alive(bool (*is_library)(long id));

/* ---- The process ------------------------------------------------------------------------------- */

/* The program's name as its user knows it (no directory, no ".exe"). */
const char *es_program_name(void);

long es_process_id(void);

/* Opens, for reading, the file where the simulator's run on `port` (digits) keeps its program token
 * for programs started by hand: program-token-<port> in EyeSim's state folder for this user
 * (EYESIM_STATE_DIR, else XDG_STATE_HOME/eyesim or ~/.local/state/eyesim on Linux, ~/Library/
 * Application Support/eyesim on macOS, %LOCALAPPDATA%\eyesim on Windows: as eyesim/paths.py
 * state_dir). `path` gets the file's name (UTF-8, for messages; "" when there is no state folder).
 * NULL when the file cannot be opened. */
FILE *es_open_token_file(const char *port, char *path, size_t path_size);

/* True when stdout is a pipe (the simulator started the program and shows its output live). */
bool es_stdout_is_pipe(void);

/* The setvbuf mode that writes piped output line by line: Windows' C library has no line buffering
 * (its _IOLBF buffers fully), so there output is unbuffered (one write per printf call). */
#if defined(_WIN32)
#define ES_LINE_BUFFERED _IONBF
#else
#define ES_LINE_BUFFERED _IOLBF
#endif

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif
