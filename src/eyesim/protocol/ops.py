"""The shape of one protocol operation, as the generated table describes it."""

from __future__ import annotations

from typing import NamedTuple


class OpSpec(NamedTuple):
    name: str
    code: int
    group: str
    cost_us: int  # virtual time the call costs in deterministic mode
    blocking: bool  # may be answered later (a pending reply)
    request: tuple[tuple[str, str], ...]  # (field name, type)
    reply: tuple[tuple[str, str], ...]
    # (request field index, low, high, unit): values outside are refused before any work
    ranges: tuple[tuple[int, int, int, str], ...] = ()
    # (request field index, most bytes): a longer str or bytes field is refused while decoding
    lengths: tuple[tuple[int, int], ...] = ()

    def out_of_range(self, args: tuple) -> str | None:
        """What is wrong with the request's values, or None when all are within their ranges."""
        for index, low, high, unit in self.ranges:
            value = args[index]
            if not low <= value <= high:
                return f"{self.request[index][0]} = {value} is outside {low}..{high} {unit}"
        return None
