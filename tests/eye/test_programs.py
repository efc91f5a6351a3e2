"""Python robot programs (`from eye import *`) run by a real `eyesim run`, as C programs are: named in a
.sim file or with --program, checked by the robot's true pose, the LCD, their output and exit code."""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pytest
from PIL import Image
from support.programs import read_trajectory, run_headless


from eyesim.robot.components.lcd import HEIGHT, MENU_HEIGHT

DRIVE = """
    import sys
    from eye import *

    LCDMenu("GO", "", "", "END")
    LCDPrintf("Hello from %s, 100%% sure\\n", "Python")
    key = KEYGet()
    LCDPrintf("key %d\\n", key)
    VWStraight(300, 200)
    VWWait()
    x, y, phi = VWGetPosition()
    LCDPrintf("odometry %d %d %d\\n", x, y, phi)
    print("done", key, x, y, phi, flush=True)
    sys.exit(0 if key == KEY2 else 9)
"""


def write_program(directory, source: str, name: str = "prog.py"):
    path = directory / name
    path.write_text(textwrap.dedent(source))
    return path


def program_output(result, robot: int = 1) -> list[str]:
    """What the robot's program printed, without the simulator's prefix."""
    prefix = f"[robot {robot}] "
    return [line[len(prefix) :] for line in result.stdout.splitlines() if line.startswith(prefix)]


def test_a_python_program_named_in_a_sim_file_drives_s4(robios_prefix, tmp_path):
    write_program(tmp_path, DRIVE, "drive.py")
    (tmp_path / "lab.sim").write_text(
        "# a Python program, started by the simulator\nworld scenes/arena.wld\nS4 500 500 0 drive.py\n"
    )
    result = run_headless("lab.sim", "--key", "1:KEY2@0.5", "--record", "path.csv", "--save-lcd", "lcd", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "program drive.py: exit code 0" in result.stdout
    done = next(line for line in program_output(result) if line.startswith("done")).split()
    assert done[1] == "2" and abs(int(done[2]) - 300) <= 5 and abs(int(done[3])) <= 5

    path = read_trajectory(tmp_path / "path.csv")[1]
    start, end = path[0], path[-1]
    assert math.hypot(end["x"] - start["x"] - 0.300, end["y"] - start["y"]) < 0.010  # 300 mm east, true pose

    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB"))
    text = lcd[: HEIGHT - MENU_HEIGHT]
    lit_rows = np.flatnonzero((text > 128).any(axis=(1, 2)))
    assert lit_rows.size and lit_rows.max() - lit_rows.min() > 20  # three printed lines
    assert (lcd[HEIGHT - MENU_HEIGHT :] > 0).any()  # and the menu bar


def test_a_failing_python_program_fails_the_run(robios_prefix, tmp_path):
    program = write_program(tmp_path, DRIVE)
    result = run_headless("--program", f"1={program}", "--key", "1:KEY1@0.2", cwd=tmp_path)
    assert result.returncode == 1
    assert "exit code 9" in result.stdout


BASICS = """
    import ctypes
    from eye import *

    def show(*values):
        print(*values, flush=True)

    show("menu", LCDMenu("A", "", "B", "C"), LCDClear())
    show("printf", LCDPrintf("%d%%", 5), LCDPrintf("50%"), LCDPrintf(42), LCDSetPrintf(3, 4, "x=%.1f", 2.25))
    show("keyread", KEYRead())
    show("keyget", KEYGet())
    start = OSGetCount()
    show("wait", OSWait(250), OSGetCount() - start)
    show("psd", PSDGet(PSD_FRONT), PSDGet(PSD_BACK))
    show("setpos", VWSetPosition(100, -200, 90), *VWGetPosition())
    show("speed", *VWGetSpeed())
    pose = SIMGetRobot(0)
    show("pose", *pose, pose[0].value + pose[1].value)
    show("moved", SIMSetRobot(0, 1200, 700, 0, 45), *SIMGetRobot(0))
    show("unknown", SIMGetRobot(99))
"""


def test_python_programs_reach_each_group_of_the_c_library(robios_prefix, tmp_path):
    program = write_program(tmp_path, BASICS)
    result = run_headless("--program", f"1={program}", "--key", "1:KEY4@0.1", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    out = {line.split()[0]: line.split()[1:] for line in program_output(result)}
    assert out["menu"] == ["0", "0"]
    assert out["printf"] == ["0", "0", "0", "0"]
    assert out["keyread"] == ["0"]
    assert out["keyget"] == ["8"]
    # simulation time, deterministic: the wait (the OSGetCount before it is local: 10 us)
    assert out["wait"][0] == "0" and int(out["wait"][1]) == 250
    front, back = map(int, out["psd"])
    assert 1300 < front < 1500 and 300 < back < 500  # 2 m arena, the robot at x = 500 facing east
    assert out["setpos"] == ["0", "100", "-200", "90"]
    assert out["speed"] == ["0", "0"]
    x, y, z, phi, total = map(int, out["pose"])
    assert abs(x - 500) <= 2 and abs(y - 500) <= 2 and phi == 0 and total == x + y
    assert out["moved"][0] == "0" and [abs(int(v)) for v in out["moved"][1:3]] == [1200, 700]
    assert out["unknown"] == ["None"]


@pytest.mark.parametrize(
    "call,message",
    [
        ("IPLaplace(b'123')", "IPLaplace: the gray image has 3 bytes, but 76800 are needed (the IP size is 320 x 240)"),
        ("OSAttachTimer(100, 5)", "OSAttachTimer: the timer function must be callable, not int"),
    ],
)
def test_bad_arguments_raise_clear_python_errors(robios_prefix, tmp_path, call, message):
    program = write_program(tmp_path, f"from eye import *\n{call}\n")
    result = run_headless("--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 1
    assert message in result.stdout + result.stderr


MOTION = """
    from eye import *

    print("motors", MOTORDrive(1, 20), MOTORDrive(2, 20))  # slowly: the manoeuvres below need room
    OSWait(500)
    print("encoders", ENCODERRead(1) > 0, ENCODERRead(2) > 0)
    print("reset", ENCODERReset(1), ENCODERRead(1))
    print("pid", MOTORPID(1, 10, 5, 1), MOTORSpeed(1, 200), MOTORPIDOff(1), MOTORDriveRaw(1, 0), MOTORDrive(2, 0))
    print("servo", SERVOSet(1, 128), SERVOSetRaw(1, 10), SERVORange(1, 0, 255))
    print("curve", VWCurve(300, 90, 200), VWRemain() > 0, VWDriveRemain() > 0, VWDone(), VWDriveDone())
    print("waited", VWWait(), VWDone(), VWRemain())
    print("drive", VWDrive(300, 100, 200), VWDriveWait(), VWStalled())
    print("counts", SIMGetRobotCount(), SIMGetObjectCount())
    print("object", *SIMGetObject(1))
    print("moved", SIMSetObject(1, 1200, 800, 0, 90), *SIMGetObject(1))
    print("unknown", SIMGetObject(5), SIMSetObject(5, 0, 0, 0, 0))
"""


def test_motors_driving_and_objects(robios_prefix, tmp_path):
    write_program(tmp_path, MOTION)
    (tmp_path / "objects.sim").write_text("world scenes/arena.wld\nS4 500 500 0 prog.py\nCan 1000 1000 0\n")
    result = run_headless("objects.sim", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    out = {line.split()[0]: line.split()[1:] for line in program_output(result)}
    assert out["motors"] == ["0", "0"]
    assert out["encoders"] == ["True", "True"]
    # the wheel turns on for one call time: 20% of 3600 deg/s for 4 ms is 9 ticks of 1100 a turn
    assert out["reset"][0] == "0" and 0 <= int(out["reset"][1]) <= 12
    assert out["pid"] == ["0"] * 5
    assert out["servo"] == ["1", "1", "1"]  # the S4 has no servos: the C library says so on stderr
    assert "SERVOSet" in result.stdout + result.stderr
    assert out["curve"] == ["0", "True", "True", "0", "0"]
    assert out["waited"] == ["0", "1", "0"]
    assert out["drive"] == ["0", "0", "0"]
    assert out["counts"] == ["1", "1"]
    assert out["object"] == ["1000", "1000", "0", "0"]
    assert out["moved"] == ["0", "1200", "800", "0", "90"]
    assert out["unknown"] == ["None", "1"]


# A stand-in, written for this test, for EyeSim's own eye.py as lab directories still hold it:
# it loads the library by its file name, as EyeSim's did, and wraps a few functions the same way.
OLD_STYLE_EYE = """
    import ctypes
    import sys

    if sys.platform.startswith("linux"):
        lib = ctypes.CDLL("libeyesim.so")
    else:
        sys.exit("eye.py: unsupported platform " + sys.platform)

    STANDIN = True
    KEY1 = 1

    lib.LCDPrintf.argtypes = [ctypes.c_char_p]
    lib.LCDGetPos.argtypes = [ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_int)]
    lib.VWStraight.argtypes = [ctypes.c_int, ctypes.c_int]
    lib.VWGetPosition.argtypes = [ctypes.POINTER(ctypes.c_int)] * 3

    def LCDPrintf(format, *args):
        return lib.LCDPrintf((format % args).encode("ascii"))

    def LCDGetPos(row, column):
        return lib.LCDGetPos(ctypes.pointer(row), ctypes.pointer(column))

    def VWStraight(dist, speed):
        return lib.VWStraight(ctypes.c_int(dist), ctypes.c_int(speed))

    def VWWait():
        return lib.VWWait()

    def VWGetPosition():
        x, y, phi = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        lib.VWGetPosition(ctypes.pointer(x), ctypes.pointer(y), ctypes.pointer(phi))
        return [x.value, y.value, phi.value]
"""

USES_OLD_EYE = """
    import ctypes
    import eye
    from eye import *

    print("standin", eye.STANDIN)
    library = next(line.split()[-1] for line in open("/proc/self/maps") if "libeyesim.so" in line)
    print("library", library)
    LCDPrintf("Lab %d\\n", 3)
    row, column = ctypes.c_int(), ctypes.c_int()
    LCDGetPos(row, column)
    print("cursor", row.value, column.value)
    VWStraight(200, 200)
    VWWait()
    print("odometry", *VWGetPosition())
"""


def test_a_program_beside_eyesims_old_eye_py_runs_with_our_library(robios_prefix, tmp_path):
    write_program(tmp_path, OLD_STYLE_EYE, "eye.py")
    write_program(tmp_path, USES_OLD_EYE, "lab.py")
    (tmp_path / "lab.sim").write_text("world scenes/arena.wld\nS4 500 500 0 lab.py\n")
    result = run_headless("lab.sim", "--record", "path.csv", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    out = {line.split()[0]: line.split()[1:] for line in program_output(result)}
    assert out["standin"] == ["True"]  # the directory's eye.py, not ours
    assert out["library"] == [str((robios_prefix / "lib" / "libeyesim.so").resolve())]
    assert out["cursor"] == ["1", "0"]
    x, y, phi = map(int, out["odometry"])
    assert abs(x - 200) <= 5 and abs(y) <= 5
    path = read_trajectory(tmp_path / "path.csv")[1]
    assert math.hypot(path[-1]["x"] - path[0]["x"] - 0.200, path[-1]["y"] - path[0]["y"]) < 0.010


PRINTF = """
    from eye import *

    LCDPrintf("Hello\\n", "")                       # a surplus argument, as C ignores it
    LCDPrintf("%5.2f|%-4d|%x|%c|%s|%ld%%", 3.14159, 7, 255, 65, "ok", 10 ** 12)
    print("cursor", *LCDGetPos())
    LCDSetPrintf(5, 2, "%*d", 6, 42, "surplus")
    print("set", *LCDGetPos())
"""


def test_python_lcd_printf_follows_c_printf(robios_prefix, tmp_path):
    write_program(tmp_path, PRINTF, "printf.py")
    (tmp_path / "lab.sim").write_text("world scenes/arena.wld\nS4 500 500 0 printf.py\n")
    result = run_headless("lab.sim", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    out = {line.split()[0]: line.split()[1:] for line in program_output(result)}
    # " 3.14|7   |ff|A|ok|1000000000000%" is 32 characters on row 1
    assert out["cursor"] == ["1", str(len(" 3.14|7   |ff|A|ok|1000000000000%"))]
    assert out["set"] == ["5", "8"]


def test_programs_get_the_library_directory_first_on_ld_library_path(monkeypatch):
    from eyesim import paths
    from eyesim.programs.launcher import program_environment

    monkeypatch.setenv("LD_LIBRARY_PATH", "/opt/other")
    env = program_environment("127.0.0.1", 9797, 2)
    assert env["LD_LIBRARY_PATH"] == f"{paths.robios_lib_dir()}:/opt/other"
    assert (env["EYESIM_HOST"], env["EYESIM_PORT"], env["EYESIM_ROBOT"]) == ("127.0.0.1", "9797", "2")
    monkeypatch.delenv("LD_LIBRARY_PATH")
    assert program_environment("127.0.0.1", 9797, 2)["LD_LIBRARY_PATH"] == str(paths.robios_lib_dir())
