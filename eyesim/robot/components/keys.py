"""The four soft keys: presses from the viewer or a script, consumed by KEYGet/KEYRead."""

from __future__ import annotations

from collections import deque

from eyesim.robot.component import Component

KEY1, KEY2, KEY3, KEY4 = 0x1, 0x2, 0x4, 0x8
KEYS = (KEY1, KEY2, KEY3, KEY4)
KEY_NAMES = {"KEY1": KEY1, "KEY2": KEY2, "KEY3": KEY3, "KEY4": KEY4}


class Keys(Component):
    """Each press is delivered exactly once, in order, to KEYGet or KEYRead."""

    kind = "keys"

    def __init__(self):
        self.presses: deque[int] = deque()

    def reset(self) -> None:
        self.presses.clear()

    def press(self, key: int) -> None:
        if key not in KEYS:
            raise ValueError(f"not a soft key: {key}")
        self.presses.append(key)

    def take(self) -> int:
        """The oldest unread press, or 0 (NOKEY)."""
        return self.presses.popleft() if self.presses else 0


def create(context) -> list[Component]:
    return [Keys()]
