"""A refused call prints "eyesim: <function>: <reason>" with the function named once."""

from support.programs import build, run_headless


def test_errors_name_the_function_once(tmp_path):
    program = build("errors_name_once", tmp_path, "-Wall", "-Wextra", "-Werror")
    result = run_headless("--program", f"1={program}", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "[robot 1] results 1 1 1 1" in result.stdout
    errors = [line.removeprefix("[robot 1] ") for line in result.stderr.splitlines() if "eyesim: " in line]
    assert errors == [
        "eyesim: VWDrive: the point (10, 100) cannot be reached on an arc: dx must be at least |dy| (and above 0)",
        "eyesim: LIDARSet: range 0 is not a field of view of 1..360 degrees",
        "eyesim: SERVOSet: robot 1 (S4) has no servo 9 (its servos: none)",
        "eyesim: SIMGetRobot: no robot 9 (0 = this robot, 1..1 = the scene's)",
    ]
