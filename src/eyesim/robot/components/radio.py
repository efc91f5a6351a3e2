"""The robot's radio: who switched it on, and the messages other robots sent it, oldest first."""

from __future__ import annotations

from collections import deque

from eyesim.protocol import generated as g
from eyesim.robot.component import Component

MAX_MESSAGE = dict(g.OPS[g.OP_RADIO_SEND].lengths)[1]  # bytes in one message (protocol.json: longer ones are refused)
MAX_WAITING = 1024  # messages a robot's inbox holds; sending to a full inbox fails


class Radio(Component):
    """The radio is on while the program that called RADIOInit is connected (`owner` is that
    program's session, anything with a `closed` flag), so it goes off when the program ends.

    Messages wait in the inbox until a program reads them, whether or not the radio was on when
    they were sent: a robot whose program starts a moment later loses nothing."""

    def __init__(self):
        self.inbox: deque[tuple[int, bytes]] = deque()
        self.owner = None

    def reset(self) -> None:
        self.inbox.clear()  # the world starts again; a connected program's radio stays on

    @property
    def on(self) -> bool:
        return self.owner is not None and not self.owner.closed

    def deliver(self, sender: int, message: bytes) -> bool:
        """Queue a message; False when the inbox is full."""
        if len(self.inbox) >= MAX_WAITING:
            return False
        self.inbox.append((sender, message))
        return True

    def take(self) -> tuple[int, bytes] | None:
        return self.inbox.popleft() if self.inbox else None


def create(context) -> list[Component]:
    return [Radio()]
