"""The kinematics interface the V-omega controller drives a robot through, which every drive's
wheel component (the *_wheels modules here) offers."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from eyesim.robot.actuators import WheelMotor


class Kinematics:
    """The interface a drive component offers the V-omega controller (robot/components/vw.py).

    Speeds are the robot's: `v` m/s ahead of the drive's reference point (the middle of its
    driven axle, or its centre), `w` rad/s counter-clockwise. Odometry works on `odometer()`
    readings (encoder ticks, and whatever else the drive needs): `motion(before, after)` is how
    far the robot moved between two of them, in the robot frame at `before`."""

    noun = "the robot"  # in error messages: "the Ackermann car cannot ..."
    motors: dict[int, WheelMotor]  # RoBIOS number -> motor; a motor command releases the controller
    tick_travel: float  # m the robot moves ahead per encoder tick of one wheel
    spot_radius: float  # m each wheel travels per radian turning on the spot; 0: cannot turn on the spot
    min_radius: float = 0.0  # m: the tightest arc it can drive (0: any)

    def odometer(self) -> tuple:
        raise NotImplementedError

    def motion(self, before: tuple, after: tuple) -> tuple[float, float, float]:
        """dx (m ahead), dy (m to the left), dphi (rad) between two odometer readings."""
        raise NotImplementedError

    def set_motion(self, v: float, w: float) -> None:
        """Sets the wheels (and steering) so the robot moves at v, w."""
        raise NotImplementedError

    def measured_speed(self) -> tuple[float, float]:
        """v (m/s) and w (rad/s) from the wheels' rotation."""
        raise NotImplementedError

    def top_speed(self, curvature: float) -> float:
        """m/s the robot may drive along an arc of `curvature` (rad/m) with every wheel within reach."""
        raise NotImplementedError

    def arc_lever(self) -> float:
        """m the outer driven wheel travels per radian of an arc beyond the reference point's path
        (half the track of a differential drive): on an arc of curvature k it travels
        1 + |k| x this as far as the reference point."""
        return self.spot_radius

    def stall_watch(self) -> tuple[tuple[int, WheelMotor, int, float], ...]:
        """What stall detection watches: (VWStalled bit, motor, index of the wheel in
        wheel_ground_positions(), m the wheel rolls over the floor per radian of its motor)."""
        raise NotImplementedError

    def wheel_ground_positions(self) -> list[tuple[float, float, float, float]]:
        """Per watched wheel: its centre's x, y on the floor (m) and its rolling direction (unit x, y)."""
        raise NotImplementedError
