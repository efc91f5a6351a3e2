"""The fuzz tests' Hypothesis settings: a fixed series of examples unless FUZZ_SEED asks for
another, as many as FUZZ_EXAMPLES says (a longer run), never a deadline or a health check."""

from __future__ import annotations

import os

from hypothesis import HealthCheck, seed, settings

SEED = os.environ.get("FUZZ_SEED")


def examples(default: int) -> int:
    """How many examples a fuzz test draws: FUZZ_EXAMPLES, else the test's own default."""
    return int(os.environ.get("FUZZ_EXAMPLES", str(default)))


def fuzz_settings(count: int):
    """A decorator giving a test `count` examples, derandomized or seeded by FUZZ_SEED."""

    def apply(test):
        test = settings(
            max_examples=count,
            deadline=None,
            derandomize=SEED is None,
            database=None,
            suppress_health_check=list(HealthCheck),
        )(test)
        return seed(int(SEED))(test) if SEED is not None else test

    return apply
