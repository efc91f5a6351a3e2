"""The page as the application: open a corpus scene from the scene browser, build on it in the
editor (robots, objects, walls drawn on the floor, moves, deletes, undo), give a robot a program,
save, and read the saved file back with `eyesim check` and `eyesim run`; against the real
simulator in headless Chromium."""

import json
import os
import re
import shutil
import subprocess
import sys
import urllib.error
import urllib.request
from pathlib import Path

import pytest
from browser import open_viewer

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.corpus import CORPUS  # noqa: E402
from support.programs import build, eyesim_command, run_headless, simulator_with_viewer  # noqa: E402

from eyesim.scene import load_scene  # noqa: E402

pytestmark = pytest.mark.browser
SHOTS = os.environ.get("EYESIM_SHOTS")  # a folder to keep the screenshots in, for looking at them


@pytest.fixture
def workspace(tmp_path):
    shutil.copytree(CORPUS / "23082899__distBug", tmp_path / "labs")
    (tmp_path / "broken.sim").write_text("world labs/obstacles4k.wld\nS4 100 100 0\nTeapot 300 300 0\n")
    build("lcd_and_key", tmp_path)
    return tmp_path


@pytest.fixture
def simulator(workspace):
    with simulator_with_viewer(cwd=workspace) as running:  # no scene, no program: the bundled arena
        yield running


def shot(page, name: str) -> None:
    if SHOTS:
        Path(SHOTS).mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(Path(SHOTS) / f"{name}.png"))


def search_one(page, text: str, expected: str) -> None:
    """Type `text` into the scene browser's search and wait until its one result is `expected`
    (the list is fetched again after a short pause: the previous search's result stays meanwhile)."""
    page.fill("#scene-search", text)
    page.wait_for_function(
        """expected => {
        const buttons = document.querySelectorAll('#scene-files button');
        return buttons.length === 1 && buttons[0].textContent.includes(expected);
    }""",
        arg=expected,
    )


def editor_state(page) -> dict:
    return page.evaluate("() => fetch('/scenes/state').then(r => r.json())")


def wait_for_edits(page, count: int) -> None:
    page.wait_for_function("n => window.eyesimEditor.editCount >= n", arg=count)


def screen_of(page, x_mm: float, y_mm: float) -> tuple[float, float]:
    point = page.evaluate("([x, y]) => window.eyesimViewer.worldScreenPosition(x, y, 0)", [x_mm / 1000, y_mm / 1000])
    return point["x"], point["y"]


def test_open_build_edit_undo_save_and_reopen(browser_context, simulator, workspace):
    process, url = simulator
    viewer = open_viewer(browser_context, url)
    page = viewer.page
    dialogs: list[str] = []

    # Started without a scene: the bundled arena, and the scene browser open on it.
    page.wait_for_selector("#scene-browser[open]")
    page.wait_for_function("() => window.eyesimEditor.browser.listings >= 1")
    assert viewer.state("robotIds") == [1]
    listed = page.locator("#scene-files button").all_inner_texts()
    assert "current folder / labs/obstacles4k.sim" in listed and "bundled scenes / default.sim" in listed
    assert "examples / scenes/maze.sim" in listed  # the examples that come with EyeSim
    shot(page, "1-browser")

    # A broken file: its error with file:line, and the arena keeps running.
    search_one(page, "broken", "broken.sim")
    page.click("#scene-files button")
    page.wait_for_function(
        "() => document.querySelector('#scene-browser-message').textContent.includes('broken.sim:3')"
    )
    assert "Teapot" in page.inner_text("#scene-browser-message")
    shot(page, "1b-broken-file")
    assert viewer.state("robotIds") == [1] and viewer.state("scene")["markers"] == 0

    # A corpus scene replaces the arena.
    search_one(page, "obstacles4k sim", "obstacles4k.sim")
    page.click("#scene-files button")
    # Opening stops the arena's programs and builds the new world: seconds on a loaded 2-core machine.
    page.wait_for_selector("#scene-browser", state="hidden", timeout=60_000)
    page.wait_for_function("() => window.eyesimViewer.scene().markers === 2")
    walls = viewer.state("scene")["walls"]
    assert walls > 4

    # Build: a robot, an object, a wall drawn on the floor.
    page.click("#edit-scene")
    page.wait_for_selector("#editor:not([hidden])")
    page.wait_for_function("() => document.querySelector('#pause').textContent === 'Resume'")  # editing pauses
    page.wait_for_function("() => document.querySelectorAll('#editor-robot-type option').length > 1")
    edits = page.evaluate("() => window.eyesimEditor.editCount")
    page.select_option("#editor-robot-type", "LabBot")
    page.click("#editor-add-robot")
    wait_for_edits(page, edits + 1)
    page.select_option("#editor-object-type", "Can")
    page.click("#editor-add-object")
    wait_for_edits(page, edits + 2)
    page.wait_for_function("() => window.eyesimViewer.robotIds().length === 2")
    page.wait_for_function("() => window.eyesimViewer.scene().objects === 1")

    page.fill("#editor-grid", "50")  # wall ends on a 50 mm grid
    page.locator("#editor-grid").dispatch_event("change")
    page.click("#editor-draw-wall")
    start, end = screen_of(page, 1010, 3010), screen_of(page, 2490, 3020)
    page.mouse.move(*start)
    page.mouse.down()
    page.mouse.move((start[0] + end[0]) / 2, (start[1] + end[1]) / 2, steps=4)
    page.mouse.move(*end, steps=4)
    shot(page, "2-drawing-wall")
    page.mouse.up()
    wait_for_edits(page, edits + 3)
    page.wait_for_function("n => window.eyesimViewer.scene().walls === n", arg=walls + 1)
    page.click("#editor-draw-wall")
    wall = editor_state(page)["items"]["walls"][-1]
    assert (wall["x1"], wall["y1"], wall["x2"], wall["y2"]) == (1000, 3000, 2500, 3000)  # on the 50 mm grid

    # Move robot 1 with the numeric fields, robot 2 by dragging it in the 3D view.
    page.click("#editor-items li[data-kind=robot][data-index='0']")
    page.fill("#editor-x", "800")
    page.fill("#editor-y", "900")
    page.fill("#editor-phi", "45")
    page.click("#editor-apply")
    wait_for_edits(page, edits + 4)
    # the new scene is drawn (robot 1 where the fields put it) before robot 2 is grabbed
    page.wait_for_function(
        "() => Math.abs((window.eyesimViewer.displayedRobotPose(1)?.pos[0] ?? 0) - 0.8) < 0.01 "
        "&& window.eyesimViewer.robotScreenPosition(2) !== null"
    )
    # grabbed on its top, off the cross of its PSD beams (a press near a beam picks the beam)
    robot = editor_state(page)["items"]["robots"][1]
    grab = page.evaluate(
        "([x, y]) => window.eyesimViewer.worldScreenPosition(x, y, 0.15)",
        [(robot["x"] + 60) / 1000, (robot["y"] - 55) / 1000],
    )
    target = screen_of(page, 3000, 1500)
    page.mouse.move(grab["x"], grab["y"])
    page.mouse.down()
    page.mouse.move(target[0], target[1], steps=8)
    page.mouse.up()
    wait_for_edits(page, edits + 5)
    robots = editor_state(page)["items"]["robots"]
    assert (robots[0]["x"], robots[0]["y"], robots[0]["phi"]) == (800, 900, 45)
    assert abs(robots[1]["x"] - 3000) < 100 and abs(robots[1]["y"] - 1500) < 100

    # Delete the can, undo it back; duplicate it, delete the copy.
    page.click("#editor-items li[data-kind=object][data-index='0']")
    page.click("#editor-delete")
    wait_for_edits(page, edits + 6)
    page.wait_for_function("() => window.eyesimViewer.scene().objects === 0")
    page.click("#editor-undo")
    wait_for_edits(page, edits + 7)
    page.wait_for_function("() => window.eyesimViewer.scene().objects === 1")
    page.click("#editor-items li[data-kind=object][data-index='0']")
    page.click("#editor-duplicate")
    wait_for_edits(page, edits + 8)
    page.wait_for_function("() => window.eyesimViewer.scene().objects === 2")
    page.click("#editor-items li[data-kind=object][data-index='1']")
    page.keyboard.press("Delete")
    wait_for_edits(page, edits + 9)
    page.wait_for_function("() => window.eyesimViewer.scene().objects === 1")

    # Robot 2 runs the program built in the scene folder.
    page.click("#editor-items li[data-kind=robot][data-index='1']")
    page.select_option("#editor-program", label="current folder / lcd_and_key")
    wait_for_edits(page, edits + 10)
    state = editor_state(page)
    assert Path(state["items"]["robots"][1]["program"]) == (workspace / "lcd_and_key").resolve()
    shot(page, "3-edited")

    # Save as .sim: a new file; the same name again is refused until the page is told to replace it.
    page.on("dialog", lambda dialog: (dialogs.append(dialog.message), dialog.dismiss()))
    page.click("#editor-save")
    page.fill("#save-name", "arena2.sim")
    page.select_option("#save-format", "sim")
    page.click("#save-confirm")
    wait_for_edits(page, edits + 11)
    assert (workspace / "arena2.sim").is_file() and (workspace / "arena2.wld").is_file()
    first = (workspace / "arena2.sim").read_text()
    page.click("#editor-save")
    page.click("#save-confirm")
    wait_for_edits(page, edits + 12)
    assert dialogs and "already exists" in dialogs[0]
    assert "already exist" in page.inner_text("#editor-message")
    assert (workspace / "arena2.sim").read_text() == first

    # Done: the programs start and the simulation goes on; robot 2 drives.
    page.click("#edit-scene")
    page.wait_for_selector("#editor", state="hidden")
    page.wait_for_function("() => window.eyesimViewer.robotPose(2) !== null")
    x0 = viewer.state("robotPose", 2)["pos"][0]
    page.wait_for_function("x0 => window.eyesimViewer.robotPose(2).pos[0] > x0 + 0.03", arg=x0)
    shot(page, "4-running")
    assert viewer.errors == []

    # The saved file: eyesim check accepts it; it loads and runs as the scene that was built.
    check = subprocess.run(eyesim_command("check", "arena2.sim"), capture_output=True, text=True, cwd=workspace)
    assert check.returncode == 0, check.stdout + check.stderr
    saved = load_scene(workspace / "arena2.sim")
    assert [(r.type_name, r.pose.x, r.pose.y, r.pose.phi) for r in saved.robots] == [
        (r["type"], r["x"], r["y"], r["phi"]) for r in state["items"]["robots"]
    ]
    assert Path(saved.robots[1].program) == (workspace / "lcd_and_key").resolve()
    assert [(o.type_name, o.pose.x, o.pose.y) for o in saved.objects] == [
        (o["type"], o["x"], o["y"]) for o in state["items"]["objects"]
    ]
    assert [(w.x1, w.y1, w.x2, w.y2) for w in saved.world.walls] == [
        (w["x1"], w["y1"], w["x2"], w["y2"]) for w in state["items"]["walls"]
    ]
    assert len(saved.markers) == 2 and saved.settings.vis and saved.settings.trace
    run = run_headless("arena2.sim", "--until", "0.01", "--program", "2=/bin/true", cwd=workspace)
    assert run.returncode == 0, run.stderr
    lines = re.findall(r"robot (\d) (\w+): x=(\d+) mm y=(\d+) mm", run.stdout)
    assert [(name, int(x), int(y)) for _, name, x, y in lines] == [
        (r["type"], round(r["x"]), round(r["y"])) for r in state["items"]["robots"]
    ]


def test_scene_routes_refuse_paths_out_of_the_roots_and_overwriting(browser_context, simulator, workspace):
    process, url = simulator
    page = open_viewer(browser_context, url).page
    post = """([route, body]) => fetch(route, {method: 'POST', headers: {'Content-Type': 'application/json'},
                                              body: JSON.stringify(body)})
                                .then(async r => [r.status, await r.json()])"""
    for path in ("../etc/passwd", "/etc/passwd", "labs/../../x.sim"):
        status, body = page.evaluate(post, ["/scenes/open", {"root": 0, "path": path}])
        assert status == 403 and "not allowed" in body["error"]
    status, body = page.evaluate(post, ["/scenes/save", {"root": 1, "path": "mine.sim", "format": "sim"}])
    assert status == 422 and "not in a scene root that can be written to" in body["error"]  # the bundled examples
    status, body = page.evaluate(post, ["/scenes/save", {"root": 0, "path": "broken.sim", "format": "sim"}])
    assert status == 409 and body["exists"] == [{"root": 0, "path": "broken.sim"}]
    assert "Teapot" in (workspace / "broken.sim").read_text()
    status, body = page.evaluate(post, ["/scenes/edit", {"op": "add-robot", "type": "R2D2", "x": 1, "y": 1}])
    assert status == 422 and "unknown robot type" in body["error"]
    # another site's page in the same browser cannot use the routes (the viewer's Origin check)
    request = urllib.request.Request(
        url.rstrip("/") + "/scenes/open",
        method="POST",
        data=json.dumps({"root": 0, "path": "broken.sim"}).encode(),
        headers={"Origin": "http://evil.example", "Content-Type": "application/json"},
    )
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(request, timeout=10)
    assert refused.value.code == 403 and "foreign Origin" in refused.value.read().decode()
    assert process.poll() is None


def test_a_new_arena_built_in_the_page_is_saved_and_reopened_the_same(browser_context, simulator, workspace):
    process, url = simulator
    viewer = open_viewer(browser_context, url)
    page = viewer.page
    page.wait_for_selector("#scene-browser[open]")
    page.click("#scene-new")
    page.wait_for_selector("#editor:not([hidden])")
    page.wait_for_function(
        "() => window.eyesimViewer.robotIds().length === 0 && window.eyesimViewer.scene().walls === 0"
    )
    page.wait_for_function("() => document.querySelectorAll('#editor-program option').length > 1")
    edits = page.evaluate("() => window.eyesimEditor.editCount")
    for n, button in enumerate(["#editor-add-robot", "#editor-add-robot", "#editor-add-object"], start=1):
        page.click(button)
        wait_for_edits(page, edits + n)
    page.click("#editor-draw-wall")
    page.click("#editor-snap")  # whole millimetres now
    for n, (a, b) in enumerate([((300, 1500), (1200, 1500)), ((1200, 1500), (1200, 700))], start=4):
        page.mouse.move(*screen_of(page, *a))
        page.mouse.down()
        page.mouse.move(*screen_of(page, *b), steps=5)
        page.mouse.up()
        wait_for_edits(page, edits + n)
    for index in (0, 1):
        page.click(f"#editor-items li[data-kind=robot][data-index='{index}']")
        page.select_option("#editor-program", label="current folder / lcd_and_key")
        wait_for_edits(page, edits + 6 + index)
    # the settings panel's choices are the scene's: kept by edits and written when saving
    page.evaluate(
        "() => fetch('/api/settings', {method: 'POST', headers: {'Content-Type': 'application/json'}, "
        "body: JSON.stringify({trace: true, psd_noise: 3})})"
    )
    built = editor_state(page)["items"]
    assert len(built["robots"]) == 2 and len(built["objects"]) == 1 and len(built["walls"]) == 2
    assert all(r["program"] for r in built["robots"])
    page.click("#editor-save")
    page.fill("#save-name", "built")
    page.select_option("#save-format", "json")
    page.click("#save-confirm")
    wait_for_edits(page, edits + 8)
    assert (workspace / "built.json").is_file() and (workspace / "built.world.json").is_file()
    shot(page, "5-new-arena")

    # Run it, then reopen the saved file from the scene browser: the same scene.
    page.click("#edit-scene")
    page.wait_for_function("() => window.eyesimViewer.programState(2)?.event === 'started'")
    page.click("#open-scenes")
    search_one(page, "built.json", "built.json")  # not built.world.json, which is listed too (a world)
    page.click("#scene-files button")
    page.wait_for_selector("#scene-browser", state="hidden", timeout=60_000)  # programs stop, the world is built
    reopened = editor_state(page)["items"]
    assert reopened["robots"] == built["robots"] and reopened["objects"] == built["objects"]
    assert reopened["walls"] == built["walls"] and reopened["floor"] == built["floor"] == {
        "width": 2000,
        "height": 2000,
    }
    settings = load_scene(workspace / "built.json").settings
    assert settings.trace and settings.psd_noise == 3
    check = subprocess.run(eyesim_command("check", "built.json"), capture_output=True, text=True, cwd=workspace)
    assert check.returncode == 0, check.stdout + check.stderr
    assert viewer.errors == []


def test_more_scene_roots_with_the_scenes_option(workspace, tmp_path_factory):
    extra = tmp_path_factory.mktemp("course")
    (extra / "week1.sim").write_text("S4 500 500 0\n")
    with simulator_with_viewer("--scenes", str(extra), cwd=workspace) as (process, url):
        with urllib.request.urlopen(url.rstrip("/") + "/scenes/files?q=week1", timeout=10) as answer:
            listing = json.load(answer)
    roots = {root["name"]: root for root in listing["roots"]}
    assert roots[str(extra)]["writable"] and not roots["examples"]["writable"]
    assert listing["files"] == [{"root": roots[str(extra)]["index"], "path": "week1.sim"}]
    missing = subprocess.run(
        eyesim_command("run", "--scenes", str(extra / "nowhere"), "--port", "0", "--viewer-port", "0"),
        capture_output=True,
        text=True,
        cwd=workspace,
    )
    assert missing.returncode == 2 and "--scenes" in missing.stderr and "no such folder" in missing.stderr


def test_the_next_run_remembers_the_recent_scenes(browser_context, workspace, tmp_path_factory, monkeypatch):
    """A scene opened in one run is the first of the recent scenes when the simulator starts again,
    and opens from there; the bundled arena a run falls back on is not listed."""
    monkeypatch.setenv("EYESIM_STATE_DIR", str(tmp_path_factory.mktemp("own-state")))
    with simulator_with_viewer(cwd=workspace) as (process, url):
        page = open_viewer(browser_context, url).page
        page.wait_for_selector("#scene-browser[open]")
        page.wait_for_function("() => window.eyesimEditor.browser.listings >= 1")
        assert page.locator("#scene-recent button").count() == 0  # the first run: nothing yet
        search_one(page, "obstacles4k sim", "obstacles4k.sim")
        page.click("#scene-files button")
        page.wait_for_selector("#scene-browser", state="hidden", timeout=60_000)
        page.close()

    with simulator_with_viewer(cwd=workspace) as (process, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.wait_for_selector("#scene-browser[open]")
        page.wait_for_function("() => window.eyesimEditor.browser.listings >= 1")
        assert page.locator("#scene-recent button").all_inner_texts() == ["current folder / labs/obstacles4k.sim"]
        shot(page, "5-recent-after-restart")
        page.click("#scene-recent button")
        page.wait_for_selector("#scene-browser", state="hidden", timeout=60_000)
        page.wait_for_function("() => window.eyesimViewer.scene().markers === 2")
        assert viewer.errors == []
        page.close()
