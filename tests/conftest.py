"""Shared test setup: makes tests/support importable and points at the shared corpus."""

import os
import re
import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
if str(TESTS) not in sys.path:
    sys.path.insert(0, str(TESTS))


def corpus_missing() -> str | None:
    """Why the tests that read the shared corpus of real EyeSim files cannot run, or None."""
    from support.corpus import CORPUS

    if (CORPUS / "MANIFEST.tsv").is_file():
        return None
    return (
        f"the shared corpus of real EyeSim files is missing: expected {CORPUS} "
        f"(shared/ beside the checkout, as CI provides it)"
    )


def pytest_sessionstart(session):
    missing = corpus_missing()
    if missing and os.environ.get("CI", "").lower() in ("1", "true", "yes"):
        pytest.exit(missing, returncode=2)  # CI has it: its absence is a broken setup, not a skip


_skipped_for_corpus: list[str] = []
READS_CORPUS = re.compile(r"\bCORPUS\b|\bcorpus_\w+\(|\brobi_snapshot\b")  # the path, or helpers over it


def pytest_ignore_collect(collection_path, config):
    """Outside CI, without the corpus, the test modules that read it are left out (some read it
    when imported), and the session says so in one line at its end."""
    if collection_path.suffix != ".py" or not collection_path.name.startswith("test_") or not corpus_missing():
        return None
    if READS_CORPUS.search(collection_path.read_text(encoding="utf-8")):
        _skipped_for_corpus.append(collection_path.name)
        return True
    return None


def pytest_terminal_summary(terminalreporter):
    if _skipped_for_corpus:
        terminalreporter.write_line(
            f"skipped {len(_skipped_for_corpus)} test module(s) that read the shared corpus: {corpus_missing()}"
        )


@pytest.fixture(autouse=True, scope="session")
def state_folder(tmp_path_factory):
    """What EyeSim remembers between runs (the recent scenes) goes to a folder of this test
    session, for every simulator the tests start, never to the home folder."""
    os.environ["EYESIM_STATE_DIR"] = str(tmp_path_factory.mktemp("eyesim-state"))
