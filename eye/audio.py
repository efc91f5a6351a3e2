"""Audio: beeps and sound files, played by the viewer (headless runs record them as events)."""

from __future__ import annotations

import os

from eye._library import C
from eye._values import path

__all__ = ["AUBeep", "AUPlay", "AUDone", "AUMicrophone"]


def AUBeep() -> int:
    """A short beep. Returns 0 (1 on error)."""
    return C.AUBeep()


def AUPlay(filename: str | os.PathLike) -> int:
    """Starts playing a WAV or MP3 file in the background. Returns 0 (1 on error)."""
    return C.AUPlay(path(filename))


def AUDone() -> int:
    """1 when the sound has finished playing, 0 while it plays."""
    return C.AUDone()


def AUMicrophone() -> int:
    """One sample of the microphone."""
    return C.AUMicrophone()
