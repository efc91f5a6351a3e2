"""Simulation.replace_scene: another scene in place of the running one (the viewer's scene browser)."""

import gc
import threading
import weakref

import pytest
from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.scene import Pose, RobotPlacement


def on_sim_thread(sim, action):
    """Run action(sim) on the simulation thread; return its result or raise its exception."""
    done, result = threading.Event(), {}

    def run(s):
        try:
            result["value"] = action(s)
        except Exception as error:  # noqa: BLE001 - raised in the test
            result["error"] = error
        finally:
            done.set()

    sim.call(run)
    assert done.wait(10)
    if "error" in result:
        raise result["error"]
    return result.get("value")


def test_a_new_scene_replaces_robots_disconnects_programs_and_time_goes_on():
    with running_simulation(arena(), "realtime") as (sim, port):
        client = ProgramClient(port)
        client.hello()
        client.call("OS_GET_COUNT")
        events = []
        sim.events.subscribe(
            type(
                "Listener",
                (),
                {"wants_lcd": False, "on_event": lambda self, m: events.append(m), "on_snapshot": lambda self, m: None},
            )()
        )
        before = sim.time_us
        bigger = arena(robots=((300, 300, 0), (900, 900, 90)), size=3000)
        on_sim_thread(sim, lambda s: s.replace_scene(bigger))
        assert [r.id for r in sim.robots] == [1, 2] and sim.floor.width == pytest.approx(3.0)
        assert sim.scene is bigger and sim.time_us >= before
        assert {"type": "new-scene", "opened": True} in events
        assert not sim.sessions
        with pytest.raises((ConnectionError, OSError)):
            client.call("OS_GET_COUNT")
        again = ProgramClient(port)  # the port stays open for the new scene's programs
        again.hello()
        assert again.call("OS_GET_COUNT")[0] >= before // 1000


def test_a_scene_the_physics_cannot_build_leaves_the_old_one_running():
    with running_simulation(arena(), "realtime") as (sim, port):
        old = sim.scene
        broken = arena()
        broken = type(broken)(**{**broken.__dict__, "robots": (RobotPlacement("NoSuchType", Pose(1, 1, 0)),)})
        with pytest.raises(Exception):
            on_sim_thread(sim, lambda s: s.replace_scene(broken))
        assert sim.scene is old and [r.id for r in sim.robots] == [1]
        client = ProgramClient(port)
        client.hello()
        client.call("OS_GET_COUNT")


def test_a_replaced_scene_is_freed_in_a_run_that_froze_its_setup():
    """`eyesim run` freezes what it set up out of the garbage collector's full passes; a scene
    replaced later must still be freed (its robots and their parts hold each other)."""
    with running_simulation(arena(), "realtime") as (sim, _):
        old_robot = weakref.ref(sim.robots[0])
        gc.freeze()
        try:
            on_sim_thread(sim, lambda s: s.replace_scene(arena(robots=((600, 600, 0),))))
            assert old_robot() is None
            assert gc.get_freeze_count()  # the new scene is frozen in its place
        finally:
            gc.unfreeze()
