"""time.sleep in simulation time, as the C library does for sleep/usleep/nanosleep.

Importing eye replaces time.sleep with `sleep` below. A call from the program's own code, once the
program talks to the simulator, waits in simulation time like OSWait (deterministic mode: exactly,
without stalling the simulation; realtime: following the speed factor). Calls from the standard
library and installed packages (subprocess polling a child, say) keep sleeping in wall time, and so
does everything before the program's first RoBIOS call. docs/api/python.md#sleeping."""

from __future__ import annotations

import ctypes
import math
import sys
import sysconfig
import time

from eye._library import lib

_system_sleep = time.sleep
_simulated = lib.eyesim_sleep
_simulated.argtypes, _simulated.restype = [ctypes.c_uint, ctypes.c_uint], ctypes.c_int
_LIBRARY_DIRS = tuple(
    sorted({path for name in ("stdlib", "platstdlib", "purelib", "platlib") if (path := sysconfig.get_path(name))})
)
_MAX_SECONDS = 2**32 - 1


def sleep(secs: float) -> None:
    """time.sleep: waits `secs` seconds of simulation time once the program talks to the simulator."""
    caller = sys._getframe(1).f_code.co_filename
    if (
        isinstance(secs, bool)
        or not isinstance(secs, (int, float))
        or not secs >= 0
        or math.isinf(secs)
        or caller.startswith(_LIBRARY_DIRS)
        or caller.startswith("<frozen")
    ):
        return _system_sleep(secs)  # its own errors for bad values (TypeError, ValueError)
    whole = min(int(secs), _MAX_SECONDS)
    nanoseconds = min(round((secs - int(secs)) * 1e9), 999_999_999)
    if _simulated(whole, nanoseconds) != 0:  # not connected yet: a sleep in wall time
        _system_sleep(secs)


# Monkey-patching the standard library, which its types do not foresee.
sleep.__wrapped__ = _system_sleep  # type: ignore[attr-defined]
time.sleep = sleep  # type: ignore[assignment]
