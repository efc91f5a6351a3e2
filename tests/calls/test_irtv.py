"""The IR remote group: codes from outside, in order, with a blocking and a polling read."""

import pytest
from support.connected import connected_program

from eyesim.core import robot_input
from eyesim.robot.components.irtv import code_of


def test_codes_arrive_in_order_and_flush_drops_them():
    with connected_program(mode="realtime") as (sim, client):
        assert client.call("IRTV_GET_STATUS") == (1,)
        assert client.call("IRTV_READ") == (0,)
        waiting = client.send("IRTV_GET")
        for code in [code_of(button) for button in ("OK", "7", "IRTV_RED", ">")]:
            sim.call(lambda s, c=code: robot_input.irtv(s, 1, c))
        assert client.reply("IRTV_GET", waiting) == (ord("O"),)
        assert client.call("IRTV_READ") == (ord("7"),)
        assert client.call("IRTV_GET") == (ord("R"),)
        client.call("IRTV_FLUSH")
        assert client.call("IRTV_READ") == (0,)


def test_unknown_buttons_are_refused():
    with pytest.raises(ValueError, match="'X' is not an IR remote button"):
        code_of("X")
    assert code_of("right") == ord(">") and code_of("POWER") == ord("P")
