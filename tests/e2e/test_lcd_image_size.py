"""LCDImageStart's size is the size of the image data (as in EyeSim), checked in a real program
built with AddressSanitizer: buffers of exactly xs * ys pixels are never read past."""

import numpy as np
from PIL import Image
from support.programs import build, run_headless


def test_image_start_sets_the_data_size_of_maps_and_tiles(tmp_path):
    program = build(
        "lcd_image_start",
        tmp_path,
        "-Wall",
        "-Wextra",
        "-Werror",
        "-g",
        "-fsanitize=address",
        "-fno-omit-frame-pointer",
    )
    result = run_headless("--program", f"1={program}", "--save-lcd", "lcd", cwd=tmp_path)
    assert "AddressSanitizer" not in result.stderr, result.stderr
    assert result.returncode == 0, result.stdout + result.stderr
    lines = [line.removeprefix("[robot 1] ") for line in result.stdout.splitlines() if line.startswith("[robot 1] ")]
    assert lines[-1] == "done"
    assert [line for line in lines if not line.startswith(("ok ", "done"))] == []
    assert len(lines) == 21

    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB")).astype(int)
    cross = lcd[10:138, 200:328].sum(axis=2) == 0
    assert cross[:, 64].all() and cross[32, :].all() and cross.sum() == 128 + 128 - 1
    np.testing.assert_array_equal(lcd[200, 0:160, 0], np.arange(160))  # the gray ramp, 1:1
    assert (lcd[160:280, 160:320] == [0, 0, 255]).all()
