"""The Windows simulator end to end, under Wine: run by `make test-windows` (`pytest tests/windows`);
plain `pytest` skips this folder (pyproject's addopts --ignore it). The tests run here on Linux;
EyeSim, the simulator and the robots' programs run under Wine with a Windows CPython and EyeSim's
Windows wheel (windows_env.py builds that environment, cached between runs)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import windows_env  # noqa: E402
from wine_sim import WindowsEyeSim  # noqa: E402

# Screenshots and other files for a person to look at, listed at the end of the run.
ARTIFACTS = windows_env.ROOT / "build" / "windows-tests"
_artifacts: list[Path] = []


@pytest.fixture(scope="session")
def windows() -> WindowsEyeSim:
    """EyeSim's Windows wheel installed in the Windows Python under Wine (built when missing)."""
    try:
        env = windows_env.ensure()
    except windows_env.EnvError as error:
        pytest.fail(f"no Windows environment: {error}", pytrace=False)
    return WindowsEyeSim(env)


@pytest.fixture(scope="session")
def x_display():
    """An X display of our own (Xvfb, Debian's xvfb) for Wine: with one, Wine's opengl32 makes WGL
    contexts (through GLX and Mesa's software renderer), so MuJoCo renders cameras the way it does
    on a Windows desktop, through GLFW and WGL. Yields the DISPLAY value."""
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        pytest.fail("Xvfb is missing: install Debian's xvfb (make test-windows does so as root)", pytrace=False)
    read_end, write_end = os.pipe()
    # -displayfd: Xvfb picks a free display number and writes it there once it accepts clients.
    server = subprocess.Popen(
        [xvfb, "-displayfd", str(write_end), "-screen", "0", "1280x1024x24", "-nolisten", "tcp"],
        pass_fds=(write_end,),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    os.close(write_end)
    with os.fdopen(read_end) as announced:
        number = announced.readline().strip()
    if not number.isdigit():
        server.kill()
        pytest.fail(f"Xvfb did not start: {server.communicate(timeout=10)[1].decode(errors='replace')}")
    # Wine's session (wineserver and its desktop process) outlives one program by a few seconds, and
    # a session started without a display keeps making windows without one: GLFW then finds no
    # OpenGL. End it, so the next program starts a session on this display.
    wineserver = shutil.which("wineserver") or "wineserver"
    subprocess.run([wineserver, "--kill"], env=windows_env.wine_env(), timeout=60)
    subprocess.run([wineserver, "--wait"], env=windows_env.wine_env(), timeout=60)
    try:
        yield f":{number}"
    finally:
        server.terminate()
        server.wait(timeout=30)


@pytest.fixture
def artifact():
    """artifact(name) -> a path under build/windows-tests/ that the run lists at its end."""
    ARTIFACTS.mkdir(parents=True, exist_ok=True)

    def make(name: str) -> Path:
        path = ARTIFACTS / name
        path.unlink(missing_ok=True)
        _artifacts.append(path)
        return path

    return make


def pytest_terminal_summary(terminalreporter):
    kept = [path for path in _artifacts if path.exists()]
    if kept:
        terminalreporter.write_sep("-", "files to look at")
        for path in kept:
            terminalreporter.write_line(str(path))
