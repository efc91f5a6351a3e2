"""What the simulation tells its observers (the viewer, the console): events and snapshots.

Messages follow docs/viewer-channel.md and are built by eyesim/viewer/messages.py and plain_messages.py; `lcd`, `camera`,
`reset`, `input` and `edit` are events of the simulation that listeners turn into what they need. Events are ordered and never dropped; snapshots replace
each other. Listeners are called on the simulation thread and must return quickly."""

from __future__ import annotations

from typing import Protocol

from eyesim.viewer import messages, plain_messages


class Listener(Protocol):
    wants_lcd: bool  # LCD images cost a copy per change; only made when someone shows them

    def on_event(self, message: dict) -> None: ...

    def on_snapshot(self, message: dict) -> None: ...


class EventBus:
    def __init__(self):
        self.listeners: list[Listener] = []

    def subscribe(self, listener: Listener) -> None:
        self.listeners.append(listener)

    def unsubscribe(self, listener: Listener) -> None:
        self.listeners.remove(listener)

    @property
    def wants_lcd(self) -> bool:
        return any(listener.wants_lcd for listener in self.listeners)

    def emit(self, message: dict) -> None:
        for listener in self.listeners:
            listener.on_event(message)

    def snapshot(self, sim) -> None:
        """A publish tick: every listener gets where everything is now."""
        message = messages.snapshot(sim)
        for listener in self.listeners:
            listener.on_snapshot(message)

    # -- the event kinds (their messages: eyesim/viewer/messages.py, plain_messages.py) -----------
    def reset(self) -> None:
        """The world went back to the scene's initial state."""
        self.emit({"type": "reset"})

    def lcd(self, robot_id: int, pixels) -> None:
        """The LCD shows something new (`pixels`: a copy); the viewer encodes it off this thread."""
        self.emit({"type": "lcd", "robot": robot_id, "pixels": pixels})

    def camera(self, robot_id: int, pixels) -> None:
        """The robot's program took a new camera image."""
        self.emit({"type": "camera", "robot": robot_id, "pixels": pixels})

    def menu(self, robot) -> None:
        self.emit(messages.menu(robot))

    def console(self, robot_id: int, stream: str, text: str) -> None:
        self.emit(plain_messages.console(robot_id, stream, text))

    def program(self, robot_id: int, event: str, name: str, exit_code: int | None) -> None:
        self.emit(plain_messages.program(robot_id, event, name, exit_code))

    def serial(self, robot_id: int, interface: int, data: bytes) -> None:
        self.emit(plain_messages.serial(robot_id, interface, data))

    def sound(self, robot_id: int, sound: dict) -> None:
        self.emit(plain_messages.audio(robot_id, sound))

    def input(self, robot_id: int, kind: str, **values) -> None:
        """Input from outside (key, touch, irtv, serial, digital, analog): for recorders, not browsers."""
        self.emit({"type": "input", "robot": robot_id, "input": kind, **values})

    def edit(self, **change) -> None:
        """A change to the scene from outside (the viewer's `place`): for recorders, not browsers."""
        self.emit({"type": "edit", **change})

    def io(self, robot) -> None:
        message = messages.robot_io(robot)
        if message is not None:
            self.emit(message)
