"""The program token with a real `eyesim run` and real C programs built with `eyesim cc`: a program
started by hand connects through the run's token file with no step of its own; a wrong
EYESIM_TOKEN is refused with the reason; the file goes with the run; --no-token is loopback only."""

import os
import signal
import stat
import subprocess
from pathlib import Path

from support.programs import build, eyesim_command, run_headless


def _start_run(tmp_path, *args: str) -> tuple[subprocess.Popen, str, Path | None]:
    """`eyesim run` on a free port; (process, port, token file it printed)."""
    simulator = subprocess.Popen(
        eyesim_command("run", "--headless", "--clock", "realtime", "--port", "0", *args),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=tmp_path,
    )
    port, token_file = None, None
    line = simulator.stdout.readline()
    while "programs connect to" not in line:
        assert line, "the simulator did not start: " + simulator.stderr.read()
        line = simulator.stdout.readline()
    port = line.rsplit(":", 1)[1].split()[0]
    if "--no-token" not in args:
        line = simulator.stdout.readline()
        assert line.startswith("EyeSim: program token for programs started by hand (as this user): "), line
        token_file = Path(line.split(": ", 2)[2].strip())
    return simulator, port, token_file


def _hand_started(program: Path, port: str, **env: str) -> subprocess.Popen:
    environment = {k: v for k, v in os.environ.items() if k not in ("EYESIM_TOKEN", "EYESIM_ROBOT")}
    return subprocess.Popen(
        [str(program)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=dict(environment, EYESIM_PORT=port, **env),
    )


def test_a_hand_started_program_connects_through_the_token_file_and_a_wrong_token_is_refused(tmp_path):
    program = build("wait_forever", tmp_path)
    simulator, port, token_file = _start_run(tmp_path)
    try:
        assert token_file.parent == Path(os.environ["EYESIM_STATE_DIR"])  # the tests' state folder
        assert token_file.name == f"program-token-{port}"
        assert stat.S_IMODE(token_file.stat().st_mode) == 0o600
        token = token_file.read_text().strip()

        wrong = _hand_started(program, port, EYESIM_TOKEN="not-the-token")
        out, err = wrong.communicate(timeout=30)
        assert wrong.returncode == 4, out + err  # ES_EXIT_REFUSED
        assert out == ""
        assert (
            f"eyesim: the simulator at 127.0.0.1:{port} refused this program: this program sent a wrong program token"
        ) in err
        assert "[it sent EYESIM_TOKEN]" in err and token not in err

        hand_started = _hand_started(program, port)  # no EYESIM_TOKEN: the file
        assert hand_started.stdout.readline().strip() == "ready"
        hand_started.kill()
        hand_started.communicate()

        simulator.send_signal(signal.SIGINT)  # Ctrl-C: the run ends as usual
        _, err = simulator.communicate(timeout=30)
        assert "refused a program from 127.0.0.1" in err and "wrong program token" in err
        assert not token_file.exists()
    finally:
        simulator.kill()
        simulator.communicate()


def test_a_program_without_any_token_is_told_how_to_get_one(tmp_path):
    program = build("wait_forever", tmp_path)
    simulator, port, token_file = _start_run(tmp_path)
    try:
        elsewhere = tmp_path / "another-state-folder"  # as for another user: no token file there
        refused = _hand_started(program, port, EYESIM_STATE_DIR=str(elsewhere))
        out, err = refused.communicate(timeout=30)
        assert refused.returncode == 4, out + err
        assert "this simulator wants its program token, and this program sent none" in err
        assert str(token_file) in err  # where a program of the same user finds it
        assert f"[EYESIM_TOKEN is not set and {elsewhere / f'program-token-{port}'} cannot be read]" in err
    finally:
        simulator.kill()
        simulator.communicate()


def test_no_token_lets_a_program_in_without_one(tmp_path):
    program = build("wait_forever", tmp_path)
    simulator, port, _ = _start_run(tmp_path, "--no-token")
    try:
        assert not any(Path(os.environ["EYESIM_STATE_DIR"]).glob(f"program-token-{port}"))
        client = _hand_started(program, port, EYESIM_STATE_DIR=str(tmp_path / "nowhere"))
        assert client.stdout.readline().strip() == "ready"
        client.kill()
        client.communicate()
    finally:
        simulator.kill()
        simulator.communicate()


def test_no_token_is_refused_on_an_address_other_machines_reach(tmp_path):
    result = run_headless("--no-token", "--host", "0.0.0.0", "--until", "1", cwd=tmp_path)
    assert result.returncode == 2
    assert "--no-token: 0.0.0.0 can be reached from other machines" in result.stderr
