"""The I/O board's 16 digital lines: inputs the outside drives (viewer, scripts), outputs the program sets."""

from __future__ import annotations

from eyesim.robot.component import Component

LINES = 16
DIRECTIONS = {"i": "input", "o": "output", "I": "input with pull-up", "J": "input with pull-down"}


class DigitalLines(Component):
    """Every line starts as a plain input. An input reads the level the outside drives; undriven,
    it reads 1 with a pull-up ('I') and 0 otherwise. An output reads what the program wrote."""

    noun = "digital I/O"

    def __init__(self):
        self.reset()

    def reset(self) -> None:
        self.directions = ["i"] * LINES
        self.outputs = [0] * LINES
        self.driven: list[int | None] = [None] * LINES  # levels from outside; None = not driven

    def _index(self, line: int) -> int:
        if not 1 <= line <= LINES:
            raise ValueError(f"digital line {line} is not 1..{LINES}")
        return line - 1

    def setup(self, line: int, direction: str) -> None:
        index = self._index(line)
        if direction not in DIRECTIONS:
            raise ValueError(f"direction {direction!r} is not 'i' (input), 'o' (output), "
                             f"'I' (input, pull-up) or 'J' (input, pull-down)")
        self.directions[index] = direction

    def write(self, line: int, level: int) -> None:
        index = self._index(line)
        if self.directions[index] != "o":
            raise ValueError(f"digital line {line} is an input; DIGITALSetup({line}, 'o') makes it an output")
        if level not in (0, 1):
            raise ValueError(f"level {level} is not 0 or 1")
        self.outputs[index] = level

    def drive(self, line: int, level: int | None) -> None:
        """The outside puts a level on a line (None: lets go of it)."""
        index = self._index(line)
        if level not in (0, 1, None):
            raise ValueError(f"level {level!r} is not 0, 1 or null (not driven)")
        self.driven[index] = level

    def read(self, line: int) -> int:
        index = self._index(line)
        if self.directions[index] == "o":
            return self.outputs[index]
        if self.driven[index] is not None:
            return self.driven[index]
        return 1 if self.directions[index] == "I" else 0

    def read_all(self) -> int:
        return sum(self.read(line) << (line - 1) for line in range(1, LINES + 1))


def create(context) -> list[Component]:
    return [DigitalLines()]
