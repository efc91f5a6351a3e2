"""System, time and timers: machine information, OSWait and OSGetCount in simulation time, timer callbacks."""

from __future__ import annotations

import atexit
import ctypes
import threading
import traceback
from typing import Callable

from eye._library import C, TIMER_FUNCTION, lib
from eye._values import text

__all__ = ["OSExecute", "OSVersion", "OSVersionIO", "OSMachineSpeed", "OSMachineType", "OSMachineName",
           "OSMachineID", "OSWait", "OSAttachTimer", "OSDetachTimer", "OSGetTime", "OSGetCount"]

TEXT_SIZE = 1024  # room for the strings OSVersion and friends write

_free = lib.free  # the C library's free(), found through libeyesim's own dependencies
_free.argtypes, _free.restype = [ctypes.c_void_p], None


def _text_out(function: str) -> str:
    buffer = ctypes.create_string_buffer(TEXT_SIZE)
    getattr(C, function)(buffer)
    return buffer.value.decode("utf-8", errors="replace")


def OSExecute(command: str) -> str | None:
    """Runs a shell command and returns what it printed, or None if it could not be run."""
    output = C.OSExecute(text(command))
    if not output:
        return None
    try:
        return ctypes.string_at(output).decode("utf-8", errors="replace")
    finally:
        _free(output)  # the C library hands over a malloc'd string


def OSVersion(buf: object = None) -> str:
    """The RoBIOS version string. (`buf` is ignored: eye.py took one but could not fill it.)"""
    return _text_out("OSVersion")


def OSVersionIO(buf: object = None) -> str:
    """The version string of the I/O board. (`buf` is ignored, as for OSVersion.)"""
    return _text_out("OSVersionIO")


def OSMachineSpeed() -> int:
    """The controller's speed."""
    return C.OSMachineSpeed()


def OSMachineType() -> int:
    """VEHICLE, PLATFORM or WALKER."""
    return C.OSMachineType()


def OSMachineName(buf: object = None) -> str:
    """The robot's name, from the scene. (`buf` is ignored, as for OSVersion.)"""
    return _text_out("OSMachineName")


def OSMachineID() -> int:
    """The robot's id number."""
    return C.OSMachineID()


def OSWait(n: int) -> int:
    """Waits n milliseconds of simulation time. Returns 0 (1 on error)."""
    return C.OSWait(n)


# Timer handle -> the C function pointer wrapping its callback, kept alive while the timer runs
# (EyeSim's eye.py did not keep it, so its timers could crash the program).
_timers: dict[int, object] = {}
_timers_lock = threading.Lock()


def OSAttachTimer(scale: int, fct: Callable[[], object]) -> int:
    """Calls fct() every `scale` milliseconds of simulation time, on the library's timer thread,
    until OSDetachTimer. An exception in fct is printed and the timer goes on. Returns the timer's
    handle, or 0 if it could not be attached."""
    if not callable(fct):
        raise TypeError(f"OSAttachTimer: the timer function must be callable, not {type(fct).__name__}")

    def call() -> None:
        try:
            fct()
        except BaseException:  # nothing may unwind into the C timer thread
            traceback.print_exc()

    function = TIMER_FUNCTION(call)
    handle = C.OSAttachTimer(scale, function)
    if handle:
        with _timers_lock:
            _timers[handle] = function
    return handle


def OSDetachTimer(t: int) -> int:
    """Stops a timer (t from OSAttachTimer). Returns 0 (1 on error)."""
    result = C.OSDetachTimer(t)
    if result == 0:
        with _timers_lock:
            _timers.pop(t, None)
    return result


@atexit.register
def _detach_all() -> None:
    """Stops the timers before Python shuts down, so that no callback runs in a dying interpreter."""
    with _timers_lock:
        handles = list(_timers)
    for handle in handles:
        C.OSDetachTimer(handle)


def OSGetTime() -> list[int]:
    """The simulation time as [hours, minutes, seconds, milliseconds]."""
    values = [ctypes.c_int() for _ in range(4)]
    C.OSGetTime(*(ctypes.byref(v) for v in values))
    return [v.value for v in values]


def OSGetCount() -> int:
    """Milliseconds of simulation time since the program started."""
    return C.OSGetCount()
