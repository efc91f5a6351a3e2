"""Headless runs: what robots do outside their LCD — serial output and sounds — printed on stdout."""

from __future__ import annotations

import sys


class RobotLog:
    """An event listener (eyesim.core.events) that prints `[robot 1 serial 0] text` and
    `[robot 1 audio] beep, 0.2 s` lines; serial output is printed line by line."""

    wants_lcd = False

    def __init__(self, out=None):
        self.out = out or sys.stdout
        self.partial: dict[tuple[int, int], str] = {}  # serial text after the last newline

    def on_event(self, message: dict) -> None:
        if message["type"] == "serial":
            key = (message["robot"], message["interface"])
            *lines, self.partial[key] = (self.partial.get(key, "") + message["text"]).split("\n")
            for line in lines:
                self._print(f"[robot {key[0]} serial {key[1]}] {line}")
        elif message["type"] == "audio":
            what = "beep" if message["sound"] == "beep" else f"plays {message['name']}"
            self._print(f"[robot {message['robot']} audio] {what}, {message['duration']:g} s")

    def on_snapshot(self, message: dict) -> None:
        pass

    def flush(self) -> None:
        """Prints serial text that never got its newline (at the end of the run)."""
        for (robot, interface), text in sorted(self.partial.items()):
            if text:
                self._print(f"[robot {robot} serial {interface}] {text}")
        self.partial.clear()

    def _print(self, line: str) -> None:
        self.out.write(line + "\n")
        self.out.flush()
