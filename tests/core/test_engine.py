"""The simulation loop: clock modes, costs, pending replies and determinism."""

import queue
import time

import pytest
from support.client import ProgramClient
from support.scenes import arena, with_call_time
from support.simulator import running_simulation

from eyesim.core import robot_input, schedules
from eyesim.core.engine import DEFAULT_CALL_TIME_US
from eyesim.net.program_server import SimulationEventLoop
from eyesim.protocol import generated as g
from eyesim.robot.components.keys import KEY2


def test_deterministic_time_stands_still_while_a_program_computes():
    with running_simulation(arena(), "deterministic") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        client.call("OS_GET_COUNT")
        before = sim.time_us
        time.sleep(0.3)  # the program "computes" for 0.3 s of wall time
        client.call("OS_GET_COUNT")
        # The first call's cost (the call time), and at most the step the next call falls into.
        assert sim.time_us - before <= sim.call_time_us + sim.step_us


def test_deterministic_device_calls_cost_the_call_time():
    with running_simulation(arena(), "deterministic") as (sim, port):
        assert sim.call_time_us == DEFAULT_CALL_TIME_US  # not the protocol's 0.1 ms
        assert sim.call_cost_us(g.OPS_BY_NAME["KEY_READ"]) == DEFAULT_CALL_TIME_US
        client = ProgramClient(port)
        client.hello()
        start = client.call("OS_GET_COUNT")[0]
        calls = 100
        for _ in range(calls):
            client.call("KEY_READ")
        # the clock read itself is local: 10 us, within the millisecond
        assert client.call("OS_GET_COUNT")[0] - start == calls * DEFAULT_CALL_TIME_US // 1000


def test_local_calls_cost_only_their_own_microseconds():
    """LCD drawing and the like are done by the EyeBot itself: the call time does not apply."""
    pixel = g.OPS_BY_NAME["LCD_PIXEL"]
    with running_simulation(arena(), "deterministic") as (sim, port):
        assert pixel.cost == "local" and sim.call_cost_us(pixel) == pixel.cost_us < 100
        client = ProgramClient(port)
        client.hello()
        start = client.call("OS_GET_COUNT")[0]
        for x in range(1000):
            client.call("LCD_PIXEL", x % 480, x // 480, 0xFF0000)
        assert (
            client.call("OS_GET_COUNT")[0] - start
            == (1000 * pixel.cost_us + g.OPS_BY_NAME["OS_GET_COUNT"].cost_us) // 1000
        )


def test_deterministic_clock_reads_never_show_the_same_millisecond_twice():
    """Time stands still while a program only does local things; a program that polls the clock
    waiting for time to pass sees it go on a millisecond a read, and sees every millisecond."""
    with running_simulation(arena(), "deterministic") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        counts = [client.call("OS_GET_COUNT")[0] for _ in range(300)]
        assert counts == list(range(counts[0], counts[0] + 300))
        client.call("LCD_PIXEL", 1, 1, 0xFFFFFF)
        assert client.call("OS_GET_COUNT")[0] == counts[-1] + 1  # a local call in between changes nothing
        client.call("KEY_READ")  # 4 ms: a later millisecond anyway, read at once
        assert client.call("OS_GET_COUNT")[0] == counts[-1] + 1 + DEFAULT_CALL_TIME_US // 1000


def test_a_call_time_of_0_leaves_the_protocols_own_costs():
    cost = g.OPS_BY_NAME["KEY_READ"].cost_us  # 0.1 ms: time must go on even then
    with running_simulation(with_call_time(arena(), 0), "deterministic") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        start = client.call("OS_GET_COUNT")[0]
        for _ in range(100):
            client.call("KEY_READ")
        assert client.call("OS_GET_COUNT")[0] - start == 100 * cost // 1000


def test_deterministic_os_wait_costs_exactly_its_milliseconds():
    with running_simulation(arena(), "deterministic") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        for wait in (1, 7, 100, 333):
            before = client.call("OS_GET_COUNT")[0]  # itself 10 us: within the millisecond
            client.call("OS_WAIT", wait)
            assert client.call("OS_GET_COUNT")[0] - before == wait


def test_realtime_os_wait_follows_the_wall_clock():
    with running_simulation(arena(), "realtime") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        start = time.perf_counter()
        client.call("OS_WAIT", 300)
        elapsed = time.perf_counter() - start
        assert 0.25 < elapsed < 1.5


def test_realtime_replies_come_after_the_call_time_of_simulation_time():
    with running_simulation(with_call_time(arena(), 10), "realtime", speed=2) as (sim, port):
        client = ProgramClient(port)
        client.hello()
        start = client.call("OS_GET_COUNT")[0]
        for _ in range(20):
            client.call("KEY_READ")
        assert client.call("OS_GET_COUNT")[0] - start >= 21 * 10


def test_realtime_at_max_speed_a_call_takes_whole_steps():
    with running_simulation(with_call_time(arena(), 3), "realtime", speed=float("inf")) as (sim, port):
        client = ProgramClient(port)
        client.hello()
        start = client.call("OS_GET_COUNT")[0]
        for _ in range(10):
            client.call("KEY_READ")
        assert client.call("OS_GET_COUNT")[0] - start >= 10 * 4  # 3 ms rounded up to two 2 ms steps


def test_while_paused_a_held_reply_waits_for_simulation_time():
    with running_simulation(arena(), "realtime") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        sim.call(lambda s: s.clock.set_paused(True, s.time_us))
        request = client.send("KEY_READ")
        client.sock.settimeout(0.3)
        with pytest.raises(TimeoutError):
            client.receive()  # no simulation time passes, so the call does not end
        client.sock.settimeout(10)
        sim.call(lambda s: s.clock.set_paused(False, s.time_us))
        assert client.reply("KEY_READ", request) == (0,)


def test_realtime_with_a_call_time_of_0_answers_at_once():
    with running_simulation(with_call_time(arena(), 0), "realtime") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        sim.call(lambda s: s.clock.set_paused(True, s.time_us))
        client.call("OS_GET_COUNT")  # paused, and still answered: nothing is held
        assert sim.call_cost_us(g.OPS_BY_NAME["OS_GET_COUNT"]) == g.OPS_BY_NAME["OS_GET_COUNT"].cost_us


def test_realtime_calls_without_a_call_time_never_take_a_programs_clock_past_the_step_under_way():
    """Each call still moves the program's clock on by its own cost, but only within the physics
    step under way: 200 calls in a row while paused see at most one step (2 ms) go by, not 200
    calls' costs; the clock follows the simulation's again once it runs."""
    with running_simulation(with_call_time(arena(), 0), "realtime") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        paused = queue.Queue()
        sim.call(lambda s: (s.clock.set_paused(True, s.time_us), paused.put(s.time_us // 1000)))
        paused_at = paused.get(timeout=60)

        def count_after_a_call():
            client.call("KEY_READ")
            return client.call("OS_GET_COUNT")[0]

        counts = [count_after_a_call() for _ in range(200)]
        step_ms = sim.step_us // 1000
        assert 200 * g.OPS_BY_NAME["KEY_READ"].cost_us // 1000 > 4 * step_ms
        # the step under way, and one more the loop may finish in the round that paused it
        assert paused_at <= counts[0] <= counts[-1] <= paused_at + 2 * step_ms
        sim.call(lambda s: s.clock.set_paused(False, s.time_us))
        while client.call("OS_GET_COUNT")[0] < paused_at + 250:  # time goes on again
            pass


def test_key_get_waits_for_a_press_while_other_calls_go_on():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 0)))) as (sim, port):
        waiter, other = ProgramClient(port), ProgramClient(port)
        waiter.hello("1")
        other.hello("2")
        request = waiter.send("KEY_GET")
        assert other.call("PSD_GET", 1)[0] > 0  # the blocked call holds up nobody
        sim.call(lambda s: robot_input.key(s, 1, KEY2))
        assert waiter.reply("KEY_GET", request) == (KEY2,)
        assert waiter.call("KEY_READ") == (0,)


def test_vw_wait_returns_when_the_manoeuvre_is_done():
    with running_simulation(arena(), "deterministic") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        client.call("VW_STRAIGHT", 300, 300)
        assert client.call("VW_DONE") == (0,)
        client.call("VW_WAIT")
        assert client.call("VW_DONE") == (1,)
        x, y, z, phi = client.call("SIM_GET_ROBOT", 0)[1:]
        assert abs(x - 800) <= 3 and abs(y - 500) <= 2


def run_scripted_program(mode):
    """Drive a fixed sequence deterministically; return the trajectory of robot 1."""
    trajectory = []
    with running_simulation(arena(), mode, expect=(1,)) as (sim, port):
        sim.step_observers.append(lambda s: trajectory.append(bytes(s.world.data.qpos)))
        client = ProgramClient(port)
        client.hello()
        client.call("VW_SET_SPEED", 200, 30)
        for _ in range(50):
            client.call("PSD_GET", 1)
        client.call("VW_TURN", 45, 90)
        client.call("VW_WAIT")
        client.call("VW_STRAIGHT", 200, 250)
        client.call("OS_WAIT", 250)
        client.call("SIM_SET_ROBOT", 0, 1000, 1000, 0, 90)
        client.call("VW_WAIT")
        client.call("OS_WAIT", 100)
        end = sim.time_us
    return trajectory[: end // sim.step_us]


def test_two_deterministic_runs_give_bit_identical_trajectories():
    first = run_scripted_program("deterministic")
    second = run_scripted_program("deterministic")
    assert len(first) > 500
    assert first == second


def test_quiet_stretches_of_steps_change_nothing_but_how_often_the_sockets_are_looked_at(monkeypatch):
    """While every program waits (OSWait, VWWait), deterministic mode takes up to QUIET_STEPS steps
    in one go instead of looking at the sockets after each: the same trajectory, step for step, as
    one step a round, with far fewer looks."""
    looks = []
    poll = SimulationEventLoop.poll

    def counted_poll(sockets, timeout):
        looks[-1] += 1
        return poll(sockets, timeout)

    monkeypatch.setattr(SimulationEventLoop, "poll", counted_poll)
    runs = []
    for quiet_steps in (1, schedules.QUIET_STEPS):
        monkeypatch.setattr(schedules, "QUIET_STEPS", quiet_steps)
        looks.append(0)
        runs.append(run_scripted_program("deterministic"))
    one_by_one, in_stretches = runs
    assert len(one_by_one) > 500 and in_stretches == one_by_one
    assert looks[1] < looks[0] / 3, looks


def test_the_simulator_survives_a_handler_crash(monkeypatch):
    from eyesim import calls

    def broken(sim, robot, request):
        raise ZeroDivisionError("boom")

    monkeypatch.setitem(calls.HANDLERS, g.OP_PSD_GET, broken)
    with running_simulation(arena()) as (sim, port):
        client = ProgramClient(port)
        client.hello()
        with pytest.raises(Exception, match="internal simulator error"):
            client.call("PSD_GET", 1)
        assert client.call("OS_GET_COUNT")[0] >= 0


@pytest.mark.parametrize("module", ["engine", "requests", "schedules"])
def test_the_engine_imports_no_component_and_no_viewer_code(module):
    """Components and the web layer collect what they need; the engine only says when (events)."""
    import ast
    import importlib
    from pathlib import Path

    tree = ast.parse(Path(importlib.import_module(f"eyesim.core.{module}").__file__).read_text())
    modules = {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
    modules |= {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
    assert [m for m in modules if m.startswith(("eyesim.robot.components", "eyesim.web"))] == []


def test_the_clock_mode_is_asked_once_by_choosing_the_schedule():
    """The step loop and request handling never branch on the mode: the schedule does what differs."""
    import ast
    import importlib
    from pathlib import Path

    asked = {}
    for module in ("engine", "requests", "schedules"):
        tree = ast.parse(Path(importlib.import_module(f"eyesim.core.{module}").__file__).read_text())
        asked[module] = [
            node.lineno for node in ast.walk(tree) if isinstance(node, ast.Attribute) and node.attr == "deterministic"
        ]
    assert asked["engine"] == asked["requests"] == [] and len(asked["schedules"]) == 1, asked
