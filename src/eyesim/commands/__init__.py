"""Registry of RoBIOS operations: one handler module per RoBIOS group, looked up by op code.

A handler is `handler(sim, robot, request) -> reply values | Pending`; it raises CommandError for
requests it cannot serve. The network layer never knows what an operation means."""

from __future__ import annotations

from eyesim.commands import audio
from eyesim.commands import io
from eyesim.commands import irtv
from eyesim.commands import cam
from eyesim.commands import key  # one import and one GROUP_MODULES line per group module
from eyesim.commands import lcd
from eyesim.commands import lidar
from eyesim.commands import motor
from eyesim.commands import os
from eyesim.commands import psd
from eyesim.commands import radio
from eyesim.commands import ser
from eyesim.commands import servo
from eyesim.commands import sim
from eyesim.commands import timer
from eyesim.commands import vw
from eyesim.commands.errors import CommandError
from eyesim.protocol import generated

GROUP_MODULES = (
    lcd,
    key,
    os,
    timer,
    ser,
    audio,
    psd,
    lidar,
    servo,
    motor,
    cam,
    radio,
    vw,
    io,
    irtv,
    sim,
)


def _build_registry() -> dict:
    registry = {}
    for module in GROUP_MODULES:
        for name, handler in module.HANDLERS.items():
            op = generated.OPS_BY_NAME[name]
            if op.code in registry:
                raise RuntimeError(f"operation {name} has two handlers")
            registry[op.code] = handler
    return registry


HANDLERS = _build_registry()

__all__ = ["HANDLERS", "CommandError"]
