"""Shared test setup: makes tests/support importable and points at the shared corpus."""

import sys
from pathlib import Path

TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:
    sys.path.insert(0, str(TESTS))


def pytest_sessionstart(session):
    from support.corpus import CORPUS

    if not (CORPUS / "MANIFEST.tsv").is_file():
        import pytest

        pytest.exit(f"the shared corpus of real EyeSim files is missing: expected {CORPUS} "
                    f"(shared/ beside the checkout, as CI provides it)", returncode=2)
