"""V-omega driving for a differential drive: speed control, manoeuvres (straight, turn, curve, drive
to a point), odometry and stall detection.

The controller closes its loop on the simulated encoders, as on the real robot; the odometry it
integrates from them (VWGetPosition) drifts with wheel slip, unlike the true pose (SIMGetRobot)."""

from __future__ import annotations

import math

from eyesim.physics.units import mm
from eyesim.robot.component import Component
from eyesim.robot.components.differential_drive import DifferentialDrive

LINEAR_ACCEL = 1.0  # m/s^2 the controller ramps linear speed by (keeps the wheels from slipping)
BRAKE_FRACTION = 0.5  # of the acceleration used to plan the stop, leaving headroom for lag
MIN_APPROACH_SPEED = 0.004  # m/s: the crawl speed that finishes a manoeuvre without stalling short
DISTANCE_TOLERANCE = 0.0002  # m
HEADING_GAIN = 8.0  # 1/s: how hard a path manoeuvre corrects its heading towards the planned one
STALL_WINDOW = 0.1  # s over which a wheel's progress is judged
STALL_FRACTION = 0.25  # a wheel turning less than this share of its set speed is stalled
STALL_MIN_TICKS = 4  # a window in which a wheel should turn fewer ticks says nothing


class Manoeuvre:
    """A drive of `distance` m (signed) along an arc that changes the heading by `rotation` rad
    (signed); distance 0 is a turn on the spot. `speed` is m/s along the path, or rad/s for a turn.

    The plan follows one quantity, `length`: metres of path, or radians for a turn on the spot;
    what it needs every step is worked out here once."""

    def __init__(self, distance: float, rotation: float, speed: float, start_ticks: tuple[int, int],
                 half_track: float, top_wheel_speed: float):
        self.distance = distance
        self.rotation = rotation
        self.start_ticks = start_ticks
        self.on_the_spot = distance == 0
        followed = rotation if self.on_the_spot else distance
        self.sign = 1.0 if followed >= 0 else -1.0
        self.length = abs(followed)
        self.curvature = 0.0 if self.on_the_spot else rotation / distance  # rad per metre
        self.top_speed = abs(speed)
        if not self.on_the_spot:  # the outer wheel must stay within its motor's reach
            self.top_speed = min(self.top_speed, top_wheel_speed / (1 + abs(self.curvature) * half_track))
        scale = 1 / half_track if self.on_the_spot else 1.0  # wheel metres -> the followed unit
        self.tolerance = DISTANCE_TOLERANCE * scale
        self.floor = MIN_APPROACH_SPEED * scale
        self.braking = 2 * BRAKE_FRACTION * LINEAR_ACCEL * scale  # speed = sqrt(braking x remaining)


class VwController(Component):
    kind = "vw"

    def __init__(self, drive: DifferentialDrive, max_speed: float, max_turn: float):
        self.drive = drive
        self.max_speed = max_speed  # m/s, the robot type's
        self.max_turn = max_turn  # rad/s
        self.metres_per_tick = 2 * math.pi * drive.radius / drive.ticks_per_rev
        self.half_track = drive.track / 2
        self.reset()

    def reset(self) -> None:
        self.v = 0.0  # commanded speed after ramping, m/s
        self.w = 0.0  # rad/s
        self.target_v = 0.0
        self.target_w = 0.0
        self.manoeuvre: Manoeuvre | None = None
        self.engaged = False  # the wheels' speeds still need setting every step (ramp, manoeuvre)
        self.driving = False  # the controller has the wheels turning: watch for stalls
        self.odometry = [0.0, 0.0, 0.0]  # x, y (m), phi (rad) since start or VWSetPosition
        self._last_left = self._last_right = None  # encoder ticks after the last step
        self.stalled = 0  # bit 0 left, bit 1 right
        self._window_time = 0.0  # s into the current stall window
        self._window_start: tuple[int, int, float, float] | None = None  # ticks and wheel speed set points

    # -- geometry ----------------------------------------------------------------------------
    def _ticks(self) -> tuple[int, int]:
        return self.drive.wheels[0].raw_ticks(), self.drive.wheels[1].raw_ticks()

    def _progress(self) -> tuple[float, float]:
        """Distance (m) and rotation (rad) since the manoeuvre started, from the encoders (as read
        after the last step: the wheels have not moved since)."""
        start = self.manoeuvre.start_ticks
        left, right = (self._last_left, self._last_right) if self._last_left is not None else self._ticks()
        left = (left - start[0]) * self.metres_per_tick
        right = (right - start[1]) * self.metres_per_tick
        return (left + right) / 2, (right - left) / self.drive.track

    # -- commands (from the VW handlers) -----------------------------------------------------
    def set_speed(self, v: float, w: float) -> None:
        self.manoeuvre = None
        self.engaged = self.driving = True
        self.target_v = max(-self.max_speed, min(self.max_speed, v))
        self.target_w = max(-self.max_turn, min(self.max_turn, w))

    def straight(self, distance: float, speed: float) -> None:
        self._start(distance, 0.0, min(abs(speed), self.max_speed))

    def turn(self, angle: float, speed: float) -> None:
        self._start(0.0, angle, min(abs(speed), self.max_turn))

    def curve(self, distance: float, angle: float, speed: float) -> None:
        """An arc of `distance` m changing the heading by `angle` rad; a zero distance turns on the
        spot with the wheels at `speed`."""
        if distance == 0:
            self.turn(angle, abs(speed) / self.half_track)
        else:
            self._start(distance, angle, min(abs(speed), self.max_speed))

    def drive_to(self, dx: float, dy: float, speed: float) -> None:
        """Along the circular arc that leaves in the current heading and passes through the point
        dx ahead, dy to the left (requires dx > |dy|, so the arc turns by less than 90 degrees)."""
        rotation = 2 * math.atan2(dy, dx)
        distance = dx if dy == 0 else (dx * dx + dy * dy) / (2 * dy) * rotation
        self.curve(distance, rotation, speed)

    def _start(self, distance: float, rotation: float, speed: float) -> None:
        self.manoeuvre = Manoeuvre(distance, rotation, speed, self._ticks(), self.half_track,
                                   self.drive.max_wheel_speed * self.drive.radius)
        self.engaged = self.driving = True
        if self.manoeuvre.length == 0 or self.manoeuvre.top_speed == 0:
            self._finish()

    def _finish(self) -> None:
        self.manoeuvre = None
        self.target_v = self.target_w = 0.0

    def release(self) -> None:
        """Direct motor commands take the wheels over until the next VW command."""
        self.manoeuvre = None
        self.engaged = self.driving = False
        self.v = self.w = self.target_v = self.target_w = 0.0

    @property
    def done(self) -> bool:
        return self.manoeuvre is None

    def remaining(self) -> float:
        """What is left of the manoeuvre in metres: of the path, or of each wheel's travel for a
        turn on the spot; 0 when done."""
        m = self.manoeuvre
        if m is None:
            return 0.0
        distance, rotation = self._progress()
        left = max(0.0, m.length - m.sign * (rotation if m.on_the_spot else distance))
        return left * self.half_track if m.on_the_spot else left

    def measured_speed(self) -> tuple[float, float]:
        """Speeds from the wheels' rotation: m/s and rad/s."""
        r = self.drive.radius
        left, right = self.drive.wheel_speed(0) * r, self.drive.wheel_speed(1) * r
        return (left + right) / 2, (right - left) / self.drive.track

    def set_odometry(self, x: float, y: float, phi: float) -> None:
        self.odometry = [x, y, phi]

    # -- control loop ------------------------------------------------------------------------
    def before_step(self, dt: float) -> None:
        if not self.engaged:
            return
        if self.manoeuvre is not None:
            self._plan()
        half_track = self.half_track
        v = self.v = _ramp(self.v, self.target_v, LINEAR_ACCEL * dt)
        w = self.w = _ramp(self.w, self.target_w, LINEAR_ACCEL / half_track * dt)
        r = self.drive.radius
        left, right = self.drive.wheels
        left.set_speed((v - w * half_track) / r)
        right.set_speed((v + w * half_track) / r)
        if self.manoeuvre is None and v == self.target_v and w == self.target_w:
            # Steady: the wheels keep these speeds on their own until the next command.
            self.engaged = False
            self.driving = v != 0.0 or w != 0.0

    def _plan(self) -> None:
        m = self.manoeuvre
        distance, rotation = self._progress()
        remaining = m.length - m.sign * (rotation if m.on_the_spot else distance)
        if remaining <= m.tolerance:
            self._finish()
            self.v = self.w = 0.0
            return
        # As fast as allowed, but slow enough to brake in what remains, never slower than a crawl.
        speed = max(min(m.top_speed, math.sqrt(m.braking * remaining)), m.floor)
        braking = speed < m.top_speed
        if m.on_the_spot:
            self.target_v, self.target_w = 0.0, m.sign * speed
            if braking:  # braking must not wait for the ramp: the approach follows the plan directly
                self.w = m.sign * min(abs(self.w), speed)
            return
        heading_error = rotation - m.curvature * distance
        self.target_v = m.sign * speed
        self.target_w = self.target_v * m.curvature - HEADING_GAIN * heading_error
        if braking:
            self.v = m.sign * min(abs(self.v), speed)
            self.w = self.v * m.curvature - HEADING_GAIN * heading_error

    def after_step(self, dt: float) -> None:
        wheels = self.drive.wheels
        left, right = wheels[0].raw_ticks(), wheels[1].raw_ticks()
        last_left, last_right = self._last_left, self._last_right
        if left != last_left or right != last_right:
            self._last_left, self._last_right = left, right
            if last_left is not None:
                self._integrate((left - last_left) * self.metres_per_tick, (right - last_right) * self.metres_per_tick)
        if self.driving:
            self._window_time += dt
            if self._window_start is None or self._window_time >= STALL_WINDOW:
                self._watch_stall(left, right)
        elif self.stalled or self._window_start is not None:
            self.stalled = 0
            self._window_start = None

    def _integrate(self, left: float, right: float) -> None:
        """Odometry: the wheels moved `left` and `right` metres since the last step."""
        distance = (left + right) / 2
        rotation = (right - left) / self.drive.track
        x, y, phi = self.odometry
        mid = phi + rotation / 2
        self.odometry = [x + distance * math.cos(mid), y + distance * math.sin(mid), phi + rotation]

    def _watch_stall(self, left: int, right: int) -> None:
        """At the end of each short window, compares each wheel's encoder progress with what its
        speed set point asked for (the smaller of the set points at the window's start and end,
        so that speeding up or slowing down is never taken for a stall)."""
        wheels = self.drive.wheels
        targets = abs(wheels[0].target), abs(wheels[1].target)
        start = self._window_start
        if start is not None:
            stalled = 0
            for bit, ticks, begun, target, earlier in ((1, left, start[0], targets[0], start[2]),
                                                       (2, right, start[1], targets[1], start[3])):
                expected = min(target, earlier) * self._window_time * self.drive.wheels[0].ticks_per_radian
                if expected >= STALL_MIN_TICKS and abs(ticks - begun) < STALL_FRACTION * expected:
                    stalled |= bit
            self.stalled = stalled
        self._window_start = (left, right, *targets)
        self._window_time = 0.0
        self._window = [0.0, 0.0, 0.0]


def _ramp(current: float, target: float, step: float) -> float:
    if target > current:
        return min(target, current + step)
    return max(target, current - step)


def create(context) -> list[Component]:
    drive = context.find(DifferentialDrive)
    if drive is None:
        return []
    robot_type = context.robot_type
    return [VwController(drive, mm(robot_type.max_speed), math.radians(robot_type.max_turn))]
