"""A custom check (kind = "python") scores what its function returns: a score 0..1 is kept as the
check's score, True and False score 1 and 0, anything else fails the check with a message."""

from __future__ import annotations

from eyesim.grade import checks

EXTRA = """
def half(sim):
    return 0.5, "half way"

def whole(sim):
    return True

def too_much(sim):
    return 2
"""


def judged(function: str, context: dict) -> dict:
    return checks.judge(None, {"kind": "python", "file": "extra.py", "function": function}, context)


def test_a_custom_check_keeps_the_score_its_function_returns():
    context = {"python_modules": {}, "python_checks": {"extra.py": EXTRA}}
    half = judged("half", context)
    assert (half["passed"], half["score"], half["message"], half["evidence"]) == (
        False,
        0.5,
        "half way",
        {"score": 0.5},
    )
    whole = judged("whole", context)
    assert (whole["passed"], whole["score"]) == (True, 1.0)
    too_much = judged("too_much", context)
    assert (too_much["passed"], too_much["score"]) == (False, 0.0)
    assert too_much["message"] == "custom check too_much returned 2, not a score 0..1"
