"""The rest of EyeSim's commands under Wine, on one small scene and one recording shared by the
module: `eyesim convert` (text to JSON and back), `eyesim schema`, a run with `--record x.mcap`,
then `eyesim export`, `eyesim plot`, `eyesim render` and `eyesim replay` of that recording, and
`eyesim grade --cluster local:1` (a Dask LocalCluster of Windows worker processes). Their outputs
are read here, on Linux: the JSON against the schemas, the CSV's poses, the PNG's pixels, the
video's frames, the replay's page and viewer channel over HTTP."""

from __future__ import annotations

import asyncio
import json
import math
import re
import shutil
import uuid
from pathlib import Path

import aiohttp
import imageio_ffmpeg
import jsonschema
import numpy as np
import pytest
from PIL import Image
from wine_sim import HERE, OutputReader, kill_processes, no_process_left, wait_until

from eyesim.record import Recording
from eyesim.record.top_view import TopView
from eyesim.record.video import frame_times

WORLD = """# a walled 1.2 m square
floor 1200 1200
0 0 1200 0
1200 0 1200 1200
1200 1200 0 1200
0 1200 0 0
"""
SCENE = """# one S4 in the bottom left, running square.py
world small.wld
S4 300 300 0 square.py
"""
# 400 mm east, a quarter turn left, 300 mm north: it ends at (700, 600) facing north.
PROGRAM = """from eye import *

LCDPrintf("square\\n")
VWStraight(400, 300)
VWWait()
VWTurn(90, 90)
VWWait()
VWStraight(300, 300)
VWWait()
print("done", flush=True)
"""
SECONDS = 6  # the run's --until: the program is done by then
END = (0.7, 0.6)  # metres


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("commands")
    (folder / "small.wld").write_text(WORLD)
    (folder / "small.sim").write_text(SCENE)
    (folder / "square.py").write_text(PROGRAM)
    return folder


@pytest.fixture(scope="module")
def recording(windows, folder) -> Path:
    """small.sim run headless under Wine, recorded to run.mcap and, as it runs, to run.csv."""
    result = windows.run(
        "run",
        "small.sim",
        "--headless",
        "--until",
        str(SECONDS),
        "--port",
        "0",
        "--record",
        "run.mcap",
        "--record",
        "run.csv",
        cwd=folder,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "program square.py: exit code 0" in result.stdout, result.stdout
    return folder / "run.mcap"


def trajectory(path: Path) -> list[dict[str, float]]:
    """The rows of a trajectory CSV (time_s, robot, x, y, z in metres, quaternion)."""
    lines = path.read_text().splitlines()
    names = lines[0].split(",")
    return [dict(zip(names, map(float, line.split(",")))) for line in lines[1:]]


def heading(row: dict[str, float]) -> float:
    """Degrees, counter-clockwise from the x axis (the robot turns about z only)."""
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


@pytest.fixture(scope="module")
def scene_json(windows, folder) -> Path:
    """small.sim converted to JSON under Wine."""
    result = windows.run("convert", "small.sim", "-o", "small.json", cwd=folder)
    assert result.returncode == 0, result.stdout + result.stderr
    return folder / "small.json"


def test_convert_writes_json_and_back(windows, folder, scene_json):
    scene = json.loads(scene_json.read_text())
    assert scene["format"] == "eyesim.scene" and scene["world"] == "small.wld"
    assert scene["placements"] == [{"type": "S4", "x": 300.0, "y": 300.0, "phi": 0.0, "program": "square.py"}]

    result = windows.run("convert", "small.json", cwd=folder)  # back to the text format, printed
    assert result.returncode == 0, result.stdout + result.stderr
    lines = [line for line in result.stdout.splitlines() if line and not line.startswith("#")]
    assert lines == ["world small.wld", "S4 300 300 0 square.py"], result.stdout


def test_schema_export_writes_schemas_the_converted_scene_meets(windows, folder, scene_json):
    result = windows.run("schema", "export", "schemas", cwd=folder)
    assert result.returncode == 0, result.stdout + result.stderr
    written = sorted(path.name for path in (folder / "schemas").iterdir())
    kinds = ["maze", "object", "robot", "scene", "world"]
    assert written == [f"{kind}.schema.json" for kind in kinds]
    for name in written:
        jsonschema.Draft202012Validator.check_schema(json.loads((folder / "schemas" / name).read_text()))

    scene_schema = json.loads((folder / "schemas" / "scene.schema.json").read_text())
    scene = json.loads(scene_json.read_text())
    jsonschema.validate(scene, scene_schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(dict(scene, placements=[{"type": "S4", "x": "far"}]), scene_schema)


def test_the_recorded_run_drives_the_square(recording):
    path = [row for row in trajectory(recording.with_suffix(".csv")) if row["robot"] == 1]
    assert len(path) == SECONDS * 100  # a row every 10 ms of simulated time
    assert (path[0]["x"], path[0]["y"]) == pytest.approx((0.3, 0.3), abs=0.002)
    assert (path[-1]["x"], path[-1]["y"]) == pytest.approx(END, abs=0.01)
    assert heading(path[-1]) == pytest.approx(90, abs=2)
    with Recording(recording) as opened:  # the Windows simulator's MCAP, read on Linux
        assert opened.duration_s == pytest.approx(SECONDS)
        [robot] = opened.snapshot_at(opened.end_us)["robots"]
        assert robot["pos"][:2] == pytest.approx(END, abs=0.01)


def test_export_writes_the_csv_the_run_wrote(windows, recording):
    result = windows.run("export", recording.name, "--csv", "exported.csv", cwd=recording.parent)
    assert result.returncode == 0, result.stdout + result.stderr
    assert f"{SECONDS * 100} rows to exported.csv" in result.stdout, result.stdout
    assert (recording.parent / "exported.csv").read_bytes() == recording.with_suffix(".csv").read_bytes()


def test_plot_draws_the_path(windows, recording, artifact):
    result = windows.run("plot", recording.name, "-o", "paths.png", cwd=recording.parent)
    assert result.returncode == 0, result.stdout + result.stderr
    image = Image.open(recording.parent / "paths.png")
    assert image.format == "PNG" and image.size[0] == 1050  # matplotlib's figure, as on Linux
    shutil.copy(recording.parent / "paths.png", artifact("windows-plot.png"))
    pixels = np.asarray(image.convert("RGB")).astype(int)
    # The floor fills the axes from 0 to 1.2 m: its colour's extent maps pixels to metres.
    floor = np.abs(pixels - pixels[image.size[1] // 4, image.size[0] // 4]).sum(axis=2) < 6
    rows, columns = np.nonzero(floor)
    left, right, top, bottom = columns.min(), columns.max(), rows.min(), rows.max()
    blue = np.abs(pixels - (31, 119, 180)).sum(axis=2) < 30  # robot 1 in matplotlib's colours
    assert blue.sum() > 500
    # The longest blue row is the leg east (y = 0.3 m), the longest column the leg north (x = 0.7 m).
    east_leg_y = (bottom - blue.sum(axis=1).argmax()) / (bottom - top) * 1.2
    north_leg_x = (blue.sum(axis=0).argmax() - left) / (right - left) * 1.2
    assert (north_leg_x, east_leg_y) == pytest.approx((0.7, 0.3), abs=0.01)


def test_render_draws_the_robot_where_the_recording_has_it(windows, recording, artifact):
    result = windows.run(
        "render", recording.name, "-o", "run.mp4", "--size", "240", "--fps", "10", cwd=recording.parent
    )
    assert result.returncode == 0, result.stdout + result.stderr
    with Recording(recording) as opened:
        times = frame_times(opened.start_us, opened.end_us, 10, 1.0)
        robot = opened.snapshot_at(times[-1])["robots"][0]
        view = TopView(opened.scene, 240)
    assert f"{len(times)} frames to run.mp4" in result.stdout, result.stdout
    video = str(recording.parent / "run.mp4")
    assert imageio_ffmpeg.count_frames_and_secs(video)[0] == len(times)
    reader = imageio_ffmpeg.read_frames(video)
    meta = next(reader)
    assert meta["size"] == view.size == (240, 240) and meta["fps"] == 10
    last = np.frombuffer(list(reader)[-1], dtype=np.uint8).reshape(240, 240, 3)
    Image.fromarray(last).save(artifact("windows-render-last-frame.png"))
    u, v = (round(c) for c in view.pixel(*robot["pos"][:2]))
    body = last[v + 3 : v + 6, u - 5 : u + 6].reshape(-1, 3).mean(axis=0)  # behind the heading line (north)
    assert np.abs(body - (40, 90, 200)).max() < 40, body  # robot 1's blue


def test_replay_serves_the_recording(windows, recording):
    with no_process_left(windows.path(recording.parent)):  # the recording's path names the folder
        process = windows.start("replay", windows.path(recording), "--viewer-port", "0", cwd=recording.parent)
        output = OutputReader(process)
        try:
            found = output.wait_for(r"EyeSim replay of run\.mcap \(([\d.]+) s\): (http://\S+)", timeout=120)
            assert float(found.group(1)) == pytest.approx(SECONDS)
            page, refused, messages = asyncio.run(talk_to_replay(found.group(2)))
        finally:
            process.terminate()  # Wine ends the Windows process
            process.wait(timeout=60)
    assert page.startswith("<!doctype html>"), page[:200]
    assert "missing or wrong access token" in refused
    scene, timeline, first, last = messages
    assert scene["type"] == "scene" and scene["name"] == "small.sim" and scene["floor"]["width"] == 1.2
    assert timeline == {"type": "timeline", "mode": "replay", "name": "run.mcap", "start": 0.0, "end": SECONDS}
    assert first["type"] == "frame" and first["time"] == 0.0
    assert last["type"] == "frame" and last["time"] == SECONDS
    [robot] = [m for m in last["messages"] if m["type"] == "snapshot"][0]["robots"]
    assert robot["pos"][:2] == pytest.approx(END, abs=0.01)
    assert any(m["type"] == "console" and m["text"] == "done\n" for m in last["messages"]), last["messages"]


async def talk_to_replay(url: str) -> tuple[str, str, list[dict]]:
    """The page at `url` (with its token), the refusal of a request without the token, and the viewer
    channel's first three messages and the frame answering a seek to the end."""
    plain = url.split("?")[0]
    async with aiohttp.ClientSession() as session:
        async with session.get(plain) as response:
            assert response.status == 403
            refused = await response.text()
        async with session.get(url) as response:
            assert response.status == 200
            page = await response.text()
        async with session.ws_connect(url.replace("/?", "/ws?")) as ws:
            messages = [json.loads((await ws.receive(timeout=60)).data) for _ in range(3)]
            await ws.send_str(json.dumps({"type": "seek", "time": SECONDS}))
            messages.append(json.loads((await ws.receive(timeout=60)).data))
    return page, refused, messages


def test_grade_on_a_dask_local_cluster(windows, tmp_path):
    """`--cluster local:1`: Dask starts a scheduler in the grader and a worker process (through
    multiprocessing's spawn), the case runs from there, and all are gone when grading ends. The
    worker's command line does not name the test's folder, so a variable set for the grader, which
    every Windows process it starts inherits (and /proc shows), marks them."""
    shutil.copytree(HERE / "grading" / "submissions" / "correct", tmp_path / "submissions" / "correct")
    run_id = uuid.uuid4().hex
    mark = f"EYESIM_TEST_RUN={run_id}"
    process = windows.start(
        "grade",
        windows.path(HERE / "grading" / "drive.toml"),
        "submissions",
        "--out",
        "report",
        "--cluster",
        "local:1",
        cwd=tmp_path,
        env=windows.env.environment(EYESIM_TEST_RUN=run_id),
    )
    output = OutputReader(process)
    seen: dict[int, str] = {}

    def ended() -> bool:
        seen.update(python_processes_marked(mark))
        return process.poll() is not None

    try:
        wait_until(ended, 400, "grading to end", interval=0.2)
    finally:
        if process.poll() is None:
            process.kill()
    text = output.finish()
    assert process.returncode == 0, text
    assert "on Dask cluster local:1 (1 worker(s))" in text, text
    assert re.search(r"^correct +100\.0 +\(3/3 checks\)$", text, flags=re.MULTILINE), text
    report = json.loads((tmp_path / "report" / "report.json").read_text())
    assert report["executor"] == "Dask cluster local:1 (1 worker(s))"
    [student] = report["students"]
    assert student["score"] == 100.0 and student["cases"][0]["status"] == "ok"
    assert any("spawn_main" in command for command in seen.values()), seen  # the worker process
    assert any("eyesim.grade.case_run" in command for command in seen.values()), seen
    try:
        wait_until(lambda: not python_processes_marked(mark), 30, "the Dask processes to end")
    finally:
        kill_processes(python_processes_marked(mark))


def python_processes_marked(mark: str) -> dict[int, str]:
    """pid -> command line of the Windows Python processes whose environment holds `mark`."""
    found = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            if mark.encode() not in (entry / "environ").read_bytes().split(b"\0"):
                continue
            command = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace").strip()
        except OSError:
            continue
        if "python.exe" in command:
            found[int(entry.name)] = command
    return found
