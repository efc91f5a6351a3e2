"""Timers: due in simulation time; in deterministic mode time waits while callbacks run and while the
main thread computes; limits and errors. The client here plays the C library's timer thread."""

import time

import pytest
from support.client import ProgramClient, RemoteError
from support.connected import connected_program
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.protocol import decode_payload
from eyesim.protocol import generated as g
from eyesim.robot.components.timers import MAX_TIMERS


def timer_reply(client, request_id):
    message = client.receive()
    assert message.request_id == request_id, message
    return decode_payload(g.OPS_BY_NAME["TIMER_WAIT"].reply, message.payload)[0]


def test_timers_fire_at_their_period_and_time_stands_still_while_callbacks_run():
    with connected_program() as (sim, client):
        attached_ms = client.call("OS_GET_COUNT")[0]  # TIMER_ATTACH is local: within the same millisecond
        handle = client.call("TIMER_ATTACH", 10)[0]
        wait = client.send("TIMER_WAIT")
        main = client.send("OS_WAIT", 35)  # the main thread waits until 35 ms after attaching
        for tick in range(1, 4):
            assert timer_reply(client, wait) == [handle]
            frozen = sim.time_us
            time.sleep(0.2)  # the "callback" takes a while: simulation time must not run on
            assert sim.time_us == frozen
            assert client.call("OS_GET_COUNT")[0] - attached_ms == 10 * tick  # the callback sees its due time
            wait = client.send("TIMER_WAIT")
        assert client.reply("OS_WAIT", main) == (0,)  # before the 4th tick at 40 ms
        assert 35 <= client.call("OS_GET_COUNT")[0] - attached_ms < 40


def test_while_the_main_thread_computes_time_waits_for_it_too():
    with connected_program() as (sim, client):
        client.call("TIMER_ATTACH", 50)  # due after the calls below (each takes the call time)
        client.send("TIMER_WAIT")
        client.call("OS_GET_COUNT")
        frozen = sim.time_us
        time.sleep(0.3)  # computing, shorter than the busy-wait grace: no tick may come
        assert sim.time_us == frozen
        client.call("TIMER_DETACH", 1)


def test_a_main_thread_that_busy_waits_for_a_timer_does_not_hang_the_simulation():
    with connected_program() as (_sim, client):
        handle = client.call("TIMER_ATTACH", 20)[0]
        wait = client.send("TIMER_WAIT")
        assert timer_reply(client, wait) == [handle]  # arrives although the main thread never waits


def test_detached_timers_stop_and_a_full_set_is_refused():
    with connected_program() as (_sim, client):
        handles = [client.call("TIMER_ATTACH", 1000)[0] for _ in range(MAX_TIMERS)]
        assert handles == list(range(1, MAX_TIMERS + 1))
        with pytest.raises(RemoteError, match=f"all {MAX_TIMERS} timers are attached"):
            client.call("TIMER_ATTACH", 1000)
        client.call("TIMER_DETACH", 7)
        assert client.call("TIMER_ATTACH", 10) == (7,)  # the free handle is used again
        for handle in handles:
            if handle != 7:
                client.call("TIMER_DETACH", handle)
        wait = client.send("TIMER_WAIT")
        main = client.send("OS_WAIT", 25)
        assert timer_reply(client, wait) == [7]
        wait = client.send("TIMER_WAIT")
        assert timer_reply(client, wait) == [7]
        client.call("TIMER_DETACH", 7)
        client.send("TIMER_WAIT")
        assert client.reply("OS_WAIT", main) == (0,)  # no third tick came first
        with pytest.raises(RemoteError, match="no timer 7 is attached"):
            client.call("TIMER_DETACH", 7)
        with pytest.raises(RemoteError, match="timer period -5 ms is not positive"):
            client.call("TIMER_ATTACH", -5)


def test_the_next_program_starts_without_the_timers_of_the_last():
    with running_simulation(arena()) as (sim, port):
        first = ProgramClient(port)
        first.hello("1")
        assert first.call("TIMER_ATTACH", 1000) == (1,)
        assert first.call("TIMER_ATTACH", 1000) == (2,)
        first.close()
        for _ in range(200):  # until the simulator has noticed
            if not sim.sessions:
                break
            time.sleep(0.01)
        second = ProgramClient(port)
        second.hello("1")
        assert second.call("TIMER_ATTACH", 50) == (1,)
        second.close()
