"""Where things are in a TOML file: the line of each table and key, so spec errors can say
`spec.toml:14`. tomllib gives values but no positions; this scanner follows table headers,
arrays of tables and keys line by line (values spanning lines are skipped over)."""

from __future__ import annotations

import re

HEADER = re.compile(r"^\[\[\s*(?P<array>[^\]]+?)\s*\]\]|^\[\s*(?P<table>[^\]]+?)\s*\]")
KEY = re.compile(r"""^(?P<key>(?:[A-Za-z0-9_-]+|"[^"]*"|'[^']*')(?:\s*\.\s*(?:[A-Za-z0-9_-]+|"[^"]*"|'[^']*'))*)\s*=""")


def _names(dotted: str) -> list[str]:
    parts = re.findall(r"""[A-Za-z0-9_-]+|"[^"]*"|'[^']*'""", dotted)
    return [p[1:-1] if p[0] in "\"'" else p for p in parts]


def key_lines(text: str) -> dict[tuple, int]:
    """Path (names and array indices, as in the parsed document) -> 1-based line."""
    lines: dict[tuple, int] = {}
    counts: dict[tuple, int] = {}  # array of tables -> index of its last element

    def resolve(names: list[str]) -> tuple:
        path: tuple = ()
        for name in names:
            path += (name,)
            if path in counts:
                path += (counts[path],)
        return path

    current: tuple = ()
    in_string = None  # the quote of a multi-line string we are inside
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if in_string:
            if line.count(in_string) % 2 == 1:
                in_string = None
            continue
        if not line or line.startswith("#"):
            continue
        header = HEADER.match(line)
        if header:
            if header["array"]:
                names = _names(header["array"])
                array = resolve(names[:-1]) + (names[-1],)
                counts[array] = counts.get(array, -1) + 1
                current = array + (counts[array],)
            else:
                current = resolve(_names(header["table"]))
            lines.setdefault(current, number)
            continue
        key = KEY.match(line)
        if key:
            lines.setdefault(current + tuple(_names(key["key"])), number)
            for quote in ('"""', "'''"):
                if line.count(quote) % 2 == 1:
                    in_string = quote
    return lines


def line_of(lines: dict[tuple, int], path: tuple) -> int | None:
    """The line of `path`, or of its nearest enclosing table or key that has one."""
    path = tuple(path)
    while path:
        if path in lines:
            return lines[path]
        path = path[:-1]
    return None
