"""Thrusters (submarines): each pushes along its own axis with MOTORDrive's percentage of its
maximum thrust, but only while it is under water. Motor numbers are the `thruster` lines' own."""

from __future__ import annotations

import math

import mujoco

from eyesim.parts.thrusters.declaration import ThrusterSpec
from eyesim.physics.units import mm
from eyesim.robot.actuators import ActuatorError
from eyesim.robot.component import Component


NO_SPEED_CONTROL = "is a thruster without an encoder: it has no speed control (use MOTORDrive)"


class Thruster:
    """A motor without an encoder: open loop only."""

    def __init__(self, spec: mujoco.MjSpec, body: mujoco.MjsBody, name: str, thruster: ThrusterSpec):
        self.name = name
        self.max_thrust = thruster.max_thrust  # N at 100 %
        length = math.sqrt(thruster.dx**2 + thruster.dy**2 + thruster.dz**2)
        body.add_site(name=name, pos=[mm(thruster.x), mm(thruster.y), mm(thruster.z)], size=[0.01, 0, 0], group=4)
        actuator = spec.add_actuator(name=name, target=name, trntype=mujoco.mjtTrn.mjTRN_SITE)
        actuator.gear = [thruster.dx / length, thruster.dy / length, thruster.dz / length, 0, 0, 0]
        self.thrust = 0.0  # N asked for

    def bind(self, world) -> None:
        self.data = world.data
        self.actuator = world.actuator_id(self.name)
        self.site = world.site_id(self.name)

    def drive(self, percent: float) -> None:
        self.thrust = percent / 100 * self.max_thrust

    def set_ticks_per_second(self, ticks: int) -> None:
        raise ActuatorError(NO_SPEED_CONTROL)

    def set_pid(self, p: int, i: int, d: int) -> None:
        raise ActuatorError(NO_SPEED_CONTROL)

    def pid_off(self) -> None:
        raise ActuatorError(NO_SPEED_CONTROL)


class Thrusters(Component):
    def __init__(self, context):
        self.motors = {
            t.motor: Thruster(context.spec, context.body, f"{context.prefix}/thruster{t.motor}", t)
            for t in context.robot_type.thrusters
        }

    def bind(self, world) -> None:
        super().bind(world)
        self.surface = world.water.surface if world.water is not None else -math.inf
        for thruster in self.motors.values():
            thruster.bind(world)

    def reset(self) -> None:
        for thruster in self.motors.values():
            thruster.thrust = 0.0

    def before_step(self, dt: float) -> None:
        data = self.world.data
        for thruster in self.motors.values():
            under_water = data.site_xpos[thruster.site][2] < self.surface
            data.ctrl[thruster.actuator] = thruster.thrust if under_water else 0.0


def create(context) -> list[Component]:
    return [Thrusters(context)] if context.robot_type.thrusters else []
