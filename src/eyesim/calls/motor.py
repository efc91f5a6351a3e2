"""RoBIOS motor group: motors (open loop, PID speed control) and their encoders.

Motor and encoder numbers depend on the drive (docs/api/motor.md): differential 1 left, 2 right;
Ackermann 1 = the driven axle; omni 1..4 front left, front right, back left, back right;
submarine = its thrusters' numbers (no encoders)."""

from eyesim.calls.errors import CallError, numbered
from eyesim.protocol import generated
from eyesim.robot.actuators import ActuatorError
from eyesim.robot.components.vw import VwController

MAX_PERCENT = 100
MAX_GAIN = 255


def _motor(robot, number: int):
    motor = numbered(robot, robot.motors, number, "motor")
    # Driving a motor directly takes it over from the V-omega controller.
    for vw in robot.components_of(VwController):
        if motor in vw.drive.motors.values():
            vw.release()
    return motor


def _encoder(robot, number: int):
    return numbered(robot, robot.encoders, number, "encoder")


def _check(value: int, low: int, high: int, what: str) -> None:
    if not low <= value <= high:
        raise CallError(f"{what} {value} is out of range {low}..{high}")


def motor_drive(sim, robot, request):
    number, speed = request.args
    _check(speed, -MAX_PERCENT, MAX_PERCENT, "speed")
    _motor(robot, number).drive(speed)
    return (0,)


def _carry_out(action) -> tuple:
    try:
        action()
    except ActuatorError as error:
        raise CallError(f"motor {error}", generated.ERR_NOT_SUPPORTED) from None
    except ValueError as error:
        raise CallError(str(error)) from None
    return (0,)


def motor_pid(sim, robot, request):
    number, p, i, d = request.args
    for value, name in ((p, "p"), (i, "i"), (d, "d")):
        _check(value, 0, MAX_GAIN, name)
    motor = _motor(robot, number)
    return _carry_out(lambda: motor.set_pid(p, i, d))


def motor_pid_off(sim, robot, request):
    (number,) = request.args
    motor = _motor(robot, number)
    return _carry_out(motor.pid_off)


def motor_speed(sim, robot, request):
    number, ticks = request.args
    motor = _motor(robot, number)
    return _carry_out(lambda: motor.set_ticks_per_second(ticks))


def encoder_read(sim, robot, request):
    (number,) = request.args
    return (_encoder(robot, number).encoder(),)


def encoder_reset(sim, robot, request):
    (number,) = request.args
    _encoder(robot, number).reset_encoder()
    return (0,)


HANDLERS = {
    "MOTOR_DRIVE": motor_drive,
    "MOTOR_DRIVE_RAW": motor_drive,  # the simulator has no HDT table: raw is the same
    "MOTOR_PID": motor_pid,
    "MOTOR_PID_OFF": motor_pid_off,
    "MOTOR_SPEED": motor_speed,
    "ENCODER_READ": encoder_read,
    "ENCODER_RESET": encoder_reset,
}
