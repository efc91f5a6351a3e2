"""The shape of one protocol operation, as the generated table describes it."""

from __future__ import annotations

from typing import NamedTuple


LOCAL, DEVICE, WAIT = "local", "device", "wait"  # protocol.json's cost classes


class OpSpec(NamedTuple):
    name: str
    code: int
    group: str
    cost_us: int  # the op's own cost in simulation time (µs); see `cost`
    blocking: bool  # may be answered later (a pending reply)
    request: tuple[tuple[str, str], ...]  # (field name, type)
    reply: tuple[tuple[str, str], ...]
    # (request field index, low, high, unit): values outside are refused before any work
    ranges: tuple[tuple[int, int, int, str], ...] = ()
    # (request field index, most bytes): a longer str or bytes field is refused while decoding
    lengths: tuple[tuple[int, int], ...] = ()
    # What a call costs in simulation time (docs/protocol.md#what-a-call-costs): LOCAL, done by the
    # EyeBot itself, costs cost_us; DEVICE, reaching its hardware or the world, the call time or
    # cost_us when that is more; WAIT, a blocking call, only what it waits.
    cost: str = "device"
    # "Component.method" for an op that only calls that method of the robot's component (its
    # request's values the arguments) and has no handler of its own (eyesim/calls/__init__.py).
    calls: str = ""

    def out_of_range(self, args: tuple) -> str | None:
        """What is wrong with the request's values, or None when all are within their ranges."""
        for index, low, high, unit in self.ranges:
            value = args[index]
            if not low <= value <= high:
                return f"{self.request[index][0]} = {value} is outside {low}..{high} {unit}"
        return None
