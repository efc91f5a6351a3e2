"""A program's output as the console and the viewer get it: whole lines, and Windows' \\r\\n line
ends as \\n (a lone \\r, as in a progress line, stays)."""

from __future__ import annotations

import os

from eyesim.programs.program_output import ProgramOutput


def test_crlf_line_ends_become_newlines():
    read_end, write_end = os.pipe()
    shown = []
    with os.fdopen(read_end, "rb") as pipe:
        output = ProgramOutput({"stdout": pipe}, lambda stream, text: shown.append(text))
        os.write(write_end, b"first\r\nsecond\r\n50%\r100%\r\n")
        os.close(write_end)
        output.read("stdout")
    assert shown == ["first\n", "second\n", "50%\r100%\n"]
