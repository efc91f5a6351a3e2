"""IR remote control: codes from the viewer's on-screen remote, the keyboard or a script."""

from __future__ import annotations

from eye._library import C

__all__ = ["IRTVGet", "IRTVRead", "IRTVFlush", "IRTVGetStatus"]


def IRTVGet() -> int:
    """Waits for the next remote code (IRTV_0 .. IRTV_9, IRTV_OK, ...) and returns it."""
    return C.IRTVGet()


def IRTVRead() -> int:
    """The next remote code, or 0 if there is none; never waits."""
    return C.IRTVRead()


def IRTVFlush() -> int:
    """Drops the codes not read yet. Returns 0."""
    return C.IRTVFlush()


def IRTVGetStatus() -> int:
    """1 when the remote receiver is on, 0 when it is off."""
    return C.IRTVGetStatus()
