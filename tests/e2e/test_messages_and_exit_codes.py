"""What a person sees at the end of a run: the version, crashes in words, the exit code of a program
that was exiting when the run ended, Ctrl-C's status, and `make demo` on other ports."""

from __future__ import annotations

import os
import signal
import subprocess
from pathlib import Path

from support.programs import build, eyesim_command, run_headless

from eyesim import __version__

ROOT = Path(__file__).resolve().parents[2]
CRASH = '#include "eyebot.h"\nint main(void) { LCDPrintf("x"); volatile int *p = 0; *p = 1; return 0; }\n'
WAIT = (
    '#include <stdio.h>\n#include "eyebot.h"\nint main(void) { printf("ready\\n"); fflush(stdout); '
    "for (;;) OSWait(100); }\n"
)


def compile_c(source: str, path: Path) -> Path:
    path.with_suffix(".c").write_text(source)
    done = subprocess.run(
        eyesim_command("cc", str(path.with_suffix(".c")), "-o", str(path)), capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    return path


def test_version():
    done = subprocess.run(eyesim_command("--version"), capture_output=True, text=True)
    assert (done.returncode, done.stdout.strip()) == (0, f"eyesim {__version__}")


def test_a_crash_is_named_in_the_summary(tmp_path):
    program = compile_c(CRASH, tmp_path / "crash")
    result = run_headless("--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 1
    assert "program crash: crashed: segmentation fault (SIGSEGV)" in result.stdout
    assert "exit code -11" not in result.stdout


def test_a_program_that_closed_its_connection_at_until_is_reported_with_its_exit_code(tmp_path):
    """slow_exit.c closes its connection, then takes 300 ms of wall time to exit with status 3;
    --until comes meanwhile (a few ms of wall time later). It is not "still running (stopped)"."""
    program = build("slow_exit", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--until", "0.2", "--program", f"1={program}", cwd=tmp_path)
    assert "[robot 1] last call at 0 ms" in result.stdout
    assert "EyeSim: stopped at t=0.200 s" in result.stdout
    assert "program slow_exit: exit code 3" in result.stdout, result.stdout
    assert result.returncode == 1  # a program that exited non-zero failed


def test_the_testing_api_reports_the_exit_code_of_a_program_exiting_at_until(tmp_path, eyesim_sim):
    program = build("slow_exit", tmp_path, "-Wall", "-Wextra", "-Werror")
    sim = eyesim_sim()
    sim.program(1, program)
    end = sim.run(until=0.2, end_with_programs=False)
    assert end.reason == "time"
    assert sim.robot(1).exit_code == 3 and sim.robot(1).stdout == "last call at 0 ms\n"


def test_ctrl_c_ends_the_run_with_status_130(tmp_path):
    program = compile_c(WAIT, tmp_path / "wait")
    process = subprocess.Popen(
        eyesim_command("run", "--headless", "--port", "0", "--program", f"1={program}"),
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    try:
        for line in process.stdout:  # the program runs: the simulator is inside its loop
            if "ready" in line:
                break
        process.send_signal(signal.SIGINT)
        rest, _ = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
    assert process.returncode == 130, rest
    assert "interrupted" in rest


def test_make_demo_takes_other_ports():
    done = subprocess.run(
        ["make", "-n", "demo", "PORT=9800", "VIEWER_PORT=8081"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env={**os.environ, "MAKEFLAGS": ""},
    )
    assert done.returncode == 0, done.stderr
    run_line = next(line for line in done.stdout.splitlines() if "eyesim run" in line)
    assert "--port 9800" in run_line and "--viewer-port 8081" in run_line
