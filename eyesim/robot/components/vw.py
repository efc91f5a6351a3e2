"""V-omega driving for a differential drive: speed control, straight/turn manoeuvres, odometry.

The controller closes its loop on the simulated encoders, as on the real robot; the odometry it
integrates from them (VWGetPosition) drifts with wheel slip, unlike the true pose (SIMGetRobot)."""

from __future__ import annotations

import math

from eyesim.robot.component import Component
from eyesim.robot.components.differential_drive import DifferentialDrive

LINEAR_ACCEL = 1.0  # m/s^2 the controller ramps linear speed by (keeps the wheels from slipping)
BRAKE_FRACTION = 0.5  # of the acceleration used to plan the stop, leaving headroom for lag
MIN_APPROACH_SPEED = 0.004  # m/s: the crawl speed that finishes a manoeuvre without stalling short
DISTANCE_TOLERANCE = 0.0002  # m
HEADING_GAIN = 8.0  # 1/s: how hard a straight run corrects its heading


class VwController(Component):
    kind = "vw"

    def __init__(self, drive: DifferentialDrive):
        self.drive = drive
        self.reset()

    def reset(self) -> None:
        self.v = 0.0  # commanded speed after ramping, m/s
        self.w = 0.0  # rad/s
        self.target_v = 0.0
        self.target_w = 0.0
        self.manoeuvre: dict | None = None
        self.odometry = [0.0, 0.0, 0.0]  # x, y (m), phi (rad) since start or VWSetPosition
        self.last_ticks: tuple[int, int] | None = None

    # -- geometry ----------------------------------------------------------------------------
    @property
    def metres_per_tick(self) -> float:
        return 2 * math.pi * self.drive.radius / self.drive.ticks_per_rev

    def _progress(self) -> tuple[float, float]:
        """Distance (m) and rotation (rad) since the manoeuvre started, from the encoders."""
        start = self.manoeuvre["start_ticks"]
        left = (self.drive.raw_ticks(0) - start[0]) * self.metres_per_tick
        right = (self.drive.raw_ticks(1) - start[1]) * self.metres_per_tick
        return (left + right) / 2, (right - left) / self.drive.track

    # -- commands (from the VW handlers) -----------------------------------------------------
    def set_speed(self, v: float, w: float) -> None:
        self.manoeuvre = None
        self.target_v, self.target_w = v, w

    def straight(self, distance: float, speed: float) -> None:
        self._start("straight", distance, abs(speed))

    def turn(self, angle: float, speed: float) -> None:
        self._start("turn", angle, abs(speed))

    def _start(self, kind: str, amount: float, speed: float) -> None:
        self.manoeuvre = {"kind": kind, "amount": abs(amount), "sign": 1.0 if amount >= 0 else -1.0,
                          "speed": speed, "start_ticks": (self.drive.raw_ticks(0), self.drive.raw_ticks(1))}
        if abs(amount) == 0 or speed == 0:
            self._finish()

    def _finish(self) -> None:
        self.manoeuvre = None
        self.target_v = self.target_w = 0.0

    @property
    def done(self) -> bool:
        return self.manoeuvre is None

    def remaining(self) -> float:
        """What is left of the manoeuvre: metres for straight, radians for turn; 0 when done."""
        if self.manoeuvre is None:
            return 0.0
        distance, rotation = self._progress()
        done = distance if self.manoeuvre["kind"] == "straight" else rotation
        return max(0.0, self.manoeuvre["amount"] - self.manoeuvre["sign"] * done)

    def measured_speed(self) -> tuple[float, float]:
        """Speeds from the wheels' rotation: m/s and rad/s."""
        r = self.drive.radius
        left, right = self.drive.wheel_speed(0) * r, self.drive.wheel_speed(1) * r
        return (left + right) / 2, (right - left) / self.drive.track

    def set_odometry(self, x: float, y: float, phi: float) -> None:
        self.odometry = [x, y, phi]

    # -- control loop ------------------------------------------------------------------------
    def before_step(self, dt: float) -> None:
        if self.manoeuvre is not None:
            self._plan()
        half_track = self.drive.track / 2
        self.v = _ramp(self.v, self.target_v, LINEAR_ACCEL * dt)
        self.w = _ramp(self.w, self.target_w, LINEAR_ACCEL / half_track * dt)
        r = self.drive.radius
        self.drive.set_wheel_speeds((self.v - self.w * half_track) / r, (self.v + self.w * half_track) / r)

    def _plan(self) -> None:
        m = self.manoeuvre
        distance, rotation = self._progress()
        if m["kind"] == "straight":
            remaining = m["amount"] - m["sign"] * distance
            accel = LINEAR_ACCEL
            correction = -HEADING_GAIN * rotation
        else:
            remaining = m["amount"] - m["sign"] * rotation
            accel = LINEAR_ACCEL / (self.drive.track / 2)
            correction = 0.0
        tolerance = DISTANCE_TOLERANCE if m["kind"] == "straight" else DISTANCE_TOLERANCE / (self.drive.track / 2)
        if remaining <= tolerance:
            self._finish()
            self.v = self.w = 0.0
            return
        floor = MIN_APPROACH_SPEED if m["kind"] == "straight" else MIN_APPROACH_SPEED / (self.drive.track / 2)
        speed = max(min(m["speed"], math.sqrt(2 * BRAKE_FRACTION * accel * remaining)), floor)
        if m["kind"] == "straight":
            self.target_v, self.target_w = m["sign"] * speed, correction
        else:
            self.target_v, self.target_w = 0.0, m["sign"] * speed
            # Braking must not wait for the ramp: approach speed follows the plan directly.
        if speed < m["speed"]:
            if m["kind"] == "straight":
                self.v = m["sign"] * min(abs(self.v), speed)
            else:
                self.w = m["sign"] * min(abs(self.w), speed)

    def after_step(self, dt: float) -> None:
        ticks = (self.drive.raw_ticks(0), self.drive.raw_ticks(1))
        if self.last_ticks is not None:
            left = (ticks[0] - self.last_ticks[0]) * self.metres_per_tick
            right = (ticks[1] - self.last_ticks[1]) * self.metres_per_tick
            distance = (left + right) / 2
            rotation = (right - left) / self.drive.track
            x, y, phi = self.odometry
            mid = phi + rotation / 2
            self.odometry = [x + distance * math.cos(mid), y + distance * math.sin(mid), phi + rotation]
        self.last_ticks = ticks


def _ramp(current: float, target: float, step: float) -> float:
    if target > current:
        return min(target, current + step)
    return max(target, current - step)


def create(context) -> list[Component]:
    drive = context.find(DifferentialDrive)
    return [VwController(drive)] if drive is not None else []
