"""AUPlay takes a path (str or os.PathLike) in the file system's encoding; the other AU functions only pass
values through (eye/audio.py)."""

from __future__ import annotations

import os

from eye._library import C
from eye._values import path

__all__ = ["AUPlay"]


def AUPlay(filename: str | os.PathLike) -> int:
    """Starts playing a WAV or MP3 file in the background. Returns 0 (1 on error)."""
    return C.AUPlay(path(filename))
