"""The robot's speaker and microphone: what plays and until when (AUBeep, AUPlay, AUDone)."""

from __future__ import annotations

from eyesim.robot.component import Component

BEEP_SECONDS = 0.2
BEEP_HERTZ = 1000


class Speaker(Component):
    """One sound at a time: a new beep or file replaces the one playing. Playing takes simulation
    time; the viewer plays the same sound for the user."""

    def __init__(self):
        self.playing_until_us = 0

    def reset(self) -> None:
        self.playing_until_us = 0

    def play(self, seconds: float, now_us: int) -> None:
        self.playing_until_us = now_us + round(seconds * 1e6)

    def done(self, now_us: int) -> bool:
        return now_us >= self.playing_until_us


def create(context) -> list[Component]:
    return [Speaker()]
