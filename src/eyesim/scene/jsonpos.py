"""Where each value of a JSON text starts (line, column), so schema errors can point at it."""

from __future__ import annotations

import re
from json.decoder import scanstring  # type: ignore[attr-defined]  # public in the module, not in typeshed

_NUMBER = re.compile(r"-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?")
_SPACE = re.compile(r"[ \t\n\r]*")

Path = tuple  # of str (object keys) and int (array indexes)


def json_positions(text: str) -> tuple[dict[Path, tuple[int, int]], dict[Path, tuple[int, int]]]:
    """(values, keys): the 1-based (line, column) of every value by its path, and of every
    object key by the path of its value. The text must already be valid JSON."""
    scanner = _Scanner(text)
    scanner.value(())
    return scanner.values, scanner.keys


class _Scanner:
    def __init__(self, text: str):
        self.text = text
        self.i = 0
        self.values: dict[Path, tuple[int, int]] = {}
        self.keys: dict[Path, tuple[int, int]] = {}
        self.line_starts = [0] + [m.end() for m in re.finditer("\n", text)]

    def position(self, offset: int) -> tuple[int, int]:
        lo, hi = 0, len(self.line_starts) - 1
        while lo < hi:  # last line start <= offset
            mid = (lo + hi + 1) // 2
            if self.line_starts[mid] <= offset:
                lo = mid
            else:
                hi = mid - 1
        return (lo + 1, offset - self.line_starts[lo] + 1)

    def skip(self) -> None:
        self.i = self._past(_SPACE)

    def value(self, path: Path) -> None:
        self.skip()
        self.values[path] = self.position(self.i)
        c = self.text[self.i]
        if c == "{":
            self.i += 1
            self.skip()
            if self.text[self.i] == "}":
                self.i += 1
                return
            while True:
                self.skip()
                key_at = self.i
                key, self.i = scanstring(self.text, self.i + 1)
                self.keys[path + (key,)] = self.position(key_at)
                self.skip()
                self.i += 1  # ':'
                self.value(path + (key,))
                self.skip()
                c = self.text[self.i]
                self.i += 1
                if c == "}":
                    return
        elif c == "[":
            self.i += 1
            self.skip()
            if self.text[self.i] == "]":
                self.i += 1
                return
            index = 0
            while True:
                self.value(path + (index,))
                index += 1
                self.skip()
                c = self.text[self.i]
                self.i += 1
                if c == "]":
                    return
        elif c == '"':
            _, self.i = scanstring(self.text, self.i + 1)
        elif c in "tfn":
            self.i += {"t": 4, "f": 5, "n": 4}[c]
        else:
            self.i = self._past(_NUMBER)

    def _past(self, pattern: re.Pattern) -> int:
        """Where what `pattern` matches at the scanner's place ends."""
        match = pattern.match(self.text, self.i)
        assert match is not None, "the text is valid JSON: a number or (maybe empty) space is here"
        return match.end()
