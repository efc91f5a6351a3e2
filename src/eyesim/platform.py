"""What differs between Windows, macOS and Linux, behind one interface: starting a program with
limits, ending it with everything it started, reading its output as it comes, where it finds
libeyesim, and why it ended in words.

POSIX: a process group per program (killpg ends the tree), rlimits set between fork and exec.
Windows: a Job Object per program (the process starts suspended, joins the job, then runs, so
nothing it starts escapes; closing or terminating the job ends the tree), with the job's per-process
CPU-time and memory limits. Nothing POSIX-only is imported at module level anywhere else."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from dataclasses import dataclass
from pathlib import Path

WINDOWS = sys.platform == "win32"
MACOS = sys.platform == "darwin"

if WINDOWS:
    import ctypes
    import socket
    from ctypes import wintypes
else:
    import resource
    import signal


@dataclass(frozen=True)
class Limits:
    """A program's resource limits; None is no limit. `processes` counts every process (and, on
    Linux, thread) of the program's user (RLIMIT_NPROC), so it means "per program" only where the
    program has a user of its own (a grading sandbox); on Windows it counts the job's processes.
    `file_bytes` is the largest file the program may write (RLIMIT_FSIZE; not on Windows)."""

    cpu_seconds: float | None = None
    memory_bytes: int | None = None
    processes: int | None = None
    file_bytes: int | None = None

    def __bool__(self) -> bool:
        return any(
            value is not None for value in (self.cpu_seconds, self.memory_bytes, self.processes, self.file_bytes)
        )


# ---- Starting and ending programs ---------------------------------------------------------------


def start(command: list[str], *, own_group: bool = False, limits: Limits = Limits(), **popen) -> subprocess.Popen:
    """subprocess.Popen with the program in a group of its own (`own_group`: ending it ends what it
    started) and under `limits`. On Windows a limited program always gets its own job."""
    if sys.platform == "win32":
        return _start_in_job(command, own_group or bool(limits), limits, popen)
    preexec = (lambda: _apply_rlimits(limits)) if limits else None
    return subprocess.Popen(command, preexec_fn=preexec, start_new_session=own_group, **popen)


def kill_tree(process: subprocess.Popen, own_group: bool) -> None:
    """End at once the program and, when it has a group (or job) of its own, all it started, even
    after the program itself has exited."""
    if sys.platform == "win32":
        job = _jobs.pop(process.pid, None)
        if job is not None:
            _kernel32.TerminateJobObject(job, _KILLED_EXIT_CODE)
            _kernel32.CloseHandle(job)
            return
    elif own_group:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        return
    try:
        process.kill()
    except OSError:
        pass


def ask_to_end(process: subprocess.Popen) -> None:
    """Ask a program to end (SIGTERM). Windows has no such request for a console program that we
    can rely on, so there it ends at once (TerminateProcess), as `kill_tree` would."""
    if WINDOWS:
        kill_tree(process, own_group=True)
    else:
        try:
            process.terminate()
        except OSError:
            pass


def release(process: subprocess.Popen) -> None:
    """The program has been waited for: free what `start` holds for it (its Windows job, whose
    closing also ends anything it left running)."""
    if sys.platform == "win32":
        job = _jobs.pop(process.pid, None)
        if job is not None:
            _kernel32.CloseHandle(job)


def _apply_rlimits(limits: Limits) -> None:
    """Runs in the child between fork and exec: only async-signal-safe work (setrlimit)."""
    if limits.cpu_seconds is not None:
        soft = max(1, int(limits.cpu_seconds + 0.999))
        resource.setrlimit(resource.RLIMIT_CPU, (soft, soft + 1))  # SIGXCPU, then SIGKILL a second later
    if limits.memory_bytes is not None:
        resource.setrlimit(resource.RLIMIT_AS, (limits.memory_bytes, limits.memory_bytes))
    if limits.processes is not None:
        resource.setrlimit(resource.RLIMIT_NPROC, (limits.processes, limits.processes))
    if limits.file_bytes is not None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limits.file_bytes, limits.file_bytes))


# ---- Windows jobs ---------------------------------------------------------------------------------

_KILLED_EXIT_CODE = 1  # what TerminateJobObject leaves as the exit code of the processes it ends
_NOT_ENOUGH_QUOTA = 1816  # ERROR_NOT_ENOUGH_QUOTA: the exit code of a process over its job's CPU time
_jobs: dict[int, int] = {}  # pid -> its job's handle

# Spelled `sys.platform == "win32"` (as are the branches that use it), not WINDOWS: type checkers
# then know that ctypes.WinDLL and the rest exist here, and skip it on other systems.
if sys.platform == "win32":

    class _IoCounters(ctypes.Structure):
        _fields_ = [
            (name, ctypes.c_ulonglong)
            for name in ("reads", "writes", "others", "read_bytes", "write_bytes", "other_bytes")
        ]

    class _BasicLimits(ctypes.Structure):
        _fields_ = [
            ("per_process_user_time", ctypes.c_int64),
            ("per_job_user_time", ctypes.c_int64),
            ("flags", wintypes.DWORD),
            ("min_working_set", ctypes.c_size_t),
            ("max_working_set", ctypes.c_size_t),
            ("active_processes", wintypes.DWORD),
            ("affinity", ctypes.c_size_t),
            ("priority_class", wintypes.DWORD),
            ("scheduling_class", wintypes.DWORD),
        ]

    class _ExtendedLimits(ctypes.Structure):
        _fields_ = [
            ("basic", _BasicLimits),
            ("io", _IoCounters),
            ("process_memory", ctypes.c_size_t),
            ("job_memory", ctypes.c_size_t),
            ("peak_process_memory", ctypes.c_size_t),
            ("peak_job_memory", ctypes.c_size_t),
        ]

    _kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
    _kernel32.CreateJobObjectW.restype = wintypes.HANDLE
    _kernel32.CreateJobObjectW.argtypes = (ctypes.c_void_p, wintypes.LPCWSTR)
    _kernel32.SetInformationJobObject.argtypes = (wintypes.HANDLE, ctypes.c_int, ctypes.c_void_p, wintypes.DWORD)
    _kernel32.AssignProcessToJobObject.argtypes = (wintypes.HANDLE, wintypes.HANDLE)
    _kernel32.TerminateJobObject.argtypes = (wintypes.HANDLE, wintypes.UINT)
    _kernel32.CloseHandle.argtypes = (wintypes.HANDLE,)
    _ntdll = ctypes.WinDLL("ntdll")
    _ntdll.NtResumeProcess.argtypes = (wintypes.HANDLE,)

    _EXTENDED_LIMIT_INFORMATION = 9  # JobObjectExtendedLimitInformation
    _LIMIT_PROCESS_TIME = 0x2
    _LIMIT_ACTIVE_PROCESS = 0x8
    _LIMIT_PROCESS_MEMORY = 0x100
    _LIMIT_KILL_ON_JOB_CLOSE = 0x2000
    _CREATE_SUSPENDED = 0x4
    _CREATE_NEW_PROCESS_GROUP = 0x200

    def _new_job(limits: Limits) -> int:
        job = _kernel32.CreateJobObjectW(None, None)
        if not job:
            raise OSError(ctypes.get_last_error(), "cannot create a job object for the program")
        info = _ExtendedLimits()
        info.basic.flags = _LIMIT_KILL_ON_JOB_CLOSE
        if limits.cpu_seconds is not None:
            info.basic.flags |= _LIMIT_PROCESS_TIME
            info.basic.per_process_user_time = int(limits.cpu_seconds * 10_000_000)  # 100 ns ticks
        if limits.memory_bytes is not None:
            info.basic.flags |= _LIMIT_PROCESS_MEMORY
            info.process_memory = limits.memory_bytes
        if limits.processes is not None:
            info.basic.flags |= _LIMIT_ACTIVE_PROCESS
            info.basic.active_processes = limits.processes
        if not _kernel32.SetInformationJobObject(
            job, _EXTENDED_LIMIT_INFORMATION, ctypes.byref(info), ctypes.sizeof(info)
        ):
            error = ctypes.get_last_error()
            _kernel32.CloseHandle(job)
            raise OSError(error, "cannot set the program's job limits")
        return job

    def _start_in_job(command: list[str], own_job: bool, limits: Limits, popen: dict) -> subprocess.Popen:
        if not own_job:
            return subprocess.Popen(command, **popen)
        job = _new_job(limits)
        flags = popen.pop("creationflags", 0) | _CREATE_SUSPENDED | _CREATE_NEW_PROCESS_GROUP
        try:
            process = subprocess.Popen(command, creationflags=flags, **popen)
        except OSError:
            _kernel32.CloseHandle(job)
            raise
        handle = int(process._handle)  # the process handle Popen holds (there is no public name for it)
        assigned = _kernel32.AssignProcessToJobObject(job, handle)
        _ntdll.NtResumeProcess(handle)
        if not assigned:
            error = ctypes.get_last_error()
            process.kill()
            process.wait()
            _kernel32.CloseHandle(job)
            raise OSError(error, "cannot put the program in its job object")
        _jobs[process.pid] = job
        return process


# ---- Reading a program's output -----------------------------------------------------------------


def readable(pipe):
    """Something the simulation thread's selector can watch for a child's output pipe, with a
    non-blocking `read_available`. POSIX selectors take pipes; Windows' take only sockets, so there a
    thread copies the pipe into a local socket pair."""
    if WINDOWS:
        return _PipeRelay(pipe)
    os.set_blocking(pipe.fileno(), False)
    return pipe


def drain(source, timeout: float = 1.0) -> None:
    """The program has exited: wait (up to `timeout` s) until what it wrote last has reached
    `source`. Nothing to do on POSIX, where it is still in the pipe; on Windows the relay thread
    may not have moved it into its socket yet (it ends at the pipe's end, at once unless a child
    of the program still holds the pipe)."""
    if WINDOWS:
        source.thread.join(timeout)


def read_available(source, size: int) -> bytes | None:
    """What `source` (from `readable`) holds now: bytes, b"" at its end, None when nothing is there yet."""
    if WINDOWS:
        return source.read_available(size)
    try:
        return os.read(source.fileno(), size)
    except BlockingIOError:
        return None
    except OSError:
        return b""


class _PipeRelay:
    """A Windows pipe seen through a socket: a thread reads the pipe and writes into one end of a
    socket pair; the selector watches the other."""

    def __init__(self, pipe):
        self.pipe = pipe
        self.inside, self.outside = socket.socketpair()
        self.outside.setblocking(False)
        self.thread = threading.Thread(target=self._copy, daemon=True)
        self.thread.start()

    def _copy(self) -> None:
        try:
            while chunk := self.pipe.read1(65536):
                self.inside.sendall(chunk)
        except (OSError, ValueError):
            pass
        finally:
            try:
                self.inside.shutdown(socket.SHUT_WR)
            except OSError:
                pass
            self.inside.close()
            self.pipe.close()

    def fileno(self) -> int:
        return self.outside.fileno()

    def read_available(self, size: int) -> bytes | None:
        try:
            return self.outside.recv(size)
        except BlockingIOError:
            return None
        except OSError:
            return b""

    def close(self) -> None:
        """Stop relaying. The pipe itself is left to the thread, which closes it at its end: a
        child of the program may hold it open for ever, and closing a BufferedReader that a thread
        is reading from waits for that read (a blocking ReadFile cannot be interrupted)."""
        self.outside.close()


# ---- Finding libeyesim ----------------------------------------------------------------------------


def library_environment(env: dict[str, str], lib_dir: Path) -> dict[str, str]:
    """`env` for a program that loads libeyesim from `lib_dir`. C programs built by `eyesim cc` find
    it by their rpath (Linux, macOS) or beside the .exe (Windows); this is for the rest. Windows
    looks for DLLs on PATH. On Linux, EyeSim-era eye.py files beside a Python program load it by
    name (CDLL("libeyesim.so")), which only LD_LIBRARY_PATH serves."""
    variable = "PATH" if WINDOWS else None if MACOS else "LD_LIBRARY_PATH"
    if variable is None:  # macOS: rpath and eye's full path are enough; DYLD_* is stripped by SIP anyway
        return env
    env[variable] = os.pathsep.join(part for part in (str(lib_dir), env.get(variable)) if part)
    return env


def is_executable(path: Path) -> bool:
    """Whether a file is a program to run: an .exe on Windows (where every file passes os.access's
    X_OK), a file with an execute bit elsewhere."""
    if WINDOWS:
        return path.suffix.lower() == ".exe" and path.is_file()
    return path.is_file() and os.access(path, os.X_OK)


def has_display() -> bool:
    """Whether a browser window can be opened here (`--open`): always on Windows and macOS, on other
    systems only with an X or Wayland display."""
    return WINDOWS or MACOS or bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def _malloc_trim():
    """glibc's malloc_trim, where the C library is glibc (not musl, macOS or Windows)."""
    if sys.platform != "linux":
        return None
    import ctypes

    trim = getattr(ctypes.CDLL(None), "malloc_trim", None)
    if trim is not None:
        trim.argtypes, trim.restype = [ctypes.c_size_t], ctypes.c_int
    return trim


_MALLOC_TRIM = _malloc_trim()


def return_free_memory() -> bool:
    """Give the memory the C heap holds free back to the system; True if some was. glibc keeps
    the pages of freed blocks between blocks still in use, so a long run whose messages and images
    come and go in many sizes grows in resident memory with nothing of it in use (a 10-minute soak:
    1-2 MB a minute); other systems' allocators give memory back themselves."""
    return bool(_MALLOC_TRIM(0)) if _MALLOC_TRIM is not None else False


# ---- Why a program ended ----------------------------------------------------------------------------

# Windows exception codes (NTSTATUS) a crashed program exits with, in words.
WINDOWS_CRASHES = {
    0xC0000005: "access violation",
    0xC000001D: "illegal instruction",
    0xC0000094: "integer division by zero",
    0xC000008E: "floating-point division by zero",
    0xC00000FD: "stack overflow",
    0xC0000409: "stack buffer overrun or fast fail (abort)",
    0xC0000374: "heap corruption",
    0xC0000096: "privileged instruction",
    0x80000003: "breakpoint",
}
WINDOWS_ENDED = {0xC000013A: "Ctrl-C", _NOT_ENOUGH_QUOTA: "its CPU time limit"}


def exit_reason(code: int | None) -> str | None:
    """Why a program with this exit status ended, in words, when it did not simply exit:
    'crashed: segmentation fault (SIGSEGV)', 'crashed: access violation (0xC0000005)',
    'was ended: its CPU time limit (SIGXCPU)'. None for an ordinary exit (or still running)."""
    if code is None:
        return None
    if WINDOWS:
        unsigned = code & 0xFFFFFFFF
        if unsigned in WINDOWS_CRASHES:
            return f"crashed: {WINDOWS_CRASHES[unsigned]} (0x{unsigned:08X})"
        if unsigned in WINDOWS_ENDED:
            return (
                f"was ended: {WINDOWS_ENDED[unsigned]} (0x{unsigned:08X})"
                if unsigned > 0xFFFF
                else f"was ended: {WINDOWS_ENDED[unsigned]}"
            )
        return None
    return signal_reason(-code) if code < 0 else None


def signal_reason(number: int) -> str:
    """'crashed: segmentation fault (SIGSEGV)'; the signals that stop a program on request or at
    a limit say 'was ended'."""
    try:
        name = signal.Signals(number).name
    except ValueError:
        return f"was ended by signal {number}"
    words = (signal.strsignal(number) or name).lower()
    ended = {signal.SIGTERM, signal.SIGKILL, signal.SIGINT, signal.SIGHUP, signal.SIGXCPU}
    if name == "SIGXCPU":
        words = "its CPU time limit"
    return f"{'was ended' if number in ended else 'crashed'}: {words} ({name})"


def crashed(code: int | None) -> bool:
    """Whether a program with this exit status crashed or was killed (not an ordinary exit)."""
    reason = exit_reason(code)
    return reason is not None


def over_limit(code: int | None) -> bool:
    """Whether a program with this exit status was ended for its CPU time (SIGXCPU, or SIGKILL
    which follows it a second later; a job's quota on Windows)."""
    if code is None:
        return False
    if WINDOWS:
        return code & 0xFFFFFFFF == _NOT_ENOUGH_QUOTA
    return code < 0 and -code in (signal.SIGXCPU, signal.SIGKILL)
