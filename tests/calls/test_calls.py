"""Operations protocol.json declares as a component's method ("calls": "Lcd.set_position") have no
handler function: the registry makes one that calls the robot's component with the request's
values and shapes the reply from the op's reply fields."""

import pytest

from eyesim import calls
from eyesim.protocol import generated as g
from eyesim.protocol.ops import OpSpec
from eyesim.robot.components.digital_io import DigitalLines
from support.client import RemoteError
from support.connected import connected_program


def test_every_declared_call_is_served_by_the_registry_and_no_module_handles_it():
    declared = {op.name for op in g.OPS.values() if op.calls}
    assert {"LCD_CLEAR", "LCD_SET_POS", "KEY_READ", "IRTV_FLUSH", "DIGITAL_READ", "SER_INIT"} <= declared
    assert len(declared) == 24
    for name in declared:
        handler = calls.HANDLERS[g.OPS_BY_NAME[name].code]
        assert handler.__qualname__ == "calling.<locals>.handler", name


def test_reply_shapes_follow_the_ops_reply_fields():
    with connected_program() as (sim, client):
        assert client.call("LCD_PIXEL", 10, 20, 0x123456) == (0,)  # a "result" field only: 0
        assert client.call("LCD_GET_PIXEL", 10, 20) == (0x123456,)  # the method's value
        assert client.call("DIGITAL_READ_ALL") == (sim.robots[0].component(DigitalLines).read_all(),)
        assert client.call("SER_INIT", 1, 9600, 0) == (0,)
        assert client.call("SER_RECEIVE", 1, 16) == (b"",)
        assert client.call("KEY_READ") == (0,)


def test_a_value_error_of_the_method_is_a_bad_argument_with_its_message():
    with connected_program() as (sim, client):
        with pytest.raises(RemoteError, match="interface 21 is not 0 .serial port. or 1..20 .USB.") as error:
            client.call("SER_FLUSH", 21)
        assert error.value.code == g.ERR_BAD_ARGUMENT
        with pytest.raises(RemoteError, match="font size 99 is outside 8..24") as error:
            client.call("LCD_SET_FONT_SIZE", 99)
        assert error.value.code == g.ERR_BAD_ARGUMENT
        assert client.call("LCD_CLEAR") == (0,)  # the simulator goes on


def op_calling(method: str, reply=(("result", "i32"),)) -> OpSpec:
    return OpSpec("TEST_OP", 9999, "lcd", 10, False, (), reply, calls=method)


@pytest.mark.parametrize(
    "method, message",
    [
        ("Lcdd.clear", "'Lcdd': 0 component classes have that name"),
        ("Lcd.wipe", "TEST_OP calls Lcd.wipe: Lcd needs the method and a noun"),
        ("Component.reset", "Component needs the method and a noun"),
    ],
)
def test_a_declaration_naming_no_component_method_is_refused(method, message):
    with pytest.raises(RuntimeError, match=message):
        calls.calling(op_calling(method))


def test_a_module_may_not_handle_an_op_declared_as_a_call(monkeypatch):
    from eyesim.calls import lcd

    monkeypatch.setitem(lcd.HANDLERS, "LCD_CLEAR", lcd.HANDLERS["LCD_GET_SIZE"])
    with pytest.raises(
        RuntimeError, match="eyesim.calls.lcd handles LCD_CLEAR, which protocol.json says calls Lcd.clear"
    ):
        calls._build_registry()
