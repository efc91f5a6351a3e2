"""The limits of what a scene may hold (docs/file-formats.md, section "Limits").

Each one keeps loading and building within seconds and a few hundred MB: past a limit a file is
refused with an error (code `limit`) that names the limit, at the line where it was passed, never
a hang, a MemoryError or a traceback. They are far above anything the real scene files need
(the largest corpus world has 443 walls in 10 kB).
"""

from __future__ import annotations

from eyesim.scene.description import Location
from eyesim.scene.diagnostics import Diagnostics

MAX_FILE_BYTES = 4 * 1024 * 1024  # any scene, world, maze, robot or object file (text or JSON)
MAX_LINES = 100_000  # lines of a keyword file (.sim, .wld, .maz, .robi, .esObj)
MAX_LINE_CHARS = 10_000  # characters of one line of a keyword file
MAX_WALLS = 20_000  # walls of one world (a maze's after joining)
MAX_ROBOTS = 256
MAX_OBJECTS = 2_000  # the world's balls and crates and the scene's objects together
MAX_MARKERS = 10_000
MAX_PATH_BYTES = 4_096  # bytes of a file name in a scene (program, world, definition, model, texture): Linux's PATH_MAX
MAX_NAME_BYTES = 255  # bytes of one folder or file name in it: NAME_MAX of common file systems

LIMIT = "limit"  # the diagnostic code


def read_limited(path) -> bytes:
    """The file's bytes, reading at most one byte past MAX_FILE_BYTES (so a huge file, a device or
    a growing file costs no more than that). Raises OSError like open()."""
    with open(path, "rb") as file:
        return file.read(MAX_FILE_BYTES + 1)


def file_too_big(data: bytes, source: str, diagnostics: Diagnostics) -> bool:
    if len(data) <= MAX_FILE_BYTES:
        return False
    diagnostics.error(
        Location(source),
        f"the file is larger than {MAX_FILE_BYTES // (1024 * 1024)} MB, the limit for a scene file: not read",
        LIMIT,
    )
    return True


def lines_too_long(text: str, source: str, diagnostics: Diagnostics) -> bool:
    """True, after an error at the first offending line, when a keyword file has more than
    MAX_LINES lines or a line longer than MAX_LINE_CHARS."""
    lines = text.split("\n")
    count = len(lines) - (lines[-1] == "")  # a last newline ends a line, it does not start one
    if count > MAX_LINES:
        diagnostics.error(
            Location(source, MAX_LINES + 1),
            f"the file has {count} lines, more than {MAX_LINES}, the limit for a scene file: not read",
            LIMIT,
        )
        return True
    if max(map(len, lines)) <= MAX_LINE_CHARS:  # the common case, without a Python loop
        return False
    number = next(n for n, line in enumerate(lines, start=1) if len(line) > MAX_LINE_CHARS)
    diagnostics.error(
        Location(source, number),
        f"the line is {len(lines[number - 1])} characters long, more than "
        f"{MAX_LINE_CHARS}, the limit for a line of a scene file: not read",
        LIMIT,
    )
    return True


def path_too_long(reference: str) -> str | None:
    """Why a file name written in a scene is past the limits ("is ...", "has ..."), or None. Counted
    in bytes of UTF-8, as the file system counts."""
    size = len(reference.encode("utf-8", "replace"))
    if size > MAX_PATH_BYTES:
        return f"is {size} bytes long, more than {MAX_PATH_BYTES}, the limit for a file name"
    longest = max((len(part.encode("utf-8", "replace")) for part in reference.replace("\\", "/").split("/")))
    if longest > MAX_NAME_BYTES:
        return f"has a folder or file name of {longest} bytes, more than {MAX_NAME_BYTES}, the limit of the file system"
    return None


def too_many(
    count: int, limit: int, what: str, where: Location, diagnostics: Diagnostics, scope: str = "a scene"
) -> bool:
    """True, after an error at `where`, when `count` things are more than `limit`."""
    if count <= limit:
        return False
    diagnostics.error(where, f"more than {limit} {what}, the limit for {scope}", LIMIT)
    return True
