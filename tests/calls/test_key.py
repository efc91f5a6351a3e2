"""The key group: KEYWait's mask, and touches on the LCD for KEYGetXY/KEYReadXY (menu bar = soft keys)."""

import pytest
from support.client import RemoteError
from support.connected import connected_program

from eyesim.core import inputs, robot_input
from eyesim.robot.components.keys import KEY1, KEY2, KEY3, KEY4

ANYKEY = -1


@pytest.fixture
def program():
    with connected_program(mode="realtime") as (sim, client):
        yield sim, client


def press(sim, *keys):
    for key in keys:
        sim.call(lambda s, k=key: robot_input.key(s, 1, k))


def touch(sim, x, y):
    sim.call(lambda s: robot_input.touch(s, 1, x, y))


def test_key_wait_returns_the_first_key_in_its_mask_and_drops_the_others(program):
    sim, client = program
    request = client.send("KEY_WAIT", KEY2 | KEY4)
    press(sim, KEY1, KEY3, KEY4, KEY2)
    assert client.reply("KEY_WAIT", request) == (KEY4,)
    assert client.call("KEY_READ") == (KEY2,)  # pressed after the one KEYWait took: still there
    press(sim, KEY3)
    assert client.call("KEY_WAIT", ANYKEY) == (KEY3,)
    with pytest.raises(RemoteError, match="mask 0x10 contains none of KEY1..KEY4"):
        client.call("KEY_WAIT", 0x10)


def test_touches_reach_key_get_xy_and_key_read_xy_in_order(program):
    sim, client = program
    assert client.call("KEY_READ_XY") == (1, 0, 0)  # nothing touched yet
    request = client.send("KEY_GET_XY")
    touch(sim, 17, 42)
    assert client.reply("KEY_GET_XY", request) == (0, 17, 42)
    touch(sim, 1, 2)
    touch(sim, 479, 281)
    client.call("OS_WAIT", 10)
    assert client.call("KEY_READ_XY") == (0, 1, 2)
    assert client.call("KEY_READ_XY") == (0, 479, 281)
    assert client.call("KEY_READ_XY") == (1, 0, 0)
    assert client.call("KEY_READ") == (0,)  # touches above the menu bar are no key presses


def test_a_touch_on_the_menu_bar_presses_the_soft_key_below_it(program):
    sim, client = program
    client.call("LCD_MENU", "A", "B", "C", "D")
    touch(sim, 300, 300)  # third quarter of the bar
    touch(sim, 0, 319)
    assert client.call("KEY_GET") == (KEY3,)
    assert client.call("KEY_GET") == (KEY1,)
    assert client.call("KEY_READ_XY") == (1, 0, 0)
    client.call("LCD_SET_MODE", 0x0800)  # LCD_HIDEMENU: the whole screen takes touches
    touch(sim, 300, 300)
    client.call("OS_WAIT", 10)
    assert client.call("KEY_READ_XY") == (0, 300, 300)


def test_touches_outside_the_lcd_are_refused():
    with connected_program() as (sim, _client):
        with pytest.raises(ValueError, match="touch: x must be a whole number from 0 to 479, not 480"):
            inputs.prepare(sim, {"type": "touch", "robot": 1, "x": 480, "y": 0})
        with pytest.raises(ValueError, match="no robot 2"):
            inputs.prepare(sim, {"type": "touch", "robot": 2, "x": 0, "y": 0})
