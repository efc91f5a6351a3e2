"""RoBIOS I/O group: 16 digital lines, 8 analog channels with 1 kHz recording, and the battery voltage
(reading a line or a channel only calls the component: protocol.json's "calls")."""

from eyesim.calls.errors import CallError, checked_arguments, component_of, require
from eyesim.net.session import Pending
from eyesim.robot.components.analog_io import AnalogInputs
from eyesim.robot.components.battery import Battery
from eyesim.robot.components.digital_io import DigitalLines


def _digital(robot) -> DigitalLines:
    return component_of(robot, DigitalLines)


def _analog(robot) -> AnalogInputs:
    return component_of(robot, AnalogInputs)


def digital_setup(sim, robot, request):
    line, direction = request.args
    with checked_arguments():
        _digital(robot).setup(line, chr(direction) if 0 < direction < 128 else repr(direction))
    sim.events.io(robot)
    return (0,)


def digital_write(sim, robot, request):
    with checked_arguments():
        _digital(robot).write(*request.args)
    sim.events.io(robot)
    return (0,)


def analog_voltage(sim, robot, request):
    return (round(require(robot.component(Battery), robot, "battery").volts * 100),)


def analog_record(sim, robot, request):
    channel, count = request.args
    with checked_arguments():
        _analog(robot).start_recording(channel, count, request.time_us)
    return (0,)


def analog_transfer(sim, robot, request):
    """Blocks until the recording is complete."""
    recording = _analog(robot).recording
    if recording is None:
        raise CallError("nothing was recorded; call ANALOGRecord first")

    def poll(at_us):
        return (recording.samples(),) if at_us >= recording.end_us else None

    reply = poll(request.time_us)
    return reply if reply is not None else Pending(poll, recording.end_us)


HANDLERS = {
    "DIGITAL_SETUP": digital_setup,
    "DIGITAL_WRITE": digital_write,
    "ANALOG_VOLTAGE": analog_voltage,
    "ANALOG_RECORD": analog_record,
    "ANALOG_TRANSFER": analog_transfer,
}
