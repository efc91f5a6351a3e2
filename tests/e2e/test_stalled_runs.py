"""A headless run that cannot go on says why, once, naming the program and what it waits for;
--wall-limit ends any run."""

from __future__ import annotations

import subprocess
import time

from support.programs import eyesim_command, run_headless

KEY_WAIT = '#include "eyebot.h"\nint main(void) { LCDPrintf("press"); KEYWait(ANYKEY); return 0; }\n'
COMPUTE = '#include "eyebot.h"\nint main(void) { LCDPrintf("plan"); volatile unsigned long n = 0; for (;;) n++; }\n'


def test_a_program_waiting_for_a_key_is_named_and_the_wall_limit_ends_the_run(tmp_path):
    (tmp_path / "maze.c").write_text(KEY_WAIT)
    started = time.monotonic()
    result = run_headless("--program", "1=maze.c", "--wall-limit", "6", cwd=tmp_path, timeout=120)
    assert result.returncode == 1
    assert "the run has not moved on for 3 s" in result.stderr
    assert "robot 1 (maze): waiting in KEYWait — press a key in the viewer or pass --key" in result.stderr
    assert result.stderr.count("has not moved on") == 1  # said once
    assert "wall-clock limit of 6 s is reached" in result.stderr
    assert "still running at the end (stopped)" in result.stdout
    assert time.monotonic() - started < 60


def test_a_program_computing_without_calls_is_named(tmp_path):
    (tmp_path / "plan.c").write_text(COMPUTE)
    result = run_headless("--program", "1=plan.c", "--until", "5", "--wall-limit", "6", cwd=tmp_path, timeout=120)
    assert "robot 1 (plan): no RoBIOS call for 3 s; deterministic time waits for it" in result.stderr
    assert "wall-clock limit" in result.stderr


def test_a_wall_limit_must_be_positive(tmp_path):
    done = subprocess.run(
        eyesim_command("run", "--headless", "--wall-limit", "0"),
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=60,
    )
    assert done.returncode == 2 and "--wall-limit 0: expected a positive number of seconds" in done.stderr


def test_the_testing_api_and_the_grader_say_why_a_case_stood_still(tmp_path):
    from eyesim.core.stalls import hung_status
    from eyesim.testing import Simulation, compile_program

    (tmp_path / "maze.c").write_text(KEY_WAIT)
    (tmp_path / "plan.c").write_text(COMPUTE)
    for name, words in (("maze", "waiting for a key"), ("plan", "hung: computing without RoBIOS calls")):
        program = compile_program(tmp_path / f"{name}.c", tmp_path / name)
        with Simulation() as sim:
            sim.program(1, program)
            end = sim.run(wall_timeout=6)
        assert end.reason == "watchdog"
        assert any(line.startswith(f"robot 1 ({name}): ") for line in end.stalled), end.stalled
        assert hung_status(list(end.stalled)) == words
