"""Headless runs: what robots do outside their LCD — serial output and sounds — printed on stdout."""

from __future__ import annotations

import sys


LINE_LIMIT = 4096  # characters of serial text without a newline printed as one line (memory stays bounded)


class RobotLog:
    """An event listener (eyesim.core.events) that prints `[robot 1 serial 0] text` and
    `[robot 1 audio] beep, 0.2 s` lines; serial output is printed line by line, and a line longer
    than LINE_LIMIT in parts of that length."""

    wants_lcd = False

    def __init__(self, out=None):
        self.out = out or sys.stdout
        # serial text after the last newline, in the pieces it came in (joined once, when printed)
        self.partial: dict[tuple[int, int], list[str]] = {}
        self.partial_length: dict[tuple[int, int], int] = {}

    def on_event(self, message: dict) -> None:
        if message["type"] == "serial":
            self._serial((message["robot"], message["interface"]), message["text"])
        elif message["type"] == "audio":
            what = "beep" if message["sound"] == "beep" else f"plays {message['name']}"
            self._print(f"[robot {message['robot']} audio] {what}, {message['duration']:g} s")

    def on_snapshot(self, message: dict) -> None:
        pass

    def _serial(self, key: tuple[int, int], text: str) -> None:
        pieces = self.partial.setdefault(key, [])
        *ends, rest = text.split("\n")
        for end in ends:
            pieces.append(end)
            self._print_line(key)
        while rest:
            room = LINE_LIMIT - self.partial_length.get(key, 0)
            pieces.append(rest[:room])
            self.partial_length[key] = self.partial_length.get(key, 0) + len(rest[:room])
            rest = rest[room:]
            if self.partial_length[key] >= LINE_LIMIT:
                self._print_line(key)

    def _print_line(self, key: tuple[int, int]) -> None:
        self._print(f"[robot {key[0]} serial {key[1]}] {''.join(self.partial[key])}")
        self.partial[key].clear()
        self.partial_length[key] = 0

    def flush(self) -> None:
        """Prints serial text that never got its newline (at the end of the run)."""
        for key, pieces in sorted(self.partial.items()):
            if pieces:
                self._print_line(key)
        self.partial.clear()
        self.partial_length.clear()

    def _print(self, line: str) -> None:
        self.out.write(line + "\n")
        self.out.flush()
