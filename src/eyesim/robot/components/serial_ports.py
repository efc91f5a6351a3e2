"""The controller's serial interfaces: 0 = the serial port, 1..20 = USB serial devices, each a byte stream.

What a program sends goes out of the simulator (the viewer's serial panel, the console of a
headless run); what comes in is typed in the viewer or scripted. A loopback plug on an interface
sends its output straight back to its input."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.protocol.constants import RTSCTS
from eyesim.robot.component import Component

INTERFACES = range(21)  # 0 = serial port, 1..20 = USB
MIN_BAUD, MAX_BAUD = 50, 230400
HANDSHAKE_NONE, HANDSHAKE_RTSCTS = 0, RTSCTS
RECEIVE_BUFFER = 65536  # bytes an interface holds for the program; more are lost (an overrun)


@dataclass
class SerialPort:
    opened: bool = False
    baud: int = 0
    handshake: int = HANDSHAKE_NONE
    received: bytearray = field(default_factory=bytearray)
    loopback: bool = False


class SerialPorts(Component):
    noun = "serial interfaces"

    def __init__(self):
        self.ports = {number: SerialPort() for number in INTERFACES}

    def reset(self) -> None:
        for port in self.ports.values():  # a loopback plug is hardware: it stays plugged in
            port.opened, port.baud, port.handshake = False, 0, HANDSHAKE_NONE
            port.received.clear()

    def port(self, interface: int) -> SerialPort:
        if interface not in self.ports:
            raise ValueError(f"interface {interface} is not 0 (serial port) or 1..20 (USB)")
        return self.ports[interface]

    def open_port(self, interface: int) -> SerialPort:
        port = self.port(interface)
        if not port.opened:
            raise ValueError(f"interface {interface} is not open; call SERInit first")
        return port

    def init(self, interface: int, baud: int, handshake: int) -> None:
        port = self.port(interface)
        if not MIN_BAUD <= baud <= MAX_BAUD:
            raise ValueError(f"baud rate {baud} is outside {MIN_BAUD}..{MAX_BAUD}")
        if handshake not in (HANDSHAKE_NONE, HANDSHAKE_RTSCTS):
            raise ValueError(f"handshake {handshake} is not 0 (none) or 1 (RTSCTS)")
        port.opened, port.baud, port.handshake = True, baud, handshake

    def send(self, interface: int, data: bytes) -> bool:
        """The program sends; returns True when the bytes leave the robot (no loopback plug)."""
        port = self.open_port(interface)
        if port.loopback:
            self.deliver(interface, data)
            return False
        return True

    def deliver(self, interface: int, data: bytes) -> None:
        """Bytes arriving from outside; kept until the program reads them, even before SERInit."""
        port = self.port(interface)
        port.received += data[: max(0, RECEIVE_BUFFER - len(port.received))]

    def receive(self, interface: int, size: int) -> bytes:
        if size < 0:
            raise ValueError(f"buffer size {size} is negative")
        port = self.open_port(interface)
        data = bytes(port.received[:size])
        del port.received[:size]
        return data

    def waiting(self, interface: int) -> int:
        return len(self.open_port(interface).received)

    def flush(self, interface: int) -> None:
        self.open_port(interface).received.clear()

    def close(self, interface: int) -> None:
        self.open_port(interface).opened = False


def create(context) -> list[Component]:
    return [SerialPorts()]
