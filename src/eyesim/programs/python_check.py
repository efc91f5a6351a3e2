"""`python -m eyesim.programs.python_check FILE`: is a Python program's syntax right?

Compiled with py_compile, nothing run, in a process of its own (so the program's Python, and a
parser choking on a monstrous file, cannot touch the simulator). Prints one JSON object:
{"ok": bool, "diagnostics": [{"line", "column", "kind", "message"}]}, errors and warnings
(SyntaxWarning: an invalid escape sequence, `is` with a literal, ...) at their lines."""

from __future__ import annotations

import json
import py_compile
import sys
import tempfile
import warnings
from pathlib import Path


def check(path: Path) -> dict:
    diagnostics = []
    with tempfile.TemporaryDirectory() as scratch, warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        try:
            # the byte code goes to a scratch folder: checking leaves no __pycache__ behind
            py_compile.compile(str(path), cfile=str(Path(scratch) / "checked.pyc"), doraise=True)
        except py_compile.PyCompileError as error:
            diagnostics.append(_error(error.exc_value))
    for warning in said:
        diagnostics.append(
            {
                "line": warning.lineno or 0,
                "column": None,
                "kind": "warning",
                "message": f"{warning.category.__name__}: {warning.message}",
            }
        )
    return {
        "ok": not any(d["kind"] == "error" for d in diagnostics),
        "diagnostics": sorted(diagnostics, key=lambda d: d["line"]),
    }


def _error(error: BaseException) -> dict:
    if isinstance(error, SyntaxError):  # IndentationError and TabError too
        return {
            "line": error.lineno or 0,
            "column": error.offset or None,
            "kind": "error",
            "message": f"{type(error).__name__}: {error.msg}",
        }
    return {"line": 0, "column": None, "kind": "error", "message": f"{type(error).__name__}: {error}"}  # NUL bytes


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python -m eyesim.programs.python_check FILE")
    print(json.dumps(check(Path(sys.argv[1]))))
