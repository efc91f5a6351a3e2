"""Progress of a grading run on stderr: a bar redrawn in place on a terminal, plain lines
(one per finished case) when the output goes to a file or a CI log."""

from __future__ import annotations

import sys
import time


class Progress:
    def __init__(self, total: int, stream=None, width: int = 30):
        self.total = total
        self.done = 0
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.width = width
        self.started = time.monotonic()

    def advance(self, result: dict, reused: bool = False) -> None:
        self.done += 1
        what = f"{result['student']}/{result['case']}: {_summary(result)}" + (" (stored earlier)" if reused else "")
        if self.tty:
            filled = self.width * self.done // max(self.total, 1)
            bar = "#" * filled + "-" * (self.width - filled)
            elapsed = time.monotonic() - self.started
            self.stream.write(f"\r\033[K[{bar}] {self.done}/{self.total} {elapsed:5.0f} s  {what}"[:200])
            if self.done == self.total:
                self.stream.write("\n")
        else:
            self.stream.write(f"[{self.done}/{self.total}] {what}\n")
        self.stream.flush()

    def message(self, text: str) -> None:
        self.stream.write(("\r\033[K" if self.tty else "") + text + "\n")
        self.stream.flush()


def _summary(result: dict) -> str:
    status = result["status"]
    score = f"{100 * result['score']:.0f}%"
    if result.get("hung"):
        return f"{score} ({result['hung']})"
    return score if status == "ok" else f"{score} ({status.replace('_', ' ')})"
