"""The LCD and key functions from a real C program in a real `eyesim run`: pixels read back by the
program, the saved LCD image, scripted keys and touches."""

import numpy as np
from PIL import Image
from support.programs import PROGRAMS, build, run_headless

from eyesim.robot.components.lcd import CELL_HEIGHT, CELL_WIDTH, HEIGHT, MENU_HEIGHT


def test_drawing_printing_images_keys_and_touches_from_c(tmp_path):
    program = build("lcd_graphics", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless(
        "--program",
        f"1={program}",
        "--key",
        "1:KEY1@0.2",
        "--key",
        "1:KEY3@0.3",
        "--key",
        "1:KEY4@0.4",
        "--touch",
        "1:100,50@0.5",
        "--touch",
        "1:5,6@0.7",
        "--save-lcd",
        "lcd",
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    lines = [line.removeprefix("[robot 1] ") for line in result.stdout.splitlines() if line.startswith("[robot 1] ")]
    assert lines[-1] == "done"
    failed = [line for line in lines if not line.startswith(("ok ", "done"))]
    assert failed == [] and len(lines) > 35
    assert "eyesim: LCDSetPos: row 21 is outside the text rows 0..20" in result.stdout + result.stderr

    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB")).astype(int)
    title = lcd[:CELL_HEIGHT, : 5 * CELL_WIDTH].reshape(-1, 3)
    assert ((title == [0, 0, 255]).all(axis=1)).sum() > 100  # blue background ...
    assert ((title == [255, 0, 0]).all(axis=1)).sum() > 10  # ... and red letters
    big = lcd[128:160, :60]
    assert (big.sum(axis=2) > 600).sum() > 150  # "Big" in 24-point Times bold
    assert (lcd[255:265, 10:40] == [0, 238, 238]).all()  # shown by LCDRefresh
    assert (lcd[255:265, 70:100] == 200).all()  # still the gray image: the cyan came after the refresh
    bar = lcd[HEIGHT - MENU_HEIGHT :]
    assert (bar[10, 125:235] == [0, 255, 0]).all(axis=1).mean() > 0.8  # KEY2's own colours


def test_menu_labels_set_one_by_one_count_positions_from_0_as_eyesim(tmp_path):
    """LCDMenuI(0..3) labels KEY1..KEY4 (EyeSim's graphics example does so); 4 is refused."""
    program = build("menu_positions", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--program", f"1={program}", "--key", "1:KEY4@0.5", "--save-lcd", "lcd", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert [f"[robot 1] LCDMenuI({pos}) = 0" in result.stdout for pos in range(4)] == [True] * 4
    assert "[robot 1] LCDMenuI(4) = 1" in result.stdout
    assert "eyesim: LCDMenuI: menu position 4 is not 0..3 (0 is KEY1 ... 3 is KEY4, as on EyeSim)" in result.stderr
    assert "[robot 1] key 8" in result.stdout  # KEY4
    bar = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB")).astype(int)[HEIGHT - MENU_HEIGHT :]
    backgrounds = [[0, 0, 255], [255, 255, 255], [255, 0, 0], [0, 255, 0]]  # as the program gave them, in key order
    for key, colour in enumerate(backgrounds):
        assert (bar[4, 120 * key + 5 : 120 * key + 20] == colour).all(), key


def test_long_lines_wrap_after_80_columns_as_with_eyesims_6x13_font(eyesim_sim, eyesim_cc):
    sim = eyesim_sim()
    sim.program(1, eyesim_cc(PROGRAMS / "long_lines.c", "-Wall", "-Wextra", "-Werror"))
    end = sim.run(until=10)
    robot = sim.robot(1)
    assert end.reason == "programs" and robot.exit_code == 0
    out = robot.stdout.splitlines()
    assert out == ["after the long line: row 1 column 10", "last cell 0", "column 80 1", "size 480 x 320"]
    line = "0123456789abcdefghijklmnopqrstuvwxyz0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-wrapped"
    assert robot.lcd_text()[:2] == [line[:80], line[80:]]
    assert robot.lcd_text()[20] == " " * 79 + "Z"
