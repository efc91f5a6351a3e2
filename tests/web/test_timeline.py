"""The timeline over a recording and over a live run's history: frames, plots' signals, the replay server."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import aiohttp
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import eyesim_command  # noqa: E402
from support.viewer import run_async  # noqa: E402
from support.recordings import record_tour  # noqa: E402

from eyesim.protocol.channel_schema import server_message_problems
from eyesim.record import Recording
from eyesim.record.live_history import LiveHistory
from eyesim.record.timeline import FrameCursor, RecordingTimeline, answer


@pytest.fixture(scope="module")
def tour(tmp_path_factory):
    return record_tour(tmp_path_factory.mktemp("tour"), robots=2)


def frame(source, cursor, seconds):
    return json.loads(run_async(answer(source, cursor, {"type": "seek", "time": seconds})))


def kinds(message):
    return [m["type"] for m in message["messages"]]


def console(message, robot=1):
    return "".join(m["text"] for m in message["messages"] if m["type"] == "console" and m["robot"] == robot)


def test_frames_going_forward_carry_what_changed_and_going_back_start_afresh(tour):
    with Recording(tour) as recording:

        def printed(start: float, end: float, robot: int = 1) -> str:
            """Robot 1's console text the recording holds from `start` (exclusive) to `end` (s). Taken
            from the recording: a program's output is stamped when the simulator reads its pipe,
            which on a loaded machine can be a few steps after the printf."""
            events = [
                e for e in recording.events_until(round(end * 1e6)) if e["type"] == "console" and e["robot"] == robot
            ]
            before = {id(e) for e in recording.events_until(round(start * 1e6))} if start >= 0 else set()
            return "".join(e["text"] for e in events if id(e) not in before)

        source, cursor = RecordingTimeline(recording), FrameCursor()
        first = frame(source, cursor, 0.6)
        assert first["clear"] == [1, 2, 3] and first["time"] == 0.6  # robot 3 has no program
        assert kinds(first).count("program") == 2 and kinds(first).count("lcd") == 3
        assert console(first) == printed(-1, 0.6) and console(first).startswith("step 1\n")
        snapshot = first["messages"][-1]
        assert snapshot["type"] == "snapshot" and snapshot == recording.snapshot_at(600_000)
        assert [r["kind"] for r in snapshot["rays"]].count("psd") == 12

        later = frame(source, cursor, 1.4)  # step 3 is printed at 1.0 s
        assert later["clear"] == [] and console(later) == printed(0.6, 1.4)
        assert console(first) + console(later) == "step 1\nstep 2\nstep 3\n"
        assert "program" not in kinds(later) and "menu" not in kinds(later)
        assert frame(source, cursor, 1.4)["messages"] == [later["messages"][-1]]  # nothing changed but the time

        back = frame(source, cursor, 0.2)
        assert back["clear"] == [1, 2, 3] and console(back) == "step 1\n"

        beyond = frame(source, cursor, 99)
        assert beyond["time"] == recording.end_us / 1e6 and "done" in console(beyond)


def test_signals_series_and_paths(tour):
    with Recording(tour) as recording:
        source, cursor = RecordingTimeline(recording), FrameCursor()
        signals = json.loads(run_async(answer(source, cursor, {"type": "signals"})))["signals"]
        ids = {s["id"] for s in signals}
        assert {"robot/1/x", "robot/1/phi", "robot/1/v", "robot/1/encoder.2", "robot/2/psd.1", "robot/2/battery"} <= ids
        series = json.loads(
            run_async(answer(source, cursor, {"type": "series", "ids": ["robot/1/x", "robot/1/psd.1"]}))
        )
        x, psd = series["series"]
        assert (
            len(x["times"]) == len(recording.pose_times)
            and x["values"][0] == recording.snapshot_at(0)["robots"][0]["pos"][0]
        )
        assert psd["times"] == [r[0] / 1e6 for r in recording.psd[1]] and len(psd["values"]) == 4
        paths = json.loads(run_async(answer(source, cursor, {"type": "paths"})))["robots"]
        assert [p["id"] for p in paths] == [1, 2, 3] and len(paths[0]["points"]) == 2 * len(paths[0]["times"]) > 40
        for bad, text in [
            ({"type": "seek", "time": "soon"}, "not a number"),
            ({"type": "series", "ids": ["robot/9/x"]}, "no signal"),
            ({"type": "series", "ids": "robot/1/x"}, "must be a list"),
            ({"type": "jump"}, "unknown message"),
        ]:
            with pytest.raises(ValueError, match=text):
                run_async(answer(source, cursor, bad))


def test_the_live_history_keeps_a_bounded_recent_past():
    history = LiveHistory([1], seconds=10)
    for step in range(0, 1000):  # 25 s at 40 snapshots per second
        time = step / 40
        history.add_snapshot(
            {
                "type": "snapshot",
                "time": time,
                "robots": [{"id": 1, "pos": [time, 0, 0], "quat": [1, 0, 0, 0]}],
                "objects": [],
                "bodies": [],
            },
            [{"robot": 1, "odometry": None, "speed": None, "encoders": {}, "battery": 8.0}],
        )
        if step % 100 == 0:
            history.add_event(
                round(time * 1e6), {"type": "console", "robot": 1, "stream": "stdout", "text": f"{step}\n"}
            )
            history.add_image(1, "lcd", round(time * 1e6), json.dumps({"type": "lcd", "robot": 1, "png": str(step)}))
    # at least the last 10 s, trimmed every 64 snapshots
    assert 13.3 <= history.start_us / 1e6 <= 15.0 and history.end_us == 24_975_000
    cursor = FrameCursor()
    old = frame(history, cursor, 0)  # before the history: its oldest moment
    assert old["time"] == history.start_us / 1e6 and old["messages"][-1]["robots"][0]["pos"][0] == old["time"]
    assert [m["png"] for m in old["messages"] if m["type"] == "lcd"] == ["500"]  # the image shown then, kept
    assert console(frame(history, FrameCursor(), 24.9)) == "600\n700\n800\n900\n"


def test_replay_server_answers_the_viewer_and_refuses_changes(tour):
    process = subprocess.Popen(
        eyesim_command("replay", str(tour), "--viewer-port", "0", "--no-token"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        url = re.search(r"(http://\S+)", process.stdout.readline()).group(1)
        messages = run_async(_talk(url, [{"type": "pause"}, "not json", {"type": "seek", "time": 1.0}]))
    finally:
        process.terminate()
        process.wait(timeout=10)
    assert [m["type"] for m in messages[:3]] == ["scene", "timeline", "frame"]
    assert (
        messages[1]
        == {"type": "timeline", "mode": "replay", "name": "tour.mcap", "start": 0.0, "end": messages[1]["end"]}
        and messages[1]["end"] > 2
    )
    assert messages[3]["type"] == "error" and "can be watched, not changed" in messages[3]["message"]
    assert messages[4]["type"] == "error" and "not valid JSON" in messages[4]["message"]
    assert messages[5]["type"] == "frame" and messages[5]["time"] == 1.0
    # a replay speaks the same channel as a live simulator (interface/viewer.schema.json)
    assert [problem for m in messages for problem in server_message_problems(m)] == []


async def _talk(url, commands):
    received = []
    async with aiohttp.ClientSession() as session:
        async with session.get(url + "scene/mesh/robot/1") as response:
            assert response.status == 404  # S4 has no .obj model
        async with session.ws_connect(url + "ws") as ws:
            for _ in range(3):
                received.append(json.loads((await ws.receive()).data))
            for command in commands:
                await ws.send_str(command if isinstance(command, str) else json.dumps(command))
                received.append(json.loads((await ws.receive(timeout=10)).data))
    return received
