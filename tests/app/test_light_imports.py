"""Commands that do not simulate do not load the simulator: the command table and everything that
reads a recording import no MuJoCo (0.25 s here, seconds under Wine), and no matplotlib or aiohttp
until a command uses them."""

import subprocess
import sys

PROBE = """
import sys
from eyesim.app import cli
cli.build_parser()
import eyesim.record.recording, eyesim.record.timeline, eyesim.record.signals
from eyesim.record import Recording
print(sorted(m for m in ("mujoco", "matplotlib", "aiohttp", "dask") if m in sys.modules))
"""


def test_the_command_table_and_reading_recordings_load_no_simulator():
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"
