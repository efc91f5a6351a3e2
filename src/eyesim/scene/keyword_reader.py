"""What every keyword-file reader (.sim, .robi, .esObj) shares: locations, errors, argument checks."""

from __future__ import annotations

from eyesim.scene.diagnostics import Location
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.lexer import Line, number


class KeywordReader:
    def __init__(self, source: str, diagnostics: Diagnostics):
        self.source = source
        self.diagnostics = diagnostics

    def at(self, line: Line, index: int = 0) -> Location:
        """Where token `index` of the line is (0 = the keyword; past the end = the last token)."""
        return Location(self.source, line.number, line.tokens[min(index, len(line.tokens) - 1)].column)

    def error(self, line: Line, message: str, index: int = 0, code: str = "syntax") -> None:
        self.diagnostics.error(self.at(line, index), message, code)

    def dispatch(self, line: Line, keyword: str) -> None:
        """Hand the line to this reader's `kw_<keyword>` method; unknown keywords are warned about
        and the line ignored, as every EyeSim version did."""
        handler = getattr(self, "kw_" + keyword, None)
        if handler is None:
            self.unknown_keyword(line)
            return
        handler(line)

    def unknown_keyword(self, line: Line) -> None:
        self.diagnostics.warning(
            self.at(line), f"unknown keyword {quoted(line.keyword)}: line ignored", "unknown-keyword"
        )

    def arity(self, line: Line, counts: tuple[int, ...], form: str) -> bool:
        """True when the line has one of the argument counts; else reports what it should look like."""
        n = len(line.args)
        if n in counts:
            return True
        found = quoted(" ".join(t.text for t in line.args)) if line.args else "nothing"
        wanted = " or ".join(str(c) for c in counts)
        index = max(counts) + 1 if n > max(counts) else 0  # the first extra argument, or the keyword
        self.error(
            line,
            f"{line.keyword}: expected {wanted} argument{'s' if counts != (1,) else ''} "
            f"({line.keyword} {form}), found {n}: {found}",
            index,
        )
        return False

    def numbers(self, line: Line, first: int, names: tuple[str, ...]) -> list[float] | None:
        """Arguments first.. (1-based token index) as numbers; every bad one is reported."""
        values: list[float] = []
        ok = True
        for offset, name in enumerate(names):
            token = line.tokens[first + offset]
            value = number(token.text)
            if value is None:
                self.error(
                    line, f"{line.keyword}: expected {name} (a number), found {quoted(token.text)}", first + offset
                )
                ok = False
            else:
                values.append(value)
        return values if ok else None
