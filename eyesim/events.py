"""What the simulation tells its observers (the viewer, the console): events and snapshots.

Messages follow docs/viewer-channel.md. Events are ordered and never dropped; snapshots replace
each other. Listeners are called on the simulation thread and must return quickly."""

from __future__ import annotations

from typing import Protocol


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

    def snapshot(self, message: dict) -> None:
        for listener in self.listeners:
            listener.on_snapshot(message)

    # -- the event kinds ---------------------------------------------------------------------
    def menu(self, robot) -> None:
        from eyesim.robot.components.lcd import Lcd

        lcd = robot.component(Lcd)
        self.emit({"type": "menu", "robot": robot.id, "labels": list(lcd.menu or ["", "", "", ""]),
                   "visible": lcd.menu_visible, "rotated": lcd.rotated})

    def console(self, robot_id: int, stream: str, text: str) -> None:
        self.emit({"type": "console", "robot": robot_id, "stream": stream, "text": text})

    def program(self, robot_id: int, event: str, name: str, exit_code: int | None) -> None:
        self.emit({"type": "program", "robot": robot_id, "event": event, "name": name, "exit_code": exit_code})

    def serial(self, robot_id: int, interface: int, data: bytes) -> None:
        # Bytes as text one to one (Latin-1), so any byte survives JSON.
        self.emit({"type": "serial", "robot": robot_id, "interface": interface, "text": data.decode("latin-1")})

    def sound(self, robot_id: int, sound: dict) -> None:
        self.emit({"type": "audio", "robot": robot_id, **sound})

    def input(self, robot_id: int, kind: str, **values) -> None:
        """Input from outside (key, touch, irtv, serial, digital, analog): for recorders, not browsers."""
        self.emit({"type": "input", "robot": robot_id, "input": kind, **values})

    def edit(self, **change) -> None:
        """A change to the scene from outside (the viewer's `place`): for recorders, not browsers."""
        self.emit({"type": "edit", **change})

    def io(self, robot) -> None:
        from eyesim.robot.components.analog_io import AnalogInputs
        from eyesim.robot.components.digital_io import LINES, DigitalLines

        digital, analog = robot.component(DigitalLines), robot.component(AnalogInputs)
        if digital is None or analog is None:
            return
        lines = [{"direction": digital.directions[k], "level": digital.read(k + 1), "driven": digital.driven[k]}
                 for k in range(LINES)]
        self.emit({"type": "io", "robot": robot.id, "digital": lines, "analog": list(analog.values)})
