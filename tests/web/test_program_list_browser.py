"""The program chooser of a simulator started in a source tree lists what a student would run, not
the tree's packages, tests, build output and environments; each robot is labelled in the 3D view
with its id and its program. Against the real simulator in headless Chromium."""

import sys
from pathlib import Path

import pytest
from browser import open_viewer, robot_panel

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms: programs starting, worlds built, on a loaded 2-core machine

ROBOT_PY = "from eye import *\nLCDPrintf('hello')\nwhile True:\n    OSWait(100)\n"
ROBOT_C = '#include "eyebot.h"\nint main(void) { LCDPrintf("hello"); for (;;) OSWait(100); }\n'
LIBRARY = "def helper():\n    return 1\n"


@pytest.fixture
def source_tree(tmp_path):
    """A project like EyeSim's own checkout: robot programs among a package, tests, build output,
    a virtual environment, node_modules and caches."""
    files = {
        "labs/wall_follow.py": ROBOT_PY,
        "labs/square.c": ROBOT_C,
        "labs/maze/solve.cpp": ROBOT_C,
        "labs/helpers.py": LIBRARY,
        "src/tool/__init__.py": "",
        "src/tool/cli.py": ROBOT_PY,
        "src/tool/main.c": ROBOT_C,
        "tests/test_robot.py": ROBOT_PY,
        "tests/conftest.py": ROBOT_PY,
        "tests/support.py": LIBRARY,
        "build/out/gen.c": ROBOT_C,
        "dist/robot.py": ROBOT_PY,
        "node_modules/x/run.py": ROBOT_PY,
        ".venv/lib/robot.py": ROBOT_PY,
        "env/pyvenv.cfg": "home = /usr\n",
        "env/lib/robot.py": ROBOT_PY,
        "__pycache__/robot.py": ROBOT_PY,
        "robios/lcd.c": '#include "eyebot.h"\nvoid LCDClear2(void) {}\n',
        "scripts/build.sh": "#!/bin/sh\necho build\n",
        "lab.sim": "S4 500 500 0 labs/wall_follow.py\nS4 1500 500 90 labs/square.c\n",
    }
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    (tmp_path / "scripts/build.sh").chmod(0o755)
    return tmp_path


def test_a_source_tree_lists_its_robot_programs_only(browser_context, source_tree):
    with simulator_with_viewer("lab.sim", cwd=source_tree) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        choice = robot_panel(page, 1).locator(".program-choice")
        page.wait_for_function("() => document.querySelector('.program-choice option[data-path]') !== null")
        listed = choice.locator("option[data-path]").evaluate_all("options => options.map((o) => o.dataset.path)")
        assert listed == ["labs/square.c", "labs/wall_follow.py", "labs/maze/solve.cpp"]
        assert choice.input_value() == "0:labs/wall_follow.py"  # the robot's own program is chosen
        # Each robot is labelled with its id and its program, not only its type.
        page.wait_for_function("""() => { const l = window.eyesimViewer.robotLabels();
            return l[1] === '1 · wall_follow.py' && l[2] === '2 · square.c'; }""")
        assert viewer.errors == []
