"""V-omega driving for any drive with kinematics (robot/wheels/kinematics.py: differential, mecanum,
Ackermann): speed control, manoeuvres (straight, turn, curve, drive to a point), odometry and
stall detection.

The controller closes its loop on the simulated encoders, as on the real robot; the odometry it
integrates from them (VWGetPosition) drifts with wheel slip, unlike the true pose (SIMGetRobot).
A drive that cannot turn on the spot (a car) follows arcs no tighter than its smallest radius."""

from __future__ import annotations

import math

from eyesim.physics.units import mm, to_mm
from eyesim.robot.component import Component
from eyesim.robot.wheels.kinematics import Kinematics

LINEAR_ACCEL = 1.0  # m/s^2 the controller ramps linear speed by (keeps the wheels from slipping)
BRAKE_FRACTION = 0.5  # of the acceleration used to plan the stop, leaving headroom for lag
MIN_APPROACH_SPEED = 0.008  # m/s: the crawl speed that finishes a manoeuvre without stalling short
HEADING_GAIN = 8.0  # 1/s: how hard a path manoeuvre corrects its heading towards the planned one
# The last part of a manoeuvre is crawled: the robot lags its wheels' set point by a few ms, and
# coming in faster it would still turn on after the end, always past the target. What it still
# rolls on after the end is carried into the next manoeuvre of its kind (VwController._owed_by),
# so the crawl is kept short: 25 ms, and a one-degree turn takes about what the ramps allow
# (S4: 70 ms; at 0.5 mm and 4 mm/s its crawl alone took 125 ms).
CRAWL_DISTANCE = 0.0002  # m of wheel travel
STALL_WINDOW = 0.1  # s over which a wheel's progress is judged
STALL_FRACTION = 0.25  # a wheel turning less than this share of its set speed is stalled
STALL_MIN_TICKS = 4  # a window in which a wheel should turn fewer ticks says nothing
STALL_END_WINDOWS = 3  # a manoeuvre stalled for this many windows in a row ends (VWWait returns)
# The controller's rate (RoBIOS's VW timer: 100 Hz). A manoeuvre is re-planned at this rate, not
# at every physics step, while it cruises at its top speed far from its end (only the heading
# correction changes) and while it brakes with a period's travel a small share of what is left
# before the crawl; within reach of its end it is planned at every step, so it stops precisely.
# The odometry and the stall watch are kept at the components' tick (Component.tick: the same
# 100 Hz); the odometry reads up to the last step whenever it is asked for.
PLAN_PERIOD = 0.01  # s
HOLD_SHARE = 0.25  # braking, a plan holds for a period if that covers at most this share of the way to the crawl


class DriveLimitError(ValueError):
    """A command the drive cannot carry out (a car turning on the spot, an arc too tight for it)."""


class Manoeuvre:
    """A drive of `distance` m (signed) along an arc that changes the heading by `rotation` rad
    (signed); distance 0 is a turn on the spot. `speed` is m/s along the path, or rad/s for a turn.

    The plan follows one quantity, `length`: radians for a turn on the spot, else metres of the
    outer wheel's travel (the path itself for a straight line): on a tight arc the outer wheel
    travels many times as far as the reference point, and the speed, the ramps and the end are
    planned on it so the wheels keep within their grip and the arc ends at its heading as well
    as its length. What the plan needs every step is worked out here once."""

    def __init__(
        self,
        distance: float,
        rotation: float,
        speed: float,
        start: tuple,
        drive: Kinematics,
        max_turn: float = math.inf,
    ):
        self.distance = distance
        self.rotation = rotation
        self.start = start  # the drive's odometer reading
        self.on_the_spot = distance == 0
        followed = rotation if self.on_the_spot else distance
        self.sign = 1.0 if followed >= 0 else -1.0
        self.curvature = 0.0 if self.on_the_spot else rotation / distance  # rad per metre
        # Outer wheel travel per metre of path (1 on a straight line), and per radian turned beyond it.
        self.lever = 0.0 if self.on_the_spot or rotation == 0 else drive.arc_lever()
        self.factor = 1.0 + abs(self.curvature) * self.lever
        self.turn_sign = 1.0 if rotation >= 0 else -1.0
        self.length = abs(rotation) if self.on_the_spot else abs(distance) * self.factor
        self.top_speed = abs(speed)
        if not self.on_the_spot:  # every wheel within its motor's reach, the turn within the robot's rate
            self.top_speed = min(self.top_speed, drive.top_speed(self.curvature))
            if self.curvature:
                self.top_speed = min(self.top_speed, max_turn / abs(self.curvature))
            self.top_speed *= self.factor
        scale = 1 / drive.spot_radius if self.on_the_spot else 1.0  # wheel metres -> the followed unit
        # The odometry's resolution (what one wheel's tick moves the robot): a coarser tolerance
        # would end every manoeuvre short by the same amount, and twelve turns add it up. On an
        # arc, a tick of an outer wheel moves the followed quantity by at most twice that (by
        # `factor` times it when the odometry follows the path, as the car's does).
        self.tolerance = drive.tick_travel * scale * min(self.factor, 2.0)
        self.floor = MIN_APPROACH_SPEED * scale
        self.crawl = CRAWL_DISTANCE * scale
        self.braking = 2 * BRAKE_FRACTION * LINEAR_ACCEL * scale  # speed = sqrt(braking x remaining)
        # Further than this from the end (followed unit), the plan is top speed until the next one:
        # the braking distance from top speed, plus twice what a PLAN_PERIOD at top speed covers.
        self.cruise_beyond = self.crawl + self.top_speed**2 / self.braking + 2 * self.top_speed * PLAN_PERIOD
        # The reference point's speed ramps so that the outer wheel's does at LINEAR_ACCEL.
        self.accel = LINEAR_ACCEL / self.factor

    def progress(self, distance: float, rotation: float) -> float:
        """How far along the followed quantity the robot is after moving `distance` and turning
        `rotation` since the start (odometry): the outer wheel's travel on an arc."""
        if self.on_the_spot:
            return self.sign * rotation
        return self.sign * distance + self.lever * self.turn_sign * rotation


class VwController(Component):
    def __init__(self, drive: Kinematics, max_speed: float, max_turn: float):
        self.drive = drive
        self.max_speed = max_speed  # m/s, the robot type's
        self.max_turn = max_turn  # rad/s
        self.spot_radius = drive.spot_radius
        # A steered drive cannot turn on its own: its turn rate follows its speed along the arc.
        self.steered = drive.spot_radius == 0
        self.turn_accel = 0.0 if self.steered else LINEAR_ACCEL / self.spot_radius  # rad/s^2 of the ramp
        self._watched = drive.stall_watch()
        self.reset()

    def reset(self) -> None:
        self.v = 0.0  # commanded speed after ramping, m/s
        self.w = 0.0  # rad/s
        self.target_v = 0.0
        self.target_w = 0.0
        self.accel = LINEAR_ACCEL  # m/s^2 the linear speed ramps by (on an arc, less: the outer wheel's does so)
        self.manoeuvre: Manoeuvre | None = None
        # ("turn" | "straight", the last one's start reading, its signed target): what it left over
        # is worked out when the next one starts, so that what the wheels did after it ended counts
        self._owed: tuple[str, tuple, float] | None = None
        self.engaged = False  # the wheels' speeds still need setting every step (ramp, manoeuvre)
        self.driving = False  # the controller has the wheels turning: watch for stalls
        self._odometry = [0.0, 0.0, 0.0]  # x, y (m), phi (rad) since start or VWSetPosition, at _reading
        # The drive's odometer when the books were last kept (before the model is bound there is
        # nothing to read yet: the engine resets every component again once it is).
        self._reading: tuple | None = self.drive.odometer() if hasattr(self, "world") else None
        self.stalled = 0  # bit 0 left, bit 1 right
        self._window_ticks = 0  # ticks into the current stall window
        self._window_start: tuple | None = None  # ticks, wheel speed set points, wheel ground positions
        self._stalled_windows = 0  # in a row, during a manoeuvre
        self._cruise_steps = 0  # steps the current plan still holds for (cruising, or braking far from the end)
        self._planned_at: tuple | None = None  # the odometer reading the last plan was made at
        self._held_steps = 0  # what the last plan set _cruise_steps to
        self.stuck = False  # the last manoeuvre ended stalled: VWStalled keeps saying so until the next command

    # -- geometry ----------------------------------------------------------------------------
    def _progress(self, m: Manoeuvre) -> tuple[float, float]:
        """Distance (m) and rotation (rad) since the manoeuvre started, from the encoders."""
        distance, _, rotation = self.drive.motion(m.start, self.drive.odometer())
        return distance, rotation

    def _refuse_spot_turn(self) -> None:
        if self.steered:
            raise DriveLimitError(f"{self.drive.noun} cannot turn on the spot; drive an arc with VWCurve or VWDrive")

    # -- commands (from the VW handlers) -----------------------------------------------------
    def set_speed(self, v: float, w: float) -> None:
        """Drives on at v, w, each limited to the robot's speeds; a steered drive's turn rate also
        to what its tightest arc gives at that speed."""
        if v == 0 and w != 0:
            self._refuse_spot_turn()
        self.manoeuvre = None
        self._owed = None
        self._new_command()
        self.engaged = self.driving = True
        self.accel = LINEAR_ACCEL
        self.target_v = max(-self.max_speed, min(self.max_speed, v))
        self.target_w = max(-self.max_turn, min(self.max_turn, w))
        if self.steered:
            limit = abs(self.target_v) / self.drive.min_radius
            self.target_w = max(-limit, min(limit, self.target_w))

    def straight(self, distance: float, speed: float) -> None:
        self._start(distance + self._owed_by("straight"), 0.0, min(abs(speed), self.max_speed))

    def turn(self, angle: float, speed: float) -> None:
        self._refuse_spot_turn()
        self._start(0.0, angle + self._owed_by("turn"), min(abs(speed), self.max_turn))

    def _owed_by(self, kind: str) -> float:
        """What the last manoeuvre of this kind left over (signed: m or rad), when it was the last
        thing the wheels did: its target less what the odometry has counted since it started. The
        encoders count in steps (an S4 turning on the spot: 0.2 degrees), so a manoeuvre ends up
        to half a step off its target, and the wheels roll on a little after it ended; carrying
        the rest into the next one keeps a series of turns or straights on target (VWGetPosition
        knows the difference, too)."""
        owed, self._owed = self._owed, None
        if owed is None or owed[0] != kind:
            return 0.0
        distance, _, rotation = self.drive.motion(owed[1], self.drive.odometer())
        return owed[2] - (rotation if kind == "turn" else distance)

    def curve(self, distance: float, angle: float, speed: float) -> None:
        """An arc of `distance` m changing the heading by `angle` rad; a zero distance turns on the
        spot with the wheels at `speed`."""
        if distance == 0:
            self._refuse_spot_turn()  # before the speed is divided by a spot radius of 0
            self.turn(angle, abs(speed) / self.spot_radius)
        else:
            radius = abs(distance / angle) if angle else math.inf
            if radius < self.drive.min_radius:
                raise DriveLimitError(
                    f"an arc of radius {to_mm(radius):.0f} mm is tighter than {self.drive.noun} can "
                    f"drive (at least {to_mm(self.drive.min_radius):.0f} mm)"
                )
            self._owed = None
            self._start(distance, angle, min(abs(speed), self.max_speed))

    def drive_to(self, dx: float, dy: float, speed: float) -> None:
        """Along the circular arc that leaves in the current heading and passes through the point
        dx ahead, dy to the left (requires dx >= |dy|, so the arc turns by at most 90 degrees)."""
        rotation = 2 * math.atan2(dy, dx)
        distance = dx if dy == 0 else (dx * dx + dy * dy) / (2 * dy) * rotation
        self.curve(distance, rotation, speed)

    def _new_command(self) -> None:
        """A new VW command: whatever stalled before is forgotten."""
        if self.stuck:
            self.stuck = False
            self.stalled = 0
        self._stalled_windows = 0
        self._window_start = None
        self._cruise_steps = 0
        self._planned_at = None

    def _start(self, distance: float, rotation: float, speed: float) -> None:
        self._new_command()
        self.manoeuvre = Manoeuvre(distance, rotation, speed, self.drive.odometer(), self.drive, self.max_turn)
        self.accel = self.manoeuvre.accel
        self.engaged = self.driving = True
        if self.manoeuvre.length == 0 or self.manoeuvre.top_speed == 0:
            self._finish()

    def _finish(self) -> None:
        self.manoeuvre = None
        self._cruise_steps = 0
        self.target_v = self.target_w = 0.0

    def release(self) -> None:
        """Direct motor commands take the wheels over until the next VW command."""
        self.manoeuvre = None
        self._owed = None
        self._new_command()
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
        distance, rotation = self._progress(m)
        left = max(0.0, m.length - m.progress(distance, rotation))
        return left * self.spot_radius if m.on_the_spot else left / m.factor

    def measured_speed(self) -> tuple[float, float]:
        """Speeds from the wheels' rotation: m/s and rad/s."""
        return self.drive.measured_speed()

    @property
    def odometry(self) -> list[float]:
        """x, y (m), phi (rad) since start or VWSetPosition, up to the last step: as kept at the
        controller's rate, with what the wheels did since added (not kept: asking changes nothing)."""
        reading, last = self.drive.odometer(), self._reading
        if last is None or reading == last:
            return list(self._odometry)
        return _moved(self._odometry, *self.drive.motion(last, reading))

    def set_odometry(self, x: float, y: float, phi: float) -> None:
        self._odometry = [x, y, phi]
        if self._reading is not None:  # counted from here (before the first step: from there)
            self._reading = self.drive.odometer()

    # -- control loop ------------------------------------------------------------------------
    # These run for every driving robot at every step: locals instead of repeated attribute
    # look-ups, and the ramp written out (docs/performance.md, "Where a step's time goes").
    def before_step(self, dt: float) -> None:
        if not self.engaged:
            return
        if self._cruise_steps > 0:
            self._cruise_steps -= 1
            if self.v == self.target_v and self.w == self.target_w:
                return  # the wheels hold the speeds set last step, and the plan still holds
        elif self.manoeuvre is not None:
            reading = self.drive.odometer()
            if reading == self._planned_at and self.v == self.target_v and self.w == self.target_w:
                # The encoders have not moved since the last plan (crawling, they count a tick every
                # few dozen steps): planning again would come out the same, and the wheels hold its speeds.
                self._cruise_steps = self._held_steps
                return
            self._plan(self.manoeuvre, dt, reading)
        v, w, target_v, target_w = self.v, self.w, self.target_v, self.target_w
        v = _ramp(v, target_v, self.accel * dt)
        if self.steered:  # the arc's curvature holds while the speed ramps
            w = target_w if v == target_v else v * target_w / target_v if target_v else 0.0
        else:
            w = _ramp(w, target_w, self.turn_accel * dt)
        self.v, self.w = v, w
        self.drive.set_motion(v, w)
        if self.manoeuvre is None and v == target_v and w == target_w:
            # Steady: the wheels keep these speeds on their own until the next command.
            self.engaged = False
            self.driving = v != 0.0 or w != 0.0

    def _plan(self, m: Manoeuvre, dt: float, reading: tuple) -> None:
        distance, _, rotation = self.drive.motion(m.start, reading)
        self._planned_at = reading
        self._held_steps = 0
        remaining = m.length - m.progress(distance, rotation)
        if remaining <= m.tolerance:
            if m.on_the_spot or m.rotation == 0:
                self._owed = ("turn", m.start, m.rotation) if m.on_the_spot else ("straight", m.start, m.distance)
            self._finish()
            self.v = self.w = 0.0
            return
        # As fast as allowed, but slow enough to brake in what remains, never slower than a crawl.
        speed = max(min(m.top_speed, math.sqrt(m.braking * max(0.0, remaining - m.crawl))), m.floor)
        holds = remaining > m.cruise_beyond
        if not holds and speed < m.top_speed and speed * PLAN_PERIOD <= HOLD_SHARE * (remaining - m.crawl):
            # Held for a period: the speed for its middle, so that the steps straddle the braking curve.
            speed = math.sqrt(m.braking * (remaining - m.crawl - speed * PLAN_PERIOD / 2))
            holds = True
        if holds:
            self._cruise_steps = self._held_steps = max(round(PLAN_PERIOD / dt) - 1, 0)
        braking = speed < m.top_speed
        if m.on_the_spot:
            self.target_v, self.target_w = 0.0, m.sign * speed
            if braking:  # braking must not wait for the ramp: the approach follows the plan directly
                self.w = m.sign * min(abs(self.w), speed)
            return
        heading_error = rotation - m.curvature * distance
        speed /= m.factor  # the reference point's, on its path
        self.target_v = m.sign * speed
        self.target_w = self.target_v * m.curvature - HEADING_GAIN * heading_error
        if braking:
            self.v = m.sign * min(abs(self.v), speed)
            self.w = self.v * m.curvature - HEADING_GAIN * heading_error

    def tick(self, dt: float) -> None:
        """The books (odometry, stall watch), kept at the components' tick, not every step."""
        reading, last = self.drive.odometer(), self._reading
        if reading != last:
            self._reading = reading
            if last is not None:
                self._odometry = _moved(self._odometry, *self.drive.motion(last, reading))
        if self.driving:
            self._window_ticks += 1
            if self._window_start is None or self._window_ticks >= round(STALL_WINDOW / dt):
                self._watch_stall(dt)
        elif (self.stalled and not self.stuck) or self._window_start is not None:
            self.stalled = self.stalled if self.stuck else 0
            self._window_start = None
            self._stalled_windows = 0

    def _watch_stall(self, dt: float) -> None:
        """At the end of each short window, compares each wheel's progress with what its speed set
        point asked for (the smaller of the set points at the window's start and end, so that
        speeding up or slowing down is never taken for a stall). Progress is both what its encoder
        counted and how far it moved over the floor: a blocked wheel fails the first, a wheel
        spinning in place (against a wall, jammed in a corner, lifted) the second. A manoeuvre
        that stays stalled ends, so VWWait returns; VWStalled then still tells why."""
        watched = self._watched
        ticks = [motor.raw_ticks() for _, motor, _, _ in watched]
        targets = [motor.target for _, motor, _, _ in watched]
        ground = self.drive.wheel_ground_positions()
        start = self._window_start
        if start is not None:
            window_time = self._window_ticks * dt
            stalled = 0
            start_ticks, start_targets, start_ground = start
            for index, (bit, motor, wheel, roll) in enumerate(watched):
                target, earlier = targets[index], start_targets[index]
                speed = min(abs(target), abs(earlier)) if target * earlier > 0 else 0.0
                expected = speed * window_time * motor.ticks_per_radian
                if expected < STALL_MIN_TICKS:
                    continue
                x, y, forward_x, forward_y = ground[wheel]
                x0, y0 = start_ground[wheel][:2]
                over_floor = ((x - x0) * forward_x + (y - y0) * forward_y) * math.copysign(1.0, target)
                expected_m = speed * window_time * roll
                if (
                    abs(ticks[index] - start_ticks[index]) < STALL_FRACTION * expected
                    or over_floor < STALL_FRACTION * expected_m
                ):
                    stalled |= bit
            self.stalled = stalled
            self._stalled_windows = self._stalled_windows + 1 if stalled and self.manoeuvre else 0
            if self._stalled_windows >= STALL_END_WINDOWS:
                self._finish()
                self.stuck = True
        self._window_start = (ticks, targets, ground)
        self._window_ticks = 0


def _moved(odometry: list[float], dx: float, dy: float, rotation: float) -> list[float]:
    """The odometry after the robot moved dx ahead, dy to the left (m) and turned by `rotation`
    (what the encoders counted since it was kept); the move is taken along the mean heading."""
    x, y, phi = odometry
    mid = phi + rotation / 2
    cos, sin = math.cos(mid), math.sin(mid)
    return [x + dx * cos - dy * sin, y + dx * sin + dy * cos, phi + rotation]


def _ramp(current: float, target: float, step: float) -> float:
    """`current` moved towards `target` by at most `step` (comparisons, not min/max: cheaper)."""
    if target > current:
        moved = current + step
        return target if target < moved else moved
    moved = current - step
    return target if target > moved else moved


def create(context) -> list[Component]:
    drive = context.find(Kinematics)
    if drive is None:
        return []
    robot_type = context.robot_type
    return [VwController(drive, mm(robot_type.max_speed), math.radians(robot_type.max_turn))]
