"""Loads libeyesim, the same C library C programs link, and binds its functions with the C prototypes
of eye/_prototypes.py (generated from interface/protocol.json)."""

from __future__ import annotations

import ctypes
import sys
from ctypes import c_int
from pathlib import Path

from eye._prototypes import PROTOTYPES, TIMER_FUNCTION  # noqa: F401  (TIMER_FUNCTION for eye.timer)
from eyesim import paths


class EyeSimError(RuntimeError):
    """The eye module cannot do what was asked (for example: the C library lacks a function)."""


def library_path() -> Path:
    """libeyesim inside the installed eyesim package, or in $EYESIM_ROBIOS (a development build)."""
    name = {"darwin": "libeyesim.dylib", "win32": "eyesim.dll", "cygwin": "cygeyesim.dll"}.get(
        sys.platform, "libeyesim.so"
    )
    return paths.robios_lib_dir() / name


def _load() -> ctypes.CDLL:
    path = library_path()
    if not path.is_file():
        raise ImportError(
            f"eye: the RoBIOS C library is not at {path}. Reinstall EyeSim (pip install eyesim), or for a "
            f"development build set EYESIM_ROBIOS to its install prefix (docs/api/python.md)"
        )
    try:
        return ctypes.CDLL(str(path))
    except OSError as error:
        raise ImportError(f"eye: cannot load the RoBIOS C library {path}: {error}") from None


lib = _load()


class _Functions:
    """libeyesim's functions with their prototypes, bound on first use: a library older than this
    module still loads, and only a call to a function it lacks fails, saying so."""

    def __getattr__(self, name: str):
        if name not in PROTOTYPES:
            raise AttributeError(name)
        try:
            function = getattr(lib, name)
        except AttributeError:
            raise EyeSimError(
                f"{name} is not in the C library {library_path()}, which is older than this eye "
                f"module; rebuild or reinstall EyeSim"
            ) from None
        function.restype, function.argtypes = PROTOTYPES[name]
        setattr(self, name, function)
        return function


C = _Functions()


def library_int(name: str) -> int | None:
    """The value of an int variable the library exports (IP_SIZE, CAMSIZE, ...), None if it has none."""
    try:
        return c_int.in_dll(lib, name).value
    except ValueError:
        return None
