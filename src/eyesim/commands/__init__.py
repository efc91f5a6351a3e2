"""Registry of RoBIOS operations: one handler module per RoBIOS group, looked up by op code.

The groups are protocol.json's: the operations of group `psd` are handled by the HANDLERS table
of `eyesim.commands.psd`, so a new group is one new module here and needs no registry line (the
session group, the handshake, is the engine's own).

A handler is `handler(sim, robot, request) -> reply values | Pending`; it raises CommandError for
requests it cannot serve. The network layer never knows what an operation means."""

from __future__ import annotations

import importlib

from eyesim.commands.errors import CommandError
from eyesim.protocol import generated

ENGINE_GROUP = "session"  # HELLO and THREADS: answered by the engine itself


def _build_registry() -> dict:
    registry = {}
    for group in sorted({op.group for op in generated.OPS.values()} - {ENGINE_GROUP}):
        module = importlib.import_module(f"{__name__}.{group}")
        for name, handler in module.HANDLERS.items():
            op = generated.OPS_BY_NAME[name]
            if op.group != group:
                raise RuntimeError(f"{module.__name__} handles {name}, an operation of group {op.group}")
            registry[op.code] = handler
    return registry


HANDLERS = _build_registry()

__all__ = ["HANDLERS", "CommandError"]
