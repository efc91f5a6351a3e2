"""The interface every robot component implements (DESIGN.md, Contracts)."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from eyesim.physics.world import PhysicsWorld


class Component:
    """One part of a robot: a drive, a sensor, the LCD, ... Components never touch the network.

    Life cycle: created while the MuJoCo model is built (adding their bodies/actuators to the
    spec), `bind` once the model is compiled, `reset` to their initial state, then
    `before_step`/`after_step` around every physics step, `tick` after every step that ends a
    tick (10 ms of simulation time), and `publish` at each publish tick while someone shows LCD
    and camera images."""

    noun = ""  # what an error names a robot without it ("robot 1 (S4) has no LCD")

    def bind(self, world: PhysicsWorld) -> None:
        self.world = world

    def reset(self) -> None:
        pass

    def before_step(self, dt: float) -> None:
        pass

    def after_step(self, dt: float) -> None:
        pass

    def tick(self, dt: float) -> None:
        """Periodic work at 100 Hz (RoBIOS's timer rate: odometry, battery), so that it does not
        cost a call at every physics step; `dt` is the tick's length."""

    def publish(self, robot_id: int, events, again: bool) -> None:
        """Emit what changed since the last tick on `events` (eyesim.core.events); `again`: also what
        did not (a browser has just connected)."""


def named(reference: str):
    """What a declaration names as "module:name" (a drive's wheel component, a part's component
    factories): declarations below the physics name them instead of importing them."""
    module, name = reference.split(":")
    return getattr(importlib.import_module(module), name)
