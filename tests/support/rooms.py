"""Scene files written by tests (a walled square room, a .sim placing robots) and headless runs
of them whose program output is sorted by robot."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path


def square_room(size: int = 2000, color: tuple[int, int, int] | None = None) -> list[str]:
    """.wld lines of a walled square room: walls 10 mm thick, 300 mm high, centred on the edges."""
    paint = f" 10 300 {color[0]} {color[1]} {color[2]}" if color else ""
    return [
        f"floor {size} {size}",
        f"0 0 {size} 0{paint}",
        f"{size} 0 {size} {size}{paint}",
        f"{size} {size} 0 {size}{paint}",
        f"0 {size} 0 0{paint}",
    ]


def write_scene(
    directory: Path, world: list[str], placements: list[str], settings: str = "", extra: list[str] = ()
) -> Path:
    """A .sim file (and its .wld) in `directory`; returns the .sim path."""
    (directory / "room.wld").write_text("\n".join(world) + "\n")
    lines = ["world room.wld", *extra, *placements]
    if settings:
        lines.insert(1, f"settings {settings}")
    scene = directory / "scene.sim"
    scene.write_text("\n".join(lines) + "\n")
    return scene


class Run:
    """A finished headless run: exit code, and each robot's program output lines."""

    def __init__(self, result: subprocess.CompletedProcess):
        self.result = result
        self.returncode = result.returncode
        self.stdout, self.stderr = result.stdout, result.stderr

    def lines(self, robot: int, stream: str = "stdout") -> list[str]:
        prefix = f"[robot {robot}] "
        text = self.stdout if stream == "stdout" else self.stderr
        return [line[len(prefix) :] for line in text.splitlines() if line.startswith(prefix)]

    def values(self, robot: int, tag: str) -> list[list[int]]:
        """The numbers of every `<tag> n n n ...` line robot printed, in order."""
        found = []
        for line in self.lines(robot):
            words = line.split()
            if words and words[0] == tag:
                found.append([int(w) for w in words[1:] if re.fullmatch(r"-?\d+", w)])
        return found
