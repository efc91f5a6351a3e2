"""Serial, IR remote, digital/analog I/O and audio from a real C program in `eyesim run`, with the
outside world scripted by its options; serial output and sounds appear in the headless log."""

import wave

from support.programs import build, run_headless


def test_serial_irtv_io_and_audio_from_c_with_scripted_input(tmp_path):
    program = build("robot_io", tmp_path, "-Wall", "-Wextra", "-Werror")
    with wave.open(str(tmp_path / "sound.wav"), "wb") as sound:  # 0.3 s of silence
        sound.setnchannels(1)
        sound.setsampwidth(1)
        sound.setframerate(8000)
        sound.writeframes(bytes(2400))
    result = run_headless(
        "--program",
        f"1={program}",
        "--serial-loopback",
        "1:1",
        "--serial",
        "1:0:hello\\n@0.1",
        "--irtv",
        "1:OK@0.3",
        "--irtv",
        "1:7@0.3",
        "--digital",
        "1:3=1@0.2",
        "--analog",
        "1:2=700@0.2",
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    lines = [line.removeprefix("[robot 1] ") for line in result.stdout.splitlines() if line.startswith("[robot 1] ")]
    assert lines[-1] == "done"
    assert [line for line in lines if not line.startswith(("ok ", "done"))] == []
    assert len(lines) > 30
    assert "[robot 1 serial 0] hello from the robot\n[robot 1 serial 0] !\n" in result.stdout
    assert "[robot 1 serial 1]" not in result.stdout  # the loopback kept it in the robot
    assert "[robot 1 audio] beep, 0.2 s" in result.stdout
    assert "[robot 1 audio] plays sound.wav, 0.3 s" in result.stdout
    assert "eyesim: AUPlay: cannot open no-such-sound.wav" in result.stderr


def test_bad_scripted_input_is_a_usage_error(tmp_path):
    result = run_headless("--digital", "1:17=1@1", "--until", "0.1", cwd=tmp_path)
    assert result.returncode == 2
    assert (
        "eyesim run: --digital '1:17=1@1': digital: line must be a whole number from 1 to 16, not 17" in result.stderr
    )
