"""The .robi robot format in its dialects (EyeSim 6, EyeSim VR 0.9, VR 1.x, ours) and its writer.

The dialects disagree on frames and on what some numbers mean; docs/file-formats.md, section
"Robot files", states the one rule we follow. In short: PSD positions are always in the robot
frame (x forward, y left, z up); the keywords EyeSim VR introduced for the body (mass centre,
colliders) are in VR model space (X right, Y up, Z forward) unless the file says
`dialect eyesim`; the VR wheel distance is half the track; VR 1.x files (id-first psd lines or
`fisheye`) give the camera as (right, forward, up).
"""

from __future__ import annotations

from eyesim.parts.psd.declaration import is_integer
from eyesim.scene.description import Location, RobotType
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.lexer import Line, Token, split_lines
from eyesim.scene.parts import KEYWORDS, PARTS
from eyesim.parts.part import PartReader
from eyesim.scene.robot_type import finish_robot_type

DIALECTS = ("eyesim", "eyesim6", "vr", "vr1")
VR_ONLY = ("mass", "collider", "axel", "lidar")


def parse_robi(text: str, source: str, diagnostics: Diagnostics, where: dict | None = None) -> RobotType:
    """A RobotType from .robi text; the model path stays as written (resolved by the loader).
    `where`, when given, receives the location of the 'model' reference."""
    lines = [Line(line.number, _merge_parentheses(line.tokens)) for line in split_lines(text, source, diagnostics)]
    reader = _RobotReader(source, diagnostics, detect_dialect(lines))
    for line in lines:
        reader.statement(line)
    if where is not None and "model" in reader.where:
        where["model"] = reader.where["model"]
    return reader.robot()


def _merge_parentheses(tokens: tuple[Token, ...]) -> tuple[Token, ...]:
    """'SERVO1(-90,' '+90)' -> 'SERVO1(-90,+90)': spaces inside parentheses do not split."""
    merged: list[Token] = []
    for token in tokens:
        if merged and not token.quoted and merged[-1].text.count("(") > merged[-1].text.count(")"):
            merged[-1] = Token(merged[-1].text + token.text, merged[-1].column)
        else:
            merged.append(token)
    return tuple(merged)


def detect_dialect(lines: list[Line]) -> str:
    """The file's dialect: as its `dialect` line says, else 'vr1' when it uses the id-first psd
    form or `fisheye`, 'vr' when it uses any keyword or form only EyeSim VR defines, else
    'eyesim6'."""
    found = set()
    for line in lines:
        word, args = line.keyword.lower(), line.args
        if word == "dialect" and args:
            if args[0].text.lower() in DIALECTS:
                return args[0].text.lower()
        elif word == "fisheye" or (
            word == "psd" and len(args) >= 2 and is_integer(args[0]) and not is_integer(args[1])
        ):
            found.add("vr1")
        elif (
            word in VR_ONLY
            or (word == "model" and len(args) == 7)
            or (word == "axis" and len(args) == 2)
            or (word == "wheel" and args and args[0].text.lower() in ("drive", "turn"))
        ):
            found.add("vr")
    return "vr1" if "vr1" in found else "vr" if "vr" in found else "eyesim6"


class _RobotReader(PartReader):
    """Hands each line to the part kind that declares its keyword (scene/parts/)."""

    def __init__(self, source: str, diagnostics: Diagnostics, dialect: str):
        super().__init__(source, diagnostics, dialect)
        self.errors_before = sum(d.kind == "error" for d in diagnostics.items)

    def statement(self, line: Line) -> None:
        word = line.keyword.lower()
        if word == "dialect":
            if self.arity(line, (1,), "eyesim|eyesim6|vr|vr1") and line.args[0].text.lower() not in DIALECTS:
                self.error(
                    line, f"dialect: expected one of {', '.join(DIALECTS)}, found {quoted(line.args[0].text)}", 1
                )
        elif word in KEYWORDS:
            KEYWORDS[word](self, line)
        else:
            self.unknown_keyword(line)

    def robot(self) -> RobotType:
        for part in PARTS:
            part.finish(self)
        robot = RobotType(source=self.source, **self.fields)
        if sum(d.kind == "error" for d in self.diagnostics.items) > self.errors_before:
            return robot  # the file is rejected: completing it would only add noise
        return finish_robot_type(robot, self.diagnostics, self.where, Location(self.source))


def write_robi(robot: RobotType) -> str:
    """RobotType as .robi text in our dialect (every position in the robot frame, full track)."""
    out = ["# EyeSim robot definition (written by eyesim convert)", "dialect eyesim"]
    for part in PARTS:
        out += part.write(robot)
    return "\n".join(out) + "\n"
