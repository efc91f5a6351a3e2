/* platform_win.c: platform.h for Windows: Winsock2 sockets, Win32 time, threads and process
 * information (built with MinGW-w64; threads are winpthreads' pthreads). */
#include "platform.h"

#include <windows.h>
#include <tlhelp32.h>

#include <limits.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <wchar.h>

/* ---- Sockets ----------------------------------------------------------------------------------- */

int es_net_start(void)
{
    static bool started;
    if (started)
        return 0;
    WSADATA data;
    int rc = WSAStartup(MAKEWORD(2, 2), &data); /* never undone: the connection lives as long as the process */
    started = rc == 0;
    return rc;
}

/* The errors a connection meets, worded as POSIX systems word them, so that messages read the same
 * on every system. Others come from FormatMessage. */
static const struct {
    int code;
    const char *text;
} socket_errors[] = {
    {WSAECONNREFUSED, "Connection refused"},
    {WSAETIMEDOUT, "Connection timed out"},
    {WSAECONNRESET, "Connection reset by peer"},
    {WSAECONNABORTED, "Software caused connection abort"},
    {WSAENETUNREACH, "Network is unreachable"},
    {WSAEHOSTUNREACH, "No route to host"},
    {WSAENETDOWN, "Network is down"},
    {WSAEADDRNOTAVAIL, "Cannot assign requested address"},
    {WSAENOTCONN, "Transport endpoint is not connected"},
    {WSAESHUTDOWN, "Cannot send after transport endpoint shutdown"},
    {WSAENOBUFS, "No buffer space available"},
    {WSAEMFILE, "Too many open files"},
    {WSAEAFNOSUPPORT, "Address family not supported by protocol"},
    {WSANOTINITIALISED, "Winsock is not initialised"},
};

const char *es_socket_error_text(int error)
{
    static _Thread_local char text[256];
    for (size_t k = 0; k < sizeof socket_errors / sizeof socket_errors[0]; k++)
        if (socket_errors[k].code == error)
            return socket_errors[k].text;
    DWORD n = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, NULL, (DWORD)error,
                             MAKELANGID(LANG_NEUTRAL, SUBLANG_DEFAULT), text, sizeof text, NULL);
    while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r' || text[n - 1] == ' ' || text[n - 1] == '.'))
        text[--n] = '\0';
    if (n == 0)
        snprintf(text, sizeof text, "Winsock error %d", error);
    return text;
}

es_socket es_socket_open(int family, int type, int protocol, int *error)
{
    /* Not inherited: programs the robot program starts must not hold the connection open. */
    SOCKET sock = WSASocketW(family, type, protocol, NULL, 0, WSA_FLAG_OVERLAPPED | WSA_FLAG_NO_HANDLE_INHERIT);
    if (sock == INVALID_SOCKET && WSAGetLastError() == WSAEINVAL) { /* Windows 7 before SP1 lacks the flag */
        sock = WSASocketW(family, type, protocol, NULL, 0, WSA_FLAG_OVERLAPPED);
        if (sock != INVALID_SOCKET)
            SetHandleInformation((HANDLE)sock, HANDLE_FLAG_INHERIT, 0);
    }
    if (sock == INVALID_SOCKET)
        *error = WSAGetLastError();
    return sock;
}

void es_socket_close(es_socket sock)
{
    closesocket(sock);
}

static int socket_error_option(SOCKET sock)
{
    int error = 0;
    int size = sizeof error;
    if (getsockopt(sock, SOL_SOCKET, SO_ERROR, (char *)&error, &size) == SOCKET_ERROR)
        return WSAGetLastError();
    return error;
}

int es_socket_connect(es_socket sock, const struct sockaddr *address, size_t length, int timeout_ms)
{
    u_long on = 1, off = 0;
    ioctlsocket(sock, FIONBIO, &on); /* so an unreachable host cannot outlast the timeout */
    int error = 0;
    if (connect(sock, address, (int)length) == SOCKET_ERROR) {
        error = WSAGetLastError();
        if (error == WSAEWOULDBLOCK || error == WSAEINPROGRESS) {
            /* select, not WSAPoll: WSAPoll does not report a refused connection on older Windows 10
             * (it waits out the timeout); select reports it in the exception set. */
            fd_set writable, failed;
            FD_ZERO(&writable);
            FD_ZERO(&failed);
            FD_SET(sock, &writable);
            FD_SET(sock, &failed);
            struct timeval timeout = {.tv_sec = timeout_ms / 1000, .tv_usec = (timeout_ms % 1000) * 1000};
            int ready = select(0, NULL, &writable, &failed, timeout_ms < 0 ? NULL : &timeout);
            if (ready == 0)
                error = WSAETIMEDOUT;
            else if (ready == SOCKET_ERROR)
                error = WSAGetLastError();
            else
                error = socket_error_option(sock);
            if (ready > 0 && !error && FD_ISSET(sock, &failed))
                error = WSAECONNREFUSED; /* failed without saying why */
        }
    }
    ioctlsocket(sock, FIONBIO, &off);
    return error;
}

void es_socket_configure(es_socket sock)
{
    BOOL on = TRUE;
    setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, (const char *)&on, sizeof on); /* calls are small and latency-bound */
}

int es_socket_send_all(es_socket sock, const void *data, size_t length)
{
    /* Windows raises no signal for a write to a closed connection: send just fails. */
    const char *next = data;
    while (length > 0) {
        int n = send(sock, next, length > INT_MAX ? INT_MAX : (int)length, 0);
        if (n == SOCKET_ERROR)
            return WSAGetLastError();
        next += n;
        length -= (size_t)n;
    }
    return 0;
}

long es_socket_receive(es_socket sock, void *data, size_t length, int *error)
{
    int n = recv(sock, data, length > INT_MAX ? INT_MAX : (int)length, 0);
    if (n == SOCKET_ERROR) {
        *error = WSAGetLastError();
        return -1;
    }
    return n;
}

int es_socket_wait_readable(es_socket sock, int timeout_ms, int *error)
{
    WSAPOLLFD p = {.fd = sock, .events = POLLRDNORM};
    int ready = WSAPoll(&p, 1, timeout_ms < 0 ? -1 : timeout_ms);
    if (ready == SOCKET_ERROR) {
        *error = WSAGetLastError();
        return -1;
    }
    return ready > 0 ? 1 : 0; /* also on POLLHUP/POLLERR: the next recv tells what happened */
}

bool es_socket_peer_closed(es_socket sock)
{
    /* Readable with nothing to read is the end of the connection (nobody else reads meanwhile). */
    WSAPOLLFD p = {.fd = sock, .events = POLLRDNORM};
    if (WSAPoll(&p, 1, 0) != 1)
        return false;
    if (p.revents & (POLLHUP | POLLERR))
        return true;
    u_long waiting = 0;
    return ioctlsocket(sock, FIONREAD, &waiting) == SOCKET_ERROR || waiting == 0;
}

/* ---- Time and threads -------------------------------------------------------------------------- */

double es_monotonic_s(void)
{
    static LARGE_INTEGER frequency;
    LARGE_INTEGER count;
    if (!frequency.QuadPart)
        QueryPerformanceFrequency(&frequency); /* fixed at boot; never fails since Windows XP */
    QueryPerformanceCounter(&count);
    return (double)count.QuadPart / (double)frequency.QuadPart;
}

/* Sleep is the system's here: only programs' calls (through eyebot.h) go to simulation time. */
void es_pause_ms(int ms)
{
    if (ms > 0)
        Sleep((DWORD)ms);
}

_Noreturn void es_wait_forever(void)
{
    for (;;)
        Sleep(INFINITE);
}

long es_thread_id(void)
{
    return (long)GetCurrentThreadId();
}

int es_start_detached_thread(void *(*run)(void *), void *arg)
{
    /* No signal masks on Windows: console control events run on threads of their own. */
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    pthread_t thread;
    int rc = pthread_create(&thread, &attr, run, arg);
    pthread_attr_destroy(&attr);
    return rc;
}

/* The thread that loaded the library: the program's main thread (a DLL the program is linked with
 * loads before main runs; the static library's constructors run on the main thread too). Watched
 * through this handle at no cost; only once it has ended are the process's threads listed. */
static HANDLE first_thread;

__attribute__((constructor)) static void note_first_thread(void)
{
    if (!DuplicateHandle(GetCurrentProcess(), GetCurrentThread(), GetCurrentProcess(), &first_thread,
                         SYNCHRONIZE, FALSE, 0))
        first_thread = NULL;
}

static bool thread_running(DWORD id)
{
    HANDLE thread = OpenThread(SYNCHRONIZE, FALSE, id);
    if (!thread)
        return false; /* gone */
    bool running = WaitForSingleObject(thread, 0) == WAIT_TIMEOUT;
    CloseHandle(thread);
    return running;
}

bool es_program_threads_alive(bool (*is_library)(long id))
{
    if (first_thread && WaitForSingleObject(first_thread, 0) == WAIT_TIMEOUT)
        return true;
    /* The main thread has ended (pthread_exit): is any other thread of the program still running?
     * A thread that ended may still be listed while a handle to it is open, so each is asked. */
    HANDLE snapshot = CreateToolhelp32Snapshot(TH32CS_SNAPTHREAD, 0);
    if (snapshot == INVALID_HANDLE_VALUE)
        return true; /* cannot tell: keep the program as it is */
    DWORD process = GetCurrentProcessId();
    bool alive = false;
    THREADENTRY32 entry = {.dwSize = sizeof entry};
    for (BOOL more = Thread32First(snapshot, &entry); more && !alive; more = Thread32Next(snapshot, &entry))
        if (entry.th32OwnerProcessID == process && !is_library((long)entry.th32ThreadID))
            alive = thread_running(entry.th32ThreadID);
    CloseHandle(snapshot);
    return alive;
}

/* ---- The process ------------------------------------------------------------------------------- */

const char *es_program_name(void)
{
    static char name[MAX_PATH * 3]; /* UTF-8, as the protocol sends text */
    wchar_t path[MAX_PATH];
    DWORD n = GetModuleFileNameW(NULL, path, MAX_PATH);
    if (n == 0 || n >= MAX_PATH)
        return "";
    const wchar_t *base = path;
    for (const wchar_t *c = path; *c; c++)
        if (*c == L'\\' || *c == L'/')
            base = c + 1;
    size_t length = wcslen(base);
    if (length > 4 && _wcsicmp(base + length - 4, L".exe") == 0)
        length -= 4; /* "drive", as on the other systems */
    int bytes = WideCharToMultiByte(CP_UTF8, 0, base, (int)length, name, sizeof name - 1, NULL, NULL);
    name[bytes > 0 ? bytes : 0] = '\0';
    return name;
}

long es_process_id(void)
{
    return (long)GetCurrentProcessId();
}

bool es_stdout_is_pipe(void)
{
    HANDLE out = GetStdHandle(STD_OUTPUT_HANDLE);
    return out && out != INVALID_HANDLE_VALUE && GetFileType(out) == FILE_TYPE_PIPE;
}

/* Appends UTF-16 text to path (of capacity size); false when it does not fit. */
static bool append_wide(wchar_t *path, size_t size, const wchar_t *text)
{
    size_t used = wcslen(path), more = wcslen(text);
    if (used + more + 1 > size)
        return false;
    memcpy(path + used, text, (more + 1) * sizeof *text);
    return true;
}

FILE *es_open_token_file(const char *port, char *path, size_t path_size)
{
    wchar_t name[32] = L"\\program-token-";
    size_t length = wcslen(name);
    for (const char *c = port; *c && length + 1 < sizeof name / sizeof *name; c++)
        name[length++] = (wchar_t)(unsigned char)*c; /* digits */
    name[length] = L'\0';

    wchar_t file[MAX_PATH * 2] = L"";
    const wchar_t *dir = _wgetenv(L"EYESIM_STATE_DIR");
    const wchar_t *local = _wgetenv(L"LOCALAPPDATA");
    const wchar_t *profile = _wgetenv(L"USERPROFILE");
    size_t size = sizeof file / sizeof *file;
    bool fits;
    if (dir && *dir)
        fits = append_wide(file, size, dir) && append_wide(file, size, name);
    else if (local && *local)
        fits = append_wide(file, size, local) && append_wide(file, size, L"\\eyesim") && append_wide(file, size, name);
    else if (profile && *profile)
        fits = append_wide(file, size, profile) && append_wide(file, size, L"\\AppData\\Local\\eyesim") &&
               append_wide(file, size, name);
    else
        fits = false;
    if (path_size)
        path[0] = '\0';
    if (!fits)
        return NULL;
    int bytes = WideCharToMultiByte(CP_UTF8, 0, file, -1, path, (int)path_size, NULL, NULL);
    if (bytes <= 0 && path_size)
        path[0] = '\0';
    return _wfopen(file, L"rb");
}
