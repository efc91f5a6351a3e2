"""Headless runs of the Windows simulator under Wine: a Python and a C program drive the robot (the
recorded path checked), the LCDs are saved as PNGs, and a program stopped at --until leaves nothing
running behind it."""

from __future__ import annotations

import csv
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from windows_env import wine_executable
from wine_sim import PROGRAMS, OutputReader, free_port, no_process_left, processes_mentioning


def trajectory(path) -> list[dict[str, float]]:
    """Robot 1's rows of a --record CSV (time_s, x, y, z in metres, quaternion)."""
    with open(path, newline="") as file:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(file)]
    return [row for row in rows if row["robot"] == 1]


def heading(row) -> float:
    """Degrees, counter-clockwise from the x axis (the robot turns about z only)."""
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


def lcd(folder) -> np.ndarray:
    image = Image.open(folder / "robot1-lcd.png")
    assert image.format == "PNG" and image.size == (480, 320)
    return np.asarray(image.convert("RGB"))


def white_pixels(rows: np.ndarray) -> int:
    return int((rows > 200).all(axis=2).sum())


def check_run(result, tmp_path) -> list[dict[str, float]]:
    assert result.returncode == 0, result.stdout + result.stderr
    path = trajectory(tmp_path / "path.csv")
    assert path[0]["time_s"] == pytest.approx(0.01)
    assert (path[0]["x"], path[0]["y"]) == pytest.approx((0.5, 0.5), abs=0.002)  # the default scene's start
    assert heading(path[0]) == pytest.approx(0, abs=0.5)
    return path


def test_a_python_program_drives_and_draws(windows, tmp_path):
    shutil.copy(PROGRAMS / "drive.py", tmp_path)
    result = windows.run(
        "run",
        "--headless",
        "--until",
        "10",
        "--port",
        "0",
        "--program",
        "1=drive.py",
        "--record",
        "path.csv",
        "--save-lcd",
        "lcd",
        cwd=tmp_path,
    )
    path = check_run(result, tmp_path)
    assert "program drive.py: exit code 0" in result.stdout, result.stdout

    # 400 mm east, then a quarter turn left on the spot.
    end = path[-1]
    assert (end["x"], end["y"]) == pytest.approx((0.9, 0.5), abs=0.01)
    assert heading(end) == pytest.approx(90, abs=2)
    assert "odometry " in result.stdout, result.stdout  # its last line, printed just before it exits
    odometry = [int(v) for v in result.stdout.split("odometry ", 1)[1].split()[:3]]  # from where it started
    assert odometry == pytest.approx([400, 0, 90], abs=5)

    image = lcd(tmp_path / "lcd")
    assert white_pixels(image[0:13]) > 40  # "Windows Python"
    assert white_pixels(image[13:26]) > 40  # "x=... y=... phi=..."
    assert white_pixels(image[26:190]) == 0
    assert (image[200:260, 380:460] == [255, 0, 0]).all()  # LCDArea(380, 200, 459, 259, RED, 1)
    assert not image[200:260, 0:370].any()


def test_a_c_program_drives_and_draws(windows, tmp_path):
    # The DLL is not copied beside the program: the simulator puts the package's lib folder on PATH.
    program = windows.compile_c(PROGRAMS / "drive.c", tmp_path / "drive.exe", "-O2", "-Wall", "-Werror")
    result = windows.run(
        "run",
        "--headless",
        "--until",
        "10",
        "--port",
        "0",
        "--program",
        "1=drive.exe",
        "--record",
        "path.csv",
        "--save-lcd",
        "lcd",
        cwd=tmp_path,
    )
    path = check_run(result, tmp_path)
    assert f"program {program.name}: exit code 0" in result.stdout, result.stdout

    # 300 mm east, a quarter turn right, 200 mm south.
    end = path[-1]
    assert (end["x"], end["y"]) == pytest.approx((0.8, 0.3), abs=0.01)
    assert heading(end) == pytest.approx(-90, abs=2)
    assert "odometry " in result.stdout, result.stdout
    odometry = [int(v) for v in result.stdout.split("odometry ", 1)[1].split()[:3]]  # from where it started
    assert odometry == pytest.approx([300, -200, -90], abs=5)

    image = lcd(tmp_path / "lcd")
    assert white_pixels(image[0:13]) > 30  # "Windows C"
    assert white_pixels(image[13:26]) > 40
    assert (image[200:260, 20:100] == [0, 255, 0]).all()  # LCDArea(20, 200, 99, 259, GREEN, 1)
    assert not image[200:260, 110:480].any()


def test_the_c_program_runs_by_hand_with_the_dll_beside_it(windows, tmp_path):
    """Started by hand (not by the simulator, so nothing on PATH), it finds eyesim.dll beside the
    .exe, and without a simulator it fails as the C library says it should, without a crash."""
    program = windows.compile_c(PROGRAMS / "drive.c", tmp_path / "drive.exe", "-O2")
    shutil.copy(windows.robios_lib / "eyesim.dll", tmp_path)
    environment = windows.env.environment(
        EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(free_port()), EYESIM_CONNECT_TIMEOUT="1"
    )
    result = subprocess.run(
        [wine_executable(), str(program)],
        cwd=tmp_path,
        env=environment,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        errors="replace",
        timeout=120,
    )
    assert result.returncode == 3, result  # the library's "no simulator answered"
    assert f"no simulator answered at 127.0.0.1:{environment['EYESIM_PORT']}" in result.stderr, result.stderr


def test_non_ascii_output(windows, tmp_path):
    """A Python program's text beyond ASCII reaches the console and the LCD. The simulator's own
    output may be in the ANSI code page (cp1252) or UTF-8, both are accepted; replacement characters
    or a traceback are not."""
    shutil.copy(PROGRAMS / "greeting.py", tmp_path)
    result = windows.run(
        "run",
        "--headless",
        "--until",
        "5",
        "--port",
        "0",
        "--program",
        "1=greeting.py",
        "--save-lcd",
        "lcd",
        cwd=tmp_path,
        text=False,
    )
    output = result.stdout + result.stderr
    shown = [output.decode(encoding, errors="replace") for encoding in ("utf-8", "cp1252")]
    assert result.returncode == 0, shown[0]
    assert any("[robot 1] Grüße 20°C" in text for text in shown), shown[0]
    assert any("program greeting.py: exit code 0" in text for text in shown), shown[0]
    image = lcd(tmp_path / "lcd")
    assert white_pixels(image[0:13]) > 40 and white_pixels(image[13:200]) == 0


@pytest.mark.parametrize("language", ["python", "c"])
def test_a_program_stopped_at_until_leaves_no_process_behind(windows, tmp_path, language):
    """The program starts a child that never ends, then loops for ever: when the run ends at --until,
    both are gone (the program's Windows job ends the whole tree). Every Windows process under Wine
    is a Linux process showing its Windows command line, so /proc tells which are running: the
    program (its path names tmp_path) and forever.exe are seen first, then neither."""
    if language == "python":
        program = Path(shutil.copy(PROGRAMS / "spawner.py", tmp_path))
    else:
        program = windows.compile_c(PROGRAMS / "spawner.c", tmp_path / "spawner.exe", "-Wall", "-Werror")
    windows.compile_c(PROGRAMS / "forever.c", tmp_path / "forever.exe", with_eyesim=False)
    token = windows.path(tmp_path)  # Z:\tmp\pytest-of-...\<test>: in both programs' command lines
    with no_process_left(token):
        process = windows.start(
            "run", "--headless", "--until", "3", "--port", "0", "--program", f"1={program.name}", cwd=tmp_path
        )
        output = OutputReader(process)
        try:
            output.wait_for(r"child \d+ running", timeout=90)
            running = processes_mentioning(token)
            assert any(program.name in command for command in running.values()), running
            assert any("forever.exe" in command for command in running.values()), running
            (tmp_path / "release").touch()
            assert process.wait(timeout=90) == 0, output.text()
        finally:
            if process.poll() is None:
                process.kill()
        assert "t=3.000" in output.finish(), output.text()
    assert not processes_mentioning(token)
