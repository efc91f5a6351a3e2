"""Where the installed parts of EyeSim live: the C library, its headers, data and viewer assets."""

from __future__ import annotations

import os
from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent
DATA_DIR = PACKAGE_DIR / "data"
STATIC_DIR = PACKAGE_DIR / "web" / "static"


def robios_dir() -> Path:
    """The C library's install prefix (include/, lib/): inside the package when installed with
    pip; `EYESIM_ROBIOS` points elsewhere (a development build)."""
    override = os.environ.get("EYESIM_ROBIOS")
    return Path(override) if override else PACKAGE_DIR / "robios"


def robios_lib_dir() -> Path:
    return robios_dir() / "lib"
