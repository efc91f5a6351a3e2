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
        self.emit({"type": "menu", "robot": robot.id, "labels": list(lcd.menu or ["", "", "", ""])})

    def console(self, robot_id: int, stream: str, text: str) -> None:
        self.emit({"type": "console", "robot": robot_id, "stream": stream, "text": text})

    def program(self, robot_id: int, event: str, name: str, exit_code: int | None) -> None:
        self.emit({"type": "program", "robot": robot_id, "event": event, "name": name, "exit_code": exit_code})
