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
