"""The C codec (robios/src/codec.c) against the shared protocol vectors, via robios/tests/test_protocol.c."""

from __future__ import annotations

import os
import shlex
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_c_codec_matches_every_shared_vector(tmp_path):
    exe = tmp_path / "test_protocol"
    compiler = shlex.split(os.environ.get("CC") or "cc")
    command = [
        *compiler,
        "-std=c11",
        "-Wall",
        "-Wextra",
        "-Werror",
        f"-I{ROOT / 'robios' / 'src'}",
        f"-I{ROOT / 'robios' / 'tests'}",
        str(ROOT / "robios" / "tests" / "test_protocol.c"),
        str(ROOT / "robios" / "src" / "codec.c"),
        "-o",
        str(exe),
    ]
    built = subprocess.run(command, capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    ran = subprocess.run([str(exe)], capture_output=True, text=True, timeout=30)
    assert ran.returncode == 0, ran.stdout + ran.stderr
    assert ran.stdout.startswith("ok:")
