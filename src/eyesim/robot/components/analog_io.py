"""The I/O board's 8 analog inputs (10-bit), channel 8 being the microphone, and 1 kHz recording."""

from __future__ import annotations

import bisect
from dataclasses import dataclass, field

from eyesim.robot.component import Component

CHANNELS = 8
MICROPHONE = 8
MAX_VALUE = 1023  # 10-bit converter
SILENCE = 512  # what the microphone reads in a quiet room: the middle of its range
MAX_SAMPLES = 100_000  # ANALOGRecord iterations (100 s at 1 kHz)
SAMPLE_US = 1000  # 1 kHz


@dataclass
class Recording:
    channel: int
    start_us: int
    count: int
    changes: list[tuple[int, int]] = field(default_factory=list)  # (time_us, value) of the channel

    @property
    def end_us(self) -> int:
        return self.start_us + self.count * SAMPLE_US

    def samples(self) -> bytes:
        """Sample k is the channel's value at start + k ms; 2 bytes each, little-endian."""
        times = [time for time, _ in self.changes]
        data = bytearray()
        for k in range(self.count):
            latest = bisect.bisect_right(times, self.start_us + k * SAMPLE_US) - 1
            data += self.changes[max(latest, 0)][1].to_bytes(2, "little")
        return bytes(data)


class AnalogInputs(Component):
    """Values are set from outside (viewer, scripts) and stay until changed."""

    noun = "analog inputs"

    def __init__(self):
        self.reset()

    def reset(self) -> None:
        self.values = [0] * CHANNELS
        self.values[MICROPHONE - 1] = SILENCE
        self.recording: Recording | None = None

    def _index(self, channel: int) -> int:
        if not 1 <= channel <= CHANNELS:
            raise ValueError(f"analog channel {channel} is not 1..{CHANNELS}")
        return channel - 1

    def read(self, channel: int) -> int:
        return self.values[self._index(channel)]

    def set_value(self, channel: int, value: int, at_us: int) -> None:
        index = self._index(channel)
        if not 0 <= value <= MAX_VALUE:
            raise ValueError(f"analog value {value} is outside 0..{MAX_VALUE}")
        self.values[index] = value
        if self.recording is not None and self.recording.channel == channel:
            self.recording.changes.append((max(at_us, self.recording.start_us), value))

    def start_recording(self, channel: int, count: int, now_us: int) -> None:
        index = self._index(channel)
        if not 1 <= count <= MAX_SAMPLES:
            raise ValueError(f"{count} samples is outside 1..{MAX_SAMPLES}")
        self.recording = Recording(channel, now_us, count, [(now_us, self.values[index])])


def create(context) -> list[Component]:
    return [AnalogInputs()]
