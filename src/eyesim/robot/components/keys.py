"""The four soft keys and the LCD's touch screen: presses and touches from the viewer or a script."""

from __future__ import annotations

from collections import deque

from eyesim.protocol.constants import KEY1, KEY2, KEY3, KEY4
from eyesim.robot.component import Component

KEYS = (KEY1, KEY2, KEY3, KEY4)
KEY_NAMES = {"KEY1": KEY1, "KEY2": KEY2, "KEY3": KEY3, "KEY4": KEY4}
MAX_WAITING = 256  # presses or touches nobody has read yet; older ones are dropped beyond this


class Keys(Component):
    """Each press is delivered exactly once, in order, to KEYGet, KEYRead or KEYWait; each touch
    (LCD pixel coordinates) once to KEYGetXY or KEYReadXY. A touch on the shown menu bar is a
    press of that soft key instead (see eyesim.core.robot_input.touch)."""

    noun = "keys"

    def __init__(self):
        self.presses: deque[int] = deque(maxlen=MAX_WAITING)
        self.touches: deque[tuple[int, int]] = deque(maxlen=MAX_WAITING)

    def reset(self) -> None:
        self.presses.clear()
        self.touches.clear()

    def press(self, key: int) -> None:
        if key not in KEYS:
            raise ValueError(f"not a soft key: {key}")
        self.presses.append(key)

    def take(self) -> int:
        """The oldest unread press, or 0 (NOKEY)."""
        return self.presses.popleft() if self.presses else 0

    def take_matching(self, mask: int) -> int:
        """The oldest press of a key in `mask`, or 0; presses of other keys are dropped (KEYWait)."""
        while self.presses:
            key = self.presses.popleft()
            if key & mask:
                return key
        return 0

    def touch(self, x: int, y: int) -> None:
        self.touches.append((x, y))

    def take_touch(self) -> tuple[int, int] | None:
        return self.touches.popleft() if self.touches else None


def create(context) -> list[Component]:
    return [Keys()]
