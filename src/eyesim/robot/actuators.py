"""Motors and servos as the MOTOR, ENCODER and SERVO functions see them, shared by the drive components.

A component that owns actuators lists them in its `motors`, `encoders` and `servos` dicts under
their RoBIOS numbers; the robot collects them (Robot.motors, .encoders, .servos), so the handlers
never need to know which component a number belongs to (docs/robots.md: the numbers per drive)."""

from __future__ import annotations

import math

import mujoco


class ActuatorError(Exception):
    """A command this actuator cannot carry out (a thruster has no encoder, ...); the handler
    turns it into an error reply."""


# -- wheel motors -------------------------------------------------------------------------------

SPEED_GAIN = 0.05  # N*m per rad/s: the built-in speed controller's proportional gain
DEFAULT_PID = (70, 0, 0)  # MOTORPID values the controller starts with (p scales SPEED_GAIN)
INTEGRAL_UNIT = 0.5  # 1/s per unit of the I gain: how fast the integral corrects a speed error
DERIVATIVE_UNIT = 0.0001  # s per unit of the D gain


class WheelMotor:
    """A geared motor with a quadrature encoder on a wheel's hinge joint, or on a fixed tendon (an
    axle with a differential: the tendon is the mean of its wheels' angles).

    Like EyeSim's motors, it runs under a fast speed controller: MuJoCo's velocity servo (stable at
    any gain, as it is integrated implicitly) pulls the wheel to its set point with at most `torque`.
    Open loop (MOTORDrive) the set point is the duty cycle times the no-load speed `max_speed`, so
    the wheel follows a command within a few hundredths of a second and 0 brakes it; closed loop
    (MOTORSpeed, VW) the set point is the asked speed, with the MOTORPID integral and derivative
    parts added here. The torque exceeds what a small robot's wheels can transmit: a full-power
    step spins them up at once and they slip until the robot catches up."""

    def __init__(
        self,
        spec: mujoco.MjSpec,
        name: str,
        target: str,
        transmission: mujoco.mjtTrn,
        ticks_per_rev: int,
        max_speed: float,
        torque: float,
    ):
        self.name = name
        self.transmission = transmission
        self.ticks_per_rev = ticks_per_rev
        self.ticks_per_radian = ticks_per_rev / (2 * math.pi)
        self.max_speed = max_speed  # rad/s
        self.torque = torque  # N*m the motor can give at most
        actuator = spec.add_actuator(name=name, target=target, trntype=transmission)
        actuator.gainprm[0] = SPEED_GAIN
        actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
        actuator.biasprm[2] = -SPEED_GAIN
        actuator.forcelimited = True
        actuator.forcerange = [-torque, torque]

    def bind(self, world) -> None:
        model, data = world.model, world.data
        self.model, self.data = model, data
        self.actuator = world.actuator_id(self.name)
        self._ctrl = data.ctrl  # the array itself: `data.ctrl` builds a new view at every access
        if self.transmission == mujoco.mjtTrn.mjTRN_JOINT:
            joint = model.actuator_trnid[self.actuator][0]
            self._angles, self._angle_index = data.qpos, int(model.jnt_qposadr[joint])
            self._speeds, self._speed_index = data.qvel, int(model.jnt_dofadr[joint])
        else:
            tendon = model.actuator_trnid[self.actuator][0]
            self._angles, self._angle_index = data.ten_length, int(tendon)
            self._speeds, self._speed_index = data.ten_velocity, int(tendon)

    def reset(self) -> None:
        self.encoder_offset = 0
        self.closed_loop = True
        self.target = 0.0  # rad/s in closed loop
        self.pid = DEFAULT_PID
        self.needs_update = False  # True while the integral or derivative part works every step
        self._integral = 0.0
        self._last_error = 0.0
        self._set_gain(SPEED_GAIN)
        self._ctrl[self.actuator] = 0.0

    def _set_gain(self, gain: float) -> None:
        self.model.actuator_gainprm[self.actuator, 0] = gain
        self.model.actuator_biasprm[self.actuator, 2] = -gain

    # -- state ---------------------------------------------------------------------------------
    @property
    def angle(self) -> float:
        return self._angles.item(self._angle_index)

    @property
    def speed(self) -> float:
        """rad/s; positive drives the robot forward."""
        return self._speeds.item(self._speed_index)

    def raw_ticks(self) -> int:
        # .item() gives a Python float: this runs every step for every robot.
        return math.floor(self._angles.item(self._angle_index) * self.ticks_per_radian)

    def encoder(self) -> int:
        """Ticks since the last ENCODERReset."""
        return self.raw_ticks() - self.encoder_offset

    def reset_encoder(self) -> None:
        self.encoder_offset = self.raw_ticks()

    # -- commands --------------------------------------------------------------------------------
    def drive(self, percent: float) -> None:
        """Open loop at `percent` (-100..100) of full power: that share of the no-load speed, under
        the motor's own fast speed controller (the MOTORPID gains do not apply)."""
        if self.closed_loop:
            self.closed_loop = self.needs_update = False
            self._set_gain(SPEED_GAIN)
        self.target = percent / 100 * self.max_speed
        self._ctrl[self.actuator] = self.target

    def set_speed(self, speed: float) -> None:
        """Closed loop at `speed` rad/s, clipped to the no-load speed."""
        if not self.closed_loop:
            self.closed_loop = True
            self.needs_update = self.pid[1] != 0 or self.pid[2] != 0
            self._integral = self._last_error = 0.0
            self._set_gain(SPEED_GAIN * max(self.pid[0], 1) / DEFAULT_PID[0])
        limit = self.max_speed
        self.target = limit if speed > limit else -limit if speed < -limit else speed
        self._ctrl[self.actuator] = self.target + self._integral

    def set_ticks_per_second(self, ticks: int) -> None:
        """Closed loop at an encoder speed (MOTORSpeed); ValueError beyond the no-load speed."""
        limit = round(self.max_speed * self.ticks_per_radian)
        if abs(ticks) > limit:
            raise ValueError(f"speed {ticks} ticks/s is out of range -{limit}..{limit} (the motor's no-load speed)")
        self.set_speed(ticks * 2 * math.pi / self.ticks_per_rev)

    def set_pid(self, p: int, i: int, d: int) -> None:
        """New controller gains; the motor holds its current speed set point under them."""
        self.pid = (p, i, d)
        self._integral = self._last_error = 0.0
        if self.closed_loop:
            self.needs_update = i != 0 or d != 0
            self._set_gain(SPEED_GAIN * max(p, 1) / DEFAULT_PID[0])
        else:
            self.set_speed(0.0)

    def pid_off(self) -> None:
        """Back to open loop at 0 %: the motor brakes the wheel to a stop."""
        self.pid = DEFAULT_PID
        self.drive(0.0)

    def update(self, dt: float) -> None:
        """The integral and derivative parts of the speed controller (call every step)."""
        error = self.target - self.speed
        self._integral += self.pid[1] * INTEGRAL_UNIT * error * dt
        self._integral = max(-self.max_speed, min(self.max_speed, self._integral))
        derivative = self.pid[2] * DERIVATIVE_UNIT * (error - self._last_error) / dt
        self._last_error = error
        self._ctrl[self.actuator] = self.target + self._integral + derivative


# -- servos ----------------------------------------------------------------------------------------

SERVO_MAX = 255  # SERVOSet positions run 0..255


class Servo:
    """A hobby servo: SERVOSet positions 0..255 map linearly onto the range it moves (radians or
    metres, from `low_value` at 0 to `high_value` at 255), and it moves there at `rate` units per
    second. Subclasses may map differently (`value_of`) or start elsewhere (`neutral_raw`).

    SERVORange(low, high) narrows the raw positions SERVOSet uses: SERVOSet(v) goes to the raw
    position low + v * (high - low) / 255, while SERVOSetRaw(v) goes to raw v itself."""

    def __init__(self, number: int, low_value: float, high_value: float, rate: float):
        self.number = number
        self.low_value, self.high_value = low_value, high_value  # what raw 0 and raw 255 mean
        self.rate = rate  # units per second
        self.reset_servo()

    def reset_servo(self) -> None:
        self.range = (0, SERVO_MAX)
        self.goal = self.value_of(self.neutral_raw())
        self.position = self.goal  # where the servo's output shaft is commanded to be now

    def neutral_raw(self) -> float:
        """The raw position a servo starts at (subclasses: e.g. straight ahead)."""
        return 0.0

    def value_of(self, raw: float) -> float:
        return self.low_value + (self.high_value - self.low_value) * raw / SERVO_MAX

    def set(self, position: int) -> None:
        low, high = self.range
        self.set_raw(low + (high - low) * position / SERVO_MAX)

    def set_raw(self, raw: float) -> None:
        self.goal = self.value_of(raw)

    def set_range(self, low: int, high: int) -> None:
        self.range = (low, high)

    @property
    def moving(self) -> bool:
        return self.position != self.goal

    def advance(self, dt: float) -> float:
        """Move the commanded position towards the goal by one step; returns it."""
        step = self.rate * dt
        if abs(self.goal - self.position) <= step:
            self.position = self.goal
        else:
            self.position += step if self.goal > self.position else -step
        return self.position
