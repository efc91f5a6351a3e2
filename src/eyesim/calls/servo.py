"""RoBIOS servo group: steering (Ackermann), arm joints and grippers, positions 0..255.

Servo numbers come from the robot file (docs/api/servo.md): the Ackermann steering is servo 1,
arm joints and grippers use the numbers of their `joint` and `gripper` lines."""

from eyesim.calls.errors import CallError
from eyesim.protocol import generated
from eyesim.robot.actuators import SERVO_MAX


def _servo(robot, number: int):
    servo = robot.servos.get(number)
    if servo is None:
        numbers = ", ".join(str(n) for n in sorted(robot.servos)) or "none"
        raise CallError(
            f"robot {robot.id} ({robot.name}) has no servo {number} (its servos: {numbers})",
            generated.ERR_BAD_ARGUMENT if robot.servos else generated.ERR_NOT_SUPPORTED,
        )
    return servo


def _position(value: int, what: str) -> None:
    if not 0 <= value <= SERVO_MAX:
        raise CallError(f"{what} {value} is out of range 0..{SERVO_MAX}")


def servo_set(sim, robot, request):
    number, angle = request.args
    _position(angle, "angle")
    _servo(robot, number).set(angle)
    return (0,)


def servo_set_raw(sim, robot, request):
    number, angle = request.args
    _position(angle, "angle")
    _servo(robot, number).set_raw(angle)
    return (0,)


def servo_range(sim, robot, request):
    number, low, high = request.args
    _position(low, "low")
    _position(high, "high")
    if low >= high:
        raise CallError(f"low {low} must be below high {high}")
    _servo(robot, number).set_range(low, high)
    return (0,)


HANDLERS = {"SERVO_SET": servo_set, "SERVO_SET_RAW": servo_set_raw, "SERVO_RANGE": servo_range}
