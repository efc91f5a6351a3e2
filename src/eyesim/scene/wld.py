"""The .wld world format: floor size, wall segments in nested frames, start pose, floor texture.

Reading is tolerant, as the real files need: a malformed line is skipped with a warning, never
an error (see docs/file-formats.md, section "World files").
"""

from __future__ import annotations

import difflib
import math

from eyesim.scene.description import Location, ObjectPlacement, Pose, Wall, World
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.lexer import Line, format_number, number, quote_token, split_lines
from eyesim.scene.limits import MAX_OBJECTS, MAX_WALLS, too_many

KEYWORDS = ("width", "height", "floor", "push", "pop", "position", "floor_texture", "ball")
DEFAULT_WALL = Wall(0, 0, 0, 0)
BALL_TYPE = "Soccer"


class _Frame:
    """A local frame: rotation (cos, sin) and translation, mapping local points to world ones."""

    __slots__ = ("c", "s", "tx", "ty", "phi")

    def __init__(self, c=1.0, s=0.0, tx=0.0, ty=0.0, phi=0.0):
        self.c, self.s, self.tx, self.ty, self.phi = c, s, tx, ty, phi

    def apply(self, x: float, y: float) -> tuple[float, float]:
        return (_clean(self.c * x - self.s * y + self.tx), _clean(self.s * x + self.c * y + self.ty))

    def child(self, x: float, y: float, phi: float) -> "_Frame":
        tx, ty = self.c * x - self.s * y + self.tx, self.s * x + self.c * y + self.ty
        total = self.phi + phi
        angle = math.radians(total)
        return _Frame(math.cos(angle), math.sin(angle), tx, ty, total)


def _clean(value: float) -> float:
    """Round away floating-point noise from rotations (cos 90 deg is 6e-17, not 0)."""
    return round(value, 6) + 0.0


def parse_wld(text: str, source: str, diagnostics: Diagnostics, where: dict | None = None) -> World:
    """A World from .wld text; the floor texture stays as written (resolved by the loader).
    `where`, when given, receives the location of the 'floor_texture' reference."""
    reader = _WorldReader(source, diagnostics)
    for line in split_lines(text, source, diagnostics, comment_chars=";#", strict=False):
        reader.statement(line)
        if reader.refused:  # past a limit: the rest would only cost time
            break
    if where is not None and reader.texture_at is not None:
        where["floor_texture"] = reader.texture_at
    return reader.world()


class _WorldReader:
    def __init__(self, source: str, diagnostics: Diagnostics):
        self.source = source
        self.diagnostics = diagnostics
        self.frame = _Frame()
        self.stack: list[_Frame] = []
        self.walls: list[Wall] = []
        self.balls: list[ObjectPlacement] = []
        self.width: float | None = None
        self.height: float | None = None
        self.texture: str | None = None
        self.start: Pose | None = None
        self.texture_at: Location | None = None
        self.refused = False

    def world(self) -> World:
        return World(
            self.source, self.width, self.height, tuple(self.walls), self.texture, self.start, objects=tuple(self.balls)
        )

    def where(self, line: Line, index: int = 0) -> Location:
        return Location(self.source, line.number, line.tokens[index].column)

    def skip(self, line: Line, message: str, index: int = 0, code: str = "malformed-line") -> None:
        self.diagnostics.warning(self.where(line, index), f"{message}; line skipped", code)

    def statement(self, line: Line) -> None:
        word = line.keyword
        if number(word) is not None:
            self.wall(line)
            return
        handler = getattr(self, "kw_" + word.lower(), None) if word.lower() in KEYWORDS else None
        if handler is None:
            hint = difflib.get_close_matches(word.lower(), KEYWORDS, n=1)
            also = f" (did you mean '{hint[0]}'?)" if hint else ""
            expected = ", ".join(KEYWORDS)
            self.skip(
                line,
                f"unknown keyword {quoted(word)}{also}: expected a wall (4, 6 or 9 numbers) or one of {expected}",
                code="unknown-keyword",
            )
            return
        handler(line)

    def numbers(self, line: Line, counts: tuple[int, ...], what: str, first: int = 1) -> list[float] | None:
        """The numeric arguments, or None after a warning when they are not `counts` numbers."""
        tokens = line.tokens[first:]
        values = []
        for i, token in enumerate(tokens):
            value = number(token.text)
            if value is None:
                self.skip(line, f"{what}: expected a number, found {quoted(token.text)}", first + i)
                return None
            values.append(value)
        if len(values) not in counts:
            wanted = " or ".join(
                [", ".join(str(c) for c in counts[:-1]), str(counts[-1])] if len(counts) > 1 else [str(counts[0])]
            )
            found = f" ({quoted(' '.join(t.text for t in tokens))})" if tokens else ""
            self.skip(
                line,
                f"{what}: expected {wanted} numbers, found {len(values)}{found}",
                min(first + len(values), len(line.tokens) - 1),
            )
            return None
        return values

    def wall(self, line: Line) -> None:
        values = self.numbers(line, (4, 6, 9), "wall", first=0)
        if values is None:
            return
        x1, y1 = self.frame.apply(values[0], values[1])
        x2, y2 = self.frame.apply(values[2], values[3])
        thickness, height, color = DEFAULT_WALL.thickness, DEFAULT_WALL.height, DEFAULT_WALL.color
        if len(values) >= 6:
            if values[4] <= 0 or values[5] <= 0:
                self.skip(
                    line,
                    f"wall thickness and height must be positive, found "
                    f"{format_number(values[4])} and {format_number(values[5])}",
                    4,
                )
                return
            thickness, height = values[4], values[5]
        if len(values) == 9:
            rgb = values[6:9]
            if any(c < 0 or c > 255 or c != int(c) for c in rgb):
                bad = next(i for i, c in enumerate(rgb) if c < 0 or c > 255 or c != int(c))
                self.skip(
                    line,
                    f"wall colour: expected whole numbers 0..255, found {quoted(line.tokens[6 + bad].text)}",
                    6 + bad,
                )
                return
            color = (int(rgb[0]), int(rgb[1]), int(rgb[2]))
        if (x1, y1) == (x2, y2):
            self.skip(line, "zero-length wall: start and end are the same point", 0, code="degenerate-wall")
            return
        if len(self.walls) == MAX_WALLS:
            too_many(MAX_WALLS + 1, MAX_WALLS, "walls", self.where(line), self.diagnostics, "a world")
            self.refused = True
            return
        self.walls.append(Wall(x1, y1, x2, y2, thickness, height, color))

    def size(self, line: Line, what: str) -> float | None:
        values = self.numbers(line, (1,), what)
        if values is None:
            return None
        if values[0] <= 0:
            self.skip(line, f"{what} must be positive, found {quoted(line.tokens[1].text)}", 1)
            return None
        return values[0]

    def kw_width(self, line: Line) -> None:
        value = self.size(line, "width")
        if value is not None:
            self.width = value

    def kw_height(self, line: Line) -> None:
        value = self.size(line, "height")
        if value is not None:
            self.height = value

    def kw_floor(self, line: Line) -> None:
        values = self.numbers(line, (2,), "floor <width> <height>")
        if values is None:
            return
        if values[0] <= 0 or values[1] <= 0:
            self.skip(line, "floor width and height must be positive", 1)
            return
        self.width, self.height = values

    def kw_push(self, line: Line) -> None:
        values = self.numbers(line, (2, 3), "push <x> <y> <phi>")
        if values is not None:
            self.stack.append(self.frame)
            self.frame = self.frame.child(values[0], values[1], values[2] if len(values) == 3 else 0.0)

    def kw_pop(self, line: Line) -> None:
        if len(line.tokens) > 1:
            self.diagnostics.warning(
                self.where(line, 1),
                f"pop takes no arguments, found {quoted(line.tokens[1].text)}; ignored",
                "malformed-line",
            )
        if self.stack:  # a pop on an empty stack is ignored, as EyeSim did
            self.frame = self.stack.pop()

    def kw_position(self, line: Line) -> None:
        values = self.numbers(line, (2, 3), "position <x> <y> <phi>")
        if values is not None:
            x, y = self.frame.apply(values[0], values[1])
            phi = (values[2] if len(values) == 3 else 0.0) + self.frame.phi
            self.start = Pose(x, y, _clean(phi))

    def kw_ball(self, line: Line) -> None:
        values = self.numbers(line, (2,), "ball <x> <y>")
        if values is not None:
            x, y = self.frame.apply(values[0], values[1])
            if len(self.balls) == MAX_OBJECTS:
                too_many(MAX_OBJECTS + 1, MAX_OBJECTS, "objects", self.where(line), self.diagnostics)
                self.refused = True
                return
            self.balls.append(ObjectPlacement(BALL_TYPE, Pose(x, y, 0.0), self.where(line)))

    def kw_floor_texture(self, line: Line) -> None:
        if len(line.tokens) != 2:
            found = quoted(" ".join(t.text for t in line.tokens[1:])) if len(line.tokens) > 1 else "nothing"
            self.skip(
                line,
                f"floor_texture: expected one image path (quote it if it has spaces), found {found}",
                min(1, len(line.tokens) - 1),
            )
            return
        self.texture = line.tokens[1].text
        self.texture_at = self.where(line, 1)


def write_wld(world: World) -> str:
    """World as .wld text in the VR-saved style (floor, walls in world coordinates)."""
    out = ["# EyeSim world file (written by eyesim convert)"]
    if world.floor_width is not None and world.floor_height is not None:
        out.append(f"floor {format_number(world.floor_width)} {format_number(world.floor_height)}")
    else:
        if world.floor_width is not None:
            out.append(f"width {format_number(world.floor_width)}")
        if world.floor_height is not None:
            out.append(f"height {format_number(world.floor_height)}")
    if world.floor_texture is not None:
        out.append(f"floor_texture {quote_token(world.floor_texture)}")
    if world.start_pose is not None:
        p = world.start_pose
        out.append(f"position {format_number(p.x)} {format_number(p.y)} {format_number(p.phi)}")
    for ball in world.objects:
        out.append(f"ball {format_number(ball.pose.x)} {format_number(ball.pose.y)}")
    for w in world.walls:
        coords = " ".join(format_number(v) for v in (w.x1, w.y1, w.x2, w.y2))
        if w.color != DEFAULT_WALL.color:
            extra = " ".join(format_number(v) for v in (w.thickness, w.height, *w.color))
            out.append(f"{coords} {extra}")
        elif (w.thickness, w.height) != (DEFAULT_WALL.thickness, DEFAULT_WALL.height):
            out.append(f"{coords} {format_number(w.thickness)} {format_number(w.height)}")
        else:
            out.append(coords)
    return "\n".join(out) + "\n"
