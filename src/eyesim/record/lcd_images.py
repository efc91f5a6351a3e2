"""Each robot's final LCD as a PNG file (`eyesim run --save-lcd`)."""

from __future__ import annotations

from pathlib import Path

from PIL import Image

from eyesim.robot.components.lcd import Lcd


def save_lcd_images(sim, directory: str | Path) -> list[Path]:
    """Write each robot's LCD as robot<id>-lcd.png; returns the paths."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for robot in sim.robots:
        lcd = robot.component(Lcd)
        if lcd is not None:
            path = directory / f"robot{robot.id}-lcd.png"
            Image.fromarray(lcd.screen().copy()).save(path)  # what the LCD shows
            paths.append(path)
    return paths
