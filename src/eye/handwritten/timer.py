"""Timers: Python callables the library's timer thread calls in simulation time, kept alive while attached."""

from __future__ import annotations

import atexit
import threading
import traceback
from typing import Callable

from eye._library import C, TIMER_FUNCTION

__all__ = ["OSAttachTimer", "OSDetachTimer"]

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
