"""The serial group: byte streams per interface, a loopback plug, input from outside, errors."""

import pytest
from support.client import RemoteError
from support.connected import connected_program

from eyesim.core import robot_input
from eyesim.robot.components.serial_ports import SerialPorts


class SerialOutput:
    wants_lcd = False

    def __init__(self):
        self.text = {}

    def on_event(self, message):
        if message["type"] == "serial":
            self.text[message["interface"]] = self.text.get(message["interface"], "") + message["text"]

    def on_snapshot(self, message):
        pass


def test_output_leaves_the_robot_and_input_arrives_in_order():
    with connected_program(mode="realtime") as (sim, client):
        output = SerialOutput()
        sim.events.subscribe(output)
        client.call("SER_INIT", 0, 115200, 0)
        client.call("SER_INIT", 3, 9600, 1)
        client.call("SER_SEND", 0, b"hello\n")
        client.call("SER_SEND", 3, bytes([0, 255, 10]))
        assert output.text == {0: "hello\n", 3: "\x00\xff\n"}  # one character per byte
        assert client.call("SER_CHECK", 0) == (0,)
        assert client.call("SER_RECEIVE", 0, 10) == (b"",)  # nothing there: no waiting
        waiting = client.send("SER_RECEIVE_CHAR", 0)
        sim.call(lambda s: robot_input.serial(s, 1, 0, b"abc"))
        assert client.reply("SER_RECEIVE_CHAR", waiting) == (ord("a"),)
        assert client.call("SER_CHECK", 0) == (1,)
        assert client.call("SER_RECEIVE", 0, 1) == (b"b",)
        assert client.call("SER_RECEIVE", 0, 10) == (b"c",)
        sim.call(lambda s: robot_input.serial(s, 1, 0, b"dropped"))
        client.call("OS_WAIT", 5)
        client.call("SER_FLUSH", 0)
        assert client.call("SER_RECEIVE", 0, 10) == (b"",)


def test_a_loopback_plug_brings_output_back_as_input():
    with connected_program() as (sim, client):
        sim.robots[0].component(SerialPorts).port(1).loopback = True
        client.call("SER_INIT", 1, 57600, 0)
        client.call("SER_SEND", 1, b"ping")
        assert client.call("SER_RECEIVE_CHAR", 1) == (ord("p"),)
        assert client.call("SER_RECEIVE", 1, 100) == (b"ing",)


def test_closed_interfaces_and_bad_settings_get_errors():
    with connected_program() as (_sim, client):
        for op, args, message in [
            ("SER_SEND", (0, b"x"), "interface 0 is not open; call SERInit first"),
            ("SER_INIT", (21, 9600, 0), "interface 21 is not 0 .serial port. or 1..20 .USB."),
            ("SER_INIT", (0, 49, 0), "baud rate 49 is outside 50..230400"),
            ("SER_INIT", (0, 9600, 2), "handshake 2 is not 0 .none. or 1 .RTSCTS."),
            ("SER_RECEIVE_CHAR", (2,), "interface 2 is not open"),
        ]:
            with pytest.raises(RemoteError, match=message):
                client.call(op, *args)
        client.call("SER_INIT", 0, 9600, 0)
        client.call("SER_CLOSE", 0)
        with pytest.raises(RemoteError, match="interface 0 is not open"):
            client.call("SER_RECEIVE", 0, 1)
