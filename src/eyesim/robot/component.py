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

    def program_started(self) -> None:
        """A new program has taken the robot (its handshake): what belongs to the program before it,
        not to the robot, starts afresh."""

    # -- how it shows itself to the viewer, the recorder, the plots and the robot editor; these
    # name no component, so a new part kind shows up there with no edit to them -------------------
    recorded_ops: frozenset[int] = frozenset()  # RoBIOS op codes whose answers `recorded` keeps

    def overlay(self) -> list[dict]:
        """What the viewer draws of it now (scene setting VIS): lines from a common origin, each
        entry {"kind", "origin", "ends"} (world, m; `ends` flat x, y, z ...), optionally with its
        "color" (RGB 0..255) and its sensor id."""
        return []

    def signals(self) -> dict[str, tuple[float, str]]:
        """Values to plot, sampled with the robot's state: {name: (value, unit)}."""
        return {}

    def recorded(self, op: int, args: tuple, reply: tuple) -> tuple[str, object] | None:
        """What a recording keeps of a request the simulator answered (an op of `recorded_ops`):
        (its robot channel, a JSON object or an image's pixels), or None."""
        return None

    def editor_view(self) -> dict:
        """What the robot editor draws over the built robot; a list value adds to the list of
        that name (several PSDs), another value is the entry of that name."""
        return {}

    def readings(self) -> dict:
        """The robot editor's test drive: what it reads now, by the read-out's name."""
        return {}

    def settings_changed(self, settings) -> None:
        """The running scene's settings changed (the viewer's settings panel)."""


def named(reference: str):
    """What a declaration names as "module:name" (a drive's wheel component, a part's component
    factories): declarations below the physics name them instead of importing them."""
    module, name = reference.split(":")
    return getattr(importlib.import_module(module), name)
