"""The I/O group: digital lines with directions and pulls, analog channels and 1 kHz recording, and a
battery whose voltage falls with use."""

import pytest
from support.client import RemoteError
from support.connected import connected_program
from support.scenes import arena

from eyesim.core import robot_input
from eyesim.robot.components.battery import Battery


class IoEvents:
    wants_lcd = False

    def __init__(self):
        self.latest = None

    def on_event(self, message):
        if message["type"] == "io":
            self.latest = message

    def on_snapshot(self, message):
        pass


def drive(sim, line, level):
    sim.call(lambda s: robot_input.digital(s, 1, line, level))


def test_digital_lines_read_what_drives_them(program_realtime):
    sim, client = program_realtime
    events = IoEvents()
    sim.events.subscribe(events)
    assert client.call("DIGITAL_READ_ALL") == (0,)  # all inputs, undriven
    client.call("DIGITAL_SETUP", 2, ord("I"))  # pull-up: reads 1 until driven
    client.call("DIGITAL_SETUP", 3, ord("J"))
    client.call("DIGITAL_SETUP", 16, ord("o"))
    client.call("DIGITAL_WRITE", 16, 1)
    assert client.call("DIGITAL_READ", 2) == (1,)
    assert client.call("DIGITAL_READ", 3) == (0,)
    assert client.call("DIGITAL_READ_ALL") == ((1 << 1) | (1 << 15),)
    drive(sim, 2, 0)
    drive(sim, 3, 1)
    drive(sim, 16, 0)  # driving an output changes nothing: it reads what the program wrote
    client.call("OS_WAIT", 5)
    assert client.call("DIGITAL_READ_ALL") == ((1 << 2) | (1 << 15),)
    drive(sim, 2, None)  # let go: the pull-up wins again
    client.call("OS_WAIT", 5)
    assert client.call("DIGITAL_READ", 2) == (1,)
    assert events.latest["digital"][15] == {"direction": "o", "level": 1, "driven": 0}
    assert events.latest["digital"][1] == {"direction": "I", "level": 1, "driven": None}
    for op, args, message in [
        ("DIGITAL_WRITE", (1, 1), "digital line 1 is an input; DIGITALSetup.1, 'o'. makes it an output"),
        ("DIGITAL_READ", (17,), "digital line 17 is not 1..16"),
        ("DIGITAL_SETUP", (1, ord("x")), "direction 'x' is not"),
        ("DIGITAL_WRITE", (16, 2), "level 2 is not 0 or 1"),
    ]:
        with pytest.raises(RemoteError, match=message):
            client.call(op, *args)


def test_analog_recording_samples_at_1_khz_of_simulation_time():
    with connected_program() as (sim, client):
        assert [client.call("ANALOG_READ", c)[0] for c in range(1, 9)] == [0] * 7 + [512]
        sim.call(lambda s: robot_input.analog(s, 1, 3, 100))
        client.call("OS_WAIT", 2)
        start_ms = client.call("OS_GET_COUNT")[0]
        client.call("ANALOG_RECORD", 3, 50)
        client.call("OS_WAIT", 20)
        sim.call(lambda s: robot_input.analog(s, 1, 3, 700))  # at the next step boundary
        samples = client.call("ANALOG_TRANSFER")[0]
        assert client.call("OS_GET_COUNT")[0] - start_ms >= 50  # waited for the recording to end
        values = [int.from_bytes(samples[k : k + 2], "little") for k in range(0, len(samples), 2)]
        assert len(values) == 50 and set(values) == {100, 700}
        switch = values.index(700)
        waited = sim.call_time_us // 1000 + 20  # the recording started one call (ANALOG_RECORD) before the wait
        assert waited <= switch <= waited + 3 and values[switch:] == [700] * (50 - switch)
        with pytest.raises(RemoteError, match="analog channel 9 is not 1..8"):
            client.call("ANALOG_READ", 9)
        with pytest.raises(RemoteError, match="0 samples is outside 1..100000"):
            client.call("ANALOG_RECORD", 1, 0)


def test_transfer_without_a_recording_is_an_error():
    with connected_program() as (_sim, client), pytest.raises(RemoteError, match="call ANALOGRecord first"):
        client.call("ANALOG_TRANSFER")


def test_the_battery_voltage_falls_and_falls_faster_while_driving():
    with connected_program(arena(robots=((500, 500, 0), (500, 1500, 0)))) as (sim, client):
        assert client.call("ANALOG_VOLTAGE") == (840,)  # full: 8.40 V
        client.call("VW_SET_SPEED", 300, 0)
        client.call("OS_WAIT", 3000)
        driving, standing = (robot.component(Battery) for robot in sim.robots)
        assert 8.39 < driving.volts < standing.volts < 8.4
        client.call("OS_WAIT", 60_000)
        assert client.call("ANALOG_VOLTAGE")[0] < 840


@pytest.fixture
def program_realtime():
    with connected_program(mode="realtime") as (sim, client):
        yield sim, client
