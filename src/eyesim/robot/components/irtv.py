"""The infrared remote-control receiver: codes from the viewer's remote, the keyboard or a script."""

from __future__ import annotations

from collections import deque

from eyesim.protocol import constants
from eyesim.robot.component import Component

# RoBIOS IRTV codes are characters; the remote's buttons by name (IRTV_OK -> OK: "O").
BUTTONS = {
    name.removeprefix("IRTV_"): chr(code) for name, code in constants.GROUPS["irtv"].items() if isinstance(code, int)
}
CODES = frozenset(ord(code) for code in BUTTONS.values())
MAX_WAITING = 64  # codes nobody has read yet; older ones are dropped beyond this


def code_of(text: str) -> int:
    """An IR code from a button name (OK, IRTV_OK) or its character (O)."""
    name = text.upper().removeprefix("IRTV_")
    if name in BUTTONS:
        return ord(BUTTONS[name])
    if len(text) == 1 and ord(text) in CODES:
        return ord(text)
    raise ValueError(
        f"{text!r} is not an IR remote button ({', '.join(BUTTONS)}) or code ({''.join(sorted(BUTTONS.values()))})"
    )


class IrReceiver(Component):
    """Each code is delivered once, in order, to IRTVGet or IRTVRead. The receiver is always on."""

    noun = "IR receiver"

    def __init__(self):
        self.codes: deque[int] = deque(maxlen=MAX_WAITING)

    def reset(self) -> None:
        self.codes.clear()

    def receive(self, code: int) -> None:
        if code not in CODES:
            raise ValueError(f"{code} is not an IR remote code")
        self.codes.append(code)

    def take(self) -> int:
        """The oldest unread code, or 0."""
        return self.codes.popleft() if self.codes else 0

    def flush(self) -> None:
        self.codes.clear()


def create(context) -> list[Component]:
    return [IrReceiver()]
