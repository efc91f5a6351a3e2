"""The .maz ASCII maze format: rows of '|' and '_' with start letters, balls and crates.

A maze is kept as its rows (that is also its JSON form) and turned into a World on demand.
Decisions on the open points are in docs/file-formats.md, section "Maze files".
"""

from __future__ import annotations

from dataclasses import dataclass

from eyesim.scene.description import Location, Marker, ObjectPlacement, Pose, StartPosition, Wall, World
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.lexer import format_number, number

DEFAULT_CELL_SIZE = 360.0  # mm, EyeSim's default
START_HEADINGS = {"s": 90.0, "u": 90.0, "d": 270.0, "l": 180.0, "r": 0.0}
OBJECT_TYPES = {"o": "Soccer", "x": "Crate"}
FINISH_COLOR = (0, 200, 0, 255)


@dataclass(frozen=True)
class MazeDocument:
    """A maze file: its rows top to bottom and the cell size (None = not given, 360 mm).
    `row_lines` are the rows' line numbers in the source, for messages."""

    rows: tuple[str, ...]
    cell_size: float | None = None
    row_lines: tuple[int, ...] = ()

    @property
    def size(self) -> float:
        return self.cell_size if self.cell_size is not None else DEFAULT_CELL_SIZE


def parse_maz(text: str, source: str, diagnostics: Diagnostics, where: dict | None = None) -> MazeDocument:
    """The rows and cell size of .maz text. A line holding only a number is the cell size; it
    may be the first or the last non-blank line (when both, the last wins). Lines starting with
    '#' are comments. Blank lines before the first and after the last row are ignored."""
    lines = [(n, raw.rstrip()) for n, raw in enumerate(text.split("\n"), start=1)]
    content = [(n, raw) for n, raw in lines if raw.strip() and not raw.lstrip().startswith("#")]
    if not content:
        diagnostics.error(Location(source, 1, 1), "empty maze: expected rows of '|', '_' and spaces", "empty-file")
        return MazeDocument(())
    sizes: list[tuple[int, float, str]] = []
    for position in (0, len(content) - 1):
        n, raw = content[position]
        value = number(raw.strip())
        if value is not None and (not sizes or sizes[-1][0] != n):
            sizes.append((n, value, raw.strip()))
    cell_size = None
    for n, value, raw in sizes:
        if value <= 0:
            diagnostics.error(Location(source, n, 1), f"cell size must be a positive number of mm, found {quoted(raw)}")
        else:
            cell_size = value
    if len(sizes) == 2 and sizes[0][1] != sizes[1][1] and cell_size is not None:
        diagnostics.warning(
            Location(source, sizes[0][0], 1),
            f"two cell sizes ({sizes[0][2]} on the first line, {sizes[1][2]} on the last); the last one is used",
            "conflicting-size",
        )
    size_lines = {n for n, _, _ in sizes}
    body = [(n, raw) for n, raw in content if n not in size_lines]
    if not body:
        diagnostics.error(
            Location(source, content[0][0], 1), "no maze rows: expected lines of '|', '_' and spaces", "empty-file"
        )
        return MazeDocument((), cell_size)
    first, last = body[0][0], body[-1][0]
    rows, row_lines = [], []
    for n, raw in lines[first - 1 : last]:
        if raw.lstrip().startswith("#"):
            continue
        if raw.strip() and number(raw.strip()) is not None:
            diagnostics.warning(
                Location(source, n, 1),
                "a cell size line between maze rows is ignored: put it on the first or last line",
                "misplaced-size",
            )
            continue
        rows.append(raw)
        row_lines.append(n)
    return MazeDocument(tuple(rows), cell_size, tuple(row_lines))


def maze_world(maze: MazeDocument, source: str, diagnostics: Diagnostics) -> World:
    """The World a maze stands for. Row n (0 = top) has its baseline at y = (N-1-n) * size; a
    character in column i sits at X(i) = ((i+1) // 2) * size (the EyeSim rule, which also
    copes with symbols in the 'wrong' column)."""
    s = maze.size
    count = len(maze.rows)
    horizontal: set[tuple[float, float]] = set()  # (x_left, y) of unit walls
    vertical: set[tuple[float, float]] = set()  # (x, y_bottom)
    starts: list[StartPosition] = []
    objects: list[ObjectPlacement] = []
    markers: list[Marker] = []
    unknown: set[str] = set()
    width = 0.0
    for n, row in enumerate(maze.rows):
        y = (count - 1 - n) * s
        line = maze.row_lines[n] if n < len(maze.row_lines) else n + 1
        for i, c in enumerate(row):
            if c == " ":
                continue
            x = ((i + 1) // 2) * s
            width = max(width, x)
            where = Location(source, line, i + 1)
            if c == "|":
                vertical.add((x, y))
            elif c == "_":
                if i > 0:  # column 0 is a corner: a wall there would lie left of the maze
                    horizontal.add((x - s, y))
            elif c == ".":
                pass  # a post between cells: no wall
            elif c in "Ff":
                cx = max(x, s) - s / 2
                markers.append(Marker(cx, y + s / 2, FINISH_COLOR))
            elif c.lower() in START_HEADINGS or c.lower() in OBJECT_TYPES:
                cx = max(x, s) - s / 2
                if c.isupper():
                    horizontal.add((cx - s / 2, y))
                pose_at = (cx, y + s / 2)
                if c.lower() in START_HEADINGS:
                    starts.append(StartPosition(c, Pose(*pose_at, START_HEADINGS[c.lower()])))
                else:
                    objects.append(ObjectPlacement(OBJECT_TYPES[c.lower()], Pose(*pose_at, 0.0), where))
            elif c not in unknown:
                unknown.add(c)
                diagnostics.warning(
                    where,
                    f"unknown maze character {quoted(c)} ignored: expected one of "
                    f"'|', '_', ' ', '.', 'F' or a start (SUDLR), ball (o) or crate (x) letter",
                    "unknown-character",
                )
    walls = _merged(horizontal, s, horizontal=True) + _merged(vertical, s, horizontal=False)
    return World(
        source,
        width,
        (count - 1) * s if count > 1 else s,
        tuple(walls),
        None,
        None,
        tuple(starts),
        tuple(objects),
        tuple(markers),
    )


def _merged(units: set[tuple[float, float]], s: float, horizontal: bool) -> list[Wall]:
    """Unit-cell walls joined into the longest straight runs (fewer bodies for the physics)."""
    lines: dict[float, list[float]] = {}
    for a, b in units:
        along, across = (a, b) if horizontal else (b, a)
        lines.setdefault(across, []).append(along)
    walls = []
    for across in sorted(lines):
        starts = sorted(lines[across])
        run_start = previous = starts[0]
        for value in starts[1:] + [None]:
            if value is not None and abs(value - (previous + s)) < 1e-9:
                previous = value
                continue
            end = previous + s
            if horizontal:
                walls.append(Wall(run_start, across, end, across))
            else:
                walls.append(Wall(across, run_start, across, end))
            if value is not None:
                run_start = previous = value
    return walls


def write_maz(maze: MazeDocument) -> str:
    text = "\n".join(maze.rows) + "\n"
    if maze.cell_size is not None:
        text += format_number(maze.cell_size) + "\n"
    return text
