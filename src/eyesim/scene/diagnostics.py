"""Collecting the warnings and errors of a load, and the one exception a bad file raises."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Location:
    """Where something came from, for messages: file, 1-based line and column (0 = unknown)."""

    file: str
    line: int = 0
    column: int = 0

    def __str__(self) -> str:
        if self.line and self.column:
            return f"{self.file}:{self.line}:{self.column}"
        if self.line:
            return f"{self.file}:{self.line}"
        return self.file


@dataclass(frozen=True)
class Diagnostic:
    """A warning or error found while loading: kind ('error' | 'warning'), where, and what.

    `code` names the kind of problem for programs (e.g. 'missing-file', 'unknown-keyword')."""

    kind: str
    location: Location
    message: str
    code: str = ""

    def __str__(self) -> str:
        return f"{self.location}: {self.kind}: {self.message}"


class SceneError(Exception):
    """A scene, world, robot or object file has errors; `diagnostics` lists every problem found
    (errors and warnings, in the order they were found)."""

    def __init__(self, diagnostics):
        self.diagnostics = sorted(diagnostics, key=_order)
        super().__init__(str(self))

    def __str__(self) -> str:
        return "\n".join(str(d) for d in self.diagnostics)

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.kind == "error"]


class Diagnostics:
    """The problems found while loading one file and the files it references."""

    def __init__(self) -> None:
        self.items: list[Diagnostic] = []

    def error(self, location: Location, message: str, code: str = "syntax") -> None:
        self.items.append(Diagnostic("error", location, message, code))

    def warning(self, location: Location, message: str, code: str = "syntax") -> None:
        self.items.append(Diagnostic("warning", location, message, code))

    def extend(self, items) -> None:
        self.items.extend(items)

    @property
    def has_errors(self) -> bool:
        return any(d.kind == "error" for d in self.items)

    @property
    def warnings(self) -> tuple[Diagnostic, ...]:
        return tuple(d for d in self.items if d.kind == "warning")

    def raise_if_errors(self) -> None:
        if self.has_errors:
            raise SceneError(self.items)


def _order(d: Diagnostic):
    """Sort key: by file, then line and column; unplaced messages first in their file."""
    return (d.location.file, d.location.line, d.location.column)


def sorted_diagnostics(items) -> list[Diagnostic]:
    return sorted(items, key=_order)


def quoted(text: str, limit: int = 60) -> str:
    """Offending text for a message: quoted, shortened, control characters made visible."""
    shown = text if len(text) <= limit else text[: limit - 3] + "..."
    return repr(shown) if not shown.isprintable() or "'" in shown else f"'{shown}'"
