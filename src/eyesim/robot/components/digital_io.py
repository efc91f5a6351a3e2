"""The I/O board's 16 digital lines: inputs the outside drives (viewer, scripts) or a part's switch
is wired to (a bumper), outputs the program sets."""

from __future__ import annotations

from typing import Callable

from eyesim.robot.component import Component

LINES = 16
DIRECTIONS = {"i": "input", "o": "output", "I": "input with pull-up", "J": "input with pull-down"}


class DigitalLines(Component):
    """Every line starts as a plain input. An input reads the level the outside drives; undriven,
    it reads 1 with a pull-up ('I') and 0 otherwise. An output reads what the program wrote. A
    line wired to a part reads the part's level as an input, whatever the outside drives."""

    noun = "digital I/O"

    def __init__(self):
        self.wired: dict[int, tuple[str, Callable[[], int]]] = {}  # index -> (the part, its level)
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
            raise ValueError(
                f"direction {direction!r} is not 'i' (input), 'o' (output), "
                f"'I' (input, pull-up) or 'J' (input, pull-down)"
            )
        if direction == "o" and index in self.wired:
            raise ValueError(f"digital line {line} is wired to {self.wired[index][0]}: it can only be an input")
        self.directions[index] = direction

    def write(self, line: int, level: int) -> None:
        index = self._index(line)
        if self.directions[index] != "o":
            raise ValueError(f"digital line {line} is an input; DIGITALSetup({line}, 'o') makes it an output")
        if level not in (0, 1):
            raise ValueError(f"level {level} is not 0 or 1")
        self.outputs[index] = level

    def wire(self, line: int, part: str, level: Callable[[], int]) -> None:
        """A part's switch is wired to an input line (once, while the robot is built)."""
        index = self._index(line)
        if index in self.wired:
            raise ValueError(f"digital line {line} is already wired to {self.wired[index][0]}")
        self.wired[index] = (part, level)

    def drive(self, line: int, level: int | None) -> None:
        """The outside puts a level on a line (None: lets go of it)."""
        index = self._index(line)
        if index in self.wired:
            raise ValueError(f"digital line {line} is wired to {self.wired[index][0]}; it cannot be driven")
        if level not in (0, 1, None):
            raise ValueError(f"level {level!r} is not 0, 1 or null (not driven)")
        self.driven[index] = level

    def read(self, line: int) -> int:
        index = self._index(line)
        if self.directions[index] == "o":
            return self.outputs[index]
        if index in self.wired:
            return self.wired[index][1]()
        driven = self.driven[index]
        if driven is not None:
            return driven
        return 1 if self.directions[index] == "I" else 0

    def read_all(self) -> int:
        return sum(self.read(line) << (line - 1) for line in range(1, LINES + 1))


def create(context) -> list[Component]:
    return [DigitalLines()]
