"""Radio: two real C programs in one scene play ping-pong, see each other on the air, receive a
burst in order; errors before RADIOInit and for unknown ids; a blocked RADIOReceive holds up nobody."""

import pytest
from support.client import ProgramClient, RemoteError
from support.rooms import square_room, write_scene
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.protocol import generated as g
from eyesim.robot.components.radio import MAX_MESSAGE


def test_two_programs_play_ping_pong(tmp_path, programs, run_scene):
    scene = write_scene(tmp_path, square_room(), ["S4 500 500 0", "S4 1500 1500 180"])
    run = run_scene(scene, {1: programs("radio_ping"), 2: programs("radio_pong")})
    assert run.returncode == 0, run.stdout + run.stderr

    lines = run.lines(1)
    assert lines[:3] == ["before 1 -1", "init 0 id 1", "hello from 2: hello"]
    assert "RADIOSend: the radio is off; call RADIOInit first" in run.stderr
    assert lines[3] == "status 2 1 2"  # both radios are on, the caller's included
    assert lines[4:24] == [f"got 2 {len(f'pong {k}')} pong {k}" for k in range(20)]
    assert lines[24] == "burst in order 1, waiting 0"
    assert lines[25] == "unknown 1, short -1"
    assert "RADIOSend: no robot 99 to send to (robot ids: [1, 2])" in run.stderr
    assert lines[26] == "release 0"
    assert run.lines(2) == ["done 2"]


def test_a_waiting_receive_blocks_only_its_caller():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 0))), "realtime") as (sim, port):
        first, second = ProgramClient(port), ProgramClient(port)
        first.hello("1")
        second.hello("2")
        first.call("RADIO_INIT")
        waiting = first.send("RADIO_RECEIVE")
        assert second.call("RADIO_STATUS") == ([1],)  # robot 2's radio is still off
        with pytest.raises(RemoteError) as error:
            second.call("RADIO_RECEIVE")
        assert error.value.code == g.ERR_NOT_SUPPORTED
        second.call("RADIO_INIT")
        assert second.call("RADIO_STATUS") == ([1, 2],)
        assert second.call("RADIO_SEND", 1, b"\x00binary\xff") == (0,)
        assert first.reply("RADIO_RECEIVE", waiting) == (2, b"\x00binary\xff")
        with pytest.raises(
            RemoteError, match=f"message: {MAX_MESSAGE + 1} bytes is too large \\(at most {MAX_MESSAGE}\\)"
        ):
            second.call("RADIO_SEND", 1, b"x" * (MAX_MESSAGE + 1))
        assert second.call("RADIO_SEND", 2, b"to myself") == (0,)
        assert second.call("RADIO_CHECK") == (1,) and second.call("RADIO_RECEIVE") == (2, b"to myself")
        first.close()  # a program that ends switches its radio off
        for _ in range(100):
            if second.call("RADIO_STATUS") == ([2],):
                break
        assert second.call("RADIO_STATUS") == ([2],)
