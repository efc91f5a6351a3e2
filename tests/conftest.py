"""Shared test setup: makes tests/support importable and points at the shared corpus."""

import os
import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:
    sys.path.insert(0, str(TESTS))


def pytest_sessionstart(session):
    from support.corpus import CORPUS

    if not (CORPUS / "MANIFEST.tsv").is_file():
        pytest.exit(f"the shared corpus of real EyeSim files is missing: expected {CORPUS} "
                    f"(shared/ beside the checkout, as CI provides it)", returncode=2)


@pytest.fixture(autouse=True, scope="session")
def state_folder(tmp_path_factory):
    """What EyeSim remembers between runs (the recent scenes) goes to a folder of this test
    session, for every simulator the tests start, never to the home folder."""
    os.environ["EYESIM_STATE_DIR"] = str(tmp_path_factory.mktemp("eyesim-state"))
