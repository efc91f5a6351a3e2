"""The menu-driven example (examples/programs/menu_demo.c) builds warning-free and does what its
soft keys say: drive, turn, beep, end; its LCD shows the title, the sensors, the drawing and the log."""

import math
import subprocess

import numpy as np
from PIL import Image
from support.programs import eyesim_command, read_trajectory, run_headless

from eyesim.robot.components.lcd import CELL_HEIGHT, HEIGHT, MENU_HEIGHT
from eyesim.paths import EXAMPLES_DIR

DEMO = EXAMPLES_DIR / "programs" / "menu_demo.c"
LOG_ROW = 12  # as in the program


def test_the_menu_demo_drives_turns_beeps_and_logs_what_it_did(tmp_path):
    built = subprocess.run(
        eyesim_command("cc", "-Wall", "-Wextra", "-Werror", str(DEMO), "-o", str(tmp_path / "menu_demo")),
        capture_output=True,
        text=True,
    )
    assert built.returncode == 0, built.stderr
    result = run_headless(
        "--program",
        "1=./menu_demo",
        "--key",
        "1:KEY1@1",
        "--key",
        "1:KEY2@3",
        "--key",
        "1:KEY3@5",
        "--key",
        "1:KEY4@6",
        "--record",
        "path.csv",
        "--save-lcd",
        "lcd",
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "program menu_demo: exit code 0" in result.stdout
    assert "[robot 1 audio] beep, 0.2 s" in result.stdout

    path = read_trajectory(tmp_path / "path.csv")[1]
    start, end = path[0], path[-1]
    assert abs(math.hypot(end["x"] - start["x"], end["y"] - start["y"]) - 0.200) < 0.01  # DRIVE: 200 mm
    turned = math.degrees(2 * (math.atan2(end["qz"], end["qw"]) - math.atan2(start["qz"], start["qw"])))
    assert abs((turned + 180) % 360 - 180 - 90) < 2  # TURN: 90 degrees

    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB")).astype(int)
    title = lcd[:24, :300]
    assert ((title[:, :, 0] > 200) & (title[:, :, 1] > 200) & (title[:, :, 2] < 80)).sum() > 300  # yellow title
    log = lcd[LOG_ROW * CELL_HEIGHT : (LOG_ROW + 3) * CELL_HEIGHT, :330]
    lit_rows = {y // CELL_HEIGHT for y in np.flatnonzero((log > 150).all(axis=2).any(axis=1))}
    assert lit_rows == {0, 1, 2}  # DRIVE, TURN and BEEP logged, one line each
    assert (lcd[200, 376:425] == [0, 0, 255]).all(axis=1).mean() > 0.7  # the robot drawn as a blue disc
    assert (lcd[HEIGHT - MENU_HEIGHT // 2, 10:110] == [0x30, 0x30, 0x30]).all()  # the last, empty menu
