"""The generated protocol tables are up to date, and every operation has exactly one handler."""

import subprocess
import sys
from pathlib import Path

from eyesim import commands
from eyesim.protocol import generated as g

ROOT = Path(__file__).resolve().parents[2]


def test_generated_files_match_protocol_json():
    result = subprocess.run([sys.executable, str(ROOT / "protocol" / "generate.py"), "--check"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_generated_viewer_channel_code_matches_viewer_schema():
    """web/src/generated/viewer_protocol.ts and eyesim/web/viewer_schema.py follow protocol/viewer.schema.json."""
    result = subprocess.run([sys.executable, str(ROOT / "protocol" / "generate_viewer.py"), "--check"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_operation_but_the_sessions_own_has_a_handler():
    # the handshake and the library's THREADS notice are the engine's own
    missing = [op.name for op in g.OPS.values() if op.group != "session" and op.code not in commands.HANDLERS]
    assert missing == []


def test_operation_codes_are_unique_and_fit_the_header():
    codes = [op.code for op in g.OPS.values()]
    assert len(codes) == len(set(codes))
    assert all(0 < code < 65536 for code in codes)
