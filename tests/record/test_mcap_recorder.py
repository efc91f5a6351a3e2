"""MCAP recordings of a real C program: channels and schemas, CSV export, replayed state equals the live run."""

from __future__ import annotations

import json
import math
import re
import subprocess

import jsonschema
import numpy as np
import pytest
from mcap.reader import make_reader
from PIL import Image
from support.programs import build, eyesim_command, run_headless

from eyesim.core.clock import DETERMINISTIC, Clock
from eyesim.core.engine import Simulation
from eyesim.net.program_server import ProgramServer
from eyesim.programs.launcher import Launcher
from eyesim.record import Recorder, Recording, schemas
from eyesim.robot.components.lcd import Lcd
from eyesim.scene import DEFAULT_SCENE, load_scene

ROBOT_CHANNELS = {
    "state": "eyesim.RobotState",
    "lcd": "foxglove.CompressedImage",
    "camera": "foxglove.CompressedImage",
    "lidar": "foxglove.LaserScan",
    "psd": "eyesim.PsdReading",
    "command": "eyesim.Command",
    "input": "eyesim.Input",
}


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    """The tour program recorded headless and deterministic, as .mcap and .csv in one run."""
    directory = tmp_path_factory.mktemp("recorded")
    program = build("record_tour", directory)
    result = run_headless(
        "--program", f"1={program}", "--record", "run.mcap", "--record", "run.csv", "--save-lcd", "lcd", cwd=directory
    )
    assert result.returncode == 0, result.stdout + result.stderr
    return directory


def test_the_recording_has_the_documented_channels_and_every_message_fits_its_schema(recorded):
    with open(recorded / "run.mcap", "rb") as file:
        reader = make_reader(file)
        summary = reader.get_summary()
        channels = {c.topic: summary.schemas[c.schema_id] for c in summary.channels.values()}
        expected = {
            "/scene": "eyesim.Scene",
            "/tf": "foxglove.FrameTransforms",
            "/events": "eyesim.ViewerEvent",
            "/log": "foxglove.Log",
            "/edits": "eyesim.SceneEdit",
            "/rays": "eyesim.SensorRays",
            **{f"/robot/1/{name}": schema for name, schema in ROBOT_CHANNELS.items()},
        }
        assert {topic: schema.name for topic, schema in channels.items()} == expected
        assert all(c.message_encoding == "json" for c in summary.channels.values())
        assert all(schema.encoding == "jsonschema" for schema in channels.values())
        counts = {}
        for schema, channel, message in reader.iter_messages():
            jsonschema.validate(json.loads(message.data), json.loads(schema.data))
            counts[channel.topic] = counts.get(channel.topic, 0) + 1
    assert counts["/scene"] == 1
    # 2.036 s at 100 Hz: four 500 ms waits, the 4 ms call time of each of the nine calls that reach the
    # robot (PSDGet, VWSetSpeed) and 10 us of each LCD call (docs/protocol.md#what-a-call-costs)
    assert counts["/tf"] == counts["/robot/1/state"] == 203
    assert counts["/robot/1/psd"] == 4 and counts["/robot/1/command"] == 5
    assert counts["/robot/1/lcd"] >= 5  # the start, four steps, "done"
    logs = [
        json.loads(m.data)["message"]
        for _, c, m in make_reader(open(recorded / "run.mcap", "rb")).iter_messages(topics=["/log"])
    ]
    assert logs[0] == "program record_tour started"  # console lines and the exit race each other through pipes
    assert sorted(logs[1:]) == sorted(
        ["step 1", "step 2", "step 3", "step 4", "done", "program record_tour exited with code 0"]
    )


def test_export_writes_the_same_csv_as_the_live_run(recorded):
    result = subprocess.run(
        eyesim_command("export", "run.mcap", "--csv", "exported.csv"), capture_output=True, text=True, cwd=recorded
    )
    assert result.returncode == 0, result.stderr
    assert (recorded / "exported.csv").read_bytes() == (recorded / "run.csv").read_bytes()


def test_the_recording_ends_with_the_lcd_the_run_ended_with(recorded):
    with Recording(recorded / "run.mcap") as recording:
        last = recording.image_time(1, "lcd", recording.end_us)
        png = recording.image(1, "lcd", last)
    assert png["format"] == "png"
    saved = np.asarray(Image.open(recorded / "lcd" / "robot1-lcd.png").convert("RGB"))
    assert np.array_equal(_decode_image(png["data"]), saved)


def test_deterministic_runs_record_the_same_poses_sensors_commands_and_lcds(recorded, tmp_path):
    result = run_headless("--program", f"1={recorded / 'record_tour'}", "--record", "again.mcap", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    racing = {schemas.EVENTS, schemas.LOG}  # console lines arrive through pipes, at no fixed simulation time

    def messages(path):
        with open(path, "rb") as file:
            return [
                (c.topic, m.log_time, m.data) for _, c, m in make_reader(file).iter_messages() if c.topic not in racing
            ]

    assert messages(recorded / "run.mcap") == messages(tmp_path / "again.mcap")


def test_replayed_poses_and_lcds_equal_the_live_run_at_chosen_times(recorded, tmp_path):
    """The in-process API: a Recorder on a Simulation that runs the C program; a probe keeps what the
    live run had at chosen times, and the recording must give exactly that back."""
    chosen = {510_000, 1_020_000, 1_530_000, 1_700_000}  # multiples of the LCD period (34 ms), and one between
    live: dict[int, tuple] = {}

    def probe(sim):
        if sim.time_us in chosen:
            robot = sim.robots[0]
            pose = [float(v) for v in (*sim.world.data.xpos[robot.body], *sim.world.data.xquat[robot.body])]
            live[sim.time_us] = (pose, robot.component(Lcd).screen().copy())

    sim = Simulation(load_scene(DEFAULT_SCENE), Clock(DETERMINISTIC))
    server = ProgramServer(sim, "127.0.0.1", 0)
    server.start()
    launcher = Launcher(sim, "127.0.0.1", server.port, echo=False)
    try:
        with Recorder(sim, tmp_path / "api.mcap"):
            sim.step_observers.append(probe)
            launcher.start(1, recorded / "record_tour")
            sim.stop_when_programs_done = True
            sim.run(until=10)
            launcher.stop_all(let_finish=5.0)
            sim.shutdown_programs()
            sim.handle_queued()  # the program's exit, for the recording
    finally:
        launcher.stop_all()
        sim.shutdown_programs()
        server.stop()
    assert set(live) == chosen

    with Recording(tmp_path / "api.mcap") as recording:
        for time_us, (pose, screen) in sorted(live.items()):
            snapshot = recording.snapshot_at(time_us)
            assert snapshot["robots"][0]["pos"] + snapshot["robots"][0]["quat"] == pose
            if time_us % recording_lcd_period(recording) == 0:
                image = recording.image(1, "lcd", recording.image_time(1, "lcd", time_us))
                assert np.array_equal(_decode_image(image["data"]), screen), f"LCD at t={time_us / 1e6} s"
        programs = [e for _, e in recording.events if e["type"] == "program"]
        assert [e["event"] for e in programs] == ["started", "exited"] and programs[-1]["exit_code"] == 0
        texts = "".join(e["text"] for e in recording.events_until(1_020_000) if e["type"] == "console")
        assert "step 1\nstep 2\n" in texts and "step 4" not in texts


def recording_lcd_period(recording) -> int:
    return round(1e6 / float(recording.metadata["eyesim"]["lcd_rate_hz"]))


def test_camera_images_and_lidar_scans_are_recorded_as_the_program_saw_them(tmp_path):
    program = build("record_sensors", tmp_path)
    result = run_headless("--program", f"1={program}", "--record", "sensors.mcap", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    camera = re.search(r"camera (\d+) (\d+) centre (\d+) (\d+) (\d+)", result.stdout)
    lidar = re.search(r"lidar ahead (\d+) left (\d+)", result.stdout)
    assert camera and lidar, result.stdout
    with open(tmp_path / "sensors.mcap", "rb") as file:
        messages = {
            c.topic: json.loads(m.data)
            for _, c, m in make_reader(file).iter_messages(topics=["/robot/1/camera", "/robot/1/lidar"])
        }
    image = messages["/robot/1/camera"]
    assert image["format"] == "jpeg" and image["frame_id"] == "robot/1"
    pixels = _decode_image(image["data"])
    width, height = int(camera.group(1)), int(camera.group(2))
    assert pixels.shape == (height, width, 3) == (240, 320, 3)
    centre = pixels[height // 2, width // 2].astype(int)
    assert np.abs(centre - [int(camera.group(k)) for k in (3, 4, 5)]).max() < 25  # JPEG is close, not exact
    scan = messages["/robot/1/lidar"]
    assert len(scan["ranges"]) == 360 and scan["start_angle"] == pytest.approx(math.pi)
    assert scan["end_angle"] == pytest.approx(math.pi - math.radians(359))
    assert round(scan["ranges"][180] * 1000) == int(lidar.group(1))  # ahead
    assert round(scan["ranges"][90] * 1000) == int(lidar.group(2))  # at start_angle - 90 degrees: left


def test_inputs_and_viewer_edits_are_recorded(tmp_path):
    from eyesim.core import inputs, robot_input

    sim = Simulation(load_scene(DEFAULT_SCENE), Clock(DETERMINISTIC))
    sim.schedule(100_000, lambda s: robot_input.key(s, 1, 2))
    sim.schedule(200_000, lambda s: robot_input.touch(s, 1, 100, 50))
    sim.schedule(300_000, lambda s: robot_input.analog(s, 1, 2, 700))
    # the viewer's command is checked, then queued: done at the next step boundary
    sim.schedule(
        400_000, lambda s: s.call(inputs.prepare(s, {"type": "place", "robot": 1, "x": 1.5, "y": 1.0, "phi": 1.0}))
    )
    with Recorder(sim, tmp_path / "inputs.mcap"):
        sim.run(until=1)
    with open(tmp_path / "inputs.mcap", "rb") as file:
        found = [
            (c.topic, m.log_time // 1000, json.loads(m.data))
            for _, c, m in make_reader(file).iter_messages(topics=["/robot/1/input", "/edits"])
        ]
    assert found == [
        ("/robot/1/input", 100_000, {"robot": 1, "input": "key", "key": 2}),
        ("/robot/1/input", 200_000, {"robot": 1, "input": "touch", "x": 100, "y": 50}),
        ("/robot/1/input", 300_000, {"robot": 1, "input": "analog", "channel": 2, "value": 700}),
        ("/edits", 402_000, {"edit": "place", "robot": 1, "x": 1.5, "y": 1.0, "phi": 1.0}),
    ]
    with Recording(tmp_path / "inputs.mcap") as recording:  # and the robot is where it was put
        assert recording.snapshot_at(500_000)["robots"][0]["pos"][:2] == pytest.approx([1.5, 1.0], abs=1e-3)


def _decode_image(data: str) -> np.ndarray:
    import base64
    import io

    return np.asarray(Image.open(io.BytesIO(base64.b64decode(data))).convert("RGB"))


def test_a_replaced_scene_goes_on_in_the_next_file(tmp_path):
    (tmp_path / "two.sim").write_text("S4 500 500 0\nS4 1500 500 90\n")
    sim = Simulation(load_scene(DEFAULT_SCENE), Clock(DETERMINISTIC))
    with Recorder(sim, tmp_path / "run.mcap") as recorder:
        sim.run(until=0.2)
        sim.replace_scene(load_scene(tmp_path / "two.sim"))
        sim.run(until=0.5)
    assert recorder.paths == [tmp_path / "run.mcap", tmp_path / "run-2.mcap"]
    with Recording(tmp_path / "run.mcap") as first, Recording(tmp_path / "run-2.mcap") as second:
        assert first.robot_ids == [1] and first.end_us <= 200_000
        assert second.robot_ids == [1, 2]
        assert second.start_us == 200_000 and second.end_us >= 498_000
        assert second.snapshot_at(400_000)["robots"][1]["pos"][:2] == pytest.approx([1.5, 0.5], abs=0.01)
