"""The system functions from a real C program on the second robot of a scene."""

from support.programs import build, run_headless

from eyesim.paths import DATA_DIR


def test_identity_versions_clock_and_os_execute(tmp_path):
    program = build("system_info", tmp_path, "-Wall", "-Wextra", "-Werror")
    scene = tmp_path / "two.sim"
    scene.write_text(f"world {DATA_DIR / 'scenes' / 'arena.wld'}\nS4 500 500 0\nLabBot 1500 500 90 {program}\n")
    result = run_headless(str(scene), cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    out = result.stdout
    assert "[robot 2] name LabBot id 2 type 1 speed 700000000" in out
    assert "[robot 2] version EyeSim RoBIOS-7 library 1.0 | EyeSim simulated I/O board 1.0" in out
    # OSGetTime at once after OSGetCount: reading the clock is local (10 us), and a deterministic
    # clock read never shows the same millisecond twice in a row (docs/protocol.md#what-a-call-costs)
    assert "[robot 2] clock difference 1" in out
    assert "[robot 2] execute [shell says hi\n[robot 2] second line\n[robot 2] ]" in out
    assert "[robot 2] execute null 1" in out
    assert "eyesim: OSExecute: the command is NULL" in result.stderr
