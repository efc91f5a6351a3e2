"""Camera images are drawn on the render thread, not on the simulation thread: another program's
calls are answered while a 5-megapixel frame is drawn, the frame's reply still comes when its
call time has passed (deterministic: at exactly that simulation time), deterministic runs with
cameras repeat bit-identically with either renderer, a frame that cannot be drawn is that call's
error alone, and a run that ends while the renderer is prepared ends normally. No timing is
asserted: a renderer held at a gate keeps the render thread busy for as long as a test needs."""

import os
import socket
import threading
from pathlib import Path

import pytest
from support.client import ProgramClient, RemoteError
from support.programs import program_builder
from support.scenes import arena
from support.rooms import square_room, write_scene
from support.simulator import running_simulation

from eyesim.physics import renderer_choice
from eyesim.protocol import generated as g

CAM5MP = 5
PSD_PROGRAMS = Path(__file__).resolve().parents[1] / "parts" / "psd" / "programs"


@pytest.fixture(scope="module")
def psd_report(tmp_path_factory):
    """The PSD tests' program that reads a robot's PSDs, built once: the robot that films nothing."""
    return program_builder(PSD_PROGRAMS, tmp_path_factory.mktemp("psd-programs"))("psd_report")


class GatedRenderer:
    """The process's real renderer (chosen on the render thread, as always), drawing only once the
    test opens the gate: while it is shut, the render thread is busy with a frame."""

    def __init__(self, choose):
        self.choose = choose
        self.gate = threading.Event()
        self.waiting = threading.Event()  # a frame has reached the gate

    def prepare(self, world, width, height):
        real = self.choose()
        if hasattr(real, "prepare"):
            real.prepare(world, width, height)

    def render(self, world, view, data=None):
        self.waiting.set()
        assert self.gate.wait(120), "the test never opened the gate"
        return self.choose().render(world, view, data)


@pytest.fixture
def gated(monkeypatch):
    renderer = GatedRenderer(renderer_choice.camera_renderer)
    monkeypatch.setattr(renderer_choice, "camera_renderer", lambda: renderer)
    yield renderer
    renderer.gate.set()


def nothing_received(client: ProgramClient) -> bool:
    """No reply has come so far (looked at without waiting)."""
    timeout = client.sock.gettimeout()
    client.sock.setblocking(False)
    try:
        return not client.inbox and not client.sock.recv(1, socket.MSG_PEEK)
    except BlockingIOError:
        return True
    finally:
        client.sock.settimeout(timeout)


def test_other_programs_are_answered_while_a_5_megapixel_frame_is_drawn(gated):
    scene = arena(robots=((500, 500, 0), (1500, 500, 180), (1000, 1500, 270)))
    with running_simulation(scene, "realtime") as (sim, port):
        camera, other = ProgramClient(port, timeout=60), ProgramClient(port)
        camera.hello("1")
        other.hello("2")
        assert camera.call("CAM_INIT", CAM5MP) == (0, 2592, 1944)
        frame = camera.send("CAM_GET")
        assert gated.waiting.wait(60)  # the render thread has the frame
        distances = [other.call("PSD_GET", 1)[0] for _ in range(50)]
        counts = [other.call("OS_GET_COUNT")[0] for _ in range(50)]
        assert all(distance > 0 for distance in distances) and counts == sorted(counts)
        newcomer = ProgramClient(port)  # a new program's handshake is answered too
        assert newcomer.hello("3")[1] == 3
        assert nothing_received(camera)  # the frame is still being drawn
        gated.gate.set()
        result, width, height, pixels = camera.reply("CAM_GET", frame)
        assert (result, width, height, len(pixels)) == (0, 2592, 1944, 2592 * 1944 * 3)
        assert len(set(pixels[::9973])) > 1  # a picture, not a blank buffer
        for client in (camera, other, newcomer):
            client.close()


def test_a_frame_being_drawn_holds_deterministic_time_at_its_reply(gated):
    """Deterministic: the frame's reply is due at its request time + CAMGet's cost. Another program,
    calling all the time, is answered up to then; its call at that time waits for the frame, and
    so does simulation time."""
    scene = arena(robots=((500, 500, 0), (1500, 500, 180)))
    with running_simulation(scene, "deterministic", expect=(1, 2)) as (sim, port):
        camera, other = ProgramClient(port, timeout=60), ProgramClient(port, timeout=60)
        camera.hello("1")
        other.hello("2")
        answered, stop = [], threading.Event()

        def keep_calling():
            while not stop.is_set():
                answered.append(other.call("OS_GET_COUNT")[0])

        caller = threading.Thread(target=keep_calling)
        caller.start()
        try:
            camera.call("CAM_INIT", CAM5MP)  # a device call: the clock read below starts a millisecond
            asked_ms = camera.call("OS_GET_COUNT")[0]  # read on a whole ms; local: CAM_GET follows 10 us later
            due_us = asked_ms * 1000 + (
                sim.call_cost_us(g.OPS_BY_NAME["OS_GET_COUNT"]) + sim.call_cost_us(g.OPS_BY_NAME["CAM_GET"])
            )
            due_ms = due_us // 1000
            frame = camera.send("CAM_GET")
            assert gated.waiting.wait(60)  # the render thread has the frame
            # The other program's clock reads show every millisecond in turn (deterministic mode);
            # it goes on up to the frame's time, and its first read after it waits for the frame.
            last_before_ms = -(-due_us // 1000) - 1
            while answered[-1] < last_before_ms:
                threading.Event().wait(0.01)
            waiting = next(s for s in sim.sessions if s.robot is not None and s.robot.id == 2)
            while not (waiting.queued or waiting.pending):  # its next call has reached the simulator
                threading.Event().wait(0.01)
            assert answered[-1] == last_before_ms
            assert [t for t in answered if t >= asked_ms]  # answered while the frame was drawn
            assert sim.time_us <= due_ms * 1000 and nothing_received(camera)  # time waits for the frame
            gated.gate.set()
            assert camera.reply("CAM_GET", frame)[:3] == (0, 2592, 1944)
            assert camera.call("OS_GET_COUNT")[0] == due_ms  # the reply came at exactly its time
        finally:
            gated.gate.set()
            camera.close()  # time no longer waits for its next call
            stop.set()
            caller.join(60)
        assert answered[-1] >= due_ms  # its waiting call was answered after the frame
        other.close()


def test_a_frame_that_cannot_be_drawn_is_an_error_reply_and_the_simulation_goes_on(monkeypatch, caplog):
    class Broken:
        def render(self, world, view, data=None):
            raise RuntimeError("the renderer broke")

    monkeypatch.setattr(renderer_choice, "camera_renderer", lambda: Broken())
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180))), "realtime") as (sim, port):
        camera, other = ProgramClient(port), ProgramClient(port)
        camera.hello("1")
        other.hello("2")
        camera.call("CAM_INIT", 0)
        with pytest.raises(RemoteError, match="internal simulator error"):
            camera.call("CAM_GET_GRAY")
        assert camera.call("OS_GET_COUNT")[0] >= 0 and other.call("PSD_GET", 1)[0] > 0
        camera.close()
        other.close()
    assert "handler for CAM_GET_GRAY from test (robot 1" in caplog.text and "the renderer broke" in caplog.text


def snapshot_run(tmp_path, programs, psd_report, run_scene, renderer: str, name: str):
    env = dict(os.environ, **({"MUJOCO_GL": "disable"} if renderer == "raycast" else {}))
    world = square_room() + ["700 1300 1300 1300 10 300 255 0 0", "1400 500 1400 900 10 300 0 0 255"]
    scene = write_scene(tmp_path, world, ["S4 600 600 30", "S4 1000 900 200", "S4 1500 1500 225"])
    program = programs("camera_drive")
    run = run_scene(
        scene, {1: program, 2: program, 3: psd_report}, "--clock", "deterministic", "--record", f"{name}.csv", env=env
    )
    assert run.returncode == 0, run.stdout + run.stderr
    return run, (tmp_path / f"{name}.csv").read_bytes()


@pytest.mark.parametrize("renderer", ["opengl", "raycast"])
def test_deterministic_runs_with_cameras_repeat_bit_identically(tmp_path, programs, psd_report, run_scene, renderer):
    first, first_path = snapshot_run(tmp_path, programs, psd_report, run_scene, renderer, "first")
    second, second_path = snapshot_run(tmp_path, programs, psd_report, run_scene, renderer, "second")
    for robot in (1, 2, 3):
        assert first.lines(robot) == second.lines(robot)
    assert first_path == second_path
    frames = first.values(1, "colour")
    assert len(frames) == 8 and all(result == 0 for result, _, _ in frames)
    assert len({checksum for _, _, checksum in frames}) > 4  # the robot drives: the pictures change
    assert len({checksum for _, _, checksum in first.values(1, "gray")}) > 4


def test_a_run_that_ends_while_the_renderer_is_prepared_exits_cleanly(tmp_path, programs, run_scene):
    """The program's CAMInit starts the render thread making an OpenGL context and the run ends at
    once: the process waits for the thread and ends normally (a context still being made at exit
    crashed it)."""
    scene = write_scene(tmp_path, square_room(), ["S4 1000 1000 0"])
    for _ in range(3):
        run = run_scene(scene, {1: programs("camera_init_exit")}, "--clock", "deterministic")
        assert run.returncode == 0, (run.returncode, run.stderr)
        assert run.values(1, "init") == [[0]]
