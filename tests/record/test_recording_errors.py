"""Files that are not good recordings get a clear error, from the API and from the commands."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from mcap.writer import Writer
from support.programs import eyesim_command

from eyesim.core.clock import DETERMINISTIC, Clock
from eyesim.core.engine import Simulation
from eyesim.record import Recorder, Recording, RecordingError
from eyesim.scene import DEFAULT_SCENE, load_scene


@pytest.fixture(scope="module")
def good(tmp_path_factory):
    """A real recording of a few seconds of the default arena (no programs)."""
    path = tmp_path_factory.mktemp("good") / "good.mcap"
    sim = Simulation(load_scene(DEFAULT_SCENE), Clock(DETERMINISTIC))
    with Recorder(sim, path):
        sim.run(until=3)
    return path


def test_a_good_recording_opens(good):
    with Recording(good) as recording:
        assert recording.end_us == 3_000_000 and len(recording.pose_times) == 300


def broken_files(good, directory):
    data = good.read_bytes()
    other = directory / "other.mcap"
    with open(other, "wb") as file:  # a valid MCAP file of someone else's
        writer = Writer(file)
        writer.start()
        channel = writer.register_channel("/chatter", "json", 0)
        writer.add_message(channel, log_time=1, data=b"{}", publish_time=1)
        writer.finish()
    damaged = bytearray(data)
    middle = len(data) // 2
    damaged[len(data) // 4 : len(data) // 4 + 64] = bytes(64)  # inside the compressed messages
    files = {
        "missing.mcap": (None, "cannot read"),
        "folder.mcap": (b"", "is a directory"),
        "empty.mcap": (b"", "is empty"),
        "notes.mcap": (b"time_s,robot,x\n0.01,1,0.5\n", "not an MCAP file"),
        "truncated.mcap": (data[:middle], "is truncated"),
        "damaged.mcap": (bytes(damaged), "is damaged"),
        "other.mcap": (other.read_bytes(), "not an EyeSim recording"),
    }
    for name, (content, _) in files.items():
        if name == "folder.mcap":
            (directory / name).mkdir()
        elif content is not None:
            (directory / name).write_bytes(content)
    return {directory / name: text for name, (_, text) in files.items()}


def test_every_kind_of_bad_file_has_its_own_clear_error(good, tmp_path):
    for path, text in broken_files(good, tmp_path).items():
        with pytest.raises(RecordingError, match=text):
            Recording(path)


def test_the_commands_say_what_is_wrong_without_a_traceback(good, tmp_path):
    files = broken_files(good, tmp_path)
    commands = [["export", str(path), "--csv", str(tmp_path / "out.csv")] for path in files]
    some = [path for path in files if path.name in ("truncated.mcap", "notes.mcap")]
    commands += [
        [name, str(path), *extra]
        for path in some
        for name, *extra in (["plot", "-o", "p.png"], ["render", "-o", "v.mp4"], ["replay", "--viewer-port", "0"])
    ]
    for command in commands:
        result = subprocess.run(eyesim_command(*command), capture_output=True, text=True, cwd=tmp_path)
        text = files[Path(command[1])]
        assert result.returncode == 2, (command, result.stderr)
        assert text in result.stderr and "Traceback" not in result.stderr, result.stderr
