"""A connected program: its connection, the robot it drives and its place in simulated time."""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field
from typing import Callable, Protocol

from eyesim.protocol.ops import OpSpec


class Connection(Protocol):
    """What the engine needs from a transport: thread-safe sending and closing."""

    def send(self, data: bytes) -> None: ...

    def close(self) -> None: ...


@dataclass
class Request:
    """A decoded request waiting for, or being handled by, the simulation thread."""

    session: "Session"
    op: OpSpec
    request_id: int
    args: tuple
    time_us: int = 0  # simulation time at which it is handled


class Pending:
    """A reply that comes later (DESIGN.md: blocking calls never block the simulation thread).

    `poll(at_us)` returns the reply values once the condition holds at simulation time `at_us`,
    else None. `wake_us` is set for purely time-based waits (OSWait), so deterministic mode can
    resume them between physics steps, at exactly the time asked for."""

    def __init__(self, poll: Callable[[int], tuple | None], wake_us: int | None = None):
        self.poll = poll
        self.wake_us = wake_us

    @classmethod
    def until(cls, wake_us: int, reply: tuple) -> "Pending":
        return cls(lambda at_us: reply if at_us >= wake_us else None, wake_us)


@dataclass
class Session:
    connection: Connection
    peer: str = ""
    robot: object | None = None  # the Robot, once the handshake bound one
    program: str = ""
    pid: int = 0
    local_time_us: int = 0  # the program's own clock in deterministic mode
    queued: deque = field(default_factory=deque)  # requests waiting for their turn (deterministic)
    pending: list = field(default_factory=list)  # (Request, Pending) answered later
    closed: bool = False

    @property
    def name(self) -> str:
        robot = f"robot {self.robot.id}" if self.robot is not None else "no robot"
        return f"{self.program or 'program'} ({robot}, {self.peer})"
