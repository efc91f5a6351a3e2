"""`--program 1=drive.c`: a program given as C or C++ source is compiled into a cache, rebuilt only
when its source changed, and run; a scene may name it without its extension, as EyeSim's do."""

from __future__ import annotations

import math
import os

from support.programs import read_trajectory, run_headless

from eyesim.programs.sources import COMPILER_OUTPUT

DRIVE = '#include "eyebot.h"\nint main(void) { VWStraight(%d, 300); VWWait(); LCDPrintf("done"); return 0; }\n'
DRIVE_CPP = (
    '#include "eyebot.h"\n#include <string>\nint main() { std::string s = "c++"; VWStraight(200, 300); '
    'VWWait(); LCDPrintf("%s", s.c_str()); return 0; }\n'
)


def moved(csv_path) -> float:
    path = read_trajectory(csv_path)[1]
    return math.hypot(path[-1]["x"] - path[0]["x"], path[-1]["y"] - path[0]["y"])


def cached_programs(cache) -> list:
    """The executables in the build cache (each kept with what the compiler said)."""
    return sorted(p for p in (cache / "programs").rglob("*") if p.is_file() and p.name != COMPILER_OUTPUT)


def test_a_c_source_is_compiled_once_and_run(tmp_path):
    cache = tmp_path / "cache"
    env = {**os.environ, "EYESIM_CACHE_DIR": str(cache)}
    (tmp_path / "drive.c").write_text(DRIVE % 300)
    result = run_headless("--program", "1=drive.c", "--record", "path.csv", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "program drive.c: exit code 0" in result.stdout
    assert abs(moved(tmp_path / "path.csv") - 0.300) < 0.010
    built = cached_programs(cache)
    assert len(built) == 1
    stamp = built[0].stat().st_mtime_ns

    assert run_headless("--program", "1=drive.c", cwd=tmp_path, env=env).returncode == 0
    assert cached_programs(cache) == built and built[0].stat().st_mtime_ns == stamp  # not built again

    (tmp_path / "drive.c").write_text(DRIVE % 500)  # changed: built again, and the new one runs
    result = run_headless("--program", "1=drive.c", "--record", "path2.csv", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stderr
    assert len(cached_programs(cache)) == 2
    assert abs(moved(tmp_path / "path2.csv") - 0.500) < 0.010


def test_a_cpp_source_runs_too(tmp_path):
    (tmp_path / "drive.cpp").write_text(DRIVE_CPP)
    env = {**os.environ, "EYESIM_CACHE_DIR": str(tmp_path / "cache")}
    result = run_headless("--program", "1=drive.cpp", "--record", "path.csv", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert abs(moved(tmp_path / "path.csv") - 0.200) < 0.010


def test_compile_errors_and_warnings_reach_the_console(tmp_path):
    env = {**os.environ, "EYESIM_CACHE_DIR": str(tmp_path / "cache")}
    (tmp_path / "broken.c").write_text('#include "eyebot.h"\nint main(void) {\n  int x = ;\n}\n')
    result = run_headless("--program", "1=broken.c", cwd=tmp_path, env=env)
    assert result.returncode == 1
    assert "broken.c does not compile" in result.stderr and "broken.c:3:" in result.stderr
    (tmp_path / "sloppy.c").write_text('#include "eyebot.h"\nint main(void) { LCDPrintf("%d\\n"); return 0; }\n')
    result = run_headless("--program", "1=sloppy.c", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stderr
    assert "sloppy.c:2:" in result.stderr and "warning" in result.stderr


def test_a_scene_names_the_program_without_its_extension(tmp_path):
    env = {**os.environ, "EYESIM_CACHE_DIR": str(tmp_path / "cache")}
    (tmp_path / "drive.c").write_text(DRIVE % 250)
    (tmp_path / "lab.sim").write_text("world %sim%/scenes/arena.wld\nS4 500 500 0 drive\n")
    result = run_headless("lab.sim", "--record", "path.csv", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "missing" not in result.stderr
    assert abs(moved(tmp_path / "path.csv") - 0.250) < 0.010
