"""Headless serial output: lines as they end, and text that never ends a line printed in parts
of LINE_LIMIT characters, so that memory stays bounded and each piece is handled once."""

from __future__ import annotations

import io

from eyesim.app.robot_log import LINE_LIMIT, RobotLog


def serial(log: RobotLog, text: str, robot: int = 1) -> None:
    log.on_event({"type": "serial", "robot": robot, "interface": 0, "text": text})


def test_lines_are_printed_as_they_end():
    out = io.StringIO()
    log = RobotLog(out)
    for piece in ("hel", "lo\nwor", "ld\n", "tail"):
        serial(log, piece)
    assert out.getvalue() == "[robot 1 serial 0] hello\n[robot 1 serial 0] world\n"
    log.flush()
    assert out.getvalue().endswith("[robot 1 serial 0] tail\n")


def test_text_without_newlines_is_printed_in_bounded_parts():
    out = io.StringIO()
    log = RobotLog(out)
    total = 5 * LINE_LIMIT + 123
    for _ in range(total):  # one character a call, as a program printing byte by byte
        serial(log, "x")
        assert log.partial_length[(1, 0)] < LINE_LIMIT
    log.flush()
    lines = out.getvalue().splitlines()
    assert [len(line) - len("[robot 1 serial 0] ") for line in lines] == [LINE_LIMIT] * 5 + [123]


def test_robots_and_interfaces_keep_their_own_lines():
    out = io.StringIO()
    log = RobotLog(out)
    serial(log, "a", robot=1)
    serial(log, "b", robot=2)
    serial(log, "c\n", robot=1)
    serial(log, "d\n", robot=2)
    assert out.getvalue() == "[robot 1 serial 0] ac\n[robot 2 serial 0] bd\n"
