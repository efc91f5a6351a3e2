"""Building real C programs with `eyesim cc` and running `eyesim run` as a separate process."""

from __future__ import annotations

import contextlib
import csv
import re
import shutil
import subprocess
import sys
from pathlib import Path

from support.rooms import Run

PROGRAMS = Path(__file__).resolve().parents[1] / "e2e" / "programs"


def eyesim_command(*args: str) -> list[str]:
    """`eyesim ARGS` as users run it: the console script installed beside the Python running the
    tests. (Not `python -m eyesim`: that puts the working directory first on sys.path, where a
    student's `traceback.py` would stand in for the standard library's.)"""
    return [str(Path(sys.executable).with_name("eyesim")), *args]


def build(name: str, out_dir: Path, *flags: str) -> Path:
    """Compile tests/e2e/programs/<name>.c with `eyesim cc`; return the executable."""
    output = out_dir / name
    result = subprocess.run(
        eyesim_command("cc", *flags, str(PROGRAMS / f"{name}.c"), "-o", str(output)),
        capture_output=True,
        text=True,
        cwd=out_dir,
    )
    assert result.returncode == 0, result.stderr
    return output


def run_headless(*args: str, cwd: Path, timeout: float = 120, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(
        eyesim_command("run", "--headless", "--port", "0", *args),
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=timeout,
        env=env,
    )


def scene_runner(directory: Path):
    """run(scene, {robot: program}, *args, env=None, timeout=120) -> rooms.Run of `eyesim run --headless`.

    Programs are copied into `directory` first and the simulator runs there: programs run in their
    own directory, so files they write land in it."""

    def run(
        scene: Path, robot_programs: dict[int, Path], *args: str, env: dict | None = None, timeout: float = 120
    ) -> Run:
        options = []
        for robot, program in robot_programs.items():
            local = directory / program.name
            if not local.exists():
                shutil.copy(program, local)
            options += ["--program", f"{robot}={local}"]
        return Run(run_headless(str(scene), *options, *args, cwd=directory, timeout=timeout, env=env))

    return run


def read_trajectory(path: Path) -> dict[int, list[dict]]:
    """Rows of a --record CSV by robot id, values as floats."""
    robots: dict[int, list[dict]] = {}
    with open(path) as file:
        for row in csv.DictReader(file):
            robots.setdefault(int(row["robot"]), []).append({k: float(v) for k, v in row.items()})
    return robots


def program_builder(source_dir: Path, out_dir: Path):
    """build(name) -> <source_dir>/<name>.c compiled once with `eyesim cc -O2 -Wall -Wextra -Werror`."""
    built: dict[str, Path] = {}

    def build_once(name: str) -> Path:
        if name not in built:
            output = out_dir / name
            result = subprocess.run(
                eyesim_command(
                    "cc", "-O2", "-Wall", "-Wextra", "-Werror", str(source_dir / f"{name}.c"), "-o", str(output)
                ),
                capture_output=True,
                text=True,
            )
            assert result.returncode == 0, result.stderr
            built[name] = output
        return built[name]

    return build_once


@contextlib.contextmanager
def simulator_with_viewer(*args: str, cwd: Path, token: bool = False):
    """`eyesim run ARGS` with its viewer on a free port, without its access token unless `token`
    (the tests of the token); yields (process, viewer URL)."""
    no_token = () if token else ("--no-token",)
    process = subprocess.Popen(
        eyesim_command("run", "--port", "0", "--viewer-port", "0", *no_token, *args),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        cwd=cwd,
    )
    try:
        url = None
        for line in process.stdout:
            match = re.search(r"viewer: (http://\S+)", line)
            if match:
                url = match.group(1)
                break
        assert url, "the simulator printed no viewer URL"
        yield process, url
    finally:
        process.terminate()
        process.wait(timeout=10)
