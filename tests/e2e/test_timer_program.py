"""OSAttachTimer from a real C program: callbacks counted over simulated time, exactly, in a
deterministic headless run; more than 16 timers; detaching; a main thread busy-waiting for a timer."""

from support.programs import build, run_headless


def program_lines(output: str) -> list[str]:
    return [line.removeprefix("[robot 1] ") for line in output.splitlines() if line.startswith("[robot 1] ")]


def test_timer_callbacks_run_at_their_period_of_simulation_time(tmp_path):
    program = build("timers", tmp_path, "-Wall", "-Wextra", "-Werror")
    # Calls as good as free (0.1 ms): the counts below need the 18 attaches to take no time worth
    # speaking of. Timers under the default call time: tests/calls/test_timer.py.
    result = run_headless("--call-time", "0", "--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    lines = program_lines(result.stdout)
    assert lines[0] == "fast 100 after detach 100 slow 8"  # 10 ms for 1 s; 250 ms for 2 s
    assert lines[1] == "extra" + " 40" * 16  # 16 more timers of 50 ms for 2 s
    assert lines[2] == "slow at 250 500 750 1000 1250 1500 1750 2000"  # called from a callback
    assert lines[3].startswith("busy wait done after ")
    assert "eyesim: OSDetachTimer: no timer 1 is attached" in result.stderr
    assert "eyesim: OSAttachTimer: timer period 0 ms is not positive" in result.stderr


def test_timer_callbacks_beside_a_polling_loop_repeat_exactly(tmp_path):
    """Callbacks making calls while the main thread polls: every deterministic run is the same
    (it used to differ from run to run, with the threads' calls in the scheduler's order)."""
    program = build("timer_control", tmp_path, "-Wall", "-Wextra", "-Werror")
    outputs = []
    for _ in range(3):
        result = run_headless("--program", f"1={program}", cwd=tmp_path)
        assert result.returncode == 0, result.stdout + result.stderr
        assert "no longer deterministic" not in result.stderr
        outputs.append(result.stdout.splitlines()[2:])  # after the lines naming the run's port
    assert program_lines("\n".join(outputs[0]))[0].startswith("ticks 150 ")
    assert outputs[1] == outputs[0] and outputs[2] == outputs[0]
