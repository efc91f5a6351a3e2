"""What a program starts ends with it: `eyesim run` gives every program a process group of its own
(a job on Windows), so a child it left running does not outlive the run."""

from __future__ import annotations

import random
import subprocess

from support.programs import run_headless


def test_a_childs_process_ends_with_the_run(tmp_path):
    marker = f"{random.randint(100000, 999999)}"
    (tmp_path / "spawner.py").write_text(
        f"import subprocess\nsubprocess.Popen(['sleep', '{marker}'])\nfrom eye import *\nwhile True:\n    OSWait(100)\n"
    )
    result = run_headless("--program", "1=spawner.py", "--until", "2", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "still running at the end (stopped)" in result.stdout
    left = subprocess.run(["pgrep", "-f", f"sleep {marker}"], capture_output=True, text=True)
    assert left.stdout == ""
