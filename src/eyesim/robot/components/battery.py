"""The robot's battery: drained by the controller and by every motor of the robot, its voltage falls."""

from __future__ import annotations

import mujoco

from eyesim.robot.component import Component

FULL_VOLTS, EMPTY_VOLTS = 8.4, 6.8  # a 2-cell lithium battery, charged and flat
CAPACITY_J = 2.2 * 7.4 * 3600  # 2.2 Ah at 7.4 V nominal
CONTROLLER_WATTS = 4.0  # the computer and its LCD: a full battery lasts about 4 hours idle
MOTOR_EFFICIENCY = 0.6  # electrical power = mechanical power / efficiency
SAMPLE_STEPS = 5  # motor power is sampled every 5 physics steps (10 ms): the voltage changes slowly


class Battery(Component):
    """Voltage falls linearly with the energy used, from FULL_VOLTS to EMPTY_VOLTS. Motors use
    what their actuators deliver (|force x velocity|), so driving drains faster than standing."""

    def __init__(self, context):
        self.prefix = context.prefix + "/"
        self.energy_j = CAPACITY_J
        self.steps = 0

    def bind(self, world) -> None:
        super().bind(world)
        model = world.model
        self.actuators = [i for i in range(model.nu)
                          if (mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, i) or "").startswith(self.prefix)]
        # The arrays themselves: `data.actuator_force` builds a new view at every access.
        self._force, self._velocity = world.data.actuator_force, world.data.actuator_velocity

    def reset(self) -> None:
        self.energy_j = CAPACITY_J
        self.steps = 0

    def after_step(self, dt: float) -> None:
        # Sampled, with plain floats: this runs for every robot at every step, and numpy
        # temporaries for two actuators would cost more than the physics of the robot.
        self.steps += 1
        if self.steps < SAMPLE_STEPS:
            return
        self.steps = 0
        force, velocity = self._force, self._velocity
        motors = 0.0
        for i in self.actuators:
            motors += abs(force.item(i) * velocity.item(i))
        used = (CONTROLLER_WATTS + motors / MOTOR_EFFICIENCY) * dt * SAMPLE_STEPS
        self.energy_j = max(0.0, self.energy_j - used)

    @property
    def volts(self) -> float:
        return EMPTY_VOLTS + (FULL_VOLTS - EMPTY_VOLTS) * self.energy_j / CAPACITY_J


def create(context) -> list[Component]:
    return [Battery(context)]
