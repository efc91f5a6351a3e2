"""What a test or a grader records during a run besides contacts: true paths, serial output and
sounds, radio messages. All are sampled or stamped on simulation time, so runs compare exactly."""

from __future__ import annotations

import math
from dataclasses import dataclass

from eyesim.robot.components.radio import Radio

PATH_PERIOD_US = 10_000  # a path point per robot every 10 ms of simulation time, as --record


@dataclass(frozen=True)
class PathPoint:
    """A true pose at a simulation time: s, mm, mm, degrees."""

    t: float
    x: float
    y: float
    phi: float


class PathRecorder:
    """A step observer keeping each robot's true pose every 10 ms (and at the start)."""

    def __init__(self, sim):
        self.paths: dict[int, list[PathPoint]] = {robot.id: [] for robot in sim.robots}
        self.sample(sim)

    def __call__(self, sim) -> None:
        if sim.time_us % PATH_PERIOD_US == 0:
            self.sample(sim)

    def sample(self, sim) -> None:
        for robot in sim.robots:
            x, y, _, yaw = robot.pose()
            self.paths[robot.id].append(PathPoint(sim.time, x * 1000, y * 1000, math.degrees(yaw)))


@dataclass(frozen=True)
class RadioMessage:
    time: float  # s of simulation time when it was sent
    sender: int
    receiver: int
    data: bytes


class RobotEvents:
    """An event listener (eyesim.core.events) keeping what robots send on serial interfaces, the
    sounds they play and program notices, stamped with the simulation time."""

    wants_lcd = False

    def __init__(self, sim):
        self.sim = sim
        self.serial: dict[tuple[int, int], bytearray] = {}
        self.sounds: list[dict] = []

    def on_event(self, message: dict) -> None:
        if message["type"] == "serial":
            key = (message["robot"], message["interface"])
            self.serial.setdefault(key, bytearray()).extend(message["text"].encode("latin-1"))
        elif message["type"] == "audio":
            self.sounds.append(dict(message, time=self.sim.time))

    def on_snapshot(self, message: dict) -> None:
        pass


def record_radio(sim) -> list[RadioMessage]:
    """Log every radio message robots send from now on (wraps each radio's delivery); returns
    the list the messages go into."""
    log: list[RadioMessage] = []
    for robot in sim.robots:
        radio = robot.component(Radio)
        if radio is None:
            continue

        def deliver(sender: int, message: bytes, radio=radio, receiver=robot.id, original=radio.deliver) -> bool:
            accepted = original(sender, message)
            if accepted:
                log.append(RadioMessage(sim.time, sender, receiver, bytes(message)))
            return accepted

        radio.deliver = deliver
    return log
