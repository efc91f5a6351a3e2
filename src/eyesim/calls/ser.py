"""RoBIOS serial group: byte streams on interface 0 (serial port) and 1..20 (USB) (SERInit,
SERReceive, SERFlush and SERClose only call the ports: protocol.json's "calls")."""

from eyesim.calls.errors import checked_arguments, component_of
from eyesim.net.session import Pending
from eyesim.robot.components.serial_ports import SerialPorts


def _ports(robot) -> SerialPorts:
    return component_of(robot, SerialPorts)


def ser_send(sim, robot, request):
    interface, data = request.args
    with checked_arguments():
        leaves = _ports(robot).send(interface, data)
    if leaves and data:
        sim.events.serial(robot.id, interface, data)
    return (0,)


def ser_receive_char(sim, robot, request):
    """Blocks until a byte arrives."""
    (interface,) = request.args
    ports = _ports(robot)
    with checked_arguments():
        port = ports.open_port(interface)

    def take(at_us):
        if not port.received:
            return None
        byte = port.received[0]
        del port.received[0]
        return (byte,)

    reply = take(request.time_us)
    return reply if reply is not None else Pending(take)


def ser_check(sim, robot, request):
    with checked_arguments():
        return (1 if _ports(robot).waiting(*request.args) else 0,)


HANDLERS = {
    "SER_SEND": ser_send,
    "SER_RECEIVE_CHAR": ser_receive_char,
    "SER_CHECK": ser_check,
}
