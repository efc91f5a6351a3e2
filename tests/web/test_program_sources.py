"""The program editor's routes (/api/sources) against a real `eyesim run --program 1=hello.c`: the
robot's source opened, saved, checked with diagnostics at their lines (C and Python), run, and
every path out of the scene roots refused, for reading and for writing."""

import os
import shutil
import sys
from pathlib import Path

import pytest
from test_program_control import call, wait_for_state

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

from eyesim.protocol.channel_schema import route_answer_problems  # noqa: E402
from eyesim.paths import EXAMPLES_DIR  # noqa: E402
from eyesim.scene.builtins import SCENES_DIR  # noqa: E402

HELLO = """#include "eyebot.h"
int main(void) {
  LCDPrintf("hello 1\\n");
  for (;;) OSWait(100);
}
"""
BROKEN = HELLO.replace('LCDPrintf("hello 1\\n");', "int x = ;")
SLOPPY = HELLO.replace('LCDPrintf("hello 1\\n");', 'int n; LCDPrintf("%d\\n"); if (n) return 1;')
PYTHON_BROKEN = "from eye import *\n\nLCDPrintf('fine')\nif True\n    pass\n"


def answered(url: str, route: str, body: dict) -> tuple[int, dict]:
    """The route's answer, checked against its definition in the schema."""
    status, answer = call(url, route, body)
    assert route_answer_problems(f"POST {route}", status, answer) == [], answer
    return status, answer


@pytest.fixture
def simulator(tmp_path):
    folder = tmp_path / "work"
    (folder / "robots").mkdir(parents=True)
    (folder / "robots" / "hello.c").write_text(HELLO)
    (folder / "robots" / "hello.c").chmod(0o640)
    (folder / "wander.py").write_text("from eye import *\nLCDPrintf('wander')\n")
    (folder / "notes.txt").write_text("not a program\n")
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "secret.c").write_text("int main(void) { return 0; }\n")
    os.symlink(outside / "secret.c", folder / "link.c")
    shutil.copy(SCENES_DIR / "arena.wld", folder)
    (folder / "two.sim").write_text("world arena.wld\nS4 500 500 0\nS4 1500 500 0\n")
    with simulator_with_viewer("two.sim", "--program", "1=robots/hello.c", cwd=folder) as (_, url):
        yield url, folder, outside


def test_the_robots_source_opens_saves_and_keeps_its_mode(simulator):
    url, folder, _ = simulator
    status, source = answered(url, "/api/sources/robot", {"robot": 1})
    assert status == 200, source
    assert (source["root"], source["path"], source["kind"], source["text"]) == (0, "robots/hello.c", "c", HELLO)

    changed = HELLO.replace("hello 1", "hello 2")
    status, saved = answered(
        url, "/api/sources/save", {"root": 0, "path": "robots/hello.c", "text": changed, "version": source["version"]}
    )
    assert status == 200 and saved["version"] != source["version"], saved
    assert (folder / "robots" / "hello.c").read_text() == changed
    assert (folder / "robots" / "hello.c").stat().st_mode & 0o777 == 0o640
    assert answered(url, "/api/sources/read", {"root": 0, "path": "robots/hello.c"})[1]["text"] == changed

    # Saved from a text opened before that save: refused, the file keeps the newer text.
    status, answer = answered(
        url, "/api/sources/save", {"root": 0, "path": "robots/hello.c", "text": HELLO, "version": source["version"]}
    )
    assert status == 409 and "changed on disk since it was opened" in answer["error"]
    assert (folder / "robots" / "hello.c").read_text() == changed


def test_compile_errors_and_warnings_come_at_their_lines(simulator):
    url, folder, _ = simulator
    (folder / "robots" / "hello.c").write_text(BROKEN)
    status, result = answered(url, "/api/sources/check", {"root": 0, "path": "robots/hello.c"})
    assert status == 200 and result["ok"] is False, result
    error = next(d for d in result["diagnostics"] if d["kind"] == "error")
    assert (error["file"], error["line"]) == ("hello.c", 3) and error["column"] is not None, error

    (folder / "robots" / "hello.c").write_text(SLOPPY)
    for _ in range(2):  # the second check takes the cached build, with the same warnings
        status, result = answered(url, "/api/sources/check", {"root": 0, "path": "robots/hello.c"})
        assert status == 200 and result["ok"] is True, result
        assert any(d["kind"] == "warning" and d["line"] == 3 for d in result["diagnostics"]), result

    (folder / "wander.py").write_text(PYTHON_BROKEN)
    status, result = answered(url, "/api/sources/check", {"root": 0, "path": "wander.py"})
    assert status == 200 and result["ok"] is False, result
    assert [(d["file"], d["line"], d["kind"]) for d in result["diagnostics"]] == [("wander.py", 4, "error")]
    assert "SyntaxError" in result["diagnostics"][0]["message"]
    assert not (folder / "__pycache__").exists()


def test_run_starts_the_saved_source_and_restart_rebuilds_it(simulator):
    url, folder, _ = simulator
    wait_for_state(url, 1, "running")
    fixed = HELLO.replace("hello 1", "hello 3")
    answered(url, "/api/sources/save", {"root": 0, "path": "robots/hello.c", "text": fixed})
    status, state = answered(url, "/api/sources/run", {"robot": 1, "root": 0, "path": "robots/hello.c"})
    assert status == 200 and state["state"] == "running" and state["program"] == {"root": 0, "path": "robots/hello.c"}
    # Restart (the program controls') runs the source again, not the build it started with.
    (folder / "robots" / "hello.c").write_text(BROKEN)
    status, state = answered(url, "/api/programs/restart", {"robot": 1})
    assert status == 200 and state["state"] == "failed" and "does not compile" in state["reason"], state
    status, answer = answered(url, "/api/sources/run", {"robot": 9, "root": 0, "path": "robots/hello.c"})
    assert (status, answer) == (400, {"error": "no robot 9"})


def test_paths_out_of_the_roots_are_refused_for_reading_and_writing(simulator):
    url, folder, outside = simulator
    cases = {
        "../outside/secret.c": (403, "'..' is not allowed"),
        str(outside / "secret.c"): (403, "absolute paths are not allowed"),
        "link.c": (403, "leads out of"),
        "notes.txt": (403, "is not a program source"),
        "missing.c": (404, "no such file"),
    }
    for path, (code, reason) in cases.items():
        for route, body in (
            ("/api/sources/read", {}),
            ("/api/sources/save", {"text": "int main;"}),
            ("/api/sources/check", {}),
        ):
            status, answer = answered(url, route, {"root": 0, "path": path, **body})
            assert status == code and reason in answer["error"], (route, path, answer)
    assert (outside / "secret.c").read_text() == "int main(void) { return 0; }\n"
    assert (folder / "notes.txt").read_text() == "not a program\n"
    assert not (folder / "missing.c").exists()
    status, answer = answered(url, "/api/sources/read", {"root": 4, "path": "robots/hello.c"})
    assert status == 404 and "no scene root 4" in answer["error"]
    status, answer = answered(url, "/api/sources/check", {"root": 0, "path": "robots"})
    assert status == 403, answer
    # Another site's page may neither read nor write.
    for route, body in (("/api/sources/read", {}), ("/api/sources/save", {"text": "x"})):
        status, answer = call(
            url, route, {"root": 0, "path": "robots/hello.c", **body}, headers={"Origin": "http://evil.example"}
        )
        assert status == 403 and "foreign Origin" in answer["text"]
    assert (folder / "robots" / "hello.c").read_text() == HELLO


def test_what_has_no_source_here_says_why(simulator):
    url, folder, _ = simulator
    status, answer = answered(url, "/api/sources/robot", {"robot": 2})
    assert status == 404 and answer["error"] == "robot 2 has no program: choose a source in the list and open it"
    (folder / "robots" / "hello.h").write_text("#define GREETING 1\n")
    status, answer = answered(url, "/api/sources/check", {"root": 0, "path": "robots/hello.h"})
    assert status == 400 and "is a header" in answer["error"]
    status, answer = answered(url, "/api/sources/save", {"root": 0, "path": "robots/hello.c", "text": "x" * 1_000_001})
    assert status == 400 and "text" in answer["error"], answer


def test_the_installed_examples_can_be_read_not_changed():
    with simulator_with_viewer("--program", "1=programs/demo.py", cwd=EXAMPLES_DIR) as (_, url):
        status, source = answered(url, "/api/sources/robot", {"robot": 1})
        assert status == 200 and (source["root"], source["path"]) == (0, "programs/demo.py"), source
        status, answer = answered(url, "/api/sources/save", {"root": 0, "path": "programs/demo.py", "text": "x = 1\n"})
        assert status == 403 and "belongs to the installed EyeSim" in answer["error"]
    assert (EXAMPLES_DIR / "programs" / "demo.py").read_text() == source["text"]
