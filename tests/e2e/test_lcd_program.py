"""The LCD and key functions from a real C program in a real `eyesim run`: pixels read back by the
program, the saved LCD image, scripted keys and touches."""

import numpy as np
from PIL import Image
from support.programs import build, run_headless

from eyesim.robot.components.lcd import CELL_HEIGHT, HEIGHT, MENU_HEIGHT


def test_drawing_printing_images_keys_and_touches_from_c(tmp_path):
    program = build("lcd_graphics", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--program", f"1={program}", "--key", "1:KEY1@0.2", "--key", "1:KEY3@0.3",
                          "--key", "1:KEY4@0.4", "--touch", "1:100,50@0.5", "--touch", "1:5,6@0.7",
                          "--save-lcd", "lcd", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    lines = [line.removeprefix("[robot 1] ") for line in result.stdout.splitlines() if line.startswith("[robot 1] ")]
    assert lines[-1] == "done"
    failed = [line for line in lines if not line.startswith(("ok ", "done"))]
    assert failed == [] and len(lines) > 35
    assert "eyesim: LCDSetPos: row 21 is outside the text rows 0..20" in result.stdout + result.stderr

    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB")).astype(int)
    title = lcd[:CELL_HEIGHT, :5 * 8].reshape(-1, 3)
    assert ((title == [0, 0, 255]).all(axis=1)).sum() > 100  # blue background ...
    assert ((title == [255, 0, 0]).all(axis=1)).sum() > 10  # ... and red letters
    big = lcd[128:160, :60]
    assert (big.sum(axis=2) > 600).sum() > 150  # "Big" in 24-point Times bold
    assert (lcd[255:265, 10:40] == [0, 238, 238]).all()  # shown by LCDRefresh
    assert (lcd[255:265, 70:100] == 200).all()  # still the gray image: the cyan came after the refresh
    bar = lcd[HEIGHT - MENU_HEIGHT:]
    assert (bar[10, 125:235] == [0, 255, 0]).all(axis=1).mean() > 0.8  # KEY2's own colours
