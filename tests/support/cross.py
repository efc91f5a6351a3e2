"""Other systems' programs on this Linux machine: C compiled for Windows and macOS with Zig (the
`ziglang` package), and Windows programs run under Wine (Debian's wine64)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

# Zig's target triples for the systems EyeSim ships wheels for.
TARGETS = {
    "windows-x86_64": "x86_64-windows-gnu",
    "macos-arm64": "aarch64-macos",
    "macos-x86_64": "x86_64-macos",
    "linux-x86_64": "x86_64-linux-gnu",
}


def zig_available() -> bool:
    try:
        import ziglang  # noqa: F401
    except ImportError:
        return False
    return True


def zig_cc(target: str, *args: str, cwd: Path | None = None, language: str = "cc") -> subprocess.CompletedProcess:
    """`zig cc -target TARGET ARGS...` (or `zig c++`); the first build for a target builds its libc
    (about a minute), later ones use Zig's cache."""
    if not zig_available():
        pytest.fail("the ziglang package is missing: it is in eyesim's [test] extra (pip install '.[test]')")
    return subprocess.run(
        [sys.executable, "-m", "ziglang", language, "-target", target, *args],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=900,
    )


def wine_prefix() -> Path:
    """A Wine prefix kept between runs (creating one takes tens of seconds)."""
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return Path(os.environ.get("EYESIM_WINEPREFIX") or base / "eyesim-windows" / "wineprefix")


def wine_environment() -> dict[str, str]:
    prefix = wine_prefix()
    prefix.parent.mkdir(parents=True, exist_ok=True)
    # No desktop, no Mono/Gecko installers, no debug chatter.
    return dict(os.environ, WINEPREFIX=str(prefix), WINEDEBUG="-all", WINEDLLOVERRIDES="mscoree,mshtml=", DISPLAY="")


def wine_command() -> str:
    wine = shutil.which("wine") or shutil.which("wine64")
    if wine is None:
        pytest.fail("wine is missing: `make test` installs Debian's wine64 (apt-get install wine64)")
    return wine


def run_under_wine(program: str | Path, *args: str, timeout: float = 300, **kwargs) -> subprocess.CompletedProcess:
    """Runs a Windows program under Wine and returns what it did."""
    return subprocess.run(
        [wine_command(), str(program), *args],
        env=kwargs.pop("env", None) or wine_environment(),
        capture_output=True,
        text=True,
        timeout=timeout,
        **kwargs,
    )
