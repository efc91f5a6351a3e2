"""The robot's battery: drained by the controller and by every motor of the robot, its voltage falls."""

from __future__ import annotations

import mujoco

from eyesim.robot.component import Component

FULL_VOLTS, EMPTY_VOLTS = 8.4, 6.8  # a 2-cell lithium battery, charged and flat
CAPACITY_J = 2.2 * 7.4 * 3600  # 2.2 Ah at 7.4 V nominal
CONTROLLER_WATTS = 4.0  # the computer and its LCD: a full battery lasts about 4 hours idle
MOTOR_EFFICIENCY = 0.6  # electrical power = mechanical power / efficiency


class Battery(Component):
    """Voltage falls linearly with the energy used, from FULL_VOLTS to EMPTY_VOLTS. Motors use
    what their actuators deliver (|force x velocity|), so driving drains faster than standing."""

    def __init__(self, context):
        self.prefix = context.prefix + "/"
        self.energy_j = CAPACITY_J

    def bind(self, world) -> None:
        super().bind(world)
        model = world.model
        self.actuators = [
            i
            for i in range(model.nu)
            if (mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, i) or "").startswith(self.prefix)
        ]
        # The arrays themselves: `data.actuator_force` builds a new view at every access.
        self._force, self._velocity = world.data.actuator_force, world.data.actuator_velocity

    def reset(self) -> None:
        self.energy_j = CAPACITY_J

    def tick(self, dt: float) -> None:
        # Motor power sampled at the components' tick (100 Hz: the voltage changes slowly), with
        # plain floats: numpy temporaries for two actuators would cost more than the robot's physics.
        force, velocity = self._force, self._velocity
        motors = 0.0
        for i in self.actuators:
            motors += abs(force.item(i) * velocity.item(i))
        used = (CONTROLLER_WATTS + motors / MOTOR_EFFICIENCY) * dt
        self.energy_j = max(0.0, self.energy_j - used)

    @property
    def volts(self) -> float:
        return EMPTY_VOLTS + (FULL_VOLTS - EMPTY_VOLTS) * self.energy_j / CAPACITY_J


def create(context) -> list[Component]:
    return [Battery(context)]
