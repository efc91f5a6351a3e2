"""Building real C programs with `eyesim cc` and running `eyesim run` as a separate process."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

PROGRAMS = Path(__file__).resolve().parents[1] / "e2e" / "programs"


def eyesim_command(*args: str) -> list[str]:
    return [sys.executable, "-m", "eyesim", *args]


def build(name: str, out_dir: Path, *flags: str) -> Path:
    """Compile tests/e2e/programs/<name>.c with `eyesim cc`; return the executable."""
    output = out_dir / name
    result = subprocess.run(eyesim_command("cc", *flags, str(PROGRAMS / f"{name}.c"), "-o", str(output)),
                            capture_output=True, text=True, cwd=out_dir)
    assert result.returncode == 0, result.stderr
    return output


def run_headless(*args: str, cwd: Path, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run(eyesim_command("run", "--headless", "--port", "0", *args), capture_output=True,
                          text=True, cwd=cwd, timeout=timeout)


def read_trajectory(path: Path) -> dict[int, list[dict]]:
    """Rows of a --record CSV by robot id, values as floats."""
    robots: dict[int, list[dict]] = {}
    with open(path) as file:
        for row in csv.DictReader(file):
            robots.setdefault(int(row["robot"]), []).append({k: float(v) for k, v in row.items()})
    return robots
