"""`eyesim render` (a top-down video with ffmpeg) and `eyesim plot` (paths over the map) of a recording."""

from __future__ import annotations

import subprocess

import imageio_ffmpeg
import numpy as np
import pytest
from PIL import Image
from support.programs import eyesim_command
from support.recordings import record_tour

from eyesim.record import Recording
from eyesim.record.top_view import TopView
from eyesim.record.video import frame_times


@pytest.fixture(scope="module")
def tour(tmp_path_factory):
    return record_tour(tmp_path_factory.mktemp("video"), robots=2)


def eyesim(*args, cwd):
    return subprocess.run(eyesim_command(*args), capture_output=True, text=True, cwd=cwd)


def test_render_writes_one_frame_per_time_step_of_the_recording(tour):
    result = eyesim("render", str(tour), "-o", "tour.mp4", cwd=tour.parent)
    assert result.returncode == 0, result.stderr
    with Recording(tour) as recording:
        expected = frame_times(recording.start_us, recording.end_us, 30, 1.0)
        robot = recording.snapshot_at(expected[45])["robots"][0]
        view = TopView(recording.scene, 720)
    assert len(expected) == 62 and f"{len(expected)} frames" in result.stdout  # 2.03 s at 30 per second
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(tour.parent / "tour.mp4"))
    assert frames == len(expected)
    reader = imageio_ffmpeg.read_frames(str(tour.parent / "tour.mp4"))
    meta = next(reader)
    assert meta["size"] == view.size == (720, 720) and meta["fps"] == 30
    frame = np.frombuffer([f for _, f in zip(range(46), reader)][-1], dtype=np.uint8).reshape(720, 720, 3)
    u, v = (round(c) for c in view.pixel(*robot["pos"][:2]))
    colour = frame[v - 3 : v + 4, u + 8 : u + 14].reshape(-1, 3).mean(axis=0)  # beside the white heading line
    assert np.abs(colour - (40, 90, 200)).max() < 30  # robot 1's body is where the recording has it


def test_render_takes_speed_fps_size_and_a_time_range(tour):
    result = eyesim(
        "render",
        str(tour),
        "-o",
        "fast.webm",
        "--fps",
        "10",
        "--speed",
        "2",
        "--size",
        "200",
        "--start",
        "0.5",
        "--end",
        "1.5",
        cwd=tour.parent,
    )
    assert result.returncode == 0, result.stderr
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(tour.parent / "fast.webm"))
    assert frames == 6  # 1 s at 2x, 10 per second: 0.5, 0.7, ..., 1.5
    assert next(imageio_ffmpeg.read_frames(str(tour.parent / "fast.webm")))["size"] == (200, 200)


@pytest.mark.parametrize(
    "args, message",
    [
        (["-o", "tour.gif"], "must end in .mp4 or .webm"),
        (["-o", "x.mp4", "--fps", "0"], "expected 1 to 120"),
        (["-o", "x.mp4", "--speed", "-1"], "positive factor"),
        (["-o", "x.mp4", "--end", "99"], "goes from 0 to"),
        (["-o", "missing/x.mp4"], "cannot write missing/x.mp4: the folder"),
    ],
)
def test_render_says_what_is_wrong_with_its_options(tour, args, message):
    result = eyesim("render", str(tour), *args, cwd=tour.parent)
    assert result.returncode == 2 and message in result.stderr and "Traceback" not in result.stderr


def test_plot_draws_the_paths_over_the_map(tour):
    result = eyesim("plot", str(tour), "-o", "paths.png", cwd=tour.parent)
    assert result.returncode == 0, result.stderr
    image = np.asarray(Image.open(tour.parent / "paths.png").convert("RGB")).astype(int)
    assert image.shape[1] == 1050
    blue, orange = np.array([31, 119, 180]), np.array([255, 127, 14])  # robots 1 and 2 in matplotlib's colours
    assert (np.abs(image - blue).sum(axis=2) < 30).sum() > 500
    assert (np.abs(image - orange).sum(axis=2) < 30).sum() > 500
    bad = eyesim("plot", str(tour), "-o", "paths.txt", cwd=tour.parent)
    assert bad.returncode == 2 and "must end in .png, .svg or .pdf" in bad.stderr


def test_a_run_edited_in_the_viewer_is_drawn_with_the_scene_that_ran(tmp_path):
    """An edit (a wall and a robot added while the run goes on) makes a new scene in the same
    recording: the video draws each frame with the scene of its time, and the plot draws the last
    scene with every robot's path."""
    from eyesim.core.clock import DETERMINISTIC, Clock
    from eyesim.core.engine import Simulation
    from eyesim.record import Recorder
    from eyesim.scene import load_scene

    (tmp_path / "room.wld").write_text("floor 2000 2000\n")
    (tmp_path / "before.sim").write_text("world room.wld\nS4 500 500 0\n")
    (tmp_path / "walled.wld").write_text("floor 2000 2000\n1000 200 1000 1800\n")
    (tmp_path / "after.sim").write_text("world walled.wld\nS4 500 500 0\nS4 1500 1500 90\n")
    sim = Simulation(load_scene(tmp_path / "before.sim"), Clock(DETERMINISTIC))
    with Recorder(sim, tmp_path / "run.mcap"):
        sim.run(until=0.5)
        sim.replace_scene(load_scene(tmp_path / "after.sim"), opened=False)  # what an edit does
        sim.run(until=1.0)
    with Recording(tmp_path / "run.mcap") as recording:
        assert len(recording.segments) == 2 and recording.robot_ids == [1, 2]
        view = TopView(recording.segments[-1].scene, 400)
    result = eyesim("render", "run.mcap", "-o", "run.mp4", "--size", "400", "--fps", "10", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    reader = imageio_ffmpeg.read_frames(str(tmp_path / "run.mp4"))
    assert next(reader)["size"] == view.size  # its first item says what the frames are
    frames = [np.frombuffer(f, np.uint8).reshape(view.size[1], view.size[0], 3) for f in reader]
    x, y = (round(v) for v in view.pixel(1.0, 1.0))  # the middle of the added wall
    floor_colour = frames[0][y, x].astype(int)
    assert np.abs(frames[-1][y, x].astype(int) - floor_colour).sum() > 100  # the wall is there at the end
    assert np.abs(frames[2][y, x].astype(int) - floor_colour).sum() < 30  # and not before the edit
    result = eyesim("plot", "run.mcap", "-o", "paths.svg", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    drawn = (tmp_path / "paths.svg").read_text()
    assert "robot 1 S4" in drawn and "robot 2 S4" in drawn and "the scene as edited at 0.5 s" in drawn
