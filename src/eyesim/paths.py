"""Where the installed parts of EyeSim live (the C library, its headers, data and viewer assets), and
where it keeps what it remembers between runs."""

from __future__ import annotations

import os
import sys
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
DATA_DIR = PACKAGE_DIR / "data"
STATIC_DIR = PACKAGE_DIR / "web" / "static"
EXAMPLES_DIR = PACKAGE_DIR / "examples"  # example scenes, programs (C and Python) and a grading lab


# A graded case's recording, beside its result: OUT/cases/<student>/<case>/case.mcap (eyesim grade
# --keep-recordings writes it, eyesim replay REPORT_FOLDER serves it).
CASE_RECORDING = "case.mcap"

# What a program named without an extension may be (EyeSim's scene files name `drive` for drive.c).
PROGRAM_SOURCE_SUFFIXES = (".c", ".cpp", ".cc", ".cxx", ".py")


def robios_dir() -> Path:
    """The C library's install prefix (include/, lib/): inside the package when installed with
    pip; `EYESIM_ROBIOS` points elsewhere (a development build)."""
    override = os.environ.get("EYESIM_ROBIOS")
    return Path(override) if override else PACKAGE_DIR / "robios"


def robios_lib_dir() -> Path:
    return robios_dir() / "lib"


def cache_dir() -> Path:
    """Where EyeSim keeps what it can make again (programs compiled from source): `EYESIM_CACHE_DIR`,
    else the platform's cache folder."""
    override = os.environ.get("EYESIM_CACHE_DIR")
    if override:
        return Path(override)
    home = Path.home()
    if os.name == "nt":
        return Path(os.environ.get("LOCALAPPDATA") or home / "AppData" / "Local") / "eyesim" / "cache"
    if sys.platform == "darwin":
        return home / "Library" / "Caches" / "eyesim"
    return Path(os.environ.get("XDG_CACHE_HOME") or home / ".cache") / "eyesim"


def state_dir() -> Path:
    """Where EyeSim keeps what it remembers from one run to the next (the scene browser's recent
    files): `EYESIM_STATE_DIR`, else the platform's place for an application's state."""
    override = os.environ.get("EYESIM_STATE_DIR")
    if override:
        return Path(override)
    home = Path.home()
    if os.name == "nt":
        base = Path(os.environ.get("LOCALAPPDATA") or home / "AppData" / "Local")
    elif sys.platform == "darwin":
        base = home / "Library" / "Application Support"
    else:
        base = Path(os.environ.get("XDG_STATE_HOME") or home / ".local" / "state")
    return base / "eyesim"
