"""The pytest plugin, as a course's own test suite meets it: installed by the package's entry
point, fixtures available without imports, failures explained in the robot's terms."""

from __future__ import annotations

import subprocess
import sys
import textwrap

from eyesim.paths import EXAMPLES_DIR

EXAMPLES = EXAMPLES_DIR

STUDENT_TESTS = f'''
import pytest
from eyesim.testing.assertions import (assert_exit_code, assert_final_pose, assert_lcd_matches,
                                       assert_lcd_shows, assert_no_collisions, assert_reached)

SCENE = r"{EXAMPLES / "scenes" / "wall_follow.sim"}"
PROGRAM = r"{EXAMPLES / "programs" / "wall_follow.c"}"


@pytest.fixture
def followed(eyesim_sim, eyesim_cc):
    sim = eyesim_sim(SCENE)
    sim.program(1, eyesim_cc(PROGRAM))
    sim.run(until=4)
    return sim


def test_passes(followed):
    assert_reached(followed, 1, 100, point=(1400, 1750), before=3)
    assert_no_collisions(followed, 1)
    assert_lcd_shows(followed, 1, "left wall at 200 mm", row=0)


def test_goal_too_far(followed):
    assert_final_pose(followed, 1, 100, point=(500, 500))


def test_wrong_text(followed):
    assert_lcd_shows(followed, 1, "Hello")


def test_lcd_image(followed, eyesim_artifacts, tmp_path):
    from PIL import Image
    blank = tmp_path / "blank.png"
    Image.new("RGB", (480, 320)).save(blank)
    assert_lcd_matches(followed, 1, blank, eyesim_artifacts)


def test_still_running(followed):
    assert_exit_code(followed, 1)


def test_does_not_compile(eyesim_cc, tmp_path):
    source = tmp_path / "broken.c"
    source.write_text("int main(void) {{ return x; }}\\n")
    eyesim_cc(source)
'''


def test_the_plugin_gives_fixtures_and_explains_failures(tmp_path):
    (tmp_path / "test_student.py").write_text(textwrap.dedent(STUDENT_TESTS))
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "test_student.py"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
    )
    out = result.stdout
    assert "1 passed" in out and "5 failed" in out, out
    assert "robot 1 ended" in out and "mm from (500, 500) (tolerance 100); it ended at (" in out
    assert "robot 1's LCD does not show 'Hello'; it shows:" in out and "0 |Wall following: left wall at 200 mm" in out
    assert "robot 1's LCD differs from" in out and "robot1-lcd-actual.png" in out and "robot1-lcd-diff.png" in out
    assert "robot 1's program was still running at the end" not in out  # the run is not over yet ...
    assert "robot 1's program is still running (expected exit code 0)" in out  # ... so it says so
    assert "broken.c does not compile" in out and "x" in out and "undeclared" in out, out
