"""The page's program and settings routes (/api) against a real `eyesim run`: compiling with file:line
errors, starting, stopping and restarting programs, crash reasons, paths kept inside the scene
roots, and settings that change the running scene."""

import json
import os
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402
from support.scenes import arena  # noqa: E402

from eyesim.core.clock import Clock  # noqa: E402
from eyesim.core.engine import Simulation  # noqa: E402
from eyesim.parts.psd.component import PsdSensor  # noqa: E402
from eyesim.web.program_control import apply_settings  # noqa: E402

WAIT_FOREVER = """#include "eyebot.h"
int main(void) { LCDPrintf("waiting\\n"); for (;;) OSWait(100); }
"""
CRASH = """#include <stdio.h>
#include "eyebot.h"
int main(void) { printf("about to crash\\n"); fflush(stdout); volatile int *p = 0; *p = 1; return 0; }
"""
LIT_PIXELS = """#include <stdio.h>
#include "eyebot.h"
int main(void) {
  int lit = 0;
  for (int y = 0; y < 16; y++)
    for (int x = 0; x < 80; x++)
      if (LCDGetPixel(x, y) != 0) lit++;
  FILE *f = fopen("lit.txt", "a");
  fprintf(f, "%d\\n", lit);
  fclose(f);
  LCDPrintf("hello there\\n");
  for (;;) OSWait(100);
}
"""
BROKEN = """#include "eyebot.h"
int main(void) {
  int x = ;
  return 0;
}
"""


def call(url: str, route: str, body: dict | None = None, headers: dict | None = None) -> tuple[int, dict]:
    data = None if body is None else json.dumps(body).encode()
    request = urllib.request.Request(
        url.rstrip("/") + route, data=data, headers=headers or {}, method="GET" if body is None else "POST"
    )
    try:
        with urllib.request.urlopen(request, timeout=60) as response:
            return response.status, json.load(response)
    except urllib.error.HTTPError as error:
        text = error.read().decode()
        return error.code, json.loads(text) if text.startswith("{") else {"text": text}


def wait_for_state(url: str, robot: int, wanted: str, timeout: float = 30) -> dict:
    deadline = time.monotonic() + timeout
    while True:
        state = next(r for r in call(url, "/api/programs")[1]["robots"] if r["id"] == robot)
        if state["state"] == wanted:
            return state
        assert time.monotonic() < deadline, state
        time.sleep(0.1)


@pytest.fixture
def simulator(tmp_path):
    (tmp_path / "wait.c").write_text(WAIT_FOREVER)
    (tmp_path / "crash.c").write_text(CRASH)
    (tmp_path / "lit.c").write_text(LIT_PIXELS)
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "broken.c").write_text(BROKEN)
    (tmp_path / "traceback.py").write_text(
        "from eye import *\nprint('before')\nraise RuntimeError('the program gave up')\n"
    )
    with simulator_with_viewer(cwd=tmp_path) as (process, url):
        yield url, tmp_path


def test_compile_errors_come_with_file_and_line(simulator):
    url, _ = simulator
    status, result = call(url, "/api/programs/compile", {"root": 0, "path": "src/broken.c"})
    assert status == 200 and result["ok"] is False and result["program"] is None
    error = next(d for d in result["diagnostics"] if d["kind"] == "error")
    assert (error["file"], error["line"]) == ("src/broken.c", 3)
    assert "expected expression" in error["message"]


def test_a_compiled_program_starts_stops_and_restarts(simulator):
    url, folder = simulator
    status, result = call(url, "/api/programs/compile", {"root": 0, "path": "wait.c"})
    assert status == 200 and result["ok"], result["output"]
    assert result["program"] == {"root": 0, "path": "wait"} and (folder / "wait").is_file()
    listed = call(url, "/api/programs")[1]["files"]
    assert {"root": 0, "path": "wait", "kind": "executable"} in listed
    assert {"root": 0, "path": "traceback.py", "kind": "python"} in listed

    status, state = call(url, "/api/programs/start", {"robot": 1, "root": 0, "path": "wait"})
    assert status == 200 and state["state"] == "running" and state["program"] == {"root": 0, "path": "wait"}
    status, state = call(url, "/api/programs/stop", {"robot": 1})
    assert status == 200 and state["state"] == "stopped" and state["reason"] is None
    assert call(url, "/api/programs/stop", {"robot": 1}) == (400, {"error": "robot 1 runs no program"})
    status, state = call(url, "/api/programs/restart", {"robot": 1})
    assert status == 200 and state["state"] == "running"
    # Restarting a running program stops it first; the new one gets the robot.
    status, state = call(url, "/api/programs/restart", {"robot": 1})
    assert status == 200 and state["state"] == "running"


def test_a_started_program_finds_a_blank_lcd(simulator):
    """What the program before drew is gone when the next one starts: each run counts the lit
    pixels of the LCD's first text row when it starts, then prints there."""
    url, folder = simulator
    status, result = call(url, "/api/programs/compile", {"root": 0, "path": "lit.c"})
    assert status == 200 and result["ok"], result["output"]
    lit = folder / "lit.txt"
    for runs in (1, 2, 3):
        route = "/api/programs/start" if runs == 1 else "/api/programs/restart"
        body = {"robot": 1, "root": 0, "path": "lit"} if runs == 1 else {"robot": 1}
        status, state = call(url, route, body)
        assert status == 200 and state["state"] == "running"
        deadline = time.monotonic() + 60
        while not (lit.exists() and len(lit.read_text().split()) == runs):
            assert time.monotonic() < deadline, "the program did not report what it found"
            time.sleep(0.05)
    assert lit.read_text().split() == ["0", "0", "0"]


def test_a_crash_says_why(simulator):
    url, _ = simulator
    assert call(url, "/api/programs/compile", {"root": 0, "path": "crash.c"})[1]["ok"]
    call(url, "/api/programs/start", {"robot": 1, "root": 0, "path": "crash"})
    state = wait_for_state(url, 1, "exited")
    assert state["exit_code"] == -11
    assert state["reason"] == "crashed: segmentation fault (SIGSEGV)"


def test_paths_outside_the_scene_roots_are_refused(simulator):
    url, folder = simulator
    outside = folder.parent / f"{folder.name}-outside"
    outside.mkdir()
    (outside / "prog.py").write_text("print('should not run')\n")
    os.symlink(outside / "prog.py", folder / "link.py")
    cases = {
        "../" + f"{folder.name}-outside/prog.py": "'..' is not allowed",
        str(outside / "prog.py"): "absolute paths are not allowed",
        "link.py": "leads out of the scene root",
        "missing.py": "no such file",
        "wait.c": "is not a program",
    }
    for path, reason in cases.items():
        status, answer = call(url, "/api/programs/start", {"robot": 1, "root": 0, "path": path})
        assert status == 400 and reason in answer["error"], (path, answer)
    assert call(url, "/api/programs/start", {"robot": 7, "root": 0, "path": "traceback.py"}) == (
        400,
        {"error": "no robot 7"},
    )
    assert call(url, "/api/programs/start", {"robot": 1, "root": 5, "path": "traceback.py"})[0] == 400
    assert all(f["path"] != "link.py" for f in call(url, "/api/programs")[1]["files"])
    # Another site's page may not use the routes at all.
    status, answer = call(
        url,
        "/api/programs/start",
        {"robot": 1, "root": 0, "path": "traceback.py"},
        headers={"Origin": "http://evil.example"},
    )
    assert status == 403 and "foreign Origin" in answer["text"]
    assert call(url, "/api/programs")[1]["robots"][0]["state"] == "none"


def test_settings_change_the_running_scene(simulator):
    url, _ = simulator
    status, settings = call(url, "/api/settings")
    assert status == 200 and settings["clock"] == "realtime"
    assert (settings["vis"], settings["psd_noise"], settings["seed"]) == (True, 0.0, 0)  # the bundled arena's
    status, settings = call(url, "/api/settings", {"vis": False, "psd_noise": 12.5, "seed": 7})
    assert status == 200 and (settings["vis"], settings["trace"], settings["psd_noise"], settings["seed"]) == (
        False,
        False,
        12.5,
        7,
    )
    assert call(url, "/api/settings")[1]["psd_noise"] == 12.5
    for body, reason in (
        ({"psd_noise": -1}, "psd_noise"),
        ({"seed": 1.5}, "seed"),
        ({"vis": "yes"}, "vis"),
        ({"gravity": 1}, "unknown field 'gravity'"),
    ):
        status, answer = call(url, "/api/settings", body)
        assert status == 400 and reason in answer["error"], answer
    assert call(url, "/api/settings")[1]["seed"] == 7


def test_applied_settings_are_the_scenes_and_the_psds():
    sim = Simulation(arena(), Clock("deterministic", 1.0))
    psd = next(c for r in sim.robots for c in r.components if isinstance(c, PsdSensor))
    exact = {psd.distance_mm() for _ in range(20)}
    assert len(exact) == 1
    apply_settings(sim, psd_noise=30.0, seed=3, trace=True)
    assert (sim.scene.settings.psd_noise, sim.scene.settings.seed, sim.scene.settings.trace) == (30.0, 3, True)
    noisy = [psd.distance_mm() for _ in range(20)]
    assert len(set(noisy)) > 5
    apply_settings(sim, psd_noise=30.0, seed=3)
    assert [psd.distance_mm() for _ in range(20)] == noisy  # the same seed, the same noise


INJECTED_OPTIONS = "-wrapper /bin/sh,-c,touch${IFS}INJECTED\n"


def test_a_file_named_like_a_response_file_is_compiled_as_a_file(simulator):
    """`@opts.c` would make gcc read options from opts.c (`-wrapper` runs any command): the viewer
    passes it as ./@opts.c, a source file that does not compile, and nothing runs."""
    url, folder = simulator
    (folder / "opts.c").write_text(INJECTED_OPTIONS)
    (folder / "@opts.c").write_text(INJECTED_OPTIONS)
    status, result = call(url, "/api/programs/compile", {"root": 0, "path": "@opts.c"})
    assert status == 200 and result["ok"] is False and "error" in result["output"]
    assert not (folder / "INJECTED").exists()


def test_compiler_warnings_come_back_with_a_built_program(simulator):
    url, folder = simulator
    (folder / "sloppy.c").write_text('#include "eyebot.h"\nint main(void) { int n; LCDPrintf("%d\\n"); return n; }\n')
    status, result = call(url, "/api/programs/compile", {"root": 0, "path": "sloppy.c"})
    assert status == 200 and result["ok"] is True and result["program"] is not None
    warnings = [d for d in result["diagnostics"] if d["kind"] == "warning"]
    assert {d["line"] for d in warnings} == {2} and any("-Wformat" in d["message"] for d in warnings)
    assert "warning:" in result["output"]
