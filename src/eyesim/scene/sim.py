"""The .sim scene format (all three dialects) as a document of references, and its writer.

Parsing does not open the files a scene names; the loader resolves the document into a Scene.
A placement line (`S4 500 500 0 prog.x`, `Can 800 300 45`, `S4 S 90 maze.x`) is kept as
written because whether a name is a robot or an object depends on the files it loads.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from typing import Any

from eyesim.scene.description import Location, Marker, Pose, Settings
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.keyword_reader import KeywordReader
from eyesim.scene.lexer import Line, format_number, integer, number, quote_token, split_lines

SETTING_FLAGS = ("vis", "trace", "eyesim6psd")
SETTING_VALUES = {
    "psdnoise": ("psd_noise", "a standard deviation in mm >= 0"),  # NAME=value settings
    "seed": ("seed", "a whole number"),
    "calltime": ("call_time", "a time in ms from 0 to 1000"),
}
MAX_CALL_TIME_MS = 1000  # more is surely a mistake of units (a call taking seconds)
KEYWORDS = ("world", "maze", "settings", "robi", "robot", "obj", "object", "marker")


@dataclass(frozen=True)
class Reference:
    """A file named in a scene, as written, and where."""

    path: str
    location: Location | None = None


@dataclass(frozen=True)
class Placement:
    """One thing placed by a scene, as written. Exactly one of `type_name` (a robot or object
    type), `robi` (EyeSim 6: define and place the robot of that file) or `model` (EyeSim 6:
    an obstacle from that 3-D model) is set. The position is x, y (mm) and phi (deg), or a maze
    start letter `start` with an optional heading `phi`, or nothing (EyeSim 6 `robi` lines:
    the world's start position)."""

    type_name: str | None = None
    x: float | None = None
    y: float | None = None
    phi: float | None = None
    start: str | None = None
    program: str | None = None
    robi: str | None = None
    model: str | None = None
    friction: float | None = None
    location: Location | None = None

    @property
    def pose(self) -> Pose | None:
        """Where it is placed when the line gives x and y (phi 0 unless given), else None."""
        if self.x is None or self.y is None:
            return None
        return Pose(self.x, self.y, self.phi or 0.0)


@dataclass(frozen=True)
class SimDocument:
    """A .sim file: the world it uses, loaded robot and object definitions, placements in file
    order, markers and settings."""

    source: str
    world: Reference | None = None
    settings: Settings = Settings()
    robot_files: tuple[Reference, ...] = ()
    object_files: tuple[Reference, ...] = ()
    placements: tuple[Placement, ...] = ()
    markers: tuple[Marker, ...] = ()


def parse_sim(text: str, source: str, diagnostics: Diagnostics, where: dict | None = None) -> SimDocument:
    reader = _SceneReader(source, diagnostics)
    for line in split_lines(text, source, diagnostics):
        reader.statement(line)
    return reader.document()


class _SceneReader(KeywordReader):
    def __init__(self, source: str, diagnostics: Diagnostics):
        super().__init__(source, diagnostics)
        self.world: Reference | None = None
        self.flags: set[str] = set()
        # Settings field -> value, of that field's type (setting_value reads SEED as a whole number)
        self.values: dict[str, Any] = {}
        self.robot_files: list[Reference] = []
        self.object_files: list[Reference] = []
        self.placements: list[Placement] = []
        self.markers: list[Marker] = []

    def document(self) -> SimDocument:
        settings = Settings(
            "vis" in self.flags, "trace" in self.flags, eyesim6_psd="eyesim6psd" in self.flags, **self.values
        )
        return SimDocument(
            self.source,
            self.world,
            settings,
            tuple(self.robot_files),
            tuple(self.object_files),
            tuple(self.placements),
            tuple(self.markers),
        )

    def statement(self, line: Line) -> None:
        handler = getattr(self, "kw_" + line.keyword.lower(), None) if not line.tokens[0].quoted else None
        if handler is None:
            self.placement(line)
        else:
            handler(line)

    def usage(self, line: Line, form: str) -> None:
        found = quoted(" ".join(t.text for t in line.args)) if line.args else "nothing"
        self.error(line, f"{line.keyword}: expected {form}, found {found} (quote paths that contain spaces)")

    def kw_world(self, line: Line) -> None:
        if len(line.args) != 1:
            self.usage(line, f"one world file ({line.keyword} <file.wld|file.maz>)")
            return
        if self.world is not None:
            self.diagnostics.warning(
                self.at(line),
                f"a second world statement: {quoted(line.args[0].text)} replaces {quoted(self.world.path)}",
                "second-world",
            )
        self.world = Reference(line.args[0].text, self.at(line, 1))

    kw_maze = kw_world

    def kw_settings(self, line: Line) -> None:
        for i, token in enumerate(line.args, start=1):
            flag, _, value = token.text.lower().partition("=")
            if flag in SETTING_FLAGS and not value:
                self.flags.add(flag)
            elif flag in SETTING_VALUES:
                self.setting_value(line, i, flag, value)
            else:
                hint = difflib.get_close_matches(flag, [*SETTING_FLAGS, *SETTING_VALUES], n=1, cutoff=0.6)
                also = f" (did you mean {hint[0].upper()}?)" if hint else ""
                self.diagnostics.warning(
                    self.at(line, i),
                    f"unknown setting {quoted(token.text)} ignored{also}: "
                    "expected VIS, TRACE, EYESIM6PSD, PSDNOISE=<mm>, SEED=<n> or CALLTIME=<ms>",
                    "unknown-setting",
                )

    def setting_value(self, line: Line, index: int, flag: str, text: str) -> None:
        field, expected = SETTING_VALUES[flag]
        value = integer(text) if field == "seed" else number(text)
        if not text:
            self.error(line, f"settings: {flag.upper()} needs a value: {flag.upper()}=<{expected}>", index, "bad-value")
            return
        if (
            value is None
            or (field == "psd_noise" and value < 0)
            or (field == "call_time" and not 0 <= value <= MAX_CALL_TIME_MS)
        ):
            self.error(line, f"settings: {flag.upper()} expects {expected}, found {quoted(text)}", index, "bad-value")
            return
        self.values[field] = value

    def kw_robi(self, line: Line) -> None:
        args = line.args
        if len(args) == 1:
            self.robot_files.append(Reference(args[0].text, self.at(line, 1)))
        elif len(args) in (2, 5):
            x = y = phi = None
            if len(args) == 5:
                values = self.numbers(line, 3, ("x in mm", "y in mm", "phi in degrees"))
                if values is None:
                    return
                x, y, phi = values
            self.placements.append(
                Placement(robi=args[0].text, program=args[1].text, x=x, y=y, phi=phi, location=self.at(line))
            )
        else:
            self.usage(line, f"{line.keyword} <file.robi>, or {line.keyword} <file.robi> <program> [<x> <y> <phi>]")

    kw_robot = kw_robi

    def kw_obj(self, line: Line) -> None:
        args = line.args
        if len(args) == 1:
            self.object_files.append(Reference(args[0].text, self.at(line, 1)))
        elif len(args) == 5:
            values = self.numbers(line, 1, ("x in mm", "y in mm", "phi in degrees", "friction"))
            if values is not None:
                self.placements.append(
                    Placement(
                        x=values[0],
                        y=values[1],
                        phi=values[2],
                        friction=values[3],
                        model=args[4].text,
                        location=self.at(line),
                    )
                )
        else:
            self.usage(line, f"{line.keyword} <file.esObj>, or {line.keyword} <x> <y> <phi> <friction> <model>")

    kw_object = kw_obj

    def kw_marker(self, line: Line) -> None:
        args = line.args
        if len(args) not in (2, 5, 6):
            self.usage(line, "marker <x> <y> [<r> <g> <b> [<alpha>]]")
            return
        values = self.numbers(line, 1, ("x in mm", "y in mm"))
        color = [255, 0, 0, 255]
        for i, token in enumerate(args[2:]):
            value = integer(token.text)
            if value is None or not 0 <= value <= 255:
                self.error(line, f"marker: expected a colour value 0..255, found {quoted(token.text)}", 3 + i)
                return
            color[i] = value
        if values is not None:
            r, g, b, a = color
            self.markers.append(Marker(values[0], values[1], (r, g, b, a)))

    def placement(self, line: Line) -> None:
        name, args = line.keyword, line.args
        form = f"{name} <x> <y> <phi> [<program>], or {name} <maze start letter> [<phi>] [<program>]"
        if not args:
            self.error(
                line,
                f"unknown keyword {quoted(name)}: expected a keyword (world, maze, settings, robi, "
                f"robot, obj, object, marker) or a placement ({form})",
            )
            return
        first = args[0].text
        if number(first) is not None:
            if len(args) < 2:
                self.error(line, f"{name}: expected <x> <y> <phi> after the type name, found only {quoted(first)}")
                return
            values = self.numbers(line, 1, ("x in mm", "y in mm"))
            rest = list(args[2:])
            phi = number(rest[0].text) if rest else None
            if phi is not None:
                rest.pop(0)
            if len(rest) > 1:
                self.error(
                    line,
                    f"{name}: expected at most <x> <y> <phi> <program>, found extra "
                    f"{quoted(' '.join(t.text for t in rest[1:]))}",
                    len(line.tokens) - len(rest) + 1,
                )
                return
            if values is not None:
                self.placements.append(
                    Placement(
                        type_name=name,
                        x=values[0],
                        y=values[1],
                        phi=phi if phi is not None else 0.0,
                        program=rest[0].text if rest else None,
                        location=self.at(line),
                    )
                )
        elif len(first) == 1 and first.isalpha() and not args[0].quoted:
            rest = list(args[1:])
            phi = number(rest[0].text) if rest else None
            if phi is not None:
                rest.pop(0)
            if len(rest) > 1:
                self.error(
                    line,
                    f"{name}: expected at most <letter> <phi> <program>, found extra "
                    f"{quoted(' '.join(t.text for t in rest[1:]))}",
                    len(line.tokens) - len(rest) + 1,
                )
                return
            self.placements.append(
                Placement(
                    type_name=name, start=first, phi=phi, program=rest[0].text if rest else None, location=self.at(line)
                )
            )
        else:
            self.error(
                line,
                f"{name}: expected a position (<x> <y> <phi>) or a maze start letter, found {quoted(first)} ({form})",
                1,
            )


def write_sim(document: SimDocument) -> str:
    """SimDocument as .sim text: definitions first, then placements in order, then markers."""
    f = format_number
    out = ["# EyeSim scene (written by eyesim convert)"]
    if document.world is not None:
        out.append(f"world {quote_token(document.world.path)}")
    settings = document.settings
    flags = [
        name
        for name, on in (("VIS", settings.vis), ("TRACE", settings.trace), ("EYESIM6PSD", settings.eyesim6_psd))
        if on
    ]
    if settings.psd_noise:
        flags.append(f"PSDNOISE={f(settings.psd_noise)}")
    if settings.seed:
        flags.append(f"SEED={settings.seed}")
    if settings.call_time is not None:
        flags.append(f"CALLTIME={f(settings.call_time)}")
    if flags:
        out.append("settings " + " ".join(flags))
    out += [f"robot {quote_token(r.path)}" for r in document.robot_files]
    out += [f"object {quote_token(r.path)}" for r in document.object_files]
    for p in document.placements:
        program = f" {quote_token(p.program)}" if p.program is not None else ""
        if p.robi is not None:
            out.append(f"robi {quote_token(p.robi)} {quote_token(p.program or '')}{_pose(p)}")
        elif p.model is not None:
            out.append(f"object{_pose(p)} {f(p.friction or 0.0)} {quote_token(p.model)}")
        else:
            assert p.type_name is not None, "a placement is of a type_name, a robi or a model"
            if p.start is not None:
                phi = f" {f(p.phi)}" if p.phi is not None else ""
                out.append(f"{_type_token(p.type_name)} {p.start}{phi}{program}")
            else:
                out.append(f"{_type_token(p.type_name)}{_pose(p)}{program}")
    for m in document.markers:
        color = " ".join(str(c) for c in (m.color if m.color[3] != 255 else m.color[:3]))
        out.append(f"marker {f(m.x)} {f(m.y)} {color}")
    return "\n".join(out) + "\n"


def _pose(p: Placement) -> str:
    """' <x> <y> <phi>' of a placement at a position, '' of one that has none."""
    if p.x is None or p.y is None:
        return ""
    return f" {format_number(p.x)} {format_number(p.y)} {format_number(p.phi or 0.0)}"


def _type_token(name: str) -> str:
    """A type name for the start of a placement line: quoted when it would read as a keyword."""
    token = quote_token(name)
    return f'"{name}"' if token == name and name.lower() in KEYWORDS else token
